#!/usr/bin/python3
"""A sweep's summary.csv as a Markdown table: one row per group, one column per metric, each cell
"mean (95 % CI low-high)". For the tables in docs/; usage:
    scripts/sweep_table.py SWEEP_DIR [METRIC ...]     (default: every metric in summary.csv)
"""
import csv
import os
import sys


def fmt(text):
    v = float(text)
    return f"{v:.3g}" if abs(v) < 1000 else f"{v:.0f}"


def main(out_dir, metrics):
    with open(os.path.join(out_dir, "summary.csv"), newline="") as f:
        reader = csv.DictReader(f)
        groups = reader.fieldnames[: reader.fieldnames.index("metric")]
        rows = list(reader)
    metrics = metrics or list(dict.fromkeys(r["metric"] for r in rows))
    table = {}
    order = []
    for r in rows:
        key = tuple(r[g] for g in groups)
        if key not in table:
            table[key] = {}
            order.append(key)
        if r["n"] in ("", "0"):
            continue
        interval = f"{fmt(r['ci95_low'])}-{fmt(r['ci95_high'])}" if r["ci95_low"] else "one run"
        table[key][r["metric"]] = (f"{fmt(r['mean'])} ({interval})", r["n"])
    head = [g.split(".")[-1] for g in groups] + ["n"] + metrics
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for key in order:
        cells = table[key]
        n = next((v[1] for v in cells.values()), "0")
        print("| " + " | ".join(list(key) + [n] + [cells.get(m, ("-",))[0] for m in metrics]) + " |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: sweep_table.py SWEEP_DIR [METRIC ...]")
    main(sys.argv[1], sys.argv[2:])
