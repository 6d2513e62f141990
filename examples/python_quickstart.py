#!/usr/bin/env python3
"""sinsim from Python, notebook style: the README's figure docs/mc-ar-vs-gm.svg (step 6), AR(5)
against Gauss-Markov, median and 95 % horizontal drift on scenarios/car.yaml, paired runs.

    /usr/bin/python3 examples/python_quickstart.py OUT.png [--runs N]

Run from anywhere after scripts/setup.sh (the module is found in build/python). Each `# %%` cell
can be pasted into a notebook as it stands. Reference: docs/python.md.
"""
# %% Setup: find the module built beside this checkout, unless PYTHONPATH already has it.
import argparse
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
repo = os.path.dirname(here)
sys.path.append(os.path.join(repo, "build", "python"))
import numpy as np  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import sinsim  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("out", help="figure to write (.png, .svg or .pdf)")
parser.add_argument("--runs", type=int, default=100, help="paired runs per model (README: 500)")
args = parser.parse_args()

# %% The scenario and the two sensor models: files, read once into typed values.
car = sinsim.Scenario(os.path.join(repo, "scenarios", "car.yaml"))
ar5 = sinsim.Model(os.path.join(repo, "scenarios", "adis16355-ar5.yaml"))
gm = sinsim.Model(os.path.join(repo, "scenarios", "adis16355-gm.yaml"))
print(car, ar5, gm, sep="\n")

# %% Monte Carlo: run k of both models uses the same random streams (a paired comparison).
batch = sinsim.mc(car, models=[ar5, gm], runs=args.runs, seed=1)
t_min = batch["t"] / 60.0

# %% Horizontal error of every run at every epoch, then its median and 95th percentile.
fig, ax = plt.subplots(figsize=(7, 4.2))
for label, colour in zip(batch["labels"], ("tab:blue", "tab:orange")):
    e = batch["errors"][label]                       # runs x epochs x 9 (north, east, down, ...)
    horizontal = np.hypot(e[:, :, 0], e[:, :, 1])    # [m]
    p50, p95 = np.percentile(horizontal, [50, 95], axis=0)
    # from the first epoch after t = 0 (the error is 0 there: no place on a log axis)
    ax.plot(t_min[1:], p50[1:], color=colour, label=f"{label}: median")
    ax.plot(t_min[1:], p95[1:], color=colour, linestyle="--", label=f"{label}: 95 %")
ax.set_yscale("log")
ax.set_xlabel("time [min]")
ax.set_ylabel("horizontal error [m]")
ax.set_title(f"{car.name}: AR(5) vs Gauss-Markov, {args.runs} paired runs")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(args.out)

# %% The numbers behind the picture: final drift of each model, and the paired ratio.
final = {label: batch["final"][label]["horizontal_m"] for label in batch["labels"]}
for label, h in final.items():
    print(f"{label}: final horizontal error median {np.median(h):.4g} m, 95 % {np.percentile(h, 95):.4g} m")
ratio = np.mean(final["adis16355-gm"]) / np.mean(final["adis16355-ar5"])
print(f"GM / AR(5) mean final drift: {ratio:.3f}; figure written to {args.out}")
assert os.path.getsize(args.out) > 0
