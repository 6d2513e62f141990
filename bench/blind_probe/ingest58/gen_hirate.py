#!/usr/bin/python3
"""rec3/epoch_ns_<rate>.csv: exact integer ns epoch stamps at high rates, white gx..az (rad/s, m/s^2)"""
import numpy as np, sys
rng = np.random.default_rng(1)
for rate in [1000, 10000, 32000, 50000]:
    n = 100000; step = round(1e9 / rate)
    t0 = 1700000000123456789
    v = rng.standard_normal((n, 6)) * 0.01 + np.array([0, 0, 0, 0, 0, -9.8])
    with open('rec3/epoch_ns_%d.csv' % rate, 'w') as f:
        f.write('t[ns],gx,gy,gz,ax,ay,az\n')
        for i in range(n):
            f.write('%d,%s\n' % (t0 + i * step, ','.join('%.6f' % x for x in v[i])))
    with open('rec3/rel_ns_%d.csv' % rate, 'w') as f:
        f.write('t[ns],gx,gy,gz,ax,ay,az\n')
        for i in range(n):
            f.write('%d,%s\n' % (i * step, ','.join('%.6f' % x for x in v[i])))
