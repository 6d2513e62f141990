import numpy as np, sys
from adev import oadev
orig, syn = sys.argv[1], sys.argv[2]
A = np.loadtxt(orig, delimiter=',', skiprows=1); S = np.loadtxt(syn, delimiter=',', skiprows=1)
ms = np.array([1, 4, 16, 64, 256, 1024, 4096, 12000]); dt = 0.01
names = ['gx','gy','gz','ax','ay','az']
print('tau[s]      ', ' '.join(f'{m*dt:8.2f}' for m in ms))
for i, c in enumerate(names):
    if len(sys.argv) > 3 and c not in sys.argv[3].split(','): continue
    a = oadev(A[:, 1+i] - A[:, 1+i].mean(), dt, ms); s = oadev(S[:, 1+i] - S[:, 1+i].mean(), dt, ms)
    print(f'{c} syn/orig  ', ' '.join(f'{r:8.3f}' for r in s/a))
