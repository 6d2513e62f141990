#!/usr/bin/python3
"""Mean ADEV over channels and files for sets of records (compare my generator with sinsim synth of a model)."""
import sys, glob, numpy as np
sys.path.insert(0, '/tmp/probe_63/work/scripts')
from adev import oadev
ms = 2**np.arange(0, 15); dt = 0.01
for pat in sys.argv[1:]:
    G, A, D = [], [], []
    for f in sorted(glob.glob(pat)):
        X = np.loadtxt(f, delimiter=',', skiprows=1, usecols=range(1, 7))
        for i in range(6):
            ad = oadev(X[:, i] - X[:, i].mean(), dt, ms)
            (G if i < 3 else A).append(ad)
            # slow content: difference of first and last 10-min means
            D.append((i, X[:60000, i].mean() - X[-60000:, i].mean()))
    G = np.array(G); A = np.array(A)
    dg = np.sqrt(np.mean([d**2 for i, d in D if i < 3])); da = np.sqrt(np.mean([d**2 for i, d in D if i >= 3]))
    print(pat, "gyro ADEV[deg/h] at tau", [f"{t:g}:{v:.2f}" for t, v in zip(ms[::2]*dt, np.sqrt((G**2).mean(0))[::2]*180/np.pi*3600)])
    print("   accel ADEV[ug]", [f"{t:g}:{v:.1f}" for t, v in zip(ms[::2]*dt, np.sqrt((A**2).mean(0))[::2]/9.80665e-6)])
    print(f"   rms(first10min mean - last10min mean): gyro {dg*180/np.pi*3600:.2f} deg/h, accel {da/9.80665e-6:.1f} ug")
