"""Does the diagnosis' Allan criterion waste the evidence a record holds for a missing slow noise?

A study, not a test (docs/diagnose-log.md, "Thirty-third session"). On records of a known base --
white noise of density N, the model the diagnosis is given -- plus one missing slow noise (a
flicker by 1/f spectral shaping, a first-order Gauss-Markov of tau = T/60, or a random walk, made
by generate.py's own functions; sized by the largest ratio of its Allan deviation to the white's
on the octave grid), it compares, on the same records, two ways of finding and naming it:

- the diagnosis: `sinsim diagnose --json`, per effect the score sqrt(drop) of its best variant,
  the drop the Allan criterion's (docs/diagnose.md, "Selection by trial": the GLS chi-square of
  ln AVAR on the octave grid, the level's prior, the six slowest cosines, ln K per parameter).
  First round (nothing accepted) against the model as given; with --beside-white X the record
  also holds a white noise X times the model's, which the diagnosis finds first, and the slow
  noise is what it reports beside it (at the next threshold);
- the record's Gaussian likelihood in the frequency domain (Whittle): -2 ln L of the periodogram
  under white noise (its level under the same prior; free beside a found white) against white +
  each slow noise with free sizes (the GM's time on the diagnosis' own grid), the same ln K per
  parameter; the name is the best penalised drop, found where its score passes the same
  threshold. By default a line and settlings of T/4, T/12 and T/40 are first taken out of the
  record: the shapes a ramp or warm-up candidate would claim, to which the diagnosis makes its
  slowest cosines blind (--raw-whittle: the record as it is).

Per truth and size: found (any slow noise passing), named right, and the median score of the
truth's effect, for both. Nothing here imports sinsim; the records are NumPy.

    /usr/bin/python3 bench/diagnose_challenge/criterion_power.py --sinsim build/sinsim \
        --seeds 40 --work /tmp/power            # also --beside-white 5, --raw-whittle
"""
import argparse
import json
import math
import os
import subprocess
import sys

import numpy as np
from scipy.optimize import minimize

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate as g  # noqa: E402  (adev, octave_grid, flicker, gauss_markov: the benchmark's own)
from challenge import yaml_effect  # noqa: E402  (the benchmark's model-file lines)


SLOW = {"bias_instability": 1, "gauss_markov": 2, "random_walk": 1}  # parameters of each


def missing_noise(rng, effect, n, fs, white_density, ratio):
    """The missing noise (a SLOW effect), scaled so that max over the octave grid of its ADEV over
    the white's (N / sqrt(tau)) is `ratio` (0: a null record)."""
    grid = g.octave_grid(n)
    base_adev = white_density / np.sqrt(np.array(grid) / fs)
    if effect == "bias_instability":
        x = g.flicker(rng, n, fs, 1.0)
    elif effect == "gauss_markov":  # tau = T / 60: its hump inside the grid
        x = g.gauss_markov(rng, n, fs, 1.0, n / fs / 60.0)
    else:
        x = g.random_walk(rng, n, fs, 1.0)
    return ratio / float(np.max(g.adev(x, 1.0 / fs, grid) / base_adev)) * x


def whittle_drops(x, fs, tau_grid, white_var, free_level, slow_shapes):
    """Per SLOW effect, the drop of -2 ln L of the record's periodogram from white noise alone to
    white + that effect (sizes free, the GM's time its best on tau_grid): flicker S = b / j, GM the
    discrete AR(1)'s, walk 1 / |1 - e^{-iw}|^2. The white level under the diagnosis' prior (ln s
    ~ N(0, ln 1.5) about white_var), or free (a white noise the model lacked, found first).
    slow_shapes: a line and settlings of T/4, T/12, T/40 first taken out of the record by least
    squares -- the slow deterministic shapes a ramp or warm-up candidate offers, to which the
    diagnosis makes its slowest cosines blind (docs/diagnose.md, "The record's longest scales")."""
    n = len(x)
    if slow_shapes:  # what the diagnosis' slowest cosines are made blind to, taken out likewise
        t = np.arange(n) / n
        A = np.column_stack([np.ones(n), t] + [np.exp(-t / c) for c in (0.25, 1 / 12, 1 / 40)])
        x = x - A @ np.linalg.lstsq(A, x, rcond=None)[0]
    I = np.abs(np.fft.rfft(x - x.mean())[1:(n - 1) // 2 + 1]) ** 2 / n
    j = np.arange(1, len(I) + 1)
    z = np.exp(-2j * math.pi * j / n)

    def crit(S, a):
        prior = 0.0 if free_level else (math.log(a / white_var) / math.log(1.5)) ** 2
        return 2.0 * float(np.sum(np.log(S) + I / S)) + prior

    starts = [math.log(white_var), math.log(I.mean())]
    null = min(minimize(lambda p: crit(np.full(len(I), math.exp(p[0])), math.exp(p[0])), [s0],
                        method="Nelder-Mead").fun for s0 in starts)
    shapes = {"bias_instability": [1.0 / j], "random_walk": [1.0 / np.abs(1 - z) ** 2],
              "gauss_markov": [(1 - phi * phi) / np.abs(1 - phi * z) ** 2
                               for phi in (math.exp(-1.0 / (fs * tau)) for tau in tau_grid)]}
    drops = {}
    for name, family in shapes.items():
        best = 0.0
        for shape in family:
            def f(p):
                return crit(np.exp(p[0]) + np.exp(p[1]) * shape, math.exp(p[0]))
            r = min((minimize(f, [a, b], method="Nelder-Mead", options={"xatol": 1e-6, "fatol": 1e-6})
                     for a in starts for b in (starts[1] - 6.0 - math.log(shape[0]), starts[1] - math.log(shape[0]))),
                    key=lambda r: r.fun)
            best = max(best, null - r.fun)
        drops[name] = best
    return drops


def diagnose(sinsim, work, x, fs, white_density, first_round):
    """sinsim diagnose of gx against white noise of the stated density: per effect its best
    variant's score -- in the first round (--threshold 1000: nothing accepted, every score against
    the model as given) or as the diagnosis runs (the score when accepted, else the last round's)
    -- and its JSON axis (chi2_points, findings) and document (threshold, next_threshold)."""
    n = len(x)
    rng = np.random.default_rng(0)
    t = np.arange(n) / fs
    cols = [x] + [white_density * math.sqrt(fs) * rng.standard_normal(n) for _ in range(5)]
    rec, mod, out = (os.path.join(work, f) for f in ("r.csv", "r.yaml", "r.json"))
    np.savetxt(rec, np.column_stack([t] + cols), delimiter=",", header="t,gx,gy,gz,ax,ay,az",
               comments="", fmt="%.12g")
    white = {"density": white_density}
    with open(mod, "w") as f:
        for sensor in ("gyro", "accel"):
            f.write(f"{sensor}:\n" + "".join(f"  {ax}:\n    - {yaml_effect('white', white, sensor)}\n" for ax in "xyz"))
    p = subprocess.run([sinsim, "diagnose", rec, "--model", mod, "--channels", "gx", "--json", out,
                        "--realisations", "16", "--threads", "2", "-o", os.path.join(work, "i.yaml")]
                       + (["--threshold", "1000"] if first_round else []), capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(p.stderr)
    d = json.load(open(out))
    a = d["axes"][0]
    scores = {}
    for f in a["findings"]:
        scores[f["effect"]] = max(scores.get(f["effect"], 0.0), f["score"])
    return scores, a, d


def score_record(a, effect, ratio, seed, study):
    """One record of the cell (effect, ratio): both methods' scores per slow effect and names."""
    fs, n, N, total, found, threshold = (study[k] for k in ("fs", "n", "N", "total", "found", "threshold"))
    rng = np.random.default_rng([int(ratio * 10), seed, list(SLOW).index(effect)])
    x = total * math.sqrt(fs) * rng.standard_normal(n) + missing_noise(rng, effect, n, fs, total, ratio)
    scores, axis, _ = diagnose(a.sinsim, a.work, x, fs, N, first_round=not found)
    reported = [f["effect"] for f in axis["findings"] if f.get("reported")]
    slow = {e: scores.get(e, 0.0) for e in SLOW}
    if found:  # the first slow effect reported beside the white, else none
        named_a = next((e for e in reported if e in SLOW), None)
    else:
        named_a = max(slow, key=slow.get) if max(slow.values()) >= threshold else None
    drops = whittle_drops(x, fs, study["tau_grid"], (total if found else N) ** 2 * fs, found, not a.raw_whittle)
    pen = {e: d - math.log(axis["chi2_points"]) * SLOW[e] for e, d in drops.items()}
    named_w = max(pen, key=pen.get)
    if math.sqrt(max(0.0, pen[named_w])) < threshold:
        named_w = None
    return {"effect": effect if ratio > 0 else None, "ratio": ratio, "seed": seed, "allan": slow,
            "allan_named": named_a, "reported": reported,
            "whittle": {e: math.sqrt(max(0.0, v)) for e, v in pen.items()}, "whittle_named": named_w}


def print_cell(effect, ratio, cell):
    truth = effect if ratio > 0 else None
    counts = []
    for m in ("allan", "whittle"):
        found = sum(c[m + "_named"] is not None for c in cell)
        right = sum(c[m + "_named"] == truth for c in cell if truth)
        counts.append(f"{found:3d} / {right:3d} of {len(cell)} / {np.median([c[m][effect] for c in cell]):6.2f}")
    print(f"{truth or '(none: null)':17s} {ratio:5.1f}  {counts[0]}                    {counts[1]}", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--work", default="/tmp/criterion_power")
    ap.add_argument("--seeds", type=int, default=40)
    ap.add_argument("--rate", type=float, default=100.0)
    ap.add_argument("--samples", type=int, default=30000)
    ap.add_argument("--ratios", default="0,1,1.5,2", help="0: null records")
    ap.add_argument("--effects", default=",".join(SLOW))
    ap.add_argument("--beside-white", type=float, default=0.0,
                    help="a white noise the model lacks, this many times its density, found first; "
                         "the slow effect is then scored beside it at the next threshold")
    ap.add_argument("--raw-whittle", action="store_true",
                    help="the likelihood of the record as it is (no line or settlings taken out)")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    fs, n, N = a.rate, a.samples, 1e-3
    tau_grid, tc = [], 8 / fs
    while tc <= (n // 10) / fs / 4:  # the diagnosis' GM grid: 8 samples to tau_max / 4, sqrt(2)
        tau_grid.append(tc)
        tc *= math.sqrt(2)
    found = a.beside_white > 0
    # the diagnosis' own thresholds (first / next), as its JSON states them on a null record
    _, _, doc = diagnose(a.sinsim, a.work, N * math.sqrt(fs) * np.random.default_rng(1).standard_normal(n),
                         fs, N, first_round=False)
    threshold = doc["next_threshold"] if found else doc["threshold"]
    study = {"fs": fs, "n": n, "N": N, "total": math.hypot(N, a.beside_white * N), "found": found,
             "threshold": threshold, "tau_grid": tau_grid}
    print(f"{n} samples at {fs:g} Hz (T = {n / fs:g} s); model white {N:g} /sqrt(Hz)"
          + (f", record's white {study['total'] / N:.2f}x that (found first)" if found else "")
          + f"; {a.seeds} seeds per cell; threshold {threshold:g}")
    print("truth             ratio  Allan: found / named right / median score   "
          "Whittle: found / named right / median score")
    rows = []
    effects = a.effects.split(",")
    for effect in effects:
        for ratio in (float(r) for r in a.ratios.split(",")):
            if ratio == 0 and effect != effects[0]:
                continue  # one null row
            cell = [score_record(a, effect, ratio, seed, study) for seed in range(a.seeds)]
            print_cell(effect, ratio, cell)
            rows += cell
    with open(os.path.join(a.work, "power.json"), "w") as f:
        json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
