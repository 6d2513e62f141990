#!/usr/bin/python3
"""Compact table: per scenario/sensor/kind and time, median over 3 seeds of ratio (min-max), and in-band counts."""
import csv, collections, numpy as np
R = collections.defaultdict(list)
for r in csv.reader(open('/tmp/probe_63/work/results.csv')):
    sc, S, seed, k, t = r[:5]; R[(sc, S, k, int(t))].append(tuple(map(float, r[5:8])))
for sc in ['car', 'carband', 'static']:
    for S in ['S1', 'S2', 'S3', 'S4']:
        for k in ['auto', 'gm', 'arpslow', 'ar']:
            ts = sorted(t for (a, b, c, t) in R if (a, b, c) == (sc, S, k))
            if not ts: continue
            cells = []; nin = [0, 0, 0]; n = 0
            for t in ts:
                v = np.array(R[(sc, S, k, t)])
                cells.append(f"{t//60}m " + "/".join(f"{v[:,j].min():.2f}-{v[:,j].max():.2f}" for j in (0, 1)))
                for j in range(3): nin[j] += int(np.sum((v[:, j] >= 0.67) & (v[:, j] <= 1.5)))
                n += len(v)
            print(f"{sc:7s} {S} {k:7s} in[0.67,1.5] med {nin[0]}/{n} p95 {nin[1]}/{n} yaw {nin[2]}/{n} | " + " | ".join(cells))
