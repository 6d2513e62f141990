#!/usr/bin/python3
"""Challenge benchmark of `sinsim diagnose` on records it has never seen.

Makes --records static IMU records with generate.py (NumPy only, independent of sinsim), runs
`sinsim diagnose RECORD --model BASE.yaml --json` on each, and scores the findings against the
hidden truth: top-1 on the effect channel, both effects on two-effect channels, false alarms on
clean channels, out-of-catalogue effects named as their physical equivalent or "unexplained",
and (with --add) the misfit after / before adding the correct effect.

    /usr/bin/python3 bench/diagnose_challenge/challenge.py --records 60 --seed 1 \
        --sinsim build/sinsim --work out/challenge

Results: a table on stdout and WORK/results.json (one row per record).
"""
import argparse
import json
import math
import os
import subprocess
import sys
from collections import Counter, defaultdict

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate as g  # noqa: E402

BASES = ["white+gm", "white+rw+flicker", "ar"]
RATES = [50.0, 100.0, 200.0, 500.0, 1000.0, 2000.0]
SIZES = [1.5, 3.0, 6.0, 10.0]
VISIBLE = 1.5  # an effect hidden by its partner: below this many times the ADEV of the rest at every tau
GYRO_SCALE = math.radians(0.005)  # rad/s/sqrt(Hz): a MEMS gyro's white density
ACCEL_SCALE = 1e-3                # m/s^2/sqrt(Hz)


GENERATORS = {"main": "generate", "alt": "generate_alt", "third": "generate_third"}
POOLS = {"all": g.CATALOGUE + g.OUT_OF_CATALOGUE, "catalogue": g.CATALOGUE, "ooc": g.OUT_OF_CATALOGUE}


def gen_module(row_or_name):
    """The generator module of a results row (its "generator", default main) or of a name: its
    CATALOGUE / OUT_OF_CATALOGUE / EQUIVALENT score the row. generate_alt.py (--generator alt) and
    generate_third.py (--generator third) are independent designs; imported only when used."""
    name = row_or_name.get("generator", "main") if isinstance(row_or_name, dict) else row_or_name
    if name == "main":
        return g
    import importlib
    return importlib.import_module(GENERATORS[name])


def size_key(row, h):
    """The top-1 table's key of a one-effect row: main's sizes are the levels of SIZES; the alt
    generator's are continuous (log-uniform 1.5-10), binned to the lower edge of [1.5, 3), [3, 6),
    [6, 10]."""
    if row.get("generator", "main") == "main":
        return h["size"]
    return max([s for s in (1.5, 3.0, 6.0) if h["size"] >= s] or [1.5])


def draw_record(rng, max_samples, null=False, effects=None, pool="all"):
    """Rate, samples and hidden effect names; `effects` forces their number (studies of one case:
    --effects 2 --pool catalogue), drawn from POOLS[pool]."""
    fs = float(rng.choice(RATES))
    T = 10 ** rng.uniform(math.log10(1200.0), math.log10(4 * 3600.0))
    n = int(min(T * fs, max_samples))
    n_effects = int(rng.choice([0, 1, 1, 2], p=[0.2, 0.5, 0.1, 0.2]))
    if null:
        n_effects = 0
    elif effects is not None:
        n_effects = effects
    pool = POOLS[pool]
    names = list(rng.choice(pool, size=n_effects, replace=False)) if n_effects else []
    return fs, n, names


def yaml_effect(name, p, sensor):
    su = "rad/s" if sensor == "gyro" else "m/s^2"
    if name == "white":
        return f"{{type: white, density: {p['density']!r} {su}/sqrt(Hz)}}"
    if name == "gauss_markov":
        return f"{{type: gauss_markov, sigma: {p['sigma']!r} {su}, tau: {p['tau']!r} s}}"
    if name == "random_walk":
        return f"{{type: random_walk, K: {p['K']!r} {su}/sqrt(s)}}"
    if name == "bias_instability":
        lo, hi = p["tau_range"]
        return f"{{type: bias_instability, B: {p['B']!r} {su}, tau_range: [{lo!r} s, {hi!r} s]}}"
    if name == "ar":
        a = ", ".join(repr(float(v)) for v in p["a"])
        return f"{{type: ar, a: [{a}], sigma: {p['sigma']!r} {su}, rate: {p['rate']!r} Hz}}"
    if name == "quantization":
        return f"{{type: quantization, lsb: {p['lsb']!r} {su}}}"
    raise ValueError(name)


def axis_key(ch):
    return ("gyro" if ch[0] == "g" else "accel"), ch[1]


def make(rng, idx, work, max_samples, bases=BASES, null=False, effects=None, pool="all"):
    fs, n, names = draw_record(rng, max_samples, null, effects, pool)
    t = np.arange(1, n + 1) / fs
    T = n / fs
    temp = 25.0 + 15.0 * (1.0 - np.exp(-t / (T / 4.0))) + 0.05 * rng.standard_normal(n)
    hidden_ch = str(rng.choice(g.CHANNELS))
    mean = {"gx": g.EARTH_RATE * math.cos(g.LATITUDE), "gy": 0.0,
            "gz": -g.EARTH_RATE * math.sin(g.LATITUDE), "ax": 0.0, "ay": 0.0, "az": -g.GRAVITY}
    cols, model, truth = {}, {"gyro": {}, "accel": {}}, []
    for ch in g.CHANNELS:
        sensor, ax = axis_key(ch)
        scale = GYRO_SCALE if sensor == "gyro" else ACCEL_SCALE
        kind = str(rng.choice(bases))
        base, effects = g.make_base(rng, n, fs, scale, kind)
        q = None
        if rng.random() < 0.25:  # a quantized base: LSB a fraction of the one-sample sd
            q = float(np.std(np.diff(base)) * 10 ** rng.uniform(-1.5, -0.7))
            effects.append(("quantization", {"lsb": q}))
        x = base.copy()
        added = []  # (index in truth, scaled effect) of the hidden channel's additive effects
        if ch == hidden_ch:
            for name in names:
                if name == "quantization" and q is None:
                    # size = LSB / (one-sample sd of the base): a lattice a diagnosis must see
                    k = float(rng.choice(SIZES)) / 2.0
                    q = k * float(np.std(np.diff(base))) / math.sqrt(2.0)
                    truth.append({"effect": name, "size": k, "lsb": q})
                    continue
                if name == "quantization":  # already quantized: another effect, not one drawn
                    name = "ramp" if "ramp" not in names else "warmup"
                e, info = g.unit_effect(rng, name, n, fs, t, temp)
                k = float(rng.choice(SIZES))
                scaled = e * g.scale_to(e, base, fs, k)
                x = x + scaled
                added.append((len(truth), scaled))
                truth.append({"effect": name, "size": k, **info})
            if len(added) == 2:
                # Each effect against the base AND the other effect (its size is against the base
                # alone): max over tau of ADEV_effect / ADEV_rest. Below ~1 the partner hides it.
                grid = g.octave_grid(n)
                for i, e in added:
                    rest = base + sum(o for j, o in added if j != i)
                    ratio = g.adev(e, 1.0 / fs, grid) / g.adev(rest, 1.0 / fs, grid)
                    truth[i]["visibility"] = float(np.max(ratio))
        x = x + mean[ch]
        cols[ch] = g.quantize(x, q) if q is not None else x
        model[sensor][ax] = [yaml_effect(nm, p, sensor) for nm, p in effects]
    rec = os.path.join(work, f"r{idx:04d}.csv")
    header = "t,gx,gy,gz,ax,ay,az" + (",temp" if "temperature" in names else "")
    data = [t] + [cols[c] for c in g.CHANNELS] + ([temp] if "temperature" in names else [])
    np.savetxt(rec, np.column_stack(data), delimiter=",", header=header, comments="", fmt="%.12g")
    mod = os.path.join(work, f"r{idx:04d}.yaml")
    with open(mod, "w") as f:
        for sensor in ("gyro", "accel"):
            f.write(f"{sensor}:\n")
            for ax in ("x", "y", "z"):
                f.write(f"  {ax}:\n" + "".join(f"    - {e}\n" for e in model[sensor][ax]))
    return {"record": rec, "model": mod, "rate_hz": fs, "samples": n, "channel": hidden_ch,
            "hidden": truth}


def null_record(generator, rng, idx, work, max_samples):
    """A record of the named generator with no hidden effect (its --null draw), as a row."""
    if generator == "main":
        return make(rng, idx, work, max_samples, BASES, True)
    return gen_module(generator).make(rng, idx, work, max_samples, None, True)


def diagnose(sinsim, row, opts, add=None):
    """Runs sinsim diagnose on the row's record; per channel the reported findings in acceptance
    order, the best drop score of any candidate (the first trial round when nothing is reported:
    what a threshold calibration needs), the second-round score (second_score, below), and the
    unexplained range. With add="EFFECT:CH" the misfit before and after adding it."""
    out = row["record"][:-4] + (".add.json" if add else ".json")
    cmd = ["nice", opts.sinsim, "diagnose", row["record"], "--model", row["model"], "--json", out,
           "--threads", str(opts.threads), "--realisations", str(opts.realisations),
           "-o", row["record"][:-4] + ".improved.yaml"]
    if opts.threshold is not None:
        cmd += ["--threshold", str(opts.threshold)]
    if add:
        cmd += ["--add", add]
    if getattr(opts, "hidden_only", False) or getattr(opts, "subset", None):
        cmd += ["--channels", row["channel"]]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        return {"error": p.stderr.strip()[-400:]}
    d = json.load(open(out))
    res = {}
    for a in d["axes"]:
        if add:
            res[a["channel"]] = {"misfit_before": a["misfit_before"], "misfit_after": a["misfit_after"],
                                 "added": a["added"]}
            continue
        rep = [f for f in a["findings"] if f.get("reported")]
        res[a["channel"]] = {"findings": [f["effect"] for f in rep], "misfit": a["misfit"],
                             "second_score": second_score(a["findings"]),
                             "fits": a["fits"],
                             "unexplained": a.get("unexplained") or a.get("unexplained_steps"),
                             "noise_level": bool(a.get("noise_level_change")),
                             "best_score": max([f["score"] for f in a["findings"]] + [0.0]),
                             "best_effect": max(a["findings"], key=lambda f: f["score"])["effect"]
                             if a["findings"] else None}
    return res


def second_score(findings):
    """What the search scored after the first finding: the second reported finding's score, else
    the largest score of the candidates not reported (0 without a first finding). On channels whose
    one effect came first this is the null of a further finding (--next-threshold's calibration)."""
    rep = [f["score"] for f in findings if f.get("reported")]
    if len(rep) >= 2:
        return rep[1]
    rest = [f["score"] for f in findings if not f.get("reported")]
    return max(rest) if rep and rest else 0.0


def score(rows):
    """Counts [hits, total] of every score of the issue (docs/diagnose.md, "Challenge benchmark")."""
    sc = {"top1": defaultdict(lambda: [0, 0]), "by_effect": defaultdict(lambda: [0, 0]),
          "both": [0, 0], "extra": [0, 0], "clean": [0, 0], "clean_unexplained": [0, 0], "clean_noise_level": [0, 0], "hidden_noise_level": Counter(), "ooc": [0, 0], "ooc_halved": [0, 0], "both_ooc": [0, 0],
          "both_visible": [0, 0], "halved": [0, 0], "ratios": [], "confusion": defaultdict(Counter), "null_scores": [],
          "second_scores": []}
    for r in rows:
        res = r.get("result", {})
        if "error" in res:
            continue
        for ch, c in res.items():
            named = c["findings"][0] if c["findings"] else ("unexplained" if c.get("unexplained") else "none")
            if ch != r["channel"] or not r["hidden"]:
                sc["clean"][1] += 1
                sc["clean"][0] += bool(c["findings"])
                sc["clean_unexplained"][1] += 1
                sc["clean_unexplained"][0] += bool(c.get("unexplained")) and not c["findings"]
                sc["clean_noise_level"][1] += 1
                sc["clean_noise_level"][0] += bool(c.get("noise_level"))
                sc["null_scores"].append(c.get("best_score", 0.0))
                sc["confusion"]["(clean)"][named] += 1
                continue
            hid = [h["effect"] for h in r["hidden"]]
            gm = gen_module(r)
            if c.get("noise_level"):
                sc["hidden_noise_level"]["+".join(sorted(hid))] += 1
            if len(hid) == 1:
                h = r["hidden"][0]
                sc["confusion"][h["effect"]][named] += 1
                if h["effect"] in gm.OUT_OF_CATALOGUE:
                    sc["ooc"][1] += 1
                    sc["ooc"][0] += named in gm.EQUIVALENT[h["effect"]]
                    add = r.get("add", {}).get(ch)
                    if add and named in gm.EQUIVALENT[h["effect"]] and add["misfit_before"] > 0:
                        sc["ooc_halved"][1] += 1
                        sc["ooc_halved"][0] += add["misfit_after"] <= 0.5 * add["misfit_before"]
                else:
                    key = "lsb" if h["effect"] == "quantization" else size_key(r, h)
                    sc["top1"][key][1] += 1
                    sc["top1"][key][0] += named == h["effect"]
                    sc["by_effect"][h["effect"]][1] += 1
                    sc["by_effect"][h["effect"]][0] += named == h["effect"]
                    if named == h["effect"]:  # the null of a further finding (--next-threshold)
                        sc["extra"][1] += 1
                        sc["extra"][0] += any(f != named for f in c["findings"])
                        if "second_score" in c:
                            sc["second_scores"].append(c["second_score"])
                    add = r.get("add", {}).get(ch)
                    if add and named == h["effect"] and add["misfit_before"] > 0:
                        ratio = add["misfit_after"] / add["misfit_before"]
                        sc["ratios"].append(ratio)
                        sc["halved"][1] += 1
                        sc["halved"][0] += ratio <= 0.5
            else:
                cat = [x for x in hid if x in gm.CATALOGUE]
                sc["confusion"]["+".join(sorted(hid))][named] += 1
                if len(cat) == 1:  # a catalogue effect beside an out-of-catalogue one named as its equivalent
                    other = next(x for x in hid if x not in gm.CATALOGUE)
                    sc["both_ooc"][1] += 1
                    sc["both_ooc"][0] += cat[0] in c["findings"] and bool(set(c["findings"]) & gm.EQUIVALENT[other])
                if len(cat) == 2:
                    sc["both"][1] += 1
                    sc["both"][0] += set(cat) <= set(c["findings"])
                    if all(h.get("visibility", VISIBLE) >= VISIBLE for h in r["hidden"]):
                        sc["both_visible"][1] += 1
                        sc["both_visible"][0] += set(cat) <= set(c["findings"])
    return sc


def at_least_3x(top1):
    """[hits, total] of the one-effect channels at >= 3x (quantization apart: its size is an LSB)."""
    return [sum(top1[k][i] for k in top1 if k != "lsb" and k >= 3) for i in (0, 1)]


def pct(a, b):
    return f"{100.0 * a / b:5.1f} % ({a}/{b})" if b else "   -   (0/0)"


def report(rows):
    sc = score(rows)
    errors = sum("error" in r.get("result", {}) for r in rows)
    print(f"records: {len(rows)}  (diagnose failed on {errors})")
    top1 = sc["top1"]
    alt = any(r.get("generator", "main") != "main" for r in rows)
    for k in sorted(x for x in top1 if x != "lsb"):
        if alt:  # size_key: the alt generator's continuous sizes binned (its own size definition)
            print(f"top-1 correct, one effect at {k:4.1f}x and up to the next bin (alt sizes): {pct(*top1[k])}")
        else:
            print(f"top-1 correct, one effect at {k:4.1f}x base ADEV: {pct(*top1[k])}")
    ge3 = at_least_3x(top1)
    print(f"top-1 correct, one effect at >= 3x:             {pct(*ge3)}")
    print(f"top-1 correct, quantization (LSB {'0.5' if alt else '0.75'}-5 sd):    {pct(*top1['lsb'])}")
    print(f"both effects found on two-effect channels:      {pct(*sc['both'])}")
    print(f"  ... where each is >= {VISIBLE}x the base + the other's ADEV at some tau: {pct(*sc['both_visible'])}")
    print(f"  one of them out of catalogue, named as its equivalent: {pct(*sc['both_ooc'])}")
    print(f"false alarms on clean channels:                 {pct(*sc['clean'])}")
    print(f"a further finding beside a right single effect: {pct(*sc['extra'])}")
    if sc["second_scores"]:  # the next threshold's null: a spurious further finding at each threshold
        ss = sc["second_scores"]
        print("  second-round score there, at or above 3.5 / 4.0 / 4.5 / 5.5: "
              + " / ".join(f"{sum(x >= t for x in ss)}" for t in (3.5, 4.0, 4.5, 5.5)) + f" of {len(ss)}")
    print(f"clean channels 'unexplained' (no finding):      {pct(*sc['clean_unexplained'])}")
    print(f"clean channels with a noise level change:       {pct(*sc['clean_noise_level'])}")
    if sc["hidden_noise_level"]:
        print("  hidden effects under a noise level change: " +
              ", ".join(f"{k} {v}" for k, v in sc["hidden_noise_level"].most_common()))
    print(f"out-of-catalogue named as equivalent/unexplained: {pct(*sc['ooc'])}")
    if sc["ooc_halved"][1]:
        print(f"  ... misfit at least halved by adding the equivalent named: {pct(*sc['ooc_halved'])}")
    if sc["halved"][1]:
        rt = np.array(sc["ratios"])
        print(f"misfit at least halved by the correct addition: {pct(*sc['halved'])} "
              f"(after/before median {np.median(rt):.3f}, worst {rt.max():.3f})")
    if sc["null_scores"]:
        ns = np.array(sc["null_scores"])
        print("best candidate score on clean channels: quantiles 50/90/99/max "
              + " / ".join(f"{np.quantile(ns, q):.2f}" for q in (0.5, 0.9, 0.99, 1.0)))
    print("top-1 by effect: " + ", ".join(f"{e} {a}/{b}" for e, (a, b) in sorted(sc["by_effect"].items())))
    print("confusion (hidden -> first reported; 'none' = no finding, 'unexplained' = misfit left, no finding):")
    for h in sorted(sc["confusion"]):
        print(f"  {h:32s} " + ", ".join(f"{k} {v}" for k, v in sc["confusion"][h].most_common()))
    return sc


def in_subset(row, subset):
    """--subset: ooc = one out-of-catalogue effect, two = two catalogue effects, weak = one
    catalogue effect at 1.5x, strong = one at >= 3x other than quantization, quantization = one
    quantization (the cases of five rows, to iterate on a benchmark slice without its other
    records)."""
    hid = [h["effect"] for h in row["hidden"]]
    gm = gen_module(row)
    if subset == "quantization":
        return hid == ["quantization"]
    if subset == "ooc":
        return len(hid) == 1 and hid[0] in gm.OUT_OF_CATALOGUE
    if subset == "weak" and gm is not g:  # alt: sizes are continuous, weak = below 3x
        return (len(hid) == 1 and hid[0] in gm.CATALOGUE and hid[0] != "quantization"
                and row["hidden"][0]["size"] < 3)
    if subset == "weak":
        return len(hid) == 1 and hid[0] in g.CATALOGUE and row["hidden"][0]["size"] == 1.5
    if subset == "strong":
        return len(hid) == 1 and hid[0] in gm.CATALOGUE and hid[0] != "quantization" and row["hidden"][0]["size"] >= 3
    return len(hid) == 2 and all(x in gm.CATALOGUE for x in hid)


def run_one(a, i):
    rng = np.random.default_rng([a.seed, i])
    generator = getattr(a, "generator", "main")
    if generator == "main":
        bases = a.bases.split(",") if a.bases else BASES
        row = make(rng, i, a.work, a.max_samples, bases, a.null, getattr(a, "effects", None),
                   getattr(a, "pool", "all"))
    else:  # the independent generator: its own base families (--bases names them), effects, sizes
        row = gen_module(generator).make(rng, i, a.work, a.max_samples,
                                         a.bases.split(",") if a.bases else None, a.null,
                                         getattr(a, "effects", None), getattr(a, "pool", "all"))
        row["generator"] = generator
    if getattr(a, "subset", None) and not in_subset(row, a.subset):
        os.remove(row["record"])
        return None
    row["result"] = diagnose(a.sinsim, row, a)
    if a.add and len(row["hidden"]) == 1:
        # the correct effect where it came first; for an out-of-catalogue effect, the catalogue
        # equivalent named first (a telegraph's gauss_markov, a step's bias_jumps)
        gm, hid = gen_module(row), row["hidden"][0]["effect"]
        first = (row["result"].get(row["channel"], {}).get("findings") or [None])[0]
        if first is not None and (first == hid or (hid in gm.OUT_OF_CATALOGUE and first in gm.EQUIVALENT[hid])):
            row["add"] = diagnose(a.sinsim, row, a, f'{first}:{row["channel"]}')
    os.remove(row["record"])
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--records", type=int, default=60)
    ap.add_argument("--first", type=int, default=0, help="index of the first record")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--sinsim", default="build/sinsim")
    ap.add_argument("--work", default="out/challenge")
    ap.add_argument("--max-samples", type=int, default=400000,
                    help="cap on samples per record (the full benchmark: 3e7)")
    ap.add_argument("--threads", type=int, default=1, help="of each diagnose")
    ap.add_argument("--jobs", type=int, default=2, help="records diagnosed at once")
    ap.add_argument("--realisations", type=int, default=32)
    ap.add_argument("--threshold", type=float, default=None, help="diagnose --threshold")
    ap.add_argument("--bases", default="", help="comma list of base families (default: all; the "
                    "alt generator's: w2gm, wgmrw, wflk, ar)")
    ap.add_argument("--generator", choices=sorted(GENERATORS), default="main",
                    help="record generator: main (generate.py), alt (generate_alt.py) or third "
                         "(generate_third.py), the last two independent designs; rows carry "
                         "\"generator\": NAME")
    ap.add_argument("--null", action="store_true", help="no hidden effects (threshold calibration)")
    ap.add_argument("--effects", type=int, default=None,
                    help="hidden effects per record (default: 0, 1 or 2 drawn); a study of one case")
    ap.add_argument("--pool", choices=sorted(POOLS), default="all", help="where hidden effects are drawn from")
    ap.add_argument("--hidden-only", action="store_true",
                    help="diagnose only the hidden channel (studies: no clean-channel counts)")
    ap.add_argument("--subset", choices=["ooc", "two", "weak", "strong", "quantization"], default=None,
                    help="diagnose only the records with one out-of-catalogue effect (ooc), two "
                         "catalogue effects (two), one at 1.5x (weak), one at >= 3x (strong) or one "
                         "quantization, on their hidden channel; the same draws")
    ap.add_argument("--add", action="store_true",
                    help="also add the correct effect where it came first: misfit after / before")
    ap.add_argument("--report", nargs="+", metavar="RESULTS_JSON",
                    help="only print the scores of earlier runs' results.json files, pooled")
    a = ap.parse_args()
    if a.report:
        report([row for path in a.report for row in json.load(open(path))])
        return
    report(run_records(a, run_one))


def run_records(a, one):
    """one(a, i) for records a.first .. a.first + a.records - 1 on a.jobs threads (a row, or None
    for a record left out), with a progress count; the rows are written to a.work/results.json."""
    os.makedirs(a.work, exist_ok=True)
    rows = []
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(max_workers=a.jobs) as ex:
        for row in ex.map(lambda i: one(a, i), range(a.first, a.first + a.records)):
            if row is not None:
                rows.append(row)
            print(f"\r{len(rows)}/{a.records} records", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)
    with open(os.path.join(a.work, "results.json"), "w") as f:
        json.dump(rows, f, indent=1, default=float)
    return rows


if __name__ == "__main__":
    main()
