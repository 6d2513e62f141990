#!/usr/bin/python3
"""The user's whole workflow on clean records: fit a model, then diagnose against it.

The challenge benchmark diagnoses each record against the model that generated it. A user has no
such model: they run `sinsim fit` on one record and `sinsim diagnose` on the same record or on a
later one from the same sensor. On a record with no hidden effect (challenge.py's --null draws of
any generator) every finding of that pipeline is a false alarm of fit and diagnose together:

  same  fit the whole record, diagnose the whole record against that model;
  next  fit the first half (--duration), diagnose the second half (--skip) against it: a model
        that predicts a record it has not seen.

    /usr/bin/python3 bench/diagnose_challenge/fitted_null.py --generator third --records 20 \
        --seed 3 --kind auto --work /tmp/fitted_null --sinsim build/sinsim

Results: per mode the channels with a reported finding (which effects), and WORK/results.json.
"""
import argparse
import json
import os
import subprocess
import sys
from collections import Counter

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import challenge as c  # noqa: E402

MODES = ("same", "next")


def window(row, mode):
    """(fit options, diagnose options) of a mode: the record's halves in seconds for next."""
    if mode == "same":
        return [], []
    half = f'{0.5 * row["samples"] / row["rate_hz"]:.6f} s'
    return ["--duration", half], ["--skip", half]


def run_mode(a, row, mode):
    stem = row["record"][:-4] + "." + mode
    fit_opts, diag_opts = window(row, mode)
    p = subprocess.run(["nice", a.sinsim, "fit", row["record"], "--kind", a.kind, "-q",
                        "-o", stem + ".fit.yaml"] + fit_opts, capture_output=True, text=True)
    if p.returncode != 0:
        return {"error": "fit: " + p.stderr.strip()[-400:]}
    p = subprocess.run(["nice", a.sinsim, "diagnose", row["record"], "--model", stem + ".fit.yaml",
                        "--json", stem + ".json", "--realisations", str(a.realisations)] + diag_opts,
                       capture_output=True, text=True)
    if p.returncode != 0:
        return {"error": "diagnose: " + p.stderr.strip()[-400:]}
    d = json.load(open(stem + ".json"))
    return {ax["channel"]: [f["effect"] for f in ax["findings"] if f.get("reported")]
            for ax in d["axes"]}


def run_one(a, i):
    rng = np.random.default_rng([a.seed, i])
    row = c.null_record(a.generator, rng, i, a.work, a.max_samples)
    row["generator"] = a.generator
    row["result"] = {mode: run_mode(a, row, mode) for mode in a.modes.split(",")}
    if not a.keep:
        os.remove(row["record"])
    return row


def report(rows, modes):
    for mode in modes:
        errors = [r["record"] for r in rows if "error" in r["result"][mode]]
        chans = [(r, ch, f) for r in rows if "error" not in r["result"][mode]
                 for ch, f in r["result"][mode].items()]
        alarms = [(r, ch, f) for r, ch, f in chans if f]
        kinds = Counter(f[0] for _, _, f in alarms)
        print(f"{mode}: {len(alarms)}/{len(chans)} clean channels with a finding "
              f"({100.0 * len(alarms) / max(len(chans), 1):.1f} %), {len(errors)} records failed")
        for e, n in kinds.most_common():
            print(f"  first {e}: {n}")
        for r, ch, f in alarms:
            print(f"    {os.path.basename(r['record'])} {r['rate_hz']:g} Hz {r['samples']} samples "
                  f"{ch}: {', '.join(f)}")
        for e in errors:
            print(f"  failed: {e}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--generator", choices=sorted(c.GENERATORS), default="main")
    ap.add_argument("--records", type=int, default=20)
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--kind", default="auto", help="fit --kind")
    ap.add_argument("--modes", default="same,next", help="comma list of: " + ", ".join(MODES))
    ap.add_argument("--max-samples", type=int, default=400000)
    ap.add_argument("--realisations", type=int, default=32)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--work", default="out/fitted_null")
    ap.add_argument("--keep", action="store_true", help="keep the record CSVs")
    ap.add_argument("--report", nargs="+", metavar="RESULTS_JSON")
    a = ap.parse_args()
    if a.report:
        rows = [r for path in a.report for r in json.load(open(path))]
        report(rows, [m for m in MODES if all(m in r["result"] for r in rows)])
        return
    report(c.run_records(a, run_one), a.modes.split(","))


if __name__ == "__main__":
    main()
