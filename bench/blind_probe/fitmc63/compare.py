#!/usr/bin/python3
"""Fitted/truth drift ratios from sinsim mc per_run.csv (median and p95 of horizontal error, and yaw |err|).
usage: compare.py MCDIR SENSOR  -> prints table, appends rows to results.csv"""
import sys, csv, numpy as np, collections
d, S = sys.argv[1], sys.argv[2]
rows = list(csv.reader(open(f"{d}/per_run.csv")))
hdr = rows[0]
def col(name):
    for i, h in enumerate(hdr):
        if h.split(' [')[0].strip() == name: return i
    raise KeyError(name + str(hdr))
im, it, ih, iy = col('model'), col('t'), col('horizontal'), col('yaw')
data = collections.defaultdict(lambda: collections.defaultdict(list))
for r in rows[1:]:
    data[r[im]][float(r[it])].append((float(r[ih]), abs(float(r[iy]))))
truth = [m for m in data if 'truth' in m][0]
times = sorted(data[truth])
out = open('/tmp/probe_63/work/results.csv', 'a')
print(f"{d}: truth model {truth}, runs {len(data[truth][times[0]])}")
print("model".ljust(18) + "".join(f"{t:>8.0f}s:med/p95/yaw" for t in times))
for m in data:
    line = m.ljust(18)
    for t in times:
        a = np.array(data[m][t]); b = np.array(data[truth][t])
        med = np.median(a[:,0]); p95 = np.percentile(a[:,0], 95); yw = np.median(a[:,1])
        if m == truth:
            line += f"  {med:8.3g}/{p95:8.3g}/{yw:8.2g}"
        else:
            rm, rp, ry = med/np.median(b[:,0]), p95/np.percentile(b[:,0], 95), yw/np.median(b[:,1])
            line += f"  {rm:6.2f}/{rp:6.2f}/{ry:6.2f}      "
            parts = m.split('_')
            out.write(f"{d.split('/')[-1].split('_')[0]},{S},{parts[1]},{parts[2]},{t:.0f},{rm:.4f},{rp:.4f},{ry:.4f}\n")
    print(line)
