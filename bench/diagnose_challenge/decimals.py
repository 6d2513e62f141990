#!/usr/bin/env python3
"""Null records of the challenge written with a fixed number of decimals, diagnosed against their exact base.

A CSV written as %.6f (pandas' float_format, printf) puts every channel on a value lattice. The
records are the challenge's null draws (`challenge.py --null`: no hidden effect, the model file =
the exact base), rewritten in FORMAT; counts the clean channels that report a finding
(docs/diagnose.md, "A CSV's printing precision is no quantization"). NumPy only, no sinsim code.

    /usr/bin/python3 bench/diagnose_challenge/decimals.py --format %.6f --records 30 --work /tmp/dec
"""
import argparse
import collections
import os

import numpy as np

import challenge


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--format", default="%.6f", help="printf format of every value")
    ap.add_argument("--records", type=int, default=30)
    ap.add_argument("--seed", type=int, default=6)
    ap.add_argument("--max-samples", type=int, default=30000)
    ap.add_argument("--realisations", type=int, default=16)
    ap.add_argument("--work", default="out/decimals")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    reported, channels, effects = 0, 0, collections.Counter()
    for i in range(a.records):
        row = challenge.make(np.random.default_rng([a.seed, i]), i, a.work, a.max_samples, challenge.BASES,
                             True, None, "all")
        with open(row["record"]) as fh:
            header = fh.readline().strip()
        data = np.loadtxt(row["record"], delimiter=",", skiprows=1)
        np.savetxt(row["record"], data, delimiter=",", header=header, comments="", fmt=a.format)
        res = challenge.diagnose(a.sinsim, row, argparse.Namespace(sinsim=a.sinsim, threads=1, threshold=None,
                                                                   realisations=a.realisations))
        os.remove(row["record"])
        if "error" in res:
            raise SystemExit(f"{row['record']}: {res['error']}")
        for found in (r["findings"] for r in res.values()):
            channels += 1
            reported += bool(found)
            effects.update(found)
        print(f"\r{i + 1}/{a.records} records", end="", flush=True)
    print(f"\n{a.format}: clean channels reporting a finding {reported}/{channels}",
          dict(effects) if effects else "")


if __name__ == "__main__":
    main()
