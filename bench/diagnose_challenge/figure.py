#!/usr/bin/python3
"""Figure of the diagnosis challenge: its scores against the issue's floors.

Reads the results.json files challenge.py writes (scored by challenge.score, pooled per run) and
draws four panels: the right effect first against the effect's size (Wilson 95 % intervals), every
floored score against its floor, the confusion of single hidden effects (first run), and the
misfit after / before the correct addition.

    /usr/bin/python3 bench/diagnose_challenge/figure.py -o docs/diagnose/challenge.png \\
        --run "seed 1" /tmp/challenge1/results.json --run "seed 2" /tmp/challenge2/results.json
"""
import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import challenge  # noqa: E402
import generate as g  # noqa: E402

# (label, key in the scores, floor or None): every score where higher is better (false alarms as
# the share of clean channels without one).
FLOORS = [("right first, >= 3x", "ge3", 0.90), ("right first, 1.5x", "w15", 0.60),
          ("quantization first (no floor)", "lsb", None), ("both of two effects", "both", 0.80),
          ("out of catalogue: equivalent", "ooc", 0.80), ("clean: no false alarm", "quiet", 0.98),
          ("misfit halved by the addition", "halved", 0.95)]


def wilson(k, n, z=1.96):
    """Wilson score interval of k of n [lower, upper]."""
    if n == 0:
        return 0.0, 1.0
    p = k / n
    c = (p + z * z / (2 * n)) / (1 + z * z / n)
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, c - h), min(1.0, c + h)


def counts(sc):
    """[hits, total] per FLOORS key."""
    top1 = sc["top1"]
    clean = sc["clean"]
    return {"ge3": challenge.at_least_3x(top1), "w15": top1.get(1.5, [0, 0]), "lsb": top1.get("lsb", [0, 0]), "both": sc["both"],
            "ooc": sc["ooc"], "quiet": [clean[1] - clean[0], clean[1]], "halved": sc["halved"]}


def panel_sizes(ax, runs):
    for j, (label, sc) in enumerate(runs):
        top1 = sc["top1"]
        sizes = sorted(k for k in top1 if k != "lsb")
        x = np.array(sizes) * (1 + 0.04 * (j - (len(runs) - 1) / 2))
        p = [top1[s][0] / top1[s][1] for s in sizes]
        lo_hi = [wilson(*top1[s]) for s in sizes]
        err = [[pi - lo for pi, (lo, _) in zip(p, lo_hi)], [hi - pi for pi, (_, hi) in zip(p, lo_hi)]]
        ax.errorbar(x, 100 * np.array(p), yerr=100 * np.array(err), fmt="o-", capsize=3, label=label)
    ax.hlines(60, 1.3, 2.2, colors="k", linestyles="--", linewidth=1)
    ax.hlines(90, 2.6, 11.5, colors="k", linestyles="--", linewidth=1, label="floor")
    ax.set_xscale("log")
    ax.set_xticks(challenge.SIZES)
    ax.set_xticklabels([f"{s:g}x" for s in challenge.SIZES])
    ax.set_ylim(40, 102)
    ax.set_xlabel("hidden effect's size (max over tau of its ADEV / the base's)")
    ax.set_ylabel("right effect named first [%]")
    ax.set_title("one hidden effect: right first, 95 % intervals")
    ax.legend(loc="lower right", fontsize=8)


def panel_floors(ax, runs):
    y = np.arange(len(FLOORS))
    h = 0.8 / len(runs)
    for j, (label, sc) in enumerate(runs):
        c = counts(sc)
        vals = [100 * c[k][0] / c[k][1] if c[k][1] else 0 for _, k, _ in FLOORS]
        bars = ax.barh(y + (j - (len(runs) - 1) / 2) * h, vals, height=h, label=label)
        for b, (_, k, _) in zip(bars, FLOORS):
            ax.text(b.get_width() + 0.5, b.get_y() + b.get_height() / 2, f"{c[k][0]}/{c[k][1]}",
                    va="center", fontsize=7)
    for i, (_, _, f) in enumerate(FLOORS):
        if f is not None:
            ax.vlines(100 * f, i - 0.45, i + 0.45, colors="k", linewidth=2)
    ax.set_yticks(y)
    ax.set_yticklabels([lab for lab, _, _ in FLOORS], fontsize=8)
    ax.invert_yaxis()
    ax.set_xlim(50, 112)
    ax.set_xlabel("% (black tick: the issue's floor)")
    ax.set_title("every score against its floor (colours as left)")


def panel_confusion(ax, label, sc):
    hidden = [e for e in g.CATALOGUE + g.OUT_OF_CATALOGUE if sum(sc["confusion"][e].values())] + ["(clean)"]
    named = [e for e in g.CATALOGUE] + ["white", "bias_jumps", "none", "unexplained"]
    m = np.array([[sc["confusion"][h][n] for n in named] for h in hidden], dtype=float)
    frac = m / np.maximum(m.sum(axis=1, keepdims=True), 1)
    ax.imshow(frac, cmap="Blues", vmin=0, vmax=1, aspect="auto")
    for i in range(len(hidden)):
        for j in range(len(named)):
            if m[i, j]:
                ax.text(j, i, f"{int(m[i, j])}", ha="center", va="center", fontsize=6,
                        color="white" if frac[i, j] > 0.6 else "black")
    ax.set_xticks(range(len(named)))
    ax.set_xticklabels(named, rotation=60, ha="right", fontsize=7)
    ax.set_yticks(range(len(hidden)))
    ax.set_yticklabels(hidden, fontsize=7)
    ax.set_xlabel("named first")
    ax.set_title(f"single hidden effect -> named first ({label}, counts)")


def panel_misfit(ax, runs):
    for label, sc in runs:
        r = np.maximum(np.array(sc["ratios"]), 1e-3)
        if len(r):
            ax.hist(np.log10(r), bins=np.linspace(-3, 1, 33), histtype="step", linewidth=1.5,
                    label=f"{label} ({len(r)})")
    ax.axvline(math.log10(0.5), color="k", linestyle="--", linewidth=1, label="halved")
    ax.set_xlabel("log10 misfit after / before the correct addition (0 plotted at -3)")
    ax.set_ylabel("channels")
    ax.set_title("adding the right effect")
    ax.legend(fontsize=8)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-o", "--output", required=True, help="image file (.png or .svg)")
    ap.add_argument("--run", nargs="+", action="append", required=True, metavar=("LABEL", "RESULTS_JSON"),
                    help="a label and the results.json files pooled under it (repeatable)")
    a = ap.parse_args()
    runs = []
    for spec in a.run:
        if len(spec) < 2:
            ap.error("--run needs a label and at least one results.json")
        try:
            rows = [row for path in spec[1:] for row in json.load(open(path))]
        except (OSError, ValueError) as e:
            ap.error(f"--run {spec[0]!r}: cannot read results: {e}")
        runs.append((spec[0], challenge.score(rows)))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(13, 9.5))
    panel_sizes(axes[0][0], runs)
    panel_floors(axes[0][1], runs)
    panel_confusion(axes[1][0], *runs[0])
    panel_misfit(axes[1][1], runs)
    fig.suptitle("sinsim diagnose on records made without sinsim code (bench/diagnose_challenge)")
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)
    print(a.output)


if __name__ == "__main__":
    main()
