#!/usr/bin/python3
"""Where seed 001's map error comes from, over a sweep directory of sonar_explorer runs (each run
dir holding metrics.json, cognitive_map.json, walls.csv and config.yaml). Every 1 cm cell inside
the reachable free space's bounding box whose label the map gets wrong is put in one class:
  room_short    truly free, outside the map's room rectangle
  bloat_margin  truly free, in a map obstacle that overlaps a true box, within 0.12 m of a box
  obst_bloat    the same farther than 0.12 m from every box (a box joined to a wall or to another)
  obst_phantom  truly free, in a map obstacle that overlaps no box
  bridge        truly free, in a bridge between two obstacles
  box_missed    inside a true box (or wall), mapped free
  other_fp      neither free nor inside a box (behind a wall), mapped free
Each class's area / A_tot is its share of that run's e (they add up to e within the 1 cm raster).
Prints mean / 90th percentile (nearest rank) / worst e, each class's summed e over the runs, and
the TOP worst runs with their classes. Needs numpy (Debian: python3-numpy).
    scripts/sonar_map_error_causes.py SWEEP_DIR [TOP]
"""
import csv
import json
import os
import re
import sys
from collections import deque

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import fail, finished_results  # noqa: E402

try:
    import numpy as np
except ImportError:
    fail(os.path.basename(sys.argv[0]), 'needs numpy (Debian: python3-numpy)')

R = 0.01
def load(run):
    m = json.load(open(os.path.join(run, 'cognitive_map.json')))
    geoms = {}
    for row in csv.DictReader(open(os.path.join(run, 'walls.csv'))):
        g = int(row['geom_id'])
        xs = [float(row['ax_m']), float(row['bx_m'])]; ys = [float(row['ay_m']), float(row['by_m'])]
        if g in geoms:
            a = geoms[g]; geoms[g] = [min(a[0], *xs), min(a[1], *ys), max(a[2], *xs), max(a[3], *ys)]
        else:
            geoms[g] = [min(xs), min(ys), max(xs), max(ys)]
    met = json.load(open(os.path.join(run, 'metrics.json')))
    return m, list(geoms.values()), met


def spawn(run):
    # robot.spawn x_m / y_m of the run's config.yaml (the map's frame starts there).
    text = open(os.path.join(run, 'config.yaml')).read()
    block = text[text.index('spawn:'):]
    x = float(re.search(r'x_m:\s*([-0-9.eE]+)', block).group(1))
    y = float(re.search(r'y_m:\s*([-0-9.eE]+)', block).group(1))
    return x, y
def analyse(run):
    m, geoms, met = load(run)
    allr = np.array(geoms)
    X0, Y0 = allr[:, 0].min() - 0.05, allr[:, 1].min() - 0.05
    X1, Y1 = allr[:, 2].max() + 0.05, allr[:, 3].max() + 0.05
    nx, ny = int((X1 - X0) / R) + 1, int((Y1 - Y0) / R) + 1
    xc = X0 + (np.arange(nx) + 0.5) * R; yc = Y0 + (np.arange(ny) + 0.5) * R
    XX, YY = np.meshgrid(xc, yc)
    occ = np.zeros((ny, nx), bool)
    # walls: long thin geoms; boxes: others
    walls, boxes = [], []
    for g in geoms:
        w, h = g[2] - g[0], g[3] - g[1]
        (walls if min(w, h) < 0.05 and max(w, h) > 1.5 else boxes).append(g)
    for g in geoms:
        occ |= (XX >= g[0]) & (XX <= g[2]) & (YY >= g[1]) & (YY <= g[3])
    # flood from the spawn point
    px, py = spawn(run)
    sx, sy = int((px - X0) / R), int((py - Y0) / R)
    free = np.zeros_like(occ)
    q = deque([(sy, sx)]); free[sy, sx] = True
    while q:
        y, x = q.popleft()
        for dy, dx in ((1,0),(-1,0),(0,1),(0,-1)):
            a, b = y+dy, x+dx
            if 0 <= a < ny and 0 <= b < nx and not occ[a, b] and not free[a, b]:
                free[a, b] = True; q.append((a, b))
    ys_, xs_ = np.nonzero(free)
    bb = (slice(ys_.min(), ys_.max()+1), slice(xs_.min(), xs_.max()+1))
    room = m['room']
    inroom = (XX >= room[0]) & (XX <= room[2]) & (YY >= room[1]) & (YY <= room[3])
    mobs = np.zeros_like(occ); ids = np.full(occ.shape, -1)
    rects = [('o', r) for r in m['obstacles']] + [('b', r) for r in m['bridges']]
    for k, (_, r) in enumerate(rects):
        msk = (XX >= r[0]) & (XX <= r[2]) & (YY >= r[1]) & (YY <= r[3])
        mobs |= msk; ids[msk & (ids < 0)] = k
    mapfree = inroom & ~mobs
    tot = free.sum() * R * R
    cats = {}
    F = free[bb]; MF = mapfree[bb]; IR = inroom[bb]; MO = mobs[bb]; ID = ids[bb]
    cats['room_short'] = (F & ~IR).sum()
    # obstacle over-extent: split by whether rect overlaps a true box
    def overlaps(r):
        for g in boxes:
            if r[0] < g[2] and r[2] > g[0] and r[1] < g[3] and r[3] > g[1]: return True
        # a wall too (box merged to wall counts as phantom for walls)
        return False
    over = F & IR & MO
    bl, ph, br = 0, 0, 0
    for k, (kind, r) in enumerate(rects):
        n = (over & (ID == k)).sum()
        if kind == 'b': br += n
        elif overlaps(r): bl += n
        else: ph += n
    near = np.zeros_like(occ)
    for g in boxes:
        dx = np.maximum(np.maximum(g[0] - XX, XX - g[2]), 0); dy = np.maximum(np.maximum(g[1] - YY, YY - g[3]), 0)
        near |= np.hypot(dx, dy) <= 0.12
    NB = near[bb]
    bm = 0
    for k, (kind, r) in enumerate(rects):
        if kind == 'o' and overlaps(r): bm += (over & (ID == k) & NB).sum()
    cats['bloat_margin'] = bm
    cats['obst_bloat'] = bl - bm; cats['obst_phantom'] = ph; cats['bridge'] = br
    cats['box_missed'] = (~F & MF & occ[bb]).sum()
    cats['other_fp'] = (~F & MF & ~occ[bb]).sum()
    A = sum(cats.values()) * R * R
    e = {k: v * R * R / tot for k, v in cats.items()}
    return met['occupancy']['error'], e, met, len(boxes)
if __name__ == '__main__':
    SCRIPT = 'sonar_map_error_causes'
    # No folder, a TOP that is no number or a folder that is no seed 001 sweep was a traceback; a
    # sweep with runs missing gave figures over the runs that finished (s66).
    if len(sys.argv) not in (2, 3) or sys.argv[1].startswith('-'):
        fail(SCRIPT, 'usage: sonar_map_error_causes.py SWEEP_DIR [TOP]')
    if len(sys.argv) > 2 and not sys.argv[2].isdigit():
        fail(SCRIPT, f"TOP: expected a whole number >= 0, got '{sys.argv[2]}'")
    d = sys.argv[1]
    whole = finished_results(SCRIPT, d, ('occupancy.error',),
                             ('metrics.json', 'cognitive_map.json', 'walls.csv', 'config.yaml'))[1]
    rows = []
    for run in sorted(os.path.join(d, 'runs', r['id']) for r in whole):
        try:
            e, cats, met, nb = analyse(run)
        except Exception as ex:
            print('ERR', run, ex); continue
        rows.append((e, cats, met['run']['world'], met['run']['seed'], met['sensors']['bumpers']['contact_samples'], met['occupancy']['grid_error'], run, nb, met['exploration']['end_reason']))
    if not rows:
        fail(SCRIPT, f'{d}: no run could be analysed (each is an ERR line above)')
    rows.sort(key=lambda r: -r[0])
    es = np.array([r[0] for r in rows])
    srt = np.sort(es); p90 = srt[int(np.ceil(0.9 * len(srt))) - 1]
    print(f'n={len(es)} mean={es.mean():.4f} p90={p90:.4f} worst={es.max():.4f} <=0.03:{(es<=0.03).sum()} >0.10:{(es>0.10).sum()} contact_runs={sum(1 for r in rows if r[4]>0)} samples={sum(r[4] for r in rows)} grid={np.mean([r[5] for r in rows]):.4f}')
    tot = {}
    for r in rows:
        for k, v in r[1].items(): tot[k] = tot.get(k, 0) + v
    S = es.sum()
    print('sum e', round(S, 3), {k: f'{v:.3f} ({100*v/S:.0f}%)' for k, v in tot.items()})
    top = int(sys.argv[2]) if len(sys.argv) > 2 else 25
    for r in rows[:top]:
        print(f"{r[0]:.3f} grid {r[5]:.3f} {r[2]} s{r[3]} c{r[4]} nb{r[7]} {r[8][:3]} " + ' '.join(f'{k}={v:.3f}' for k, v in r[1].items() if v > 0.002) + ' ' + os.path.basename(r[6]))
