#!/usr/bin/python3
"""Issue 14's keeping rule read on pooled held-out sweeps (docs/sonar_map/history.md, "The keeping rule,
stop 57"): may a change that moves seed-001 runs become the default? Takes pairs of finished
sweep folders, BASE then NEW, one pair per generator seed, pairs their runs as
scripts/sweep_compare.py does, and prints per sweep mean / p90 (nearest rank) / worst / runs above
0.10 / runs with a contact and whether the sweep meets issue 14's bar (mean <= 0.03, p90 <= 0.05,
no run above 0.10), base and new; then the same figures pooled over every pair, and each
criterion of the rule with its verdict:
  pooled mean, p90 and worst not higher; pooled runs above 0.10 not more;
  no sweep that meets the bar stops meeting it;
  pooled runs with a bumper contact not more.
(The layouts' e <= 0.03 with no contact, the classical model and the fresh seeds are separate
calls of this script or of sweep_compare.py.) Exit 0 when every criterion holds, 1 when one fails.

usage: scripts/keeping_rule.py BASE NEW [BASE NEW ...] [--metric M] [--contacts M]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sweep_compare import number, paired_runs, percentile  # noqa: E402
from sweep_folder import OneLineParser, end_quietly_when_the_reader_goes, fail  # noqa: E402

SCRIPT = "keeping_rule"

MEAN_BAR, P90_BAR, RUN_BAR = 0.03, 0.05, 0.10


def figures(values, contacts):
    v = sorted(values)
    return {"mean": sum(v) / len(v), "p90": percentile(v, 0.9), "worst": v[-1],
            "above": sum(x > RUN_BAR for x in v), "contacts": sum(c > 0 for c in contacts)}


def meets_bar(f):
    return f["mean"] <= MEAN_BAR and f["p90"] <= P90_BAR and f["above"] == 0


def text(f):
    return (f"{f['mean']:.4f} / {f['p90']:.4f} / {f['worst']:.4f} / {f['above']} / "
            f"{f['contacts']}")


def main():
    parser = OneLineParser(prog=SCRIPT, description=__doc__.split("\n")[0])
    parser.add_argument("folders", nargs="+", help="BASE NEW [BASE NEW ...]")
    parser.add_argument("--metric", default="occupancy.error")
    parser.add_argument("--contacts", default="sensors.bumpers.contact_samples")
    args = parser.parse_args()
    if len(args.folders) % 2:
        fail(SCRIPT, "folders come in pairs, BASE then NEW")
    for role, folders in (("BASE", args.folders[0::2]), ("NEW", args.folders[1::2])):
        # A sweep is its folder or the results.csv in it (as sweep_compare.py reads either):
        # `X/results.csv` and `X` given as two pairs' BASE were not seen as one (s66 review).
        real = [os.path.realpath(os.path.dirname(f) if os.path.basename(os.path.normpath(f)) ==
                                 "results.csv" and os.path.isfile(f) else f) for f in folders]
        for f, r in zip(folders, real):
            if real.count(r) > 1:
                # Its runs counted twice in every pooled figure and criterion (s66).
                fail(SCRIPT, f"{f}: given twice as a {role} sweep; give each pair once")

    # Every pair read and checked before the table starts: a refusal (exit 2, not the 1 of "not
    # kept") leaves no half table, and a sweep missing runs or a run without a partner is refused,
    # not judged on the runs that happened to finish or pair (s66).
    checked = []
    for base, new in zip(args.folders[0::2], args.folders[1::2]):
        pairs, _, extra_axes, fields, new_rows = paired_runs(base, new, args.metric, args.contacts,
                                                             SCRIPT, whole=True)
        if any(len({r[a] for r in new_rows}) > 1 for a in extra_axes):
            fail(SCRIPT, f"{new} sweeps an option over several values; compare one")
        checked.append((new, pairs, fields))
    pooled_b, pooled_n, pooled_bc, pooled_nc = [], [], [], []
    lost, gained_bar = [], []
    print(f"| sweep | runs | base mean / p90 / worst / >{RUN_BAR:g} / contacts | new | "
          "bar base / new |")
    print("|---|---|---|---|---|")
    for new, pairs, fields in checked:
        be = [number(b[args.metric]) for b, _ in pairs]
        ne = [number(n[args.metric]) for _, n in pairs]
        has_contacts = args.contacts in fields
        bc = [number(b[args.contacts]) if has_contacts else 0.0 for b, _ in pairs]
        nc = [number(n[args.contacts]) if has_contacts else 0.0 for _, n in pairs]
        fb, fn = figures(be, bc), figures(ne, nc)
        name = os.path.basename(os.path.normpath(new))
        status = f"{'meets' if meets_bar(fb) else 'fails'} / {'meets' if meets_bar(fn) else 'fails'}"
        print(f"| {name} | {len(pairs)} | {text(fb)} | {text(fn)} | {status} |")
        if meets_bar(fb) and not meets_bar(fn):
            lost.append(name)
        if meets_bar(fn) and not meets_bar(fb):
            gained_bar.append(name)
        pooled_b += be
        pooled_n += ne
        pooled_bc += bc
        pooled_nc += nc

    fb, fn = figures(pooled_b, pooled_bc), figures(pooled_n, pooled_nc)
    print(f"| pooled | {len(pooled_b)} | {text(fb)} | {text(fn)} | |")
    down = sum(n < b for b, n in zip(pooled_b, pooled_n))
    up = sum(n > b for b, n in zip(pooled_b, pooled_n))
    print(f"\nruns down / up: {down} / {up}; sweeps newly meeting the bar: "
          f"{', '.join(gained_bar) or 'none'}")
    criteria = [
        ("pooled mean not higher", fn["mean"] <= fb["mean"]),
        ("pooled p90 not higher", fn["p90"] <= fb["p90"]),
        ("pooled worst not higher", fn["worst"] <= fb["worst"]),
        (f"pooled runs above {RUN_BAR:g} not more", fn["above"] <= fb["above"]),
        (f"no sweep stops meeting the bar ({', '.join(lost) or 'none does'})", not lost),
        ("pooled runs with a contact not more", fn["contacts"] <= fb["contacts"]),
    ]
    for label, ok in criteria:
        print(f"  {'holds' if ok else 'FAILS'}: {label}")
    kept = all(ok for _, ok in criteria)
    print(f"verdict: {'kept' if kept else 'not kept'} by the pooled rule")
    return 0 if kept else 1


if __name__ == "__main__":
    end_quietly_when_the_reader_goes()
    sys.exit(main())
