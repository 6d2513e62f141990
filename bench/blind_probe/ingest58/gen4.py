#!/usr/bin/python3
"""rec3/mag_sparse.csv: magnetometer at 10 Hz, empty cells between (common in multi-rate loggers); rec3/aux_nan.csv: NaN in temp"""
L = open('rec/ref.csv').read().split('\n')[:-1]
out = [L[0] + ',mx,my,mz']
for i, l in enumerate(L[1:]):
    out.append(l + (',0.2,-0.1,0.4' if i % 10 == 0 else ',,,'))
open('rec3/mag_sparse.csv', 'w').write('\n'.join(out) + '\n')
out = [L[0] + ',temp']
for i, l in enumerate(L[1:]):
    out.append(l + (',nan' if i == 500 else ',25.0'))
open('rec3/aux_nan.csv', 'w').write('\n'.join(out) + '\n')
