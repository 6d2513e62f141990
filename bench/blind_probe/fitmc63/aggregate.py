#!/usr/bin/python3
"""Aggregate results.csv (scenario,sensor,seed,kind,t,ratio_med,ratio_p95,ratio_yaw): per sensor/kind/time the 3 seeds' ratios."""
import csv, collections, numpy as np
R = collections.defaultdict(list)
for r in csv.reader(open('/tmp/probe_63/work/results.csv')):
    sc, S, seed, k, t = r[:5]; R[(sc, S, k, int(t))].append(tuple(map(float, r[5:8])))
tot = collections.Counter(); inn = collections.Counter()
for sc in ['car', 'carband', 'static']:
    for S in ['S1', 'S2', 'S3', 'S4']:
        for k in ['auto', 'gm', 'arpslow', 'ar']:
            ts = sorted(t for (a, b, c, t) in R if (a, b, c) == (sc, S, k))
            if not ts: continue
            line = f"{sc:7s} {S} {k:8s}"
            for t in ts:
                v = np.array(R[(sc, S, k, t)])
                line += f" | {t/60:4.0f}m med {','.join(f'{x:.2f}' for x in v[:,0])} p95 {','.join(f'{x:.2f}' for x in v[:,1])}"
                for j, nm in enumerate(['med', 'p95', 'yaw']):
                    n_in = int(np.sum((v[:, j] >= 0.67) & (v[:, j] <= 1.5)))
                    tot[(sc, S, k, nm)] += len(v); inn[(sc, S, k, nm)] += n_in
            print(line)
print("\nwithin [0.67,1.5] counts (seeds x times):")
for key in sorted(tot):
    print(key, f"{inn[key]}/{tot[key]}")
