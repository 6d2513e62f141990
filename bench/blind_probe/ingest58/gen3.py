#!/usr/bin/python3
"""rec3/: epoch stamps under a plain t, date columns"""
import os, datetime
os.makedirs('rec3', exist_ok=True)
L = open('rec/ref.csv').read().split('\n')[1:-1]
vals = [l.split(',', 1)[1] for l in L]
H = 'gx,gy,gz,ax,ay,az'
def w(n, h, rows): open('rec3/' + n, 'w').write('\n'.join([h] + rows) + '\n')
w('epoch_ms_plain.csv', 't,' + H, ['%d,%s' % (1700000000123 + 10 * i, v) for i, v in enumerate(vals)])
w('epoch_us_plain.csv', 't,' + H, ['%d,%s' % (1700000000123456 + 10000 * i, v) for i, v in enumerate(vals)])
w('epoch_ns_plain.csv', 't,' + H, ['%d,%s' % (1700000000123456789 + 10000000 * i, v) for i, v in enumerate(vals)])
t0 = datetime.datetime(2026, 12, 7, 6, 0, 0)
w('iso_plus_t.csv', 'date,t,' + H, ['%s,%.2f,%s' % ((t0 + datetime.timedelta(seconds=i / 100)).isoformat(timespec='milliseconds'), i / 100, v) for i, v in enumerate(vals)])
w('iso_only.csv', 'time,' + H, ['%s,%s' % ((t0 + datetime.timedelta(seconds=i / 100)).isoformat(timespec='milliseconds'), v) for i, v in enumerate(vals)])
w('clock_only.csv', 'time,' + H, ['%s,%s' % ((t0 + datetime.timedelta(seconds=i / 100)).strftime('%H:%M:%S.%f')[:-4], v) for i, v in enumerate(vals)])
