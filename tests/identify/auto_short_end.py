#!/usr/bin/python3
"""`sinsim fit` (auto) on blind white + flicker + random-walk records: the written model keeps the
record's short tau.

The records are the blind round-trip generator's (bench/fit_blind/generate.py: NumPy, no sinsim
code; 100 Hz, 20 min, its flicker sampled up to Nyquist), indices 700 and 706, where auto's AR
screen finds short correlation and its AR + slow-terms fit, scanned from 0.32 s and 0.16 s, left
the model at 0.55x and 0.66x the record's ADEV at 10 ms (the AR's driving variance set by the
longer tau). Auto now writes the latent terms there, which fit the whole range consistently
(identify_auto.cpp): asserted is that the written model has no warning of a model off the record
below its fitted start, and that it holds the record's flicker and random walk.

    auto_short_end.py SINSIM WORKDIR
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bench", "fit_blind"))
import generate  # noqa: E402
from model_file import written_effects  # noqa: E402


def main():
    sinsim, work = sys.argv[1], sys.argv[2]
    failures = []
    for idx in (700, 706):
        path, _ = generate.make("white+flicker+rw", 100.0, 1200.0, idx, work)
        model = path[:-4] + ".auto.yaml"
        r = subprocess.run([sinsim, "fit", path, "--rate", "100", "--gyro-unit", "deg/s", "-o", model, "-q"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            failures.append(f"{idx}: fit failed: {r.stderr.strip()}")
            continue
        text = open(model).read()
        effects = written_effects(model, "gyro", "x")  # the record's one column, gx
        print(f"#{idx}: {', '.join(effects)}")
        if "below the fitted range" in text:
            failures.append(f"{idx}: the written model is off the record below its fitted start")
        for need in ("bias_instability", "random_walk"):
            if need not in effects:
                failures.append(f"{idx}: no {need} written ({effects})")
    for f in failures:
        print("FAILED", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
