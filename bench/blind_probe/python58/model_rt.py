# model file: load via Python, check SI conversions, write/read fixed point, CLI acceptance
import sinsim, math, os, subprocess, filecmp
os.chdir("/tmp/probe_58")
m = sinsim.Model("models/hand.yaml")
print(m, m.label, m.description)
for e in m.effects(): print("  ", e)
print("names", m.effect_names())
d2r = math.pi/180
checks = [("gyro","all",0,"density", 0.3*d2r/60), ("gyro","all",1,"value", 5*d2r/3600), ("gyro","all",1,"sigma", 10*d2r/3600),
          ("gyro","x",0,"sigma",0.01*d2r), ("gyro","x",0,"tau",30.0), ("gyro","x",1,"K", 2*d2r/3600/60),
          ("accel","all",0,"density",100e-6*9.80665), ("accel","z",0,"amplitude",1e-3*9.80665), ("accel","z",0,"phase",30*d2r),
          ("accel","z",0,"frequency",0.5)]
for s,l,i,k,exp in checks:
    got = m.get(s,l,i,k); print(f"  {s}.{l}[{i}].{k} = {got!r} expected {exp!r} relerr {abs(got-exp)/abs(exp):.2e}")
print("  triad diag", m.get("gyro","triad",0,"diagonal"), "mis", m.get("gyro","triad",1,"matrix"))
m.write("out/hand_w1.yaml"); m1 = sinsim.Model("out/hand_w1.yaml"); m1.write("out/hand_w2.yaml")
print("read-write-read equal:", m == m1, " w1==w2 bytes:", filecmp.cmp("out/hand_w1.yaml", "out/hand_w2.yaml", shallow=False))
print("yaml() == file:", m.yaml() == open("out/hand_w1.yaml").read())
print(open("out/hand_w1.yaml").read())
for f in ["models/hand.yaml", "out/hand_w1.yaml"]:
    p = subprocess.run(["/tmp/probe_bin58/sinsim", "synth", f, "--rate", "100", "--duration", "60", "--seed", "1", "-o", f"out/{os.path.basename(f)}.csv"], capture_output=True, text=True)
    print("cli synth", f, p.returncode, p.stderr.strip()[:200])
print("synth orig vs rewritten identical:", filecmp.cmp("out/hand.yaml.csv", "out/hand_w1.yaml.csv", shallow=False))
