#!/usr/bin/python3
"""Finer classes of seed 001's map error than scripts/sonar_map_error_causes.py, by what the map did
(issue 14, round 34), for the runs of sweep directories whose e lies in (LO, HI]. Every 1 cm cell of
the true free space reachable from the spawn (and every true box cell) whose label the map gets
wrong is put in one class:
  room_short          truly free, outside the map's room rectangle
  ext_to_wall         truly free, in a map obstacle (or bridge) that overlaps a true box and reaches
                      a room side, between the hull of the boxes it overlaps and that side (a box
                      extended to the wall across a gap, or the strip beside it)
  fill_between_boxes  truly free, in such an obstacle, inside that hull (an L's notch, the gap
                      between two boxes mapped as one)
  margin<=0.12        truly free, in such an obstacle, outside the hull, within 0.12 m of a box
  other_bloat         the same farther off, or in an obstacle overlapping no box
  box_unmapped        inside a true box that map obstacles cover < 20 % of, mapped free
  box_short           inside a true box that map obstacles cover >= 20 % of, mapped free
  other_fp            neither free nor inside a box (behind a wall), mapped free
Prints each run (directory, world, seed, e, classes above 0.002) and the summed class e.
    scripts/sonar_map_error_mechanisms.py LO HI SWEEP_DIR [SWEEP_DIR ...]
Needs numpy (Debian: python3-numpy).
"""
import collections
import importlib.util
import json
import os
import sys
from collections import deque

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import error_range_and_sweeps, fail  # noqa: E402

try:
    import numpy as np
except ImportError:
    fail('sonar_map_error_mechanisms', 'needs numpy (Debian: python3-numpy)')

_spec = importlib.util.spec_from_file_location(
    'causes', os.path.join(os.path.dirname(os.path.abspath(__file__)), 'sonar_map_error_causes.py'))
causes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(causes)
R = 0.01


def mechanisms(run):
    m, geoms, met = causes.load(run)
    allr = np.array(geoms)
    X0, Y0 = allr[:, 0].min() - 0.05, allr[:, 1].min() - 0.05
    X1, Y1 = allr[:, 2].max() + 0.05, allr[:, 3].max() + 0.05
    nx, ny = int((X1 - X0) / R) + 1, int((Y1 - Y0) / R) + 1
    XX, YY = np.meshgrid(X0 + (np.arange(nx) + 0.5) * R, Y0 + (np.arange(ny) + 0.5) * R)
    boxes = [g for g in geoms if not (min(g[2] - g[0], g[3] - g[1]) < 0.05 and max(g[2] - g[0], g[3] - g[1]) > 1.5)]
    inside = lambda r: (XX >= r[0]) & (XX <= r[2]) & (YY >= r[1]) & (YY <= r[3])
    occ = np.zeros((ny, nx), bool)
    for g in geoms:
        occ |= inside(g)
    px, py = causes.spawn(run)
    sx, sy = int((px - X0) / R), int((py - Y0) / R)
    free = np.zeros_like(occ)
    free[sy, sx] = True
    q = deque([(sy, sx)])
    while q:
        y, x = q.popleft()
        for dy, dx in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            a, b = y + dy, x + dx
            if 0 <= a < ny and 0 <= b < nx and not occ[a, b] and not free[a, b]:
                free[a, b] = True
                q.append((a, b))
    room = m['room']
    inroom = inside(room)
    rects = list(m['obstacles']) + list(m['bridges'])
    mobs = np.zeros_like(occ)
    for r in rects:
        mobs |= inside(r)
    dbox = np.full(occ.shape, 9.0)
    for g in boxes:
        dx = np.maximum(np.maximum(g[0] - XX, XX - g[2]), 0)
        dy = np.maximum(np.maximum(g[1] - YY, YY - g[3]), 0)
        dbox = np.minimum(dbox, np.hypot(dx, dy))
    hull = np.zeros_like(occ)
    wallext = np.zeros_like(occ)
    for r in rects:
        ov = [g for g in boxes if r[0] < g[2] and r[2] > g[0] and r[1] < g[3] and r[3] > g[1]]
        if not ov:
            continue
        h = [min(g[0] for g in ov), min(g[1] for g in ov), max(g[2] for g in ov), max(g[3] for g in ov)]
        rm = inside(r)
        hull |= rm & inside(h)
        for reaches, beyond in ((r[0] <= room[0] + 1e-6, XX < h[0]), (r[2] >= room[2] - 1e-6, XX > h[2]),
                                (r[1] <= room[1] + 1e-6, YY < h[1]), (r[3] >= room[3] - 1e-6, YY > h[3])):
            if reaches:
                wallext |= rm & beyond
    over = free & inroom & mobs
    out = collections.Counter()
    out['room_short'] = (free & ~inroom).sum()
    out['fill_between_boxes'] = (over & hull).sum()
    out['ext_to_wall'] = (over & ~hull & wallext).sum()
    out['margin<=0.12'] = (over & ~hull & ~wallext & (dbox <= 0.12)).sum()
    out['other_bloat'] = (over & ~hull & ~wallext & (dbox > 0.12)).sum()
    mapfree = inroom & ~mobs
    for g in boxes:
        bm = inside(g)
        covered = (bm & mobs).sum() / max(1, bm.sum())
        out['box_unmapped' if covered < 0.2 else 'box_short'] += (bm & mapfree & ~free).sum()
    out['other_fp'] = (~free & mapfree & ~occ).sum()
    tot = free.sum()
    return met['occupancy']['error'], {k: v / tot for k, v in out.items()}, met


if __name__ == '__main__':
    SCRIPT = 'sonar_map_error_mechanisms'
    lo, hi, whole = error_range_and_sweeps(
        SCRIPT, sys.argv[1:], ('metrics.json', 'cognitive_map.json', 'walls.csv', 'config.yaml'))
    total, n, summed = collections.Counter(), 0, 0.0
    for d in sys.argv[3:]:
        for run in sorted(os.path.join(d, 'runs', r['id']) for r in whole[d]):
            if not lo < json.load(open(os.path.join(run, 'metrics.json')))['occupancy']['error'] <= hi:
                continue
            e, cl, met = mechanisms(run)
            n += 1
            summed += e
            total.update(cl)
            print(os.path.basename(os.path.normpath(d)), met['run']['world'], met['run']['seed'], f'{e:.3f}',
                  ' '.join(f'{k}={v:.3f}' for k, v in sorted(cl.items(), key=lambda kv: -kv[1]) if v > 0.002))
    print('runs', n, 'sum e', round(summed, 3), {k: round(v, 3) for k, v in total.most_common()})
