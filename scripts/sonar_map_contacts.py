#!/usr/bin/python3
"""Where the explorer's bumper contacts happen (issue 14, stop 39), over sweep directories of
seed 001 runs. Each contact episode (a pressed sample after an unpressed one in bumpers.csv) is
placed from the truth pose at that time and the first pressed panel (Magellan Pro: panel i centred
at 22.5 i deg, ring radius 0.205 m), then matched to the nearest true face in walls.csv; it is a
corner contact when it lies within 0.06 m of that face's end, and on a box when the geom's longest
face is <= 2.5 m (room walls are longer). Panels 0, 1, 15 are the front, 2-4 and 12-14 the sides,
5-11 the rear. Runs with more than 10 episodes (a robot caught between two things) are listed and
counted apart.
    scripts/sonar_map_contacts.py SWEEP_DIR [SWEEP_DIR ...]
"""
import csv
import json
import math
import os
import statistics
import sys
from collections import Counter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import fail, finished_results  # noqa: E402

SCRIPT = 'sonar_map_contacts'


def episodes(run):
    traj = {round(float(r['time_s']), 2): r
            for r in csv.DictReader(open(os.path.join(run, 'trajectory.csv')))}
    faces = list(csv.DictReader(open(os.path.join(run, 'walls.csv'))))
    longest = Counter()
    for f in faces:
        length = math.hypot(float(f['bx_m']) - float(f['ax_m']), float(f['by_m']) - float(f['ay_m']))
        longest[f['geom_id']] = max(longest[f['geom_id']], length)
    previous = ''
    for row in csv.DictReader(open(os.path.join(run, 'bumpers.csv'))):
        pressed = row['pressed_panels']
        pose = traj.get(round(float(row['time_s']), 2))
        if pressed and not previous and pose is not None:
            panel = int(pressed.split()[0])  # space-separated indices
            bearing = float(pose['truth_theta_rad']) + math.radians(22.5 * panel)
            cx = float(pose['truth_x_m']) + 0.205 * math.cos(bearing)
            cy = float(pose['truth_y_m']) + 0.205 * math.sin(bearing)
            best = None
            for f in faces:
                ax, ay, bx, by = (float(f[k]) for k in ('ax_m', 'ay_m', 'bx_m', 'by_m'))
                vx, vy = bx - ax, by - ay
                length2 = vx * vx + vy * vy
                u = max(0.0, min(1.0, ((cx - ax) * vx + (cy - ay) * vy) / length2)) if length2 else 0.0
                distance = math.hypot(ax + u * vx - cx, ay + u * vy - cy)
                if best is None or distance < best[0]:
                    best = (distance, min(u, 1 - u) * math.sqrt(length2), f['geom_id'])
            distance, to_end, geom = best
            where = ('wall' if longest[geom] > 2.5 else 'box') + (' corner' if to_end < 0.06 else ' face')
            side = 'front' if panel in (0, 1, 15) else 'side' if panel in (2, 3, 4, 12, 13, 14) else 'rear'
            yield side, where, distance
        previous = pressed


def main(dirs):
    per_run = {}
    # Every folder a finished sweep's, each run of it counted: a missing folder was a traceback, and
    # a sweep killed half way or with failed runs was counted on the runs that finished (s66).
    whole = {d: finished_results(SCRIPT, d, run_files=('metrics.json',))[1] for d in dirs}
    for d in dirs:
        cells = {r['id']: r for r in csv.DictReader(open(os.path.join(d, 'cells.csv')))}
        for run in sorted(os.path.join(d, 'runs', r['id']) for r in whole[d]):
            path = os.path.join(run, 'metrics.json')
            if not os.path.exists(path):
                fail(SCRIPT, f'{path}: no such file (a run the sweep lists as finished)')
            metrics = json.load(open(path))
            if metrics.get('sensors', {}).get('bumpers', {}).get('contact_samples', 0) == 0:
                continue
            cell = cells.get(os.path.basename(run), {})
            name = '%s s%s' % (os.path.basename(cell.get('world', run)), cell.get('seed', '?'))
            per_run[name] = list(episodes(run))
    caught = {k: v for k, v in per_run.items() if len(v) > 10}
    rest = [e for k, v in per_run.items() if k not in caught for e in v]
    print('runs with a contact: %d, episodes: %d' % (len(per_run), sum(map(len, per_run.values()))))
    for k, v in caught.items():
        print('  caught: %s, %d episodes, %s' % (k, len(v), dict(Counter(e[0] for e in v))))
    if rest:
        print('the other %d episodes by panel and place:' % len(rest))
        for (side, where), n in sorted(Counter((e[0], e[1]) for e in rest).items(), key=lambda x: -x[1]):
            print('  %-5s %-11s %d' % (side, where, n))
        print('contact point to the face: median %.3f m, max %.3f m'
              % (statistics.median(e[2] for e in rest), max(e[2] for e in rest)))


if __name__ == '__main__':
    if len(sys.argv) < 2 or any(a.startswith('-') for a in sys.argv[1:]):
        fail(SCRIPT, 'usage: sonar_map_contacts.py SWEEP_DIR [SWEEP_DIR ...]')
    main(sys.argv[1:])
