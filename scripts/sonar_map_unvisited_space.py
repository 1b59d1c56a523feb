#!/usr/bin/python3
"""What of seed 001's map error lies in space the robot never went near (issue 14, rounds 25 and
35), for the runs of sweep directories whose e lies in (LO, HI]. From each run's walls.csv,
trajectory.csv, cognitive_map.json and metrics.json, on a 1 cm raster of the true geometry:
  unvisited  the free space the body (radius 0.205 m) can reach from the spawn, farther than
             0.6 m from every truth pose (m^2)
  regions    its 8-connected parts of at least 0.1 m^2, each as area@gap: the gap is the widest
             passage into the part, twice the largest clearance of any path from the spawn (the
             widest-path bottleneck) to one of its cells (m)
  behind     the share of the run's wrongly labelled cells within 0.3 m of the unvisited space
  e w/o      e times (1 - behind): about what e would be were that space mapped right
Also the end reason and time, contact samples and the encoder's heading / end position error.
    scripts/sonar_map_unvisited_space.py LO HI SWEEP_DIR [SWEEP_DIR ...]
Needs numpy and scipy (Debian: python3-numpy, python3-scipy).
"""
import csv
import heapq
import importlib.util
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import error_range_and_sweeps, fail  # noqa: E402

try:
    import numpy as np
    from scipy import ndimage
except ImportError:
    fail('sonar_map_unvisited_space', 'needs numpy and scipy (Debian: python3-numpy, python3-scipy)')

_spec = importlib.util.spec_from_file_location(
    'causes', os.path.join(os.path.dirname(os.path.abspath(__file__)), 'sonar_map_error_causes.py'))
causes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(causes)
R = 0.01
BODY_RADIUS = 0.205
UNVISITED_M = 0.6
NEAR_M = 0.3


def widest_path(clear, occ, start):
    """The largest bottleneck clearance of any 8-connected path from start to each cell."""
    best = np.full(clear.shape, -1.0)
    best[start] = clear[start]
    heap = [(-clear[start], start)]
    ny, nx = clear.shape
    while heap:
        c, (i, j) = heapq.heappop(heap)
        c = -c
        if c < best[i, j]:
            continue
        for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)):
            a, b = i + di, j + dj
            if 0 <= a < ny and 0 <= b < nx and not occ[a, b]:
                v = min(c, clear[a, b])
                if v > best[a, b]:
                    best[a, b] = v
                    heapq.heappush(heap, (-v, (a, b)))
    return best


def unvisited(run):
    m, geoms, met = causes.load(run)
    g = np.array(geoms)
    X0, Y0 = g[:, 0].min() - 0.05, g[:, 1].min() - 0.05
    nx, ny = int((g[:, 2].max() + 0.05 - X0) / R) + 1, int((g[:, 3].max() + 0.05 - Y0) / R) + 1
    XX, YY = np.meshgrid(X0 + (np.arange(nx) + 0.5) * R, Y0 + (np.arange(ny) + 0.5) * R)
    occ = np.zeros((ny, nx), bool)
    for r in g:
        occ |= (XX >= r[0]) & (XX <= r[2]) & (YY >= r[1]) & (YY <= r[3])
    poses = np.array([[float(r['truth_x_m']), float(r['truth_y_m'])]
                      for r in csv.DictReader(open(os.path.join(run, 'trajectory.csv')))])
    start = (int((poses[0, 1] - Y0) / R), int((poses[0, 0] - X0) / R))
    labels, _ = ndimage.label(~occ)
    free = labels == labels[start]
    clear = ndimage.distance_transform_edt(~occ) * R
    best = widest_path(clear, occ, start)
    reach = free & (clear >= BODY_RADIUS) & (best >= BODY_RADIUS)
    stood = np.zeros_like(occ)
    for x, y in poses[::5]:
        stood[int((y - Y0) / R), int((x - X0) / R)] = True
    far = reach & (ndimage.distance_transform_edt(~stood) * R > UNVISITED_M)
    parts, n = ndimage.label(far, structure=np.ones((3, 3)))
    regions = []
    for k in range(1, n + 1):
        part = parts == k
        if part.sum() * R * R >= 0.1:
            regions.append(f'{part.sum() * R * R:.2f}@{2 * best[part].max():.2f}')
    near = ndimage.distance_transform_edt(~far) * R <= NEAR_M if far.any() else np.zeros_like(occ)
    room = m['room']
    mapfree = (XX >= room[0]) & (XX <= room[2]) & (YY >= room[1]) & (YY <= room[3])
    for r in m['obstacles'] + m['bridges']:
        mapfree &= ~((XX >= r[0]) & (XX <= r[2]) & (YY >= r[1]) & (YY <= r[3]))
    ys, xs = np.nonzero(free)
    box = np.zeros_like(occ)
    box[ys.min():ys.max() + 1, xs.min():xs.max() + 1] = True
    wrong = box & (free != mapfree)
    behind = (wrong & near).sum() / max(1, wrong.sum())
    return met, far.sum() * R * R, regions, behind


if __name__ == '__main__':
    SCRIPT = 'sonar_map_unvisited_space'
    lo, hi, whole = error_range_and_sweeps(
        SCRIPT, sys.argv[1:], ('metrics.json', 'cognitive_map.json', 'walls.csv', 'trajectory.csv'))
    for d in sys.argv[3:]:
        for run in sorted(os.path.join(d, 'runs', r['id']) for r in whole[d]):
            e = json.load(open(os.path.join(run, 'metrics.json')))['occupancy']['error']
            if not lo < e <= hi:
                continue
            met, area, regions, behind = unvisited(run)
            ex, od = met['exploration'], met['odometry']['encoder']
            print(f"{os.path.basename(d)} {met['run']['world']} s{met['run']['seed']} e {e:.3f} "
                  f"grid {met['occupancy']['grid_error']:.3f} {ex['end_reason']} "
                  f"{ex['end_time_s']:.0f}s contacts {met['sensors']['bumpers']['contact_samples']} "
                  f"hdg {od['heading_error_deg']:.2f} pos {od['final_error_m']:.3f} "
                  f"unvisited {area:.2f} [{' '.join(regions)}] behind {behind:.2f} e_wo {e * (1 - behind):.3f}")
