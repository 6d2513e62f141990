#!/usr/bin/python3
"""Term sets written per channel by each fit (from the model YAMLs)."""
import glob, re, collections
for S in ['S1','S2','S3','S4']:
    for k in ['auto','gm','arpslow','ar']:
        cnt = collections.Counter()
        for f in sorted(glob.glob(f'/tmp/probe_63/work/models/{S}_s*_{k}.yaml')):
            cur = None; sets = collections.defaultdict(list)
            sens = None
            for line in open(f):
                m = re.match(r'^(gyro|accel):', line)
                if m: sens = m.group(1)[0]
                m = re.match(r'^  ([xyz]):', line)
                if m: cur = sens + m.group(1)
                m = re.search(r'type: (\w+)', line)
                if m and cur and not line.lstrip().startswith('#'): sets[cur].append(m.group(1))
            for ch, v in sets.items(): cnt[(ch[0], '+'.join(v))] += 1
        print(S, k, dict(cnt))
