#!/usr/bin/python3
"""rec/big_gap.csv: ref with stamps 100.00..159.99 s dropped (60 s outage); level step +1 deg/s on gx from t>=300 s to see which window --skip picks"""
L = open('rec/ref.csv').read().split('\n')[:-1]
out = [L[0]]
for l in L[1:]:
    t = float(l.split(',')[0])
    if 100 <= t < 160: continue
    f = l.split(',')
    if t >= 300: f[1] = '%.9f' % (float(f[1]) + 1.0)
    out.append(','.join(f))
open('rec/big_gap.csv', 'w').write('\n'.join(out) + '\n')
