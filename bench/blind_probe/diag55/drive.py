#!/usr/bin/python3
"""drive.py EFFECT SEED SIZE [RATE DUR CHANS] -> runs gen, diagnose, diagnose --add; appends results.jsonl"""
import sys, json, subprocess, os, time
S = os.environ.get('SINSIM', 'build/sinsim')
E, seed, size = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
rate = sys.argv[4] if len(sys.argv) > 4 else '100'; dur = sys.argv[5] if len(sys.argv) > 5 else '1800'
chans = sys.argv[6] if len(sys.argv) > 6 else 'gx,az'
extra = sys.argv[7:] if len(sys.argv) > 7 else []
EXP = dict(sinusoid='sinusoid', ramp='ramp', warmup='warmup', steps='bias_jumps', telegraph='bias_jumps',
           outliers='outliers', quant='quantization', temp='temperature', rw='random_walk', flicker='bias_instability', none=None)
tag = f"r_{E}_{seed}_{size:g}_{rate}_{dur}"
os.makedirs('runs', exist_ok=True); P = f"runs/{tag}"
subprocess.run(['/usr/bin/python3', 'gen.py', '--effect', E, '--seed', str(seed), '--size', str(size), '--rate', rate,
                '--dur', dur, '--chans', chans, '--out', P] + extra, check=True)
def diag(args, js):
    t0 = time.time(); r = subprocess.run([S, 'diagnose', P + '.csv', '--model', P + '.model.yaml', '--json', js, '--threads', '2'] + args,
                       capture_output=True, text=True, timeout=900)
    return r, time.time() - t0
r, el = diag([], P + '.json')
out = dict(tag=tag, effect=E, seed=seed, size=size, rate=rate, dur=dur, rc=r.returncode, t=round(el, 1))
if r.returncode: out['err'] = r.stderr[-500:]; print(json.dumps(out)); open(os.environ.get('RES','results.jsonl'), 'a').write(json.dumps(out) + '\n'); sys.exit()
open(P + '.txt', 'w').write(r.stdout + r.stderr)
d = json.load(open(P + '.json')); tr = json.load(open(P + '.truth.json'))
effch = tr['chans']; ch = {}
for a in d['axes']:
    rep = [f['effect'] for f in a['findings'] if f['reported']]
    ch[a['channel']] = dict(rep=rep, misfit=round(a['misfit'], 4), fits=a['fits'], eff=a['channel'] in effch,
                            kind=tr['base'][a['channel']]['kind'], unexpl=bool(a.get('unexplained') or a.get('unexplained_steps')))
out['ch'] = ch
exp = os.environ.get('ADD', EXP[E])
if exp and effch:
    adds = [f'{exp}:{c}' for c in effch]
    r2, el2 = diag(['--add'] + adds + ['-o', P + '.improved.yaml'], P + '.add.json')
    open(P + '.add.txt', 'w').write(r2.stdout + r2.stderr)
    out['add_rc'] = r2.returncode
    if r2.returncode == 0:
        d2 = json.load(open(P + '.add.json'))
        for a in d2['axes']:
            if a['channel'] in effch:
                ch[a['channel']]['mb'] = round(a.get('misfit_before', float('nan')), 4); ch[a['channel']]['ma'] = round(a.get('misfit_after', float('nan')), 4)
    else: out['add_err'] = r2.stderr[-400:]
print(json.dumps(out)); open(os.environ.get('RES','results.jsonl'), 'a').write(json.dumps(out) + '\n')
