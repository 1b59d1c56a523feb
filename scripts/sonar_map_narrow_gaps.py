#!/usr/bin/python3
"""How much of each generated seed-001 room lies behind narrow gaps, and where the bad runs are.

Usage: scripts/sonar_map_narrow_gaps.py RESULTS.csv... [--share 0.9] [--worlds]

For every world a sweep's results.csv names (worlds/... under the sweep's folder), from the walls
and obstacle boxes of its MJCF: the largest clearance c (robot centre to the nearest face, 1 cm
steps from 0.20 m) at which the centre positions reachable from spawn_0 (0, 0), grown by c (the
floor the robot's body can cover), hold at least --share of the room's free floor. A room whose
figure is below the explorer's narrowest tier (squeeze_clearance_m 0.30) keeps part of its floor
behind gaps under 0.60 m. Prints, per bin of c, the worlds, the runs and the runs with
occupancy.error above 0.10 (--worlds: every world's c and its runs' errors).

Only axis-aligned boxes are read (the seed001 family's walls and obstacles); any other geom named
wall_* or obstacle_* is refused.
"""
import csv
import math
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import OneLineParser, fail, finished_results, finite  # noqa: E402

SCRIPT = "sonar_map_narrow_gaps.py"

try:
    import numpy as np
    from scipy import ndimage
except ImportError:
    sys.exit("sonar_map_narrow_gaps.py: needs numpy and scipy (Debian: python3-scipy; scripts/setup installs it)")

CELL_M = 0.01
BINS = [(0.0, 0.26), (0.26, 0.29), (0.29, 0.32), (0.32, 0.35), (0.35, 0.40), (0.40, math.inf)]


def boxes_of(world):
    boxes = []
    # A world that is not there (a sweep folder copied without worlds/) or no XML was a
    # traceback (s66 review).
    try:
        root = ET.parse(world).getroot()
    except FileNotFoundError:
        fail(SCRIPT, f"{world}: no such file (a world the sweep's results.csv names)")
    except (OSError, ET.ParseError) as error:
        fail(SCRIPT, f"{world}: cannot read: {getattr(error, 'strerror', None) or error}")
    for geom in root.iter("geom"):
        name = geom.get("name", "")
        if not name.startswith(("wall_", "obstacle_")):
            continue
        if geom.get("type", "box") != "box":
            sys.exit(f"{world}: geom {name}: only boxes are read")
        x, y = (float(v) for v in geom.get("pos").split()[:2])
        hx, hy = (float(v) for v in geom.get("size").split()[:2])
        yaw = float(geom.get("euler", "0 0 0").split()[2])
        if abs(yaw / 90.0 - round(yaw / 90.0)) > 1e-9:
            sys.exit(f"{world}: geom {name}: euler yaw {yaw} is not a multiple of 90 deg")
        if round(yaw / 90.0) % 2:
            hx, hy = hy, hx
        boxes.append((x - hx, y - hy, x + hx, y + hy))
    if not boxes:
        sys.exit(f"{world}: no wall_* or obstacle_* geoms")
    return boxes


def reachable_clearance(world, share):
    boxes = boxes_of(world)
    x0, y0 = min(b[0] for b in boxes), min(b[1] for b in boxes)
    nx = int((max(b[2] for b in boxes) - x0) / CELL_M) + 1
    ny = int((max(b[3] for b in boxes) - y0) / CELL_M) + 1
    occupied = np.zeros((ny, nx), bool)
    for bx0, by0, bx1, by1 in boxes:
        occupied[int((by0 - y0) / CELL_M):math.ceil((by1 - y0) / CELL_M),
                 int((bx0 - x0) / CELL_M):math.ceil((bx1 - x0) / CELL_M)] = True
    si, sj = int(-y0 / CELL_M), int(-x0 / CELL_M)
    parts, _ = ndimage.label(~occupied)
    if parts[si, sj] == 0:
        sys.exit(f"{world}: spawn_0 (0, 0) lies in a box")
    room = parts == parts[si, sj]
    to_face = ndimage.distance_transform_edt(~occupied) * CELL_M
    best = 0.0
    for step in range(20, 60):
        c = step / 100.0
        centres, _ = ndimage.label((to_face >= c) & room)
        if centres[si, sj] == 0:
            break
        reach = centres == centres[si, sj]
        covered = (ndimage.distance_transform_edt(~reach) * CELL_M <= c) & room
        if covered.sum() < share * room.sum():
            break
        best = c
    return best


def main():
    parser = OneLineParser(prog=SCRIPT, description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="+")
    parser.add_argument("--share", default="0.9")
    parser.add_argument("--worlds", action="store_true")
    args = parser.parse_args()
    args.share = finite(SCRIPT, "--share", args.share)
    # A results.csv that is not there was a traceback after the tables of those before it, and a
    # sweep missing runs was binned on the runs that finished (s66).
    for results in args.results:
        if os.path.basename(results) != "results.csv" or not os.path.isfile(results):
            what = "no such file" if not os.path.exists(results) else "not a sweep's results.csv"
            fail(SCRIPT, f"{results}: {what}")
        finished_results(SCRIPT, os.path.dirname(os.path.abspath(results)))
    if not 0.0 < args.share <= 1.0:
        sys.exit(f"sonar_map_narrow_gaps.py: --share must be in (0, 1], got {args.share}")
    clearance = {}
    tally = {b: [set(), 0, 0] for b in BINS}
    for results in args.results:
        folder = os.path.dirname(os.path.abspath(results))
        per_world = {}
        with open(results, newline="") as f:
            for line, row in enumerate(csv.DictReader(f), start=2):
                try:
                    world, error = row["world"], float(row["occupancy.error"])
                except (KeyError, TypeError, ValueError):
                    sys.exit(f"{results}:{line}: needs the columns world and occupancy.error")
                if world == "":
                    # The experiment's own world (a sweep without worlds:, as the shipped
                    # sonar_map_layouts.yaml): the folder itself was opened as the world, a
                    # traceback (s66 review).
                    fail(SCRIPT, f"{results}: line {line}: world: empty (the run's world is its "
                         "experiment's own): this reads the generated worlds a sweep names in "
                         "its worlds: list")
                per_world.setdefault(os.path.join(folder, world), []).append(error)
        for world, errors in sorted(per_world.items()):
            if world not in clearance:
                clearance[world] = reachable_clearance(world, args.share)
            c = clearance[world]
            for b in BINS:
                if b[0] <= c < b[1]:
                    tally[b][0].add(world)
                    tally[b][1] += len(errors)
                    tally[b][2] += sum(e > 0.10 for e in errors)
            if args.worlds:
                print(f"{os.path.relpath(world)}\t{c:.2f}\t" + " ".join(f"{e:.4f}" for e in errors))
        print(f"read {results}", file=sys.stderr, flush=True)
    print(f"| clearance c (m) at which the robot covers {args.share:.0%} of the floor | worlds | runs | runs above 0.10 |")
    print("|---|---|---|---|")
    for (lo, hi), (worlds, runs, bad) in tally.items():
        label = f">= {lo:.2f}" if hi == math.inf else f"{lo:.2f}-{hi:.2f}"
        print(f"| {label} | {len(worlds)} | {runs} | {bad} |")


if __name__ == "__main__":
    main()
