# Python vs CLI parity: run, mc, synth, analyze, fit, diagnose. Usage: python parity.py
import sinsim, subprocess, json, os, filecmp, numpy as np, shutil, sys, warnings
B = "/tmp/probe_bin58/sinsim"
os.chdir("/tmp/probe_58")
O = "out/par"; shutil.rmtree(O, ignore_errors=True); os.makedirs(O)
def cli(*a):
    p = subprocess.run([B, *a], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr
def cmpdir(a, b):
    for f in sorted(os.listdir(a)):
        fa, fb = os.path.join(a, f), os.path.join(b, f)
        if os.path.isdir(fa): continue
        same = os.path.exists(fb) and filecmp.cmp(fa, fb, shallow=False)
        print(f"   {f}: {'identical' if same else 'DIFFERENT'}")
    print("   only in CLI:", sorted(set(os.listdir(b)) - set(os.listdir(a))))
M = "scenarios/grade-tactical.yaml"; SC = "scenarios/car.yaml"
print("== run")
r = sinsim.run(SC, model=M, seed=3, output=f"{O}/pyrun")
rc, out, err = cli("run", SC, "--model", M, "--seed", "3", "-o", f"{O}/clirun")
print("  py line :", r["summary"]["line"]); print("  cli out :", out.strip().splitlines()[-1] if out.strip() else err)
cmpdir(f"{O}/pyrun", f"{O}/clirun")
e = np.genfromtxt(f"{O}/clirun/errors.csv", delimiter=",", names=True)
print("  errors.csv cols:", e.dtype.names[:6])
print("== mc")
b = sinsim.mc(SC, models=["scenarios/adis16355-ar5.yaml", "scenarios/adis16355-gm.yaml"], runs=6, seed=5, threads=2, output=f"{O}/pymc")
rc, out, err = cli("mc", SC, "--runs", "6", "--seed", "5", "--threads", "1", "--model", "scenarios/adis16355-ar5.yaml", "--model", "scenarios/adis16355-gm.yaml", "-o", f"{O}/climc", "--no-progress")
print("  cli rc", rc); print("  cli tail:", "\n   ".join(out.strip().splitlines()[-6:]))
print("  py headline:", b["headline"])
cmpdir(f"{O}/pymc", f"{O}/climc")
import csv
rows = list(csv.DictReader(open(f"{O}/climc/stats.csv")))
for lab in b["labels"]:
    last = [x for x in rows if x.get("model", lab) == lab][-1] if "model" in rows[0] else rows[-1]
    print("  ", lab, "np p50", np.percentile(b["final"][lab]["horizontal_m"], 50), "stats.csv p50", last.get("horizontal_m_p50"))
print("  stats.csv header:", list(rows[0].keys())[:8])
print("== synth")
rec = sinsim.synth(M, 100, 600, f"{O}/py_synth.csv", seed=7)
rc, out, err = cli("synth", M, "--rate", "100", "--duration", "600", "--seed", "7", "-o", f"{O}/cli_synth.csv")
print("  synth identical:", filecmp.cmp(f"{O}/py_synth.csv", f"{O}/cli_synth.csv", shallow=False), "keys", sorted(rec.keys()))
print("== analyze")
a = sinsim.analyze(f"{O}/cli_synth.csv", json=f"{O}/py_an.json")
rc, out, err = cli("analyze", f"{O}/cli_synth.csv", "--json", f"{O}/cli_an.json")
print("  analyze json identical:", filecmp.cmp(f"{O}/py_an.json", f"{O}/cli_an.json", shallow=False))
j = json.load(open(f"{O}/cli_an.json"))
print("  json top keys:", list(j.keys())[:10])
print("  py gx adev first 3:", a["gx"]["allan"]["adev"][:3])
print("== fit")
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    m = sinsim.fit(f"{O}/cli_synth.csv", kind="gm")
    print("  py warnings:", [str(x.message)[:100] for x in w])
m.write(f"{O}/py_fit.yaml")
rc, out, err = cli("fit", f"{O}/cli_synth.csv", "--kind", "gm", "-o", f"{O}/cli_fit.yaml", "-q")
print("  cli rc", rc, err.strip()[:300])
same = filecmp.cmp(f"{O}/py_fit.yaml", f"{O}/cli_fit.yaml", shallow=False)
print("  fit files identical:", same)
if not same: os.system(f"diff {O}/py_fit.yaml {O}/cli_fit.yaml | head -20")
print("  model equal:", sinsim.Model(f"{O}/cli_fit.yaml") == m)
print("== diagnose")
d = sinsim.diagnose(f"{O}/cli_synth.csv", M, realisations=8, seed=11, channels=["gx", "ax"])
rc, out, err = cli("diagnose", f"{O}/cli_synth.csv", "--model", M, "--realisations", "8", "--seed", "11", "--channels", "gx,ax", "--json", f"{O}/cli_diag.json")
print("  cli rc", rc, err.strip()[:300])
jd = json.load(open(f"{O}/cli_diag.json"))
print("  py keys:", list(d.keys())[:8]); print("  json keys:", list(jd.keys())[:10])
json.dump(d, open(f"{O}/py_diag_dump.json", "w"), default=lambda o: o.tolist() if hasattr(o, "tolist") else str(o), indent=1)
