#!/usr/bin/env python3
"""The channels whose base model carries a known drift (`ramp`), diagnosed alone.

Draws the benchmark's records exactly as challenge.py does (same generator, seed and index), keeps
those whose model file has a `ramp` on some channel, and runs `sinsim diagnose` on those channels
only (the others do not depend on how a model's ramp is handled). Prints false alarms on the clean
ones and, for the hidden channel, what was found; --compare OLD.json lists the channels whose
findings differ from an earlier run's (e.g. another binary's). docs/diagnose-log.md, "Twenty-ninth
session".

  /usr/bin/python3 bench/diagnose_challenge/drift_base_study.py --generator third --seed 2 \\
      --work /tmp/drift2 --sinsim build/sinsim
"""
import argparse
import importlib
import json
import os
import subprocess
import sys
from multiprocessing import Pool

import numpy as np
import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import challenge  # noqa: E402

AXES = {"gyro": ("gx", "gy", "gz"), "accel": ("ax", "ay", "az")}


def drift_channels(model_path):
    m = yaml.safe_load(open(model_path)) or {}
    out = []
    for sensor, names in AXES.items():
        for axis, effects in (m.get(sensor) or {}).items():
            if any(e.get("type") == "ramp" for e in effects or []):
                out += list(names) if axis == "all" else [names["xyz".index(axis)]]
    return out


def one(job):
    a, i = job
    rng = np.random.default_rng([a.seed, i])
    if a.generator == "main":
        row = challenge.make(rng, i, a.work, a.max_samples)
    else:
        mod = importlib.import_module(challenge.GENERATORS[a.generator])
        row = mod.make(rng, i, a.work, a.max_samples, None, False, None, "all")
    chans = drift_channels(row["model"])
    result = None
    if chans:
        out = row["record"][:-4] + ".json"
        p = subprocess.run(["nice", a.sinsim, "diagnose", row["record"], "--model", row["model"], "--json", out,
                            "--threads", "1", "--realisations", str(a.realisations), "--channels"] + chans,
                           capture_output=True, text=True)
        if p.returncode:
            result = {"error": p.stderr.strip()[-300:]}
        else:
            d = json.load(open(out))
            result = {x["channel"]: [f["effect"] for f in x["findings"] if f.get("reported")] for x in d["axes"]}
    os.remove(row["record"])
    return {"i": i, "channel": row["channel"], "hidden": [(h["effect"], h["size"]) for h in row["hidden"]],
            "drift_channels": chans, "result": result}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--generator", choices=sorted(challenge.GENERATORS), default="third")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--records", type=int, default=500)
    ap.add_argument("--max-samples", type=int, default=30000)
    ap.add_argument("--realisations", type=int, default=16)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--work", required=True)
    ap.add_argument("--compare", help="an earlier run's drift.json: list the channels that changed")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    with Pool(a.jobs) as p:
        rows = p.map(one, [(a, i) for i in range(a.records)])
    json.dump(rows, open(os.path.join(a.work, "drift.json"), "w"))
    clean = alarms = 0
    for r in rows:
        res = r["result"] or {}
        if "error" in res:
            print(f"r{r['i']:04d}: diagnose failed: {res['error']}")
            continue
        for ch, found in res.items():
            if ch == r["channel"] and r["hidden"]:
                print(f"r{r['i']:04d} {ch} hidden {[(e, round(s, 1)) for e, s in r['hidden']]} -> {found}")
            else:
                clean += 1
                alarms += bool(found)
    print(f"records with a model ramp: {sum(bool(r['drift_channels']) for r in rows)}; "
          f"clean channels with one: {clean}, false alarms {alarms}")
    if a.compare:
        old = {r["i"]: r for r in json.load(open(a.compare))}
        changed = 0
        for r in rows:
            for ch, found in (r["result"] or {}).items():
                before = (old.get(r["i"], {}).get("result") or {}).get(ch)
                if ch != "error" and found != before:
                    changed += 1
                    print(f"changed r{r['i']:04d} {ch}: {before} -> {found}")
        print(f"channels changed against {a.compare}: {changed}")


if __name__ == "__main__":
    main()
