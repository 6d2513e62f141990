#!/usr/bin/python3
"""detail.py OUTDIR REC LENGTH : per channel truth, reported findings (score), misfit before->after"""
import json, sys
o, r, L = sys.argv[1:4]
t = json.load(open(f'{o}/{r}.truth.json'))
d = json.load(open(f'{o}/{r}.{L}.json'))
for ax in d['axes']:
    c = ax['channel']
    tr = [(e['effect'], e['size']) for e in t['channels'][c]]
    f = [(x['effect'], round(x['score'], 1)) for x in ax['findings'] if x.get('reported')]
    print(f"{r:4s} {L:5s} {c} truth={tr} found={f} misfit {ax.get('misfit_before',0):.3f}->{ax.get('misfit_after',0):.3f}"
          f" unexpl={'Y' if ax.get('unexplained') or ax.get('unexplained_steps') else '-'} nlc={'Y' if ax.get('noise_level_change') else '-'} scale={ax.get('noise_scale',0):.2f}")
