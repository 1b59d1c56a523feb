#!/usr/bin/python3
"""Plots of a finished sweep: one PNG per chosen metric, values of every run against the sweep's
groups (set-axis values, plus group_by columns), as a box plot with each run as a dot and the mean
with its 95 % confidence interval. Called by `plywood sweep` after collecting; usage:
    scripts/plot_sweep.py SWEEP_DIR
"""
import json
import math
import os
import sys

# Exit status of a plot that could not be written, after its one line: `plywood sweep` then adds
# no note of its own and exits 1.
CANNOT_WRITE = 3
# The group columns whose values are files (results.csv: paths; summary.csv: stems).
FILE_COLUMNS = ("experiment", "world")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_folder import BAD_INPUT, fail, read_csv, sweep_dir, value  # noqa: E402


def pyplot():
    """matplotlib.pyplot, imported once the sweep's files have been read and checked (a refusal
    of bad input does not wait the second matplotlib takes to load)."""
    try:
        import matplotlib
    except ImportError:
        # plywood sweep checks for matplotlib before it calls this; run by hand without it, this
        # was a ModuleNotFoundError traceback (s66).
        print("plot_sweep: no plots: python3-matplotlib is not installed (Debian: apt-get install "
              "python3-matplotlib)", file=sys.stderr)
        sys.exit(BAD_INPUT)
    matplotlib.use("Agg")
    try:
        import matplotlib.pyplot as plt
    except OSError as e:
        # matplotlib writes its font cache into MPLCONFIGDIR (or ~/.config/matplotlib) on first
        # use; a folder it may not write in (MPLCONFIGDIR=/sys) was a 30-line traceback (s65
        # fifty-fourth pass).
        where = os.environ.get("MPLCONFIGDIR")
        hint = f"MPLCONFIGDIR={where}" if where else "HOME"
        print(f"plywood sweep: no plots: matplotlib cannot write its cache: {e.filename}: "
              f"{e.strerror} (point {hint} at a writable folder)", file=sys.stderr)
        sys.exit(CANNOT_WRITE)
    return plt


def stem(path):
    """A file's name without its folder and last extension, as std::filesystem::path::stem."""
    name = os.path.basename(path)
    dot = name.rfind(".")
    # As C++17: "." and ".." and a name whose only period leads it have no extension ("..foo"'s
    # stem is ".", where os.path.splitext keeps "..foo").
    return name if name in (".", "..") or dot <= 0 else name[:dot]


def say(text):
    """A line on stdout. A reader that went away (`plywood sweep ... | head -1`) ended the script
    with a BrokenPipeError traceback and the plots after the first unmade (s65 fifty-fourth pass);
    the rest of what it prints is dropped instead."""
    try:
        print(text, flush=True)
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())


def save(fig, path):
    """Staged and renamed into place: a full disk or a file-size limit left a cut PNG in plots/
    and a Python traceback, the sweep exiting 0 (s63 fiftieth pass)."""
    partial = f"{path}.partial-{os.getpid()}"
    try:
        fig.savefig(partial, dpi=110, format="png")
        os.replace(partial, path)
    except OSError as e:
        try:
            os.remove(partial)
        except OSError:
            pass
        print(f"plywood sweep: {path}: cannot write: {e.strerror}", file=sys.stderr)
        sys.exit(CANNOT_WRITE)


def main(out_dir):
    # A folder that is not a finished sweep's, an empty or cut CSV file or a value that is no
    # number was a Python traceback; a NaN or inf value was left out of the plot without a word
    # (s66). Plots of a sweep with failed runs are of its finished runs, as summary.csv is: the
    # sweep itself says how many finished, and exits 1.
    sweep_dir("plot_sweep", out_dir)
    meta_path = os.path.join(out_dir, "sweep.json")
    try:
        with open(meta_path, encoding="utf-8") as f:
            meta = json.load(f)
    except FileNotFoundError:
        fail("plot_sweep", f"{meta_path}: no such file: {out_dir} is not a sweep's folder")
    except (OSError, ValueError) as error:
        why = getattr(error, "strerror", None) or error
        fail("plot_sweep", f"{meta_path}: cannot read ({why})")
    if not isinstance(meta, dict):
        fail("plot_sweep", f"{meta_path}: expected a JSON object")
    summary_path = os.path.join(out_dir, "summary.csv")
    header, summary, summary_lines = read_csv("plot_sweep", summary_path,
                                              ("metric", "n", "mean", "ci95_low", "ci95_high"))
    # The summary's group columns are those before "metric".
    group_columns = header[: header.index("metric")]
    results_path = os.path.join(out_dir, "results.csv")
    _, results, result_lines = read_csv("plot_sweep", results_path, group_columns)
    metrics = meta.get("metrics") or []
    if not isinstance(metrics, list) or not all(isinstance(m, str) for m in metrics):
        fail("plot_sweep", f"{meta_path}: metrics: expected a list of names")
    if not metrics:
        say("plot_sweep: no metrics chosen in the sweep; no plots")
        return
    if not results:
        # Every cell failed (fuzz30: this was a ValueError traceback from max() of nothing).
        say("plot_sweep: no finished run in results.csv; no plots")
        return

    # results.csv keeps the world and experiment paths where summary.csv labels them by stem,
    # unless two paths share one (eval/sweep/sweep_results.cc); the results' groups take the same
    # rule, or a sweep grouped by world got plots without a mean (s67).
    paths_of_stem = {}
    for row in results:
        for c in FILE_COLUMNS:
            if c in group_columns:
                paths_of_stem.setdefault((c, stem(row[c])), set()).add(row[c])

    def as_in_summary(column, text):
        if column in FILE_COLUMNS and len(paths_of_stem.get((column, stem(text)), ())) == 1:
            return stem(text)
        return text

    def label(row, from_results=True):
        if not group_columns:
            return "all runs"
        # The last part of each key path keeps labels short ("sigma_m=0.01").
        return "\n".join(
            f"{c.split('.')[-1]}={as_in_summary(c, row[c]) if from_results else row[c]}"
            for c in group_columns)

    groups = []
    for row in results:
        key = label(row)
        if key not in groups:
            groups.append(key)
    # Every value read before the first plot: a refusal leaves no plots of part of the sweep.
    values_of = {}
    for metric in metrics:
        values = values_of[metric] = {g: [] for g in groups}
        for line, row in zip(result_lines, results):
            if row.get(metric, "") != "":
                values[label(row)].append(value("plot_sweep", results_path, line, row, metric))
    intervals = {}
    for line, s in zip(summary_lines, summary):
        if s["n"] not in ("", "0") and s["ci95_low"] != "":
            intervals[line] = tuple(value("plot_sweep", summary_path, line, s, c)
                                    for c in ("mean", "ci95_low", "ci95_high"))
    # matplotlib only when there is something to plot, before plots/ is made (without it, no
    # empty plots/ is left behind).
    plt = pyplot() if any(any(v.values()) for v in values_of.values()) else None
    plots = os.path.join(out_dir, "plots")
    try:
        os.makedirs(plots, exist_ok=True)
    except OSError as e:
        # A plots/ that is a file, or a folder it may not write in, was a traceback (s66).
        why = "a file, not a folder" if os.path.isfile(plots) else e.strerror
        print(f"plywood sweep: {plots}: cannot write: {why}", file=sys.stderr)
        sys.exit(CANNOT_WRITE)
    for metric in metrics:
        values = values_of[metric]
        if not any(values.values()):
            # Every run's value is null (undefined there: drift_percent of a robot that stood):
            # an empty box plot would draw axes round a figure of nothing.
            say(f"plot_sweep: {metric}: no run has a value (every run's is null); no plot")
            continue
        stats = {label(r, from_results=False): (line, r) for line, r in zip(summary_lines, summary)
                 if r["metric"] == metric}
        width = max(4.0, 0.09 * max(len(line) for g in groups for line in g.split("\n")) * len(groups) + 1.5)
        fig, ax = plt.subplots(figsize=(min(width, 30.0), 4.6))
        data = [values[g] for g in groups]
        labelled = False
        ax.boxplot([d if d else [math.nan] for d in data], labels=groups, widths=0.5,
                   showfliers=False)
        for i, d in enumerate(data, start=1):
            # Deterministic spread so the same results give the same picture.
            xs = [i + 0.18 * (((k * 0.618034) % 1.0) - 0.5) for k in range(len(d))]
            ax.plot(xs, d, "o", ms=3, alpha=0.6, color="tab:blue")
            s = stats.get(groups[i - 1])
            # One run has no interval (summary.csv leaves it empty): its dot is the whole story.
            if s and s[0] in intervals:
                mean, lo, hi = intervals[s[0]]
                ax.errorbar([i + 0.3], [mean], yerr=[[mean - lo], [hi - mean]], fmt="D",
                            color="tab:red", ms=5, capsize=4,
                            label=None if labelled else "mean, 95 % CI")
                labelled = True
        ax.set_ylabel(metric)
        if len(groups) > 6:
            plt.setp(ax.get_xticklabels(), rotation=45, ha="right", fontsize=8)
        ax.set_title(f"{meta.get('name', 'sweep')}: {metric}")
        ax.grid(axis="y", alpha=0.3)
        if labelled:
            ax.legend(loc="best", fontsize=8)
        fig.tight_layout()
        path = os.path.join(plots, metric.replace("/", "_") + ".png")
        save(fig, path)
        plt.close(fig)
        say(f"plot_sweep: {path}")


if __name__ == "__main__":
    # A folder named -x (plywood sweep --out=-x) is a folder; an absent one a flag.
    if len(sys.argv) != 2 or (sys.argv[1].startswith("-") and not os.path.isdir(sys.argv[1])):
        fail("plot_sweep", "usage: plot_sweep.py SWEEP_DIR")
    main(sys.argv[1])
