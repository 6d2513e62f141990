# Is white-noise variance biased high? 12 seeds x 3 gyro axes x 100k samples at 100 Hz; density 0.3 deg/sqrt(h).
# Also ARW unit check: ADEV(1 s) vs N in rad/s/sqrt(Hz); accel white in ug/sqrt(Hz).
import sinsim, numpy as np, math, os
os.chdir("/tmp/probe_58"); d2r = math.pi / 180
N = 0.3 * d2r / 60; Na = 100e-6 * 9.80665
open("out/cf/w2.yaml", "w").write("gyro:\n  all: [{type: white, density: 0.3 deg/sqrt(h)}]\naccel:\n  all: [{type: white, density: 100 ug/sqrt(Hz)}]\n")
def oadev(y, m):
    c = np.concatenate([[0.0], np.cumsum(y)]); n = len(y); a = (c[m:n+1] - c[:n+1-m]) / m; d = a[m:] - a[:-m]
    return math.sqrt(0.5 * np.mean(d * d))
v, va, ad1, ad1a = [], [], [], []
for s in range(1, 13):
    r = sinsim.synth("out/cf/w2.yaml", 100, 1000, "out/cf/w2.csv", seed=s)
    for ch in "xyz":
        g = r["g" + ch]; a = r["a" + ch]
        v.append(np.var(g) / (N * N * 100)); va.append(np.var(a) / (Na * Na * 100))
        ad1.append(oadev(g, 100) / N); ad1a.append(oadev(a, 100) / Na)
for name, x in [("gyro var/(N^2 rate)", v), ("accel var/(N^2 rate)", va), ("gyro ADEV(1s)/N", ad1), ("accel ADEV(1s)/N", ad1a)]:
    x = np.array(x); print(f"{name}: mean {x.mean():.5f} +- {x.std(ddof=1)/math.sqrt(len(x)):.5f} (n={len(x)}) min {x.min():.4f} max {x.max():.4f}")
