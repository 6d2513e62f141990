#!/usr/bin/python3
"""Percentile of each replayed record's drift among the model runs (mc --measured), at report times."""
import csv, glob, numpy as np, collections
times = [120, 300, 600, 1200, 1800]
P = collections.defaultdict(list)
for f in sorted(glob.glob('/tmp/probe_63/work/mc/meas_S?_s?/measured.csv')):
    rows = list(csv.reader(open(f))); h = rows[0]
    t = np.array([float(r[0]) for r in rows[1:]])
    rec = f.split('/')[-2][5:]
    line = rec
    for j, name in enumerate(h):
        if name.endswith('horizontal percentile'):
            m = name.split(' ')[0]; kind = 'truth' if 'truth' in m else m.split('_')[-1]
            vals = [float(rows[1+int(np.argmin(abs(t-tt)))][j]) for tt in times]
            P[kind].extend(vals)
            line += f" | {kind}: " + ",".join(f"{v:.0f}" for v in vals)
    print(line)
print("percentiles pooled over records and times (2,5,10,20,30 min):")
for k, v in P.items():
    v = np.array(v)
    print(f"  {k:8s} n={len(v)} median {np.median(v):.0f}, inside 2.5-97.5: {np.sum((v>=2.5)&(v<=97.5))}/{len(v)}, <10: {np.sum(v<10)}, >90: {np.sum(v>90)}")
