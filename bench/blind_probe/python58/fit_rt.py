# synth a record from a hand model (white + GM + RW on gx), fit it (latent), write/reload/re-write; compare params.
import sinsim, os, filecmp, warnings, math
os.chdir("/tmp/probe_58"); d2r = math.pi / 180
open("models/fitme.yaml", "w").write("""description: fit me
gyro:
  all:
    - {type: white, density: 0.3 deg/sqrt(h)}
  x:
    - {type: gauss_markov, sigma: 0.005 deg/s, tau: 20 s}
    - {type: random_walk, K: 5 deg/h/sqrt(h)}
""")
rec = sinsim.synth("models/fitme.yaml", 100, 2400, "out/fitme.csv", seed=3)
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    m = sinsim.fit(rec, kind="latent", axes=["gx", "gy"])
print("warnings:", [str(x.message)[:120] for x in w])
m.write("out/fitme_fit.yaml"); m1 = sinsim.Model("out/fitme_fit.yaml"); m1.write("out/fitme_fit2.yaml")
print("written twice identical bytes:", filecmp.cmp("out/fitme_fit.yaml", "out/fitme_fit2.yaml", shallow=False), "| reload == reload2:", m1 == sinsim.Model("out/fitme_fit2.yaml"))
for e in m1.effects(): print("  ", e["sensor"], e["list"], e["index"], e["type"], e["params"])
print("truth SI: white", 0.3 * d2r / 60, "GM sigma", 0.005 * d2r, "tau 20, K", 5 * d2r / 3600 / 60)
r = sinsim.run("scenarios/static.yaml", model=m1, seed=1); print("run with fitted model:", r["summary"]["line"])
