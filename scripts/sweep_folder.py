"""A sweep folder as the scripts that read one take it (sweep_table.py, sweep_compare.py,
keeping_rule.py, plot_sweep.py, false_lines.py): bad input is one line on stderr naming the file
and the field (or the flag), exit 2, never a Python traceback and never a table over fewer runs
than the sweep has (s66 fifty-sixth pass). Exit 2 as plywood's bad input: keeping_rule.py's 1
means "not kept", which a refusal must not read as.
"""
import argparse
import collections
import csv
import math
import os
import signal
import sys

BAD_INPUT = 2


def fail(script, text):
    print(f"{script}: {text}", file=sys.stderr)
    sys.exit(BAD_INPUT)


def end_quietly_when_the_reader_goes():
    """A table piped into a reader that stops early (`sweep_table.py DIR | head -3`) ended in a
    BrokenPipeError traceback (s66): the script ends as `cat` would, without a word. Not for
    plot_sweep.py, whose plots must still be written (s65)."""
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)


class OneLineParser(argparse.ArgumentParser):
    """argparse's usage errors (an unknown flag, a missing folder) in one line, exit 2."""

    def error(self, message):
        fail(self.prog, f"{message} (--help for the usage)")


def finite(script, flag, text):
    """A flag's value as a finite number (argparse's float takes 'nan' and 'inf')."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        fail(script, f"{flag}: expected a finite number, got '{text}'")
    return value


def sweep_dir(script, path):
    """PATH as a sweep's folder: it must exist and be a folder."""
    if not os.path.exists(path):
        fail(script, f"{path}: no such folder")
    if not os.path.isdir(path):
        fail(script, f"{path}: not a folder (give the sweep's output folder)")
    return path


def read_csv(script, path, required=()):
    """(header, rows as dicts, first line number of each row) of a CSV file with a header line,
    every row as wide as the header and the required columns present."""
    try:
        with open(path, newline="", encoding="utf-8-sig") as f:
            reader = csv.reader(f)
            lines = [(reader.line_num, row) for row in reader]
    except FileNotFoundError:
        fail(script, f"{path}: no such file")
    except IsADirectoryError:
        fail(script, f"{path}: a folder, not a file")
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        fail(script, f"{path}: cannot read: {getattr(error, 'strerror', None) or error}")
    if not lines:
        fail(script, f"{path}: empty file (no header line)")
    header = lines[0][1]
    for column in required:
        if column not in header:
            fail(script, f"{path}: no column '{column}'")
    rows, numbers = [], []
    for line, row in lines[1:]:
        if not row:
            continue  # a blank line
        if len(row) != len(header):
            fail(script, f"{path}: line {line}: {len(row)} fields, the header has {len(header)}")
        rows.append(dict(zip(header, row)))
        numbers.append(line)
    return header, rows, numbers


def value(script, path, line, row, column, allow_empty=False):
    """A row's field as a finite number, or None when empty and allow_empty (a null metric)."""
    text = row[column]
    if text == "" and allow_empty:
        return None
    try:
        v = float(text)
    except ValueError:
        v = math.nan
    if not math.isfinite(v):
        run = f" (run {row['id']})" if row.get("id") else ""
        fail(script, f"{path}: line {line}{run}: {column}: expected a number, got '{text}'")
    return v


def count_rows(path):
    """Data rows of a CSV file (0 when it is absent)."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            return max(0, sum(1 for row in csv.reader(f) if row) - 1)
    except (OSError, UnicodeDecodeError, csv.Error):
        return 0


def finished_results(script, folder, required=(), run_files=()):
    """(header, rows, line numbers) of a sweep's results.csv, refused unless it holds every run of
    the sweep's manifest (cells.csv): a sweep still running, killed half way or with failed runs
    has fewer rows, and a mean, p90 or bar over them is not the sweep's. Each run's folder must
    hold run_files (runs/ID/NAME)."""
    sweep_dir(script, folder)
    cells_path = os.path.join(folder, "cells.csv")
    if not os.path.isfile(cells_path):
        fail(script, f"{cells_path}: no such file: {folder} is not a sweep's folder (plywood "
             "sweep writes its manifest there)")
    _, cells, _ = read_csv(script, cells_path, ("id",))
    path = os.path.join(folder, "results.csv")
    if not os.path.exists(path):
        fail(script, f"{path}: no such file: the sweep has not finished (still running, killed, "
             "or never collected: plywood sweep --collect)")
    header, rows, lines = read_csv(script, path, ("id",) + tuple(required))
    ids = [r["id"] for r in rows]
    # Counted once (ids.count per row was quadratic: 6.6 s for a sweep of 20,000 runs).
    times = collections.Counter(ids)
    for line, run in zip(lines, ids):
        if times[run] > 1:
            fail(script, f"{path}: line {line}: run {run} is listed twice")
    unknown = sorted(set(ids) - {c["id"] for c in cells})
    if unknown:
        fail(script, f"{path}: run {unknown[0]} is not in {cells_path} (another sweep's row?)")
    if len(rows) != len(cells):
        failed = count_rows(os.path.join(folder, "failures.csv"))
        fail(script, f"{path}: holds {len(rows)} of the sweep's {len(cells)} runs ({failed} "
             f"failed, in failures.csv; {max(0, len(cells) - len(rows) - failed)} unfinished): "
             "a figure over them is not the sweep's; finish the sweep (plywood sweep again)")
    for run in ids:
        for name in run_files:
            path = os.path.join(folder, "runs", run, name)
            if not os.path.isfile(path):
                # A run folder without its metrics.json was skipped, or a traceback (s66).
                fail(script, f"{path}: no such file (results.csv lists run {run} as finished)")
    return header, rows, lines


def error_range_and_sweeps(script, argv, run_files):
    """The arguments LO HI SWEEP_DIR [SWEEP_DIR ...] of the seed 001 analyses that look at the runs
    whose occupancy.error lies in (LO, HI]: (lo, hi, {sweep folder: its results rows}). A bound
    that is no number was a traceback, NaN bounds or a missing folder printed no run (exit 0), a
    folder that is no seed 001 sweep was a KeyError, and a sweep missing runs was read on the runs
    that finished (s66); each is now one line, exit 2."""
    flags = [a for a in argv if a.startswith('-') and a.lstrip('-')[:1].isalpha()]
    if len(argv) < 3 or flags:
        fail(script, f'usage: {script}.py LO HI SWEEP_DIR [SWEEP_DIR ...]')
    lo, hi = finite(script, 'LO', argv[0]), finite(script, 'HI', argv[1])
    if not lo < hi:
        fail(script, f'LO {argv[0]} is not below HI {argv[1]}: the range (LO, HI] holds no e')
    sweeps = {d: finished_results(script, d, ('occupancy.error',), run_files)[1] for d in argv[2:]}
    return lo, hi, sweeps

