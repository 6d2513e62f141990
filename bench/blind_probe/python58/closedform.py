# Closed-form ADEV checks through Python: white (N/sqrt(tau)), random walk (K sqrt(tau/3)),
# Gauss-Markov (exact AVAR), bias instability (floor 0.664 B), per-channel over several seeds.
# ADEV from sinsim.analyze, cross-checked with an independent numpy overlapping ADEV.
import sinsim, numpy as np, os, math, sys
os.chdir("/tmp/probe_58"); os.makedirs("out/cf", exist_ok=True)
d2r = math.pi / 180
def oadev(y, m):
    c = np.concatenate([[0.0], np.cumsum(y)]); n = len(y)
    a = (c[m:n + 1] - c[:n + 1 - m]) / m            # averages of m samples
    d = a[m:] - a[:-m]
    return math.sqrt(0.5 * np.mean(d * d))
def gm_avar(s, T, tau):
    x = tau / T
    return 2 * s * s * T / tau * (1 - (3 - 4 * np.exp(-x) + np.exp(-2 * x)) / (2 * x))
cases = {
  "white": ("{type: white, density: 0.3 deg/sqrt(h)}", 100, 1000, lambda t: (0.3 * d2r / 60) ** 2 / t),
  "rw":    ("{type: random_walk, K: 20 deg/h/sqrt(h)}", 10, 20000, lambda t: (20 * d2r / 3600 / 60) ** 2 * t / 3),
  "gm":    ("{type: gauss_markov, sigma: 0.01 deg/s, tau: 30 s}", 10, 20000, lambda t: gm_avar(0.01 * d2r, 30, t)),
  "bi":    ("{type: bias_instability, B: 10 deg/h, tau_range: [1 s, 1000 s]}", 10, 20000, lambda t: (0.664 * 10 * d2r / 3600) ** 2 + 0 * t),
}
seeds = [1, 2, 3, 4]
for name, (eff, rate, dur, avar) in cases.items():
    f = f"out/cf/{name}.yaml"; open(f, "w").write(f"gyro:\n  all:\n    - {eff}\n")
    ratios = {}; cover = [0, 0]; worst_np = 0
    for s in seeds:
        rec = sinsim.synth(f, rate, dur, f"out/cf/{name}_{s}.csv", seed=s)
        a = sinsim.analyze(rec, tau="octave")
        for ch in ["gx", "gy", "gz"]:
            al = a[ch]["allan"]; tau = np.asarray(al["tau"])
            for i, t in enumerate(tau):
                m = int(round(t * rate))
                if name == "bi" and not (1 <= t <= 1000): continue
                if t > dur / 10: continue
                true = math.sqrt(avar(t)); ad = al["adev"][i]
                ratios.setdefault(t, []).append((ad / true) ** 2)
                cover[0] += al["lo"][i] <= true <= al["hi"][i]; cover[1] += 1
                if i % 3 == 0:
                    worst_np = max(worst_np, abs(oadev(rec[ch], m) / ad - 1))
    print(f"== {name}: rate {rate} Hz, {dur} s, seeds {seeds}, 3 axes; truth inside analyze's 68.3 % bounds: {cover[0]}/{cover[1]} = {cover[0]/cover[1]:.3f}; max |numpy oadev/analyze - 1| = {worst_np:.2e}")
    for t in sorted(ratios):
        r = np.array(ratios[t]); se = r.std(ddof=1) / math.sqrt(len(r))
        print(f"   tau {t:9.3f} s  mean AVAR_hat/AVAR_true = {r.mean():.4f} +- {se:.4f}  z = {(r.mean()-1)/se:+.2f}")
