# accel vs gyro random walk, 10 seeds x 3 axes each, 10 Hz, 20000 s: AVAR_hat/AVAR_true at several tau
import sinsim, numpy as np, os, math, warnings
warnings.simplefilter("ignore"); os.chdir("/tmp/probe_58"); d2r = math.pi / 180
open("out/cf/rw2.yaml", "w").write("gyro:\n  all: [{type: random_walk, K: 20 deg/h/sqrt(h)}]\naccel:\n  all: [{type: random_walk, K: 0.01 m/s^2/sqrt(h)}]\n")
Kg, Ka = 20 * d2r / 3600 / 60, 0.01 / 60
R = {"g": {}, "a": {}}
for s in range(10, 20):
    rec = sinsim.synth("out/cf/rw2.yaml", 10, 20000, "out/cf/rw2.csv", seed=s)
    a = sinsim.analyze(rec)
    for ch in ["gx", "gy", "gz", "ax", "ay", "az"]:
        K = Kg if ch[0] == "g" else Ka
        for t, ad in zip(a[ch]["allan"]["tau"], a[ch]["allan"]["adev"]):
            if t <= 2000: R[ch[0]].setdefault(t, []).append(ad * ad / (K * K * t / 3))
for s in "ga":
    print(("gyro " if s == "g" else "accel") + ": " + " ".join(f"{t:g}:{np.mean(v):.3f}±{np.std(v,ddof=1)/math.sqrt(len(v)):.3f}" for t, v in sorted(R[s].items())))
