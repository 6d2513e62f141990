#!/usr/bin/env python3
"""False settling warnings of `sinsim fit` on records without a settling, from the diagnosis
challenge's three generators (bench/diagnose_challenge/generate.py, generate_alt.py,
generate_third.py: NumPy/SciPy, written for the diagnosis without this test in view) with their
null option: six channels per record, bases white + GM, white + walk + flicker, random stable AR(p)
and the others' own families, rates 50 Hz - 2 kHz, 20 min - 4 h capped at --max-samples.

Each record is fitted with --kind latent and --kind gm; a channel counts when fit warns of a
settling on it (a warning names the channel). The AR bases are where --kind latent approximates
the record with the terms it has. The narrow lines fit writes (its line warnings) are counted too:
on a null record each is a false line.

With --effects 1 each record has one hidden effect on one channel, drawn from the generator's
whole pool (its catalogue: warm-up, ramp, walk, temperature, ...; and out of it: telegraph, bias
step, ...) at its own sizes: the warnings are counted per hidden effect, on the hidden channel
and on the five others.

  /usr/bin/python3 bench/fit_settling/null_records.py --generator main --records 40 --work /tmp/null
  /usr/bin/python3 bench/fit_settling/null_records.py --generator alt --effects 1 --kinds latent \
      --records 60 --work /tmp/hidden
"""
import argparse, os, re, subprocess, sys
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "diagnose_challenge"))
import challenge  # noqa: E402

WARN = re.compile(r"warning: (\w\w): the record starts with a settling: .*?tau (\S+) s.*?z (\S+),")
LINE = re.compile(r"warning: (\w\w): a narrow line at (\S+) Hz")


def one(a, i):
    rng = np.random.default_rng([a.seed, i])
    null = a.effects == 0
    effects = None if null else a.effects
    if a.generator == "main":
        row = challenge.make(rng, i, a.work, a.max_samples, null=null, effects=effects)
    else:
        row = challenge.gen_module(a.generator).make(rng, i, a.work, a.max_samples, None, null, effects)
    out = {"rate": row["rate_hz"], "samples": row["samples"], "kinds": {}, "channel": row["channel"],
           "hidden": [h["effect"] for h in row["hidden"]],
           "sizes": [f'{h["effect"]} {h["size"]:.3g}x' + (f' tau {h.get("tau_c", h.get("tau_s")):.3g} s' if "tau_c" in h or "tau_s" in h else "")
                     for h in row["hidden"]]}
    for kind in a.kinds.split(","):
        r = subprocess.run([a.sinsim, "fit", row["record"], "--kind", kind, "-o", row["record"][:-4] + f".{kind}.yaml"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        out["kinds"][kind] = {"error": r.returncode != 0, "warned": WARN.findall(r.stderr),
                              "lines": LINE.findall(r.stderr)}
        if r.returncode != 0:
            out["kinds"][kind]["message"] = r.stderr.strip().splitlines()[-1:] if r.stderr.strip() else ["exit %d" % r.returncode]
    os.remove(row["record"])
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--generator", default="main", choices=["main", "alt", "third"])
    ap.add_argument("--records", type=int, default=40)
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--max-samples", type=int, default=400000)
    ap.add_argument("--kinds", default="latent,gm")
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--work", default="/tmp/settling_null")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--effects", type=int, default=0, choices=[0, 1])
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    count = defaultdict(lambda: defaultdict(int))
    hidden = defaultdict(lambda: defaultdict(int))  # (kind, effect) -> counts
    with ThreadPoolExecutor(a.jobs) as pool:
        for k, r in enumerate(pool.map(lambda i: one(a, i), range(a.records))):
            for kind, v in r["kinds"].items():
                c = count[kind]
                c["records"] += 1
                c["errors"] += v["error"]
                c["channels"] += 0 if v["error"] else 6
                c["warned"] += len(v["warned"])
                c["lines"] += len(v["lines"])
                for effect in r["hidden"]:
                    h = hidden[(kind, effect)]
                    h["records"] += not v["error"]
                    h["on"] += any(ch == r["channel"] for ch, _, _ in v["warned"])
                    h["off"] += sum(ch != r["channel"] for ch, _, _ in v["warned"])
            print(f"record {k}: {r['rate']:g} Hz, {r['samples']} samples, hidden {r['sizes']} on "
                  f"{r['channel']}: " + "; ".join(f"{kind} {v['warned'] or '-'}" + (f" lines {v['lines']}" if v["lines"] else "")
                             + (f" FAILED {v['message']}" if v["error"] else "")
                             for kind, v in r["kinds"].items()),
                  file=sys.stderr, flush=True)
    for kind, c in count.items():
        print(f"{a.generator} --kind {kind}: settling warned on {c['warned']}/{c['channels']} channels "
              f"({c['records']} records, {c['errors']} fits failed); lines written {c['lines']}")
    for (kind, effect), h in sorted(hidden.items()):
        print(f"  --kind {kind}, hidden {effect}: warned on its channel {h['on']}/{h['records']}, "
              f"on the others {h['off']}/{5 * h['records']}")


if __name__ == "__main__":
    main()
