#!/usr/bin/python3
"""profile.py TAG [step_s]: run-averaged NEES and yaw z^2 over time bins from runs/TAG/stats.npz"""
import sys, numpy as np
d = np.load(f'runs/{sys.argv[1]}/stats.npz'); step = float(sys.argv[2]) if len(sys.argv) > 2 else 60
t, mn, out, e, sg = d['t'], d['nees_mean'], d['out'], d['e'], d['sg']
z2 = (e / sg) ** 2
for a in np.arange(0, t[-1] + 1e-9, step):
    m = (t >= a) & (t < a + step)
    if not m.any(): continue
    print(f'{a:7.0f}-{a+step:<6.0f} out={int(out[m].mean()*100):3d}%  NEES {mn[m].mean():6.2f} max {mn[m].max():6.2f}  z2 yaw {z2[:, m, 8].mean():5.2f} psiN {z2[:, m, 6].mean():5.2f} psiE {z2[:, m, 7].mean():5.2f} vN {z2[:, m, 3].mean():5.2f} |yaw err| rms deg {np.degrees(np.sqrt((e[:, m, 8]**2).mean())):.3f} sig {np.degrees(sg[:, m, 8].mean()):.3f}')
