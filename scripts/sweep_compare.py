#!/usr/bin/python3
"""Two runs of the same sweep, run by run: did a change help? For metrics that are errors (lower
is better), e.g. seed 001's occupancy.error. Pairs the runs of two sweep folders by experiment file
name, world, profile, seed and the set axes both have (from each folder's sweep.json); an axis only
NEW has (the option under test) labels the groups. Prints per group mean / p90 (nearest rank) /
worst / runs above a threshold / runs with a contact, base and new, then how many runs went down
and up, crossed the threshold either way, rose by more than --rise, and gained a contact. With -v
it lists the runs that moved most. With --rooms each group gets a second row read per room: a
room's figure is the mean over its runs (its run seeds), and mean / p90 / worst / count above the
threshold / rooms with a contact are taken over rooms (the other reading of issue 14's "no room
above 0.10"; docs/sonar_map.md, "Issue 14: where it stands").

usage: scripts/sweep_compare.py BASE NEW [--metric M] [--threshold T] [--rise R]
                                 [--contacts M] [--rooms] [-v]
BASE and NEW are finished sweep folders (or the results.csv inside one).
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import (OneLineParser, end_quietly_when_the_reader_goes, fail,  # noqa: E402
                          finished_results, finite, value)

CELL_COLUMNS = ("experiment", "world", "profile", "seed")


def read_sweep(path, metric, contacts, script="sweep_compare"):
    """The header and rows of a finished sweep's results.csv (every run of its manifest, each with
    a number for the metric and, where the column is, for the contacts) and its set axes (from
    sweep.json beside it). A folder that does not exist, a sweep with failed or unfinished runs,
    an absent column or a value that is no finite number is refused in one line (s66: tracebacks,
    a verdict over the runs that happened to finish, inf taken as a value, a null contact count
    read as no contact)."""
    if os.path.isdir(path):
        folder = path
    elif os.path.basename(path) == "results.csv" and os.path.isfile(path):
        folder = os.path.dirname(path) or "."
    elif os.path.exists(path):
        fail(script, f"{path}: not a sweep folder nor its results.csv")
    else:
        fail(script, f"{path}: no such folder")
    meta_path = os.path.join(folder, "sweep.json")
    try:
        with open(meta_path, encoding="utf-8") as f:
            axes = json.load(f)["axes"]
    except FileNotFoundError:
        fail(script, f"{meta_path}: no such file: {folder} is not a finished sweep's folder")
    except (OSError, KeyError, TypeError, ValueError) as error:
        fail(script, f"{meta_path}: axes: cannot read ({getattr(error, 'strerror', None) or error})")
    if not isinstance(axes, list) or not all(isinstance(a, str) for a in axes):
        fail(script, f"{meta_path}: axes: expected a list of names")
    fields, rows, lines = finished_results(script, folder,
                                           CELL_COLUMNS + tuple(axes) + (metric,))
    csv_path = os.path.join(folder, "results.csv")
    for line, row in zip(lines, rows):
        value(script, csv_path, line, row, metric)
        if contacts in fields:
            value(script, csv_path, line, row, contacts)
    return fields, rows, axes


def percentile(sorted_values, q):
    # Nearest rank, as scripts/sonar_map_error_causes.py and docs/sonar_map.md's tables use.
    return sorted_values[max(0, math.ceil(q * len(sorted_values)) - 1)]


def summary(values, contacts, threshold):
    v = sorted(values)
    return (f"{sum(v) / len(v):.4f} / {percentile(v, 0.9):.4f} / {v[-1]:.4f} / "
            f"{sum(x > threshold for x in v)} / {sum(c > 0 for c in contacts)}")


def print_row(label, be, ne, bc, nc, args):
    """One table row: base and new summaries, then how the paired values moved."""
    down = sum(n < b for b, n in zip(be, ne))
    up = sum(n > b for b, n in zip(be, ne))
    cross_up = sum(b <= args.threshold < n for b, n in zip(be, ne))
    cross_down = sum(n <= args.threshold < b for b, n in zip(be, ne))
    rises = sum(n - b > args.rise for b, n in zip(be, ne))
    gained = sum(c_b <= 0 < c_n for c_b, c_n in zip(bc, nc))
    print(f"| {label} | {len(be)} | {summary(be, bc, args.threshold)} | "
          f"{summary(ne, nc, args.threshold)} | {down} / {up} | {cross_up} / {cross_down} | "
          f"{rises} | {gained} |")


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def paired_runs(base_path, new_path, metric, contacts, script="sweep_compare", whole=False):
    """The runs of two sweeps paired run by run: (pairs, shared axes, axes only NEW has, fields
    both have, NEW's rows). A run is the same run in both sweeps when its experiment file's name
    (the two may sit in different trees), world, profile, seed and the set axes both sweeps have
    agree. Axes only the new sweep has (the option under test) label its groups."""
    base_fields, base_rows, base_axes = read_sweep(base_path, metric, contacts, script)
    new_fields, new_rows, new_axes = read_sweep(new_path, metric, contacts, script)
    shared_axes = [a for a in base_axes if a in new_axes]
    extra_axes = [a for a in new_axes if a not in base_axes]
    for a in base_axes:
        if a not in new_axes and len({r[a] for r in base_rows}) > 1:
            fail(script, f"BASE sweeps '{a}' over several values and NEW does not")

    def key(row):
        return ((os.path.basename(row["experiment"]), row["world"], row["profile"], row["seed"]) +
                tuple(row[a] for a in shared_axes))

    # Two runs of one sweep alike in all of these (experiment files of one name in two folders)
    # were paired with one run of the other sweep, the second silently dropped (s66).
    for path, rows, extra in ((base_path, base_rows, []), (new_path, new_rows, extra_axes)):
        seen = set()
        for r in rows:
            k = key(r) + tuple(r[a] for a in extra)
            if k in seen:
                fail(script, f"{path}: runs {r['id']} and another are alike in experiment file "
                     "name, world, profile, seed and axes: they cannot be paired run by run")
            seen.add(k)
    base_by_key = {key(r): r for r in base_rows}
    pairs = [(base_by_key[key(r)], r) for r in new_rows if key(r) in base_by_key]
    if not pairs:
        fail(script, f"no run of {new_path} is in {base_path} (different sweeps?)")
    paired_base = {key(n) for _, n in pairs}
    if whole and (len(paired_base) != len(base_rows) or len(pairs) != len(new_rows)):
        # keeping_rule.py reads the bar on whole sweeps: a verdict on the runs that happened to
        # pair is not the sweep's (s66).
        fail(script, f"{len(base_rows) - len(paired_base)} runs of {base_path} and "
             f"{len(new_rows) - len(pairs)} of {new_path} have no partner in the other sweep: "
             "the bar and the rule are read on whole sweeps of the same runs")
    if len(paired_base) != len(base_rows) or len(pairs) != len(new_rows):
        print(f"note: {len(base_rows) - len(paired_base)} base runs and "
              f"{len(new_rows) - len(pairs)} new runs have no partner; only pairs are compared")
    fields = [f for f in new_fields if f in base_fields]
    return pairs, shared_axes, extra_axes, fields, new_rows


def main():
    parser = OneLineParser(prog="sweep_compare", description=__doc__.split("\n")[0])
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("--metric", default="occupancy.error")
    parser.add_argument("--threshold", default="0.10")
    parser.add_argument("--rise", default="0.02")
    parser.add_argument("--contacts", default="sensors.bumpers.contact_samples")
    parser.add_argument("--rooms", action="store_true",
                        help="also print each group read per room (mean over its runs)")
    parser.add_argument("-v", "--verbose", action="store_true")
    args = parser.parse_args()
    # float() took nan and inf: with nan no run was above the threshold (s66).
    args.threshold = finite("sweep_compare", "--threshold", args.threshold)
    args.rise = finite("sweep_compare", "--rise", args.rise)

    pairs, shared_axes, extra_axes, fields, new_rows = paired_runs(args.base, args.new,
                                                                   args.metric, args.contacts)

    has_contacts = args.contacts in fields
    groups = {}
    for b, n in pairs:
        groups.setdefault(tuple(f"{a}={n[a]}" for a in shared_axes + extra_axes
                                if len({r[a] for r in new_rows}) > 1 or a in extra_axes),
                          []).append((b, n))
    header = ("group", "runs", f"base mean / p90 / worst / >{args.threshold:g} / contacts",
              "new", "down / up", f"cross {args.threshold:g} up / down", f"rises > {args.rise:g}",
              "new contacts")
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for group, members in sorted(groups.items()):
        be = [number(b[args.metric]) for b, _ in members]
        ne = [number(n[args.metric]) for _, n in members]
        bc = [number(b[args.contacts]) if has_contacts else 0.0 for b, _ in members]
        nc = [number(n[args.contacts]) if has_contacts else 0.0 for _, n in members]
        label = ", ".join(group) if group else "all"
        print_row(label, be, ne, bc, nc, args)
        if args.rooms:
            # A room's figure is the mean over its runs; it has a contact if any run has.
            rooms = {}
            for i, (b, _) in enumerate(members):
                rooms.setdefault(b["world"], []).append(i)
            def per_room(values, pool):
                return [pool([values[i] for i in r]) for r in rooms.values()]

            def mean(values):
                return sum(values) / len(values)

            print_row(f"{label} (rooms)", per_room(be, mean), per_room(ne, mean),
                      per_room(bc, max), per_room(nc, max), args)
        if args.verbose:
            moved = sorted(members, key=lambda p: -abs(number(p[1][args.metric]) -
                                                        number(p[0][args.metric])))
            for b, n in moved[:12]:
                delta = number(n[args.metric]) - number(b[args.metric])
                if delta == 0:
                    break
                where = os.path.basename(b["world"]) if b.get("world") else b["experiment"]
                contact = (f", contacts {b[args.contacts]} -> {n[args.contacts]}"
                           if has_contacts else "")
                print(f"    {where} s{b['seed']}: {b[args.metric]} -> {n[args.metric]} "
                      f"({delta:+.4f}{contact})")


if __name__ == "__main__":
    end_quietly_when_the_reader_goes()
    main()
