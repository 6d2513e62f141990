#!/usr/bin/python3
"""win.py TAG a-b ...: from runs/TAG/stats.npz, per window: run-averaged NEES mean, epochs above the 99% band, per-state mean z^2"""
import sys, numpy as np
from scipy.stats import chi2
d = np.load(f'runs/{sys.argv[1]}/stats.npz'); t, mn, e, sg = d['t'], d['nees_mean'], d['e'], d['sg']; R = e.shape[0]
hi = chi2.ppf(0.995, 9 * R) / R
for w in sys.argv[2:]:
    a, b = map(float, w.split('-')); m = (t >= a) & (t <= b)
    z2 = ((e[:, m] / sg[:, m]) ** 2).mean((0, 1))
    print(f'{w}: R={R} NEES mean {mn[m].mean():.2f}, above {np.sum(mn[m] > hi)}/{m.sum()}; z2 ' + ' '.join(f'{v:.2f}' for v in z2))
