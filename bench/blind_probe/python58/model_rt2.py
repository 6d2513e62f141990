# which parameters change in read-write-read, and by how much; is the second cycle exact?
import sinsim, numpy as np
m = sinsim.Model("models/hand.yaml"); m1 = sinsim.Model("out/hand_w1.yaml"); m2 = sinsim.Model("out/hand_w2.yaml")
for a, b in zip(m.effects(), m1.effects()):
    for k, v in a["params"].items():
        w = b["params"][k]
        if v != w: print(a["sensor"], a["list"], a["index"], a["type"], k, v, w, np.max(np.abs(np.subtract(v, w)) / np.maximum(np.abs(v), 1e-300)))
    if {k: v for k, v in a.items() if k != "params"} != {k: v for k, v in b.items() if k != "params"}: print("meta differs", a, b)
print("m1 == m2 (second cycle):", m1 == m2)
x = np.genfromtxt("out/hand.yaml.csv", delimiter=",", skip_header=1); y = np.genfromtxt("out/hand_w1.yaml.csv", delimiter=",", skip_header=1)
print("synth max abs diff per col:", np.max(np.abs(x - y), axis=0))
