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
import argparse
import csv
import json
import math
import os
import sys

def read_sweep(path):
    """The rows of a sweep's results.csv and its set axes (from sweep.json beside it)."""
    folder = path if os.path.isdir(path) else os.path.dirname(path) or "."
    csv_path = os.path.join(folder, "results.csv") if os.path.isdir(path) else path
    try:
        with open(os.path.join(folder, "sweep.json")) as f:
            axes = json.load(f)["axes"]
        with open(csv_path, newline="") as f:
            reader = csv.DictReader(f)
            return reader.fieldnames, list(reader), axes
    except (OSError, KeyError, ValueError) as error:
        sys.exit(f"sweep_compare: {path}: not a finished sweep folder ({error})")


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


def paired_runs(base_path, new_path, metric):
    """The runs of two sweeps paired run by run: (pairs, shared axes, axes only NEW has, fields
    both have, NEW's rows). A run is the same run in both sweeps when its experiment file's name
    (the two may sit in different trees), world, profile, seed and the set axes both sweeps have
    agree. Axes only the new sweep has (the option under test) label its groups."""
    base_fields, base_rows, base_axes = read_sweep(base_path)
    new_fields, new_rows, new_axes = read_sweep(new_path)
    if metric not in base_fields or metric not in new_fields:
        sys.exit(f"sweep_compare: metric '{metric}' is not a column of both results.csv files")
    shared_axes = [a for a in base_axes if a in new_axes]
    extra_axes = [a for a in new_axes if a not in base_axes]
    for a in base_axes:
        if a not in new_axes and len({r[a] for r in base_rows}) > 1:
            sys.exit(f"sweep_compare: BASE sweeps '{a}' over several values and NEW does not")

    def key(row):
        return ((os.path.basename(row["experiment"]), row["world"], row["profile"], row["seed"]) +
                tuple(row[a] for a in shared_axes))

    base_by_key = {key(r): r for r in base_rows}
    pairs = [(base_by_key[key(r)], r) for r in new_rows if key(r) in base_by_key]
    if not pairs:
        sys.exit(f"sweep_compare: no run of {new_path} is in {base_path} (different sweeps?)")
    paired_base = {key(n) for _, n in pairs}
    if len(paired_base) != len(base_rows) or len(pairs) != len(new_rows):
        print(f"note: {len(base_rows) - len(paired_base)} base runs and "
              f"{len(new_rows) - len(pairs)} new runs have no partner; only pairs are compared")
    fields = [f for f in new_fields if f in base_fields]
    return pairs, shared_axes, extra_axes, fields, new_rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("--metric", default="occupancy.error")
    parser.add_argument("--threshold", type=float, default=0.10)
    parser.add_argument("--rise", type=float, default=0.02)
    parser.add_argument("--contacts", default="sensors.bumpers.contact_samples")
    parser.add_argument("--rooms", action="store_true",
                        help="also print each group read per room (mean over its runs)")
    parser.add_argument("-v", "--verbose", action="store_true")
    args = parser.parse_args()

    pairs, shared_axes, extra_axes, fields, new_rows = paired_runs(args.base, args.new,
                                                                   args.metric)

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
        if any(math.isnan(x) for x in be + ne):
            sys.exit(f"sweep_compare: a run of group {group} has no number for {args.metric}")
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
    main()
