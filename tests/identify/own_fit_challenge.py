#!/usr/bin/python3
"""`sinsim fit` writes a model that its own record does not contradict.

The records are the independent challenge generators' null draws (bench/diagnose_challenge/
generate_alt.py and generate_third.py: NumPy/SciPy, no sinsim code, nothing hidden; seed 4 as in
fitted_null.py --seed 4). On four channels the diagnosis of the record against its own fit named
what the fit had left out:
  - alt record 11, ax (800 Hz, 500 s; white + six GMs of tau 0.014-81 s) and alt record 18, gy
    (800 Hz, 500 s; white + GMs of tau 0.26 s and 13.6 s): the set was chosen by the exact
    likelihood of the block means, but the GLS fit of the octave Allan variance put its slower GM
    below 0.5 s (taus 0.027 / 0.50 s and 0.21 / 0.32 s), so the model's ADEV lay 2.2-2.4x under
    the record from 5-10 s up; the diagnosis named `random_walk` and a `gauss_markov` of tau
    14.5 s. Asserted also: the written model's slowest GM has tau >= 5 s (the record's slow power).
  - alt record 9, gy (64 Hz; an oscillating AR(3) rounded on an LSB of 1.2 sd): the rounding's share
    was taken out of the AR's driving noise, which lowered its whole spectrum, so the model was
    0.85-0.94x the record's ADEV from 0.25 s up; the diagnosis named a `gauss_markov`.
  - third record 8, gy (1534 Hz, 261 s; white + slow noises + a ramp of ~600 deg/h^2, rounded on an
    LSB of about the white noise's sd): on that correlated lattice the Allan points choose the set,
    which saw no drift; the diagnosis named `ramp`. Asserted also: a drift is written.
Asserted per channel: the record diagnosed against its own fit shows nothing.

    own_fit_challenge.py SINSIM WORKDIR
"""
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bench", "diagnose_challenge"))
import challenge  # noqa: E402
from model_file import gm_taus, reported_findings, written_effects  # noqa: E402

# (generator, record, section, axis, channel, what else the written model must hold: "slow GM", a GM
# of tau >= 5 s, or "drift")
CASES = [("alt", 11, "accel", "x", "ax", "slow GM"), ("alt", 18, "gyro", "y", "gy", "slow GM"),
         ("alt", 9, "gyro", "y", "gy", None), ("third", 8, "gyro", "y", "gy", "drift")]


def main():
    sinsim, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    failures = []
    for generator, idx, section, axis, channel, holds in CASES:
        name = f"{generator} record {idx} {channel}"
        row = challenge.null_record(generator, np.random.default_rng([4, idx]), idx,
                                    os.path.join(work, generator), 400000)
        model = row["record"][:-4] + ".fit.yaml"
        report = row["record"][:-4] + ".json"
        p = subprocess.run([sinsim, "fit", row["record"], "-q", "-o", model, "--axes", channel],
                           capture_output=True, text=True)
        if p.returncode != 0:
            failures.append(f"{name}: fit failed: {p.stderr.strip()}")
            continue
        p = subprocess.run([sinsim, "diagnose", row["record"], "--model", model, "--json", report,
                            "--channels", channel], capture_output=True, text=True)
        if p.returncode != 0:
            failures.append(f"{name}: diagnose failed: {p.stderr.strip()}")
            continue
        found = reported_findings(report, channel)
        taus, effects = gm_taus(model, section, axis), written_effects(model, section, axis)
        print(f"{name}: written {', '.join(effects)} (GM taus {taus} s); the record against its own fit: "
              f"{found or 'nothing'}")
        if holds == "slow GM" and (not taus or max(taus) < 5.0):
            failures.append(f"{name}: slowest GM tau {max(taus) if taus else 'none'} s < 5 s")
        if holds == "drift" and "ramp" not in effects:
            failures.append(f"{name}: no drift (ramp) written")
        if found:
            failures.append(f"{name}: {found} against its own fit, with nothing hidden")
    for f in failures:
        print("FAILED", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
