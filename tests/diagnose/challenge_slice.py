#!/usr/bin/python3
"""A small seeded slice of the diagnosis challenge (bench/diagnose_challenge) as a test.

Records made by the NumPy generator (no sinsim code), diagnosed by `sinsim diagnose` at the default
(calibrated) threshold. The bounds are statistical: each is the count that a diagnosis meeting the
issue's floors would miss with probability < 1 % (binomial tail), so a failure means the rate is
worse than the floor, not bad luck of this seed.

    challenge_slice.py SINSIM WORKDIR
"""
import math
import os
import sys
from types import SimpleNamespace

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bench", "diagnose_challenge"))
import challenge  # noqa: E402
import quantization_noise  # noqa: E402

RECORDS = 16
OOC_RECORDS = 12  # one out-of-catalogue effect each (telegraph or bias step), hidden channel only
ALT_RECORDS = 24  # the independent generator, one catalogue effect each, hidden channel only
QN_RECORDS = 8  # quantization noise without a lattice (GMWM's QN) on the independent generator's bases


def binom_cdf(k, n, p):
    return sum(math.comb(n, i) * p ** i * (1 - p) ** (n - i) for i in range(k + 1))


def max_allowed(n, p, alpha=0.01):
    """Largest count c with P(X > c) < alpha for X ~ Binomial(n, p)."""
    c = 0
    while 1 - binom_cdf(c, n, p) >= alpha:
        c += 1
    return c


def min_required(n, p, alpha=0.01):
    """Smallest count c with P(X < c) < alpha for X ~ Binomial(n, p)."""
    c = n
    while c > 0 and binom_cdf(c - 1, n, p) >= alpha:
        c -= 1
    return c


def main():
    sinsim, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    a = SimpleNamespace(seed=12, work=work, max_samples=20000, bases="", null=False, add=False,
                        sinsim=sinsim, threads=1, realisations=16, threshold=None)
    rows = [challenge.run_one(a, i) for i in range(RECORDS)]
    sc = challenge.report(rows)
    errors = sum("error" in r.get("result", {}) for r in rows)
    fa, clean = sc["clean"]
    ge3 = challenge.at_least_3x(sc["top1"])
    # Floors of issue 12: false alarms <= 2 % per clean channel; top-1 >= 90 % at >= 3x.
    fa_max = max_allowed(clean, 0.02)
    top_min = min_required(ge3[1], 0.90)
    print(f"diagnose errors {errors}; false alarms {fa}/{clean} (allowed <= {fa_max}); "
          f"top-1 at >= 3x {ge3[0]}/{ge3[1]} (required >= {top_min})")
    # Out of catalogue (a bias step, a telegraph): named as its physical equivalent or left
    # unexplained >= 80 % (issue 12). Other draws than the benchmark's (seed 12, pool "ooc").
    o = SimpleNamespace(**{**vars(a), "work": os.path.join(work, "ooc"), "effects": 1, "pool": "ooc",
                           "hidden_only": True})
    os.makedirs(o.work, exist_ok=True)
    ooc_rows = [challenge.run_one(o, i) for i in range(OOC_RECORDS)]
    errors += sum("error" in r.get("result", {}) for r in ooc_rows)
    ooc, ooc_n = challenge.score(ooc_rows)["ooc"]
    ooc_min = min_required(ooc_n, 0.80)
    print(f"out of catalogue as equivalent or unexplained {ooc}/{ooc_n} (required >= {ooc_min})")
    # The independent generator (generate_alt.py, --generator alt): one catalogue effect per record,
    # hidden channel only; its records carry a temperature column on ~40 % that no channel follows.
    # Top-1 >= 90 % at >= 3x its own size (issue 12's floor on records not made for the method).
    g = SimpleNamespace(**{**vars(a), "work": os.path.join(work, "alt"), "effects": 1, "pool": "catalogue",
                           "hidden_only": True, "generator": "alt"})
    os.makedirs(g.work, exist_ok=True)
    alt_rows = [challenge.run_one(g, i) for i in range(ALT_RECORDS)]
    errors += sum("error" in r.get("result", {}) for r in alt_rows)
    alt3 = challenge.at_least_3x(challenge.score(alt_rows)["top1"])
    alt_min = min_required(alt3[1], 0.90)
    print(f"independent generator: top-1 at >= 3x {alt3[0]}/{alt3[1]} (required >= {alt_min})")
    # Quantization noise as GMWM generates it (no value lattice), 1.5-10x the base at one sample:
    # named first >= 90 % (the floor of a catalogue effect), on other draws than the study's.
    q = SimpleNamespace(**{**vars(a), "work": os.path.join(work, "qn"), "generator": "alt", "hidden_only": True})
    os.makedirs(q.work, exist_ok=True)
    qn_rows = [quantization_noise.run_one(q, i) for i in range(QN_RECORDS)]
    errors += sum("error" in r.get("result", {}) for r in qn_rows)
    qn = sum((r["result"][r["channel"]]["findings"] or [None])[0] == "quantization" for r in qn_rows
             if "error" not in r["result"])
    qn_min = min_required(QN_RECORDS, 0.90)
    print(f"quantization noise without a lattice named first {qn}/{QN_RECORDS} (required >= {qn_min})")
    ok = errors == 0 and fa <= fa_max and ge3[0] >= top_min and clean >= 60 and ge3[1] >= 3
    ok = ok and ooc >= ooc_min and ooc_n == OOC_RECORDS and alt3[0] >= alt_min and alt3[1] >= 8
    ok = ok and qn >= qn_min
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
