# OCXO record through sinsim.analyze (as a "gx" channel at 1 Hz) vs Stable32's overlapping ADEV (5 digits).
import sinsim, numpy as np, warnings
warnings.simplefilter("ignore")
D = "/work/shared/data/ocxo-stable32/"
f = np.loadtxt(D + "ocxo_frequency.txt", comments="#"); y = f / 10e6 - 1
ref = {round(r[1]): r[5] for r in np.loadtxt(D + "stable32_oadev_alltau.txt", comments="#")}
for grid in ["octave", "decade"]:
    a = sinsim.analyze({"rate": 1, "gx": y}, tau=grid)["gx"]["allan"]
    n = bad = 0; worst = 0
    for t, d in zip(a["tau"], a["adev"]):
        if abs(t - round(t)) < 1e-9 and round(t) in ref:
            n += 1; s = float(f"{d:.4e}"); worst = max(worst, abs(d / ref[round(t)] - 1))
            if s != ref[round(t)]: bad += 1; print("   mismatch tau", t, s, ref[round(t)])
    print(f"{grid}: {n} taus compared, {bad} differ at 5 significant digits, max rel diff {worst:.2e}")
