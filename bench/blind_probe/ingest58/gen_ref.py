#!/usr/bin/python3
"""Reference record: 100 Hz, N samples, gx..gz in deg/s (white density + constant), ax..az in g."""
import numpy as np, sys
N = int(sys.argv[1]) if len(sys.argv) > 1 else 60000
rate = 100.0
rng = np.random.default_rng(59)
# white density in deg/s/sqrt(Hz): sd = dens*sqrt(rate)
gdens = np.array([0.004, 0.005, 0.006]); gbias = np.array([0.4, -0.42, -0.29])
adens = np.array([1e-4, 1.2e-4, 1.5e-4]); abias = np.array([0.01, -0.02, -1.0])
g = gbias + rng.standard_normal((N, 3)) * gdens * np.sqrt(rate)
a = abias + rng.standard_normal((N, 3)) * adens * np.sqrt(rate)
# round to a fixed 9 significant decimal output
np.save('rec/g.npy', g); np.save('rec/a.npy', a)
t = np.arange(N) / rate
with open('rec/ref.csv', 'w') as f:
    f.write('t,gx,gy,gz,ax,ay,az\n')
    for i in range(N):
        f.write('%.2f,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f\n' % (t[i], *g[i], *a[i]))
