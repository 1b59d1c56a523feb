#!/usr/bin/python3
"""What an extractor's false lines are, over a lines sweep (docs/lines.md): every segment of every
run's lines.csv with no matched face, placed in the world by the rig pose in the run's config.yaml
and sorted into causes by the world's round things (columns and table legs, from the world XML):
  chord r<0.1 / chord r>=0.1   both endpoints within 4 cm of one round thing's surface
  radial                       within 20 deg of the line of sight (an edge, its mixed pixels and
                               what lies behind)
  near round thing             an endpoint within 0.3 m of a round thing's surface
  other
Usage: scripts/false_lines.py SWEEP_DIR [EXTRACTOR] [--list]   (default split_and_merge)
--list prints one row per false line: cause, run id, scan, points, length m, angle to the line of
sight deg, nearest round thing (name, radius m, endpoint distance m).
"""
import collections
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import (end_quietly_when_the_reader_goes, fail, finished_results,  # noqa: E402
                          read_csv, value)

SCRIPT = "false_lines"
LINE_COLUMNS = ("extractor", "scan", "points", "truth_segment", "x1_m", "y1_m", "x2_m", "y2_m")


def read_text(path):
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except FileNotFoundError:
        fail(SCRIPT, f"{path}: no such file")
    except (OSError, UnicodeDecodeError) as error:
        fail(SCRIPT, f"{path}: cannot read: {getattr(error, 'strerror', None) or error}")


def round_things(world_xml):
    """(name, x, y, radius) of every cylinder geom (columns, table legs)."""
    things = []
    for geom in re.finditer(r"<geom\b[^>]*>", read_text(world_xml)):
        tag = geom.group(0)
        name = re.search(r'name="([^"]*)"', tag)
        pos = re.search(r'pos="(\S+) (\S+)', tag)
        size = re.search(r'size="(\S+)', tag)
        is_cylinder = 'type="cylinder"' in tag or 'class="table_leg"' in tag
        if is_cylinder and name and pos and size:
            things.append((name.group(1), float(pos.group(1)), float(pos.group(2)),
                           float(size.group(1))))
    return things


def rig_pose(config_path):
    config_text = read_text(config_path)
    world = re.search(r"^world: (.*)$", config_text, re.M)
    spawn = re.search(r"spawn:\n\s+x_m: (\S+)\n\s+y_m: (\S+)\n\s+theta_deg: (\S+)", config_text)
    if not world or not spawn:
        fail(SCRIPT, f"{config_path}: {'world' if not world else 'robot.spawn'}: not found as "
             "plywood run writes it")
    pose = []
    for text in spawn.groups():
        try:
            pose.append(float(text))
        except ValueError:
            fail(SCRIPT, f"{config_path}: robot.spawn: expected a number, got '{text}'")
    return world.group(1), pose[0], pose[1], math.radians(pose[2])


def main(sweep_dir, extractor, listing):
    causes = collections.Counter()
    total = false = 0
    rows = []
    # Every run of the sweep, each with its lines.csv: runs that failed or never finished were
    # skipped without a word, a precision over part of the sweep (s66).
    _, results, _ = finished_results(SCRIPT, sweep_dir, run_files=("config.yaml", "lines.csv"))
    runs_dir = os.path.join(sweep_dir, "runs")
    extractors = set()
    for run in sorted(r["id"] for r in results):
        path = os.path.join(runs_dir, run)
        lines_path = os.path.join(path, "lines.csv")
        world, sx, sy, theta = rig_pose(os.path.join(path, "config.yaml"))
        things = round_things(world)
        c, s = math.cos(theta), math.sin(theta)

        def to_world(x, y):
            return (sx + c * x - s * y, sy + s * x + c * y)

        _, line_rows, line_numbers = read_csv(SCRIPT, lines_path, LINE_COLUMNS)
        for line, row in zip(line_numbers, line_rows):
            extractors.add(row["extractor"])
            if row["extractor"] != extractor:
                continue
            total += 1
            if row["truth_segment"] != "":
                continue
            false += 1
            a, b = ((value(SCRIPT, lines_path, line, row, x),
                     value(SCRIPT, lines_path, line, row, y))
                    for x, y in (("x1_m", "y1_m"), ("x2_m", "y2_m")))
            length = math.dist(a, b)
            mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
            cross = abs(mid[0] * (b[1] - a[1]) - mid[1] * (b[0] - a[0]))
            to_sight = math.degrees(math.asin(min(1.0, cross / (math.hypot(*mid) * length
                                                                 + 1e-12))))
            wa, wb = to_world(*a), to_world(*b)
            nearest = None
            for name, x, y, radius in things:
                off = max(abs(math.dist(wa, (x, y)) - radius),
                          abs(math.dist(wb, (x, y)) - radius))
                if nearest is None or off < nearest[2]:
                    nearest = (name, radius, off)
            if nearest and nearest[2] < 0.04:
                cause = "chord r<0.1" if nearest[1] < 0.1 else "chord r>=0.1"
            elif to_sight < 20.0:
                cause = "radial"
            elif nearest and nearest[2] < 0.3:
                cause = "near round thing"
            else:
                cause = "other"
            causes[cause] += 1
            rows.append((cause, run, row["scan"], row["points"], f"{length:.3f}",
                         f"{to_sight:.1f}",
                         f"{nearest[0]} {nearest[1]} {nearest[2]:.3f}" if nearest else "-"))
    if total == 0:
        # An extractor no run has (a misspelt name, a flag) was "0 lines, 0 false (pooled precision
        # 1.000)" (s66).
        fail(SCRIPT, f"{sweep_dir}: extractor '{extractor}': no line of it in any run's lines.csv "
             f"(extractors there: {', '.join(sorted(extractors)) or 'none'})")
    print(f"{extractor}: {total} lines, {false} false (pooled precision "
          f"{1 - false / max(total, 1):.3f})")
    for cause, count in causes.most_common():
        print(f"  {cause}: {count}")
    if listing:
        for r in sorted(rows):
            print(*r)


if __name__ == "__main__":
    end_quietly_when_the_reader_goes()
    args = [a for a in sys.argv[1:] if a != "--list"]
    if not args or len(args) > 2:
        fail(SCRIPT, "usage: false_lines.py SWEEP_DIR [EXTRACTOR] [--list]")
    for a in args:
        if a.startswith("-"):
            fail(SCRIPT,
                 f"{a}: unknown flag (usage: false_lines.py SWEEP_DIR [EXTRACTOR] [--list])")
    main(args[0], args[1] if len(args) > 1 else "split_and_merge", "--list" in sys.argv)
