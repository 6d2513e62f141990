#!/usr/bin/python3
"""by_size.py OUTDIR PREFIX LENGTH : one-effect channels, right effect first, by size (2x / 5x); plus misfit-raised list"""
import json, sys, glob, os
sys.path.insert(0, os.path.dirname(__file__))
from score import EQUIV, present_in_cut, matches
o, p, L = sys.argv[1:4]
cnt = {}
raised = []
for tf in sorted(glob.glob(f'{o}/{p}*.truth.json')):
    r = os.path.basename(tf)[:-11]
    if not os.path.exists(f'{o}/{r}.{L}.json'): continue
    t = json.load(open(tf)); d = json.load(open(f'{o}/{r}.{L}.json'))
    for ax in d['axes']:
        effs = t['channels'][ax['channel']]
        if L == 'short': effs = [e for e in effs if present_in_cut(e)]
        names = [f['effect'] for f in ax['findings'] if f.get('reported')]
        if ax.get('misfit_after', 0) > ax.get('misfit_before', 0) + 1e-9:
            raised.append((r, ax['channel'], [e['effect'] for e in effs], round(ax['misfit_before'], 3), round(ax['misfit_after'], 3)))
        if len(effs) != 1: continue
        s = effs[0]['size']; c = cnt.setdefault(s, [0, 0])
        c[0] += 1; c[1] += bool(names and matches(effs[0]['effect'], names[:1]))
print(L, p, 'one-effect top-1 by size {size: [n, first right]}:', cnt)
print('misfit raised by --add found:', raised)
