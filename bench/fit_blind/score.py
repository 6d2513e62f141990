#!/usr/bin/env python3
"""Blind round trip of `sinsim fit`: generate records (generate.py), fit each with
`--kind gm`, `--kind latent` (and `--kind auto` on a subset), score term set and parameters.

  /usr/bin/python3 bench/fit_blind/score.py run --work /tmp/fit_blind/run \
      --cell 100:1200:30 --cell 1000:1200:20 --cell 100:7200:20 --cell 208:1200:10 --cell 1000:7200:2
  /usr/bin/python3 bench/fit_blind/score.py report --work /tmp/fit_blind/run

Results are appended to WORK/results.jsonl (one line per record and kind), so a run can be
resumed; records whose fit failed in any kind are kept in WORK/failures/ with truth and models.
"""
import argparse, json, math, os, re, shutil, subprocess, sys, time
import numpy as np
import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate as gen  # noqa: E402

# the binary: $SINSIM_BIN, else the repository's build/sinsim
SINSIM = os.environ.get("SINSIM_BIN") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                                      "build", "sinsim")

# ---------------------------------------------------------------- units -> SI
BASE = {"rad": 1.0, "deg": math.pi / 180, "mrad": 1e-3, "urad": 1e-6, "arcsec": math.pi / 180 / 3600,
        "s": 1.0, "ms": 1e-3, "us": 1e-6, "min": 60.0, "h": 3600.0, "Hz": 1.0, "kHz": 1e3, "mHz": 1e-3,
        "ppm": 1e-6, "": 1.0}


def unit_factor(u):
    """'deg/h/sqrt(h)' -> SI factor.  Grammar: factors joined by '/' or '*', each NAME,
    NAME^p or sqrt(NAME)."""
    u = u.strip()
    parts = re.split(r"([/*])", u)
    f, op = 1.0, "*"
    for p in parts:
        if p in "/*" and p != "":
            op = p
            continue
        m = re.fullmatch(r"sqrt\((\w+)\)", p)
        if m:
            v = math.sqrt(BASE[m.group(1)])
        else:
            m = re.fullmatch(r"(\w*)(?:\^(-?[\d.]+))?", p)
            if not m or m.group(1) not in BASE:
                raise KeyError("unit %r in %r" % (p, u))
            v = BASE[m.group(1)] ** (float(m.group(2)) if m.group(2) else 1.0)
        f = f * v if op == "*" else f / v
    return f


def qty(s):
    """'0.0519 deg/sqrt(h)' -> (SI value, unit)."""
    s = str(s).strip()
    m = re.match(r"([-+0-9.eE]+)\s*(.*)$", s)
    return float(m.group(1)) * unit_factor(m.group(2)), m.group(2)


# ---------------------------------------------------------------- model file
NUM = r"[-+0-9.eE]+"
UNC = re.compile(r"(\w+) \+- (" + NUM + r") (\S+)(?: \(lsb\))? \(1 sigma; (?:ln-space|profile-likelihood "
                 r"1-sigma interval) (" + NUM + r") ?([^ .]*)\.\.(" + NUM + r") ?([^ ,;]*?)\)(?=,|$)")
# an interval the record does not bound (model_writer.cpp, wider than e^20 either way)
UNBOUNDED = re.compile(r"(\w+) \+- (" + NUM + r") (\S+)(?: \(lsb\))? \(1 sigma; (?:ln-space|profile-likelihood "
                       r"1-sigma interval) not bounded by the record\)(?=,|$)")
NAME_MAP = {"white": "density", "random_walk": "K", "flicker": "B", "lsb": "lsb", "sigma": "sigma",
            "tau": "tau", "drift": "slope", "quantization": "lsb"}


def parse_model(path, rate):
    """Returns a list of terms [{type, params: {name: SI}, sigma: {name: SI}, interval: {name: (lo, hi)}}]
    for gyro x, plus the free-text summary comment."""
    text = open(path).read()
    doc = yaml.safe_load(text) or {}
    effects = ((doc.get("gyro") or {}).get("x")) or []
    lines = text.splitlines()
    # comment blocks directly above each effect line of gyro.x
    blocks, cur, in_x, summary = [], [], False, ""
    for ln in lines:
        if re.match(r"^  x:\s*$", ln):
            in_x = True
            continue
        if in_x and re.match(r"^  \S", ln) or re.match(r"^\S", ln) and in_x:
            break
        if not in_x:
            continue
        s = ln.strip()
        if s.startswith("# composite"):
            summary = s[2:]
        if s.startswith("#"):
            cur.append(s[1:].strip())
        elif s.startswith("- "):
            blocks.append(cur)
            cur = []
    out = []
    for i, e in enumerate(effects):
        t = e.get("type")
        term = {"type": t, "params": {}, "sigma": {}, "interval": {}, "raw": e}
        for k, v in e.items():
            if k in ("type", "note", "enabled", "tau_range", "a", "carry", "dithered"):
                continue
            try:
                term["params"][k] = qty(v)[0]
                if k == "lsb":
                    term["lsb_unit"] = qty(v)[1]
            except Exception:
                pass
        if t == "quantization":
            term["dithered"] = e.get("dithered")
            term["carry"] = e.get("carry")
        blk = blocks[i] if i < len(blocks) else []
        last = blk[-1] if blk else ""
        for m in UNC.finditer(last):
            name = NAME_MAP.get(m.group(1), m.group(1))
            f = unit_factor(m.group(3))
            term["sigma"][name] = float(m.group(2)) * f
            uhi = m.group(7) or m.group(3)
            ulo = m.group(5) or uhi
            term["interval"][name] = (float(m.group(4)) * unit_factor(ulo), float(m.group(6)) * unit_factor(uhi))
        for m in UNBOUNDED.finditer(last):
            name = NAME_MAP.get(m.group(1), m.group(1))
            term["sigma"][name] = float(m.group(2)) * unit_factor(m.group(3))
            term["interval"][name] = (0.0, math.inf)
        out.append(term)
    return out, summary


# ---------------------------------------------------------------- comparison
FIT2TRUTH = {"white": "white", "quantization": "quantization", "gauss_markov": "gm",
             "random_walk": "random_walk", "bias_instability": "flicker", "ramp": "drift"}


def truth_params(term, rate):
    k = term["type"]
    if k == "white":
        return {"density": term["N"]}
    if k == "gm":
        return {"sigma": term["sigma"], "tau": term["tau"]}
    if k == "random_walk":
        return {"K": term["K"]}
    if k == "flicker":
        return {"B": term["B"]}
    if k == "quantization":
        return {"lsb": term["lsb_angle"]}
    return {}


def fitted_params(term, rate):
    p = dict(term["params"])
    s = dict(term["sigma"])
    iv = dict(term["interval"])
    if term["type"] == "quantization" and "lsb" in p:
        # a rate LSB (signal units) is turned into an increment LSB: x h
        u = term.get("lsb_unit", "")
        if u.endswith("/s") and u.count("/") >= 1 and not u.endswith("sqrt(s)"):
            p["lsb"] /= rate
            if "lsb" in s:
                s["lsb"] /= rate
            if "lsb" in iv:
                iv["lsb"] = (iv["lsb"][0] / rate, iv["lsb"][1] / rate)
    if term["type"] == "white" and "density" not in p and "sigma" in p:
        p["density"] = p.pop("sigma") / math.sqrt(rate)
    return p, s, iv


def compare(truth, fitted, rate):
    tset = sorted(t["type"] for t in truth["terms"])
    fset = sorted(FIT2TRUTH.get(t["type"], t["type"]) for t in fitted
                  if t["type"] not in ("bias",))
    right = tset == fset
    checks = []
    # match each truth term type with fitted terms of the same type (GMs by tau order)
    for typ in sorted(set(tset)):
        tt = [t for t in truth["terms"] if t["type"] == typ]
        ff = [t for t in fitted if FIT2TRUTH.get(t["type"], t["type"]) == typ]
        if typ == "gm":
            tt = sorted(tt, key=lambda t: t["tau"])
            ff = sorted(ff, key=lambda t: t["params"].get("tau", 0))
        if len(tt) != len(ff):
            continue
        for j, (a, b) in enumerate(zip(tt, ff)):
            tp = truth_params(a, rate)
            fp, fs, fiv = fitted_params(b, rate)
            for name, tv in tp.items():
                if name not in fp:
                    continue
                est = fp[name]
                c = {"term": typ + (str(j + 1) if typ == "gm" else ""), "param": name, "truth": tv,
                     "est": est, "ratio": est / tv}
                if name in fs:
                    c["sigma"] = fs[name]
                    c["z"] = (est - tv) / fs[name] if fs[name] > 0 else float("inf")
                    c["cover2"] = abs(c["z"]) <= 2
                if name in fiv and est > 0:
                    lo, hi = fiv[name]
                    if lo > 0 and hi > 0:
                        lo2 = est * (lo / est) ** 2
                        hi2 = est * (hi / est) ** 2
                        c["cover2_interval"] = bool(lo2 <= tv <= hi2)
                checks.append(c)
    return right, tset, fset, checks


# ---------------------------------------------------------------- run
CASES_DEFAULT = gen.CASES


def run_fit(rec, rate, kind, out_yaml, timeout):
    cmd = [SINSIM, "fit", rec, "--rate", "%g" % rate, "--gyro-unit", "deg/s", "--kind", kind,
           "--threads", "1", "-o", out_yaml]
    t0 = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        rc, err, out = p.returncode, p.stderr, p.stdout
    except subprocess.TimeoutExpired:
        rc, err, out = "timeout", "", ""
    return cmd, rc, time.time() - t0, out, err


def cmd_run(a):
    os.makedirs(a.work, exist_ok=True)
    resf = os.path.join(a.work, "results.jsonl")
    done = set()
    if os.path.exists(resf):
        for ln in open(resf):
            r = json.loads(ln)
            done.add((r["case"], r["rate"], r["duration"], r["index"], r["kind"]))
    cases = a.cases.split(",") if a.cases else CASES_DEFAULT
    recdir = os.path.join(a.work, "rec")
    faildir = os.path.join(a.work, "failures")
    os.makedirs(faildir, exist_ok=True)
    for cell in a.cell:
        rate, dur, n = cell.split(":")
        rate, dur, n = float(rate), float(dur), int(n)
        for idx in range(a.first, a.first + n):
            for case in cases:
                kinds = list(a.kinds.split(","))
                if idx - a.first < a.auto_first:
                    kinds.append("auto")
                todo = [k for k in kinds if (case, rate, dur, idx, k) not in done]
                if not todo:
                    continue
                t0 = time.time()
                rec, truth = gen.make(case, rate, dur, idx, recdir, flicker_mode=a.flicker_mode,
                                      gm_mode=a.gm_mode)
                tgen = time.time() - t0
                failed = False
                rows = []
                for kind in todo:
                    yml = rec[:-4] + "." + kind + ".yaml"
                    cmd, rc, wall, out, err = run_fit(rec, rate, kind, yml,
                                                      a.gm_timeout if kind == "gm" else a.timeout)
                    row = {"case": case, "rate": rate, "duration": dur, "index": idx, "kind": kind,
                           "seed": truth["seed"], "flicker_mode": a.flicker_mode, "gm_mode": a.gm_mode,
                           "rc": rc, "wall": wall, "gen_s": tgen,
                           "cmd": " ".join(cmd), "stderr": err.strip()[-2000:], "stdout": out.strip()[-1000:]}
                    if rc == 0:
                        try:
                            fitted, summary = parse_model(yml, rate)
                            right, tset, fset, checks = compare(truth, fitted, rate)
                            row.update(right=right, tset=tset, fset=fset, checks=checks, summary=summary,
                                       warnings=[l for l in err.splitlines() if "warning" in l.lower()])
                            cov_fail = any(c.get("cover2") is False for c in checks)
                            missing_sigma = right and any("sigma" not in c for c in checks)
                            row["cov_fail"] = cov_fail
                            row["missing_sigma"] = missing_sigma
                            if not right or cov_fail:
                                failed = True
                        except Exception as ex:  # parse problem: keep it
                            row.update(right=None, parse_error=repr(ex))
                            failed = True
                    else:
                        failed = True
                    rows.append((row, yml))
                base = os.path.basename(rec)[:-4]
                for row, yml in rows:
                    if failed:
                        if os.path.exists(yml):
                            shutil.copy(yml, os.path.join(faildir, os.path.basename(yml)))
                    row["record"] = os.path.join(faildir, base + ".csv") if failed else None
                    with open(resf, "a") as f:
                        f.write(json.dumps(row) + "\n")
                if failed:
                    tj = rec[:-4] + ".truth.json"
                    shutil.copy(tj, os.path.join(faildir, os.path.basename(tj)))
                    if truth["rate_hz"] * truth["duration_s"] <= 2e6:
                        shutil.move(rec, os.path.join(faildir, os.path.basename(rec)))
                for fn in os.listdir(recdir):
                    os.remove(os.path.join(recdir, fn))
                r0 = rows[0][0]
                print("%-17s %5g Hz %5g s #%03d gen %.1fs %s" % (
                    case, rate, dur, idx, tgen,
                    " ".join("%s:%s/%.2fs" % (r["kind"], {True: "ok", False: "SET", None: "ERR"}[r.get("right")]
                                              + ("" if not r.get("cov_fail") else "+cov"), r["wall"])
                             for r, _ in rows)), flush=True)


# ---------------------------------------------------------------- report
def cmd_report(a):
    rows = [json.loads(l) for l in open(os.path.join(a.work, "results.jsonl"))]
    kinds = sorted(set(r["kind"] for r in rows), key=lambda k: ["latent", "gm", "auto"].index(k)
                   if k in ("latent", "gm", "auto") else 9)
    out = []
    for kind in kinds:
        out.append("\n### --kind %s\n" % kind)
        out.append("| case | rate | T | right set | 2σ cover (±σ) | 2σ cover (interval) | median est/truth (right set) | wall median / max [s] |")
        out.append("|---|---|---|---|---|---|---|---|")
        cells = sorted(set((r["case"], r["rate"], r["duration"]) for r in rows if r["kind"] == kind),
                       key=lambda c: (gen.CASES.index(c[0]), c[2], c[1]))
        tot = {"n": 0, "k": 0, "cn": 0, "ck": 0}
        for c in cells:
            rr = [r for r in rows if r["kind"] == kind and (r["case"], r["rate"], r["duration"]) == c]
            n = len(rr)
            k = sum(1 for r in rr if r.get("right"))
            chk = [x for r in rr if r.get("right") for x in r["checks"]]
            cs = [x for x in chk if "cover2" in x]
            ck = sum(1 for x in cs if x["cover2"])
            ci = [x for x in chk if "cover2_interval" in x]
            cik = sum(1 for x in ci if x["cover2_interval"])
            by = {}
            for x in chk:
                by.setdefault(x["term"] + "." + x["param"], []).append(x["ratio"])
            med = ", ".join("%s %.2f" % (key, float(np.median(v))) for key, v in sorted(by.items()))
            walls = [r["wall"] for r in rr]
            errs = sum(1 for r in rr if r["rc"] != 0)
            out.append("| %s | %g Hz | %s | %d/%d (%.0f %%)%s | %d/%d (%.1f %%) | %d/%d | %s | %.2f / %.2f |" % (
                c[0], c[1], "%g min" % (c[2] / 60), k, n, 100.0 * k / max(n, 1),
                (" , %d errors" % errs) if errs else "", ck, len(cs), 100.0 * ck / max(len(cs), 1),
                cik, len(ci), med, float(np.median(walls)), max(walls)))
            tot["n"] += n; tot["k"] += k; tot["cn"] += len(cs); tot["ck"] += ck
        out.append("| **all** | | | %d/%d (%.1f %%) | %d/%d (%.1f %%) | | | |" % (
            tot["k"], tot["n"], 100.0 * tot["k"] / max(tot["n"], 1), tot["ck"], tot["cn"],
            100.0 * tot["ck"] / max(tot["cn"], 1)))
    # coverage per parameter (latent, right set), all cells pooled per case
    out.append("\n### 2σ coverage per parameter, --kind latent, right set, cells pooled (mean z = bias in units of the stated 1σ)\n")
    out.append("| case | parameter | covered (±σ) | mean z | median est/truth |")
    out.append("|---|---|---|---|---|")
    for case in gen.CASES:
        by = {}
        for r in rows:
            if r["kind"] == "latent" and r["case"] == case and r.get("right"):
                for x in r["checks"]:
                    if "z" in x:
                        by.setdefault(x["term"] + "." + x["param"], []).append(x)
        for key, xs in sorted(by.items()):
            k = sum(1 for x in xs if x["cover2"])
            out.append("| %s | %s | %d/%d (%.0f %%) | %+.2f | %.3f |" % (
                case, key, k, len(xs), 100.0 * k / len(xs), float(np.mean([x["z"] for x in xs])),
                float(np.median([x["ratio"] for x in xs]))))
    # confusion: what set was chosen when wrong
    out.append("\n### wrong sets (latent)\n")
    conf = {}
    for r in rows:
        if r["kind"] == "latent" and r.get("right") is False:
            key = (r["case"], "+".join(r["fset"]))
            conf[key] = conf.get(key, 0) + 1
    for (case, fs), v in sorted(conf.items()):
        out.append("- %s -> %s: %d" % (case, fs, v))
    # errors / warnings
    errs = [r for r in rows if r["rc"] != 0]
    out.append("\n### non-zero exits: %d" % len(errs))
    for r in errs[:20]:
        out.append("- rc %s: `%s`: %s" % (r["rc"], r["cmd"], r["stderr"][-300:]))
    txt = "\n".join(out)
    print(txt)
    if a.out:
        open(a.out, "w").write(txt + "\n")


DISP = {"density": (180 / math.pi * 60, "deg/sqrt(h)"), "K": (180 / math.pi * 3600 * 60, "deg/h/sqrt(h)"),
        "sigma": (180 / math.pi, "deg/s"), "tau": (1.0, "s"), "B": (180 / math.pi, "deg/s"),
        "lsb": (180 / math.pi, "deg"), "slope": (180 / math.pi * 3600 ** 2, "deg/h^2")}


def describe_truth(truth):
    out = []
    for t in truth["terms"]:
        ps = truth_params(t, truth["rate_hz"])
        out.append("%s(%s; vis %s)" % (t["type"], ", ".join("%s %.4g %s" % (k, v * DISP[k][0], DISP[k][1])
                                                          for k, v in ps.items()),
                                       "-" if t.get("visibility") is None else "%.2f" % t["visibility"]))
    return " + ".join(out)


def cmd_failures(a):
    rows = [json.loads(l) for l in open(os.path.join(a.work, "results.jsonl"))]
    rows = [r for r in rows if r["kind"] == a.kind]
    items = []
    for r in rows:
        truth = gen.draw_truth(r["case"], r["rate"], r["duration"], np.random.default_rng(r["seed"]))
        vis = min([t["visibility"] for t in truth["terms"] if t.get("visibility")] or [float("inf")])
        if r["rc"] != 0:
            items.append((1e9, r, truth, "exit %s: %s" % (r["rc"], r["stderr"][-200:])))
        elif r.get("right") is False:
            items.append((1e6 * vis, r, truth, "set %s" % "+".join(r["fset"])))
        else:
            bad = [c for c in r.get("checks", []) if c.get("cover2") is False]
            if bad:
                zmax = max(abs(c["z"]) for c in bad)
                items.append((zmax, r, truth, "; ".join("%s.%s est/truth %.3f z %+.1f" % (
                    c["term"], c["param"], c["ratio"], c["z"]) for c in bad)))
    items.sort(key=lambda x: -x[0])
    for sc, r, truth, what in items[:a.n]:
        print("- %s %g Hz %g s #%d (seed %d): %s" % (r["case"], r["rate"], r["duration"], r["index"], r["seed"], what))
        print("  truth: %s" % describe_truth(truth))
        if r.get("summary"):
            print("  fit: %s" % r["summary"][:260])
        name = "%s_%gHz_%gs_%03d" % (r["case"].replace("+", "-"), r["rate"], r["duration"], r["index"])
        print("  repro: /usr/bin/python3 bench/fit_blind/generate.py --case %s --rate %g --duration %g --index %d "
              "--out /tmp/fit_blind/repro%s && build/sinsim fit /tmp/fit_blind/repro/%s.csv --rate %g "
              "--gyro-unit deg/s --kind %s -o /tmp/fit_blind/repro/%s.%s.yaml" % (
                  r["case"], r["rate"], r["duration"], r["index"],
                  "" if r.get("flicker_mode", "sampled") == "sampled" else " --flicker-mode averaged",
                  name, r["rate"], r["kind"], name, r["kind"]))
    print("(%d items)" % len(items))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--work", default="/tmp/fit_blind/run")
    r.add_argument("--cell", action="append", required=True, help="RATE:DURATION:N")
    r.add_argument("--cases", default="")
    r.add_argument("--kinds", default="latent,gm")
    r.add_argument("--auto-first", type=int, default=5, help="also --kind auto on the first N records per cell")
    r.add_argument("--first", type=int, default=0)
    r.add_argument("--timeout", type=float, default=60)
    r.add_argument("--gm-timeout", type=float, default=60, help="timeout of --kind gm (slow at odd rates)")
    r.add_argument("--flicker-mode", choices=["sampled", "averaged"], default="sampled")
    r.add_argument("--gm-mode", choices=["averaged", "sampled"], default="averaged")
    p = sub.add_parser("report")
    p.add_argument("--work", default="/tmp/fit_blind/run")
    p.add_argument("--out", default="")
    f = sub.add_parser("failures")
    f.add_argument("--work", default="/tmp/fit_blind/run")
    f.add_argument("--kind", default="latent")
    f.add_argument("-n", type=int, default=40)
    a = ap.parse_args()
    {"run": cmd_run, "report": cmd_report, "failures": cmd_failures}[a.cmd](a)


if __name__ == "__main__":
    main()
