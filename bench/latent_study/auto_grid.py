"""`sinsim fit` (any --kind, default auto) on the round-trip generators' records, through the CLI.

Reads the stream of bench/latent_study/generate.py or generate_alt.py on stdin (one JSON line per
record, then its float64 samples), writes each record as a CSV (t [s], gx [rad/s]) under --work,
fits it with `sinsim fit --kind KIND`, and counts per case how often the written model holds
exactly the generating terms ("right set"; a ramp counts as a drift term). Prints one line per
case with the sets written. NumPy only; the fit is the product's, run as a user runs it.

    python3 bench/latent_study/generate.py --rate 100 --duration 1200 --seeds 40 --first-seed 300 \\
        | python3 bench/latent_study/auto_grid.py --work /tmp/auto_grid --sinsim build/sinsim
"""
import argparse
import collections
import json
import os
import re
import subprocess
import sys

import numpy as np


def records(stream):
    while True:
        line = stream.readline()
        if not line:
            return
        meta = json.loads(line)
        x = np.frombuffer(stream.read(8 * meta["n"]), dtype="<f8")
        yield meta, x


def written_terms(model_text):
    types = re.findall(r"\{type: (\w+)", model_text)
    return {"quantization": "quantization" in types, "white": "white" in types,
            "gm": types.count("gauss_markov"), "flicker": "bias_instability" in types,
            "random_walk": "random_walk" in types, "drift": "ramp" in types, "ar": "ar" in types}, types


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", required=True, help="folder for the CSV records and the model files")
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--kind", default="auto")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    right = collections.Counter()
    total = collections.Counter()
    sets = collections.defaultdict(collections.Counter)
    for meta, x in records(sys.stdin.buffer):
        name = "%s_%g_%g_s%d" % (meta["case"].replace("+", "-"), meta["rate"], meta["duration"], meta["seed"])
        csv = os.path.join(a.work, name + ".csv")
        model = os.path.join(a.work, name + "." + a.kind + ".yaml")
        t = (np.arange(len(x)) + 1) / meta["rate"]
        with open(csv, "w") as f:
            f.write("t [s],gx [rad/s]\n")
            np.savetxt(f, np.column_stack([t, x]), delimiter=",", fmt="%.9g")
        r = subprocess.run([a.sinsim, "fit", csv, "-o", model, "--kind", a.kind, "-q"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        got, types = written_terms(open(model).read()) if r.returncode == 0 else ({}, ["(fit failed)"])
        want = {k: meta["terms"].get(k, False) for k in ("quantization", "white", "gm", "flicker",
                                                          "random_walk", "drift", "ar")}
        total[meta["case"]] += 1
        right[meta["case"]] += got == want
        sets[meta["case"]]["+".join(sorted(types))] += 1
        os.remove(csv)
    for case in total:
        print("%-20s %s: right set %d/%d; written: %s" % (
            case, a.kind, right[case], total[case],
            ", ".join("%s %d" % kv for kv in sets[case].most_common())))


if __name__ == "__main__":
    main()
