#!/usr/bin/python3
import json, sys, collections
EXP = dict(sinusoid='sinusoid', ramp='ramp', warmup='warmup', steps='bias_jumps', telegraph='bias_jumps',
           outliers='outliers', quant='quantization', temp='temperature', rw='random_walk', flicker='bias_instability', none=None)
ALT = dict(telegraph={'gauss_markov', 'bias_jumps'}, rw={'random_walk'}, flicker={'bias_instability', 'random_walk', 'gauss_markov'})
fn = sys.argv[1] if len(sys.argv) > 1 else 'results.jsonl'
R = [json.loads(l) for l in open(fn)]
per = collections.defaultdict(lambda: dict(n=0, top1=0, top1alt=0, none=0, halved=0, addn=0, fa=0, clean=0, names=collections.Counter(), fa_names=collections.Counter()))
for r in R:
    key = (r['effect'], r['size'], r['rate'], r['dur'])
    s = per[key]
    if 'ch' not in r: s['names']['CRASH rc=%d' % r['rc']] += 1; continue
    for c, v in r['ch'].items():
        if v['eff']:
            s['n'] += 1; first = v['rep'][0] if v['rep'] else '-'
            s['names'][first] += 1
            s['top1'] += first == EXP[r['effect']]
            s['top1alt'] += first in ALT.get(r['effect'], {EXP[r['effect']]})
            if 'mb' in v:
                s['addn'] += 1; s['halved'] += (v['mb'] > 0 and v['ma'] <= 0.5*v['mb']); s['addn'] -= (v['mb'] == 0)
        else:
            s['clean'] += 1
            if v['rep']: s['fa'] += 1; s['fa_names'][','.join(v['rep']) + f"({r['tag']}:{c}:{v['kind']})"] += 1
for k, s in sorted(per.items()):
    print(f"{k[0]:9s} size {k[1]:g} {k[2]}Hz {k[3]}s: top1 {s['top1']}/{s['n']} (acc.equiv {s['top1alt']}) halved {s['halved']}/{s['addn']} FA {s['fa']}/{s['clean']}  first: {dict(s['names'])}")
    for n, c in s['fa_names'].items(): print('     FA:', n)
