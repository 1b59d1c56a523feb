#!/usr/bin/python3
"""A sweep's summary.csv as a Markdown table: one row per group, one column per metric, each cell
"mean (95 % CI low-high)", or "low to high" where a bound is negative ("-5-6" read as a range
from -5 to -6). For the tables in docs/; usage:
    scripts/sweep_table.py SWEEP_DIR [METRIC ...]     (default: every metric in summary.csv)
n is the most runs any of the row's metrics has a value in; a cell over fewer (a metric null in
some runs) says its own n, "[n 2]". A sweep missing runs (failed, unfinished) is refused.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import (end_quietly_when_the_reader_goes, fail, finished_results,  # noqa: E402
                          read_csv, sweep_dir, value)

SCRIPT = "sweep_table"


def fmt(v):
    v += 0.0  # -0.0 (a rounded bound) would print "-0" and read as a negative bound (s67)
    return f"{v:.3g}" if abs(v) < 1000 else f"{v:.0f}"


def main(out_dir, metrics):
    sweep_dir(SCRIPT, out_dir)
    # summary.csv is over the finished runs only: a sweep with failed or unfinished runs would
    # give means and ns of part of it under the sweep's name (s66).
    finished_results(SCRIPT, out_dir)
    path = os.path.join(out_dir, "summary.csv")
    header, rows, lines = read_csv(SCRIPT, path, ("metric", "n", "mean", "ci95_low", "ci95_high"))
    if not rows:
        fail(SCRIPT, f"{path}: no rows (a header line only): no metric to tabulate")
    groups = header[: header.index("metric")]
    known = list(dict.fromkeys(r["metric"] for r in rows))
    for m in metrics:
        if m.startswith("-"):
            fail(SCRIPT, f"{m}: unknown flag (usage: sweep_table.py SWEEP_DIR [METRIC ...])")
        if m not in known:
            # A misspelt metric was a column of '-' (s66).
            fail(SCRIPT, f"{path}: metric '{m}' has no row (known: {', '.join(known) or 'none'})")
    metrics = metrics or known
    table = {}
    order = []
    for line, r in zip(lines, rows):
        key = tuple(r[g] for g in groups)
        if key not in table:
            table[key] = {}
            order.append(key)
        if not r["n"].isdigit():
            fail(SCRIPT, f"{path}: line {line}: n: expected a whole number, got '{r['n']}'")
        n = int(r["n"])
        if n == 0:
            continue
        mean = value(SCRIPT, path, line, r, "mean")
        if r["ci95_low"] == "" and n == 1:
            interval = "one run"
        else:
            low = value(SCRIPT, path, line, r, "ci95_low")
            high = value(SCRIPT, path, line, r, "ci95_high")
            # A hyphen between two bounds one of which is negative reads as "(-5-6)" (s67).
            sep = " to " if min(low, high) < 0 else "-"
            interval = f"{fmt(low)}{sep}{fmt(high)}"
        table[key][r["metric"]] = (f"{fmt(mean)} ({interval})", n)
    head = [g.split(".")[-1] for g in groups] + ["n"] + metrics
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for key in order:
        cells = table[key]
        # The row's n was its first metric's: a mean over 2 runs sat under "n 3" (s66).
        n = max((cells[m][1] for m in metrics if m in cells), default=0)
        texts = []
        for m in metrics:
            if m not in cells:
                texts.append("-")
            else:
                texts.append(cells[m][0] + ("" if cells[m][1] == n else f" [n {cells[m][1]}]"))
        print("| " + " | ".join(list(key) + [str(n)] + texts) + " |")


if __name__ == "__main__":
    end_quietly_when_the_reader_goes()
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr if len(sys.argv) < 2 else sys.stdout)
        sys.exit(2 if len(sys.argv) < 2 else 0)
    if sys.argv[1].startswith("-") and not os.path.exists(sys.argv[1]):
        fail(SCRIPT, f"{sys.argv[1]}: unknown flag (usage: sweep_table.py SWEEP_DIR [METRIC ...])")
    main(sys.argv[1], sys.argv[2:])
