# Python vs CLI on the real ADIS16405 record (20 min after 10 min skip): fit gm/ar, analyze, diagnose
import sinsim, subprocess, json, os, filecmp, numpy as np, warnings
warnings.simplefilter("ignore")
B = "/tmp/probe_bin58/sinsim"; os.chdir("/tmp/probe_58"); O = "out/parr"; os.makedirs(O, exist_ok=True)
R = "/work/shared/data/adis16405/run1.csv.gz"
rec = sinsim.load_record(R, gyro_unit="deg/s", accel_unit="g", rate=100)
print("loaded", rec["rate"], len(rec["gx"]), rec["gx"][:2], sorted(rec))
i0, n = 60000, 120000
d = {"rate": 100.0, **{k: rec[k][i0:i0+n] for k in ["gx","gy","gz","ax","ay","az"]}}
common = ["--rate", "100", "--gyro-unit", "deg/s", "--accel-unit", "g", "--skip", "10 min", "--duration", "20 min"]
for kind in ["gm", "ar"]:
    m = sinsim.fit(d, kind=kind, axes=["gx", "ay"]); m.write(f"{O}/py_{kind}.yaml")
    p = subprocess.run([B, "fit", R, *common, "--kind", kind, "--axes", "gx,ay", "-q", "-o", f"{O}/cli_{kind}.yaml"], capture_output=True, text=True)
    same = filecmp.cmp(f"{O}/py_{kind}.yaml", f"{O}/cli_{kind}.yaml", shallow=False)
    print(kind, "cli rc", p.returncode, "identical:", same)
    if not same: os.system(f"diff {O}/py_{kind}.yaml {O}/cli_{kind}.yaml | head -30")
# same via path + skip arg in python (no duration arg in python fit) -> skip only
m2 = sinsim.fit(R, kind="gm", axes=["gx"], skip="10 min", gyro_unit="deg/s", accel_unit="g", rate=100)
m2.write(f"{O}/py_gm_skip.yaml")
p = subprocess.run([B, "fit", R, "--rate", "100", "--gyro-unit", "deg/s", "--accel-unit", "g", "--skip", "10 min", "--kind", "gm", "--axes", "gx", "-q", "-o", f"{O}/cli_gm_skip.yaml"], capture_output=True, text=True)
print("gm skip path identical:", filecmp.cmp(f"{O}/py_gm_skip.yaml", f"{O}/cli_gm_skip.yaml", shallow=False))
# diagnose the gm fit on the 20-min window
dd = sinsim.diagnose(d, f"{O}/cli_gm.yaml", channels=["gx"], realisations=8, seed=3)
p = subprocess.run([B, "diagnose", R, *common, "--model", f"{O}/cli_gm.yaml", "--channels", "gx", "--realisations", "8", "--seed", "3", "--json", f"{O}/cli_diag.json"], capture_output=True, text=True)
print("diag cli rc", p.returncode); print(p.stdout[-1500:])
j = json.load(open(f"{O}/cli_diag.json"))["axes"][0]
print("misfit py/cli", dd["gx"]["misfit"], j["misfit"], "chi2", dd["gx"]["chi2"], j["chi2"])
print("findings py ", [(f["effect"], round(f["score"], 4), f["reported"]) for f in dd["gx"]["findings"]])
print("findings cli", [(f.get("effect"), round(f.get("score", float('nan')), 4), f.get("reported")) for f in j["findings"]])
a = sinsim.analyze(d, json=f"{O}/py_an.json")
p = subprocess.run([B, "analyze", R, *common, "--json", f"{O}/cli_an.json"], capture_output=True, text=True)
ja, jc = json.load(open(f"{O}/py_an.json")), json.load(open(f"{O}/cli_an.json"))
print("analyze source py/cli", ja.get("source"), jc.get("source"))
ja.pop("source"); jc.pop("source")
print("analyze json equal except source:", ja == jc)
if ja != jc:
    for k in ja:
        if ja[k] != jc.get(k): print("  differs:", k, str(ja[k])[:200], "|", str(jc.get(k))[:200])
