#!/usr/bin/python3
"""mcwin.py MCDIR a-b ...: per outage window, epochs above/below the tool's own NEES band from filter_consistency.csv"""
import csv, sys, numpy as np
r = list(csv.DictReader(open(sys.argv[1] + '/filter_consistency.csv')))
for w in sys.argv[2:]:
    a, b = map(float, w.split('-'))
    x = [q for q in r if q['class'] == 'outage' and a <= float(q['t_s']) <= b + 1e-6]
    n = np.array([float(q['nees_mean']) for q in x]); hi = np.array([float(q['nees_hi99']) for q in x]); lo = np.array([float(q['nees_lo99']) for q in x])
    print(f'{w}: {len(x)} epochs, above {np.sum(n>hi)}, below {np.sum(n<lo)}, mean {n.mean():.2f}')
