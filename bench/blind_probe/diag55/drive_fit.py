#!/usr/bin/python3
"""drive_fit.py EFFECT SEED SIZE RATE DUR CHANS KIND: clean record -> sinsim fit --kind KIND -> diagnose effect record vs fitted model (+ --add expected)"""
import sys, json, subprocess, os, time
S = os.environ.get('SINSIM', 'build/sinsim')
E, seed, size, rate, dur, chans, kind = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5], sys.argv[6], sys.argv[7]
EXP = dict(sinusoid='sinusoid', ramp='ramp', warmup='warmup', steps='bias_jumps', telegraph='bias_jumps',
           outliers='outliers', quant='quantization', temp='temperature', rw='random_walk', flicker='bias_instability', none=None)
os.makedirs('fitruns', exist_ok=True); P = f"fitruns/f_{E}_{seed}_{size:g}_{rate}_{dur}_{kind}"; C = f"fitruns/clean_{seed}_{rate}_{dur}"
tc = ['--tempcol'] if E == 'temp' else []
subprocess.run(['/usr/bin/python3', 'gen.py', '--effect', E, '--seed', str(seed), '--size', str(size), '--rate', rate, '--dur', dur, '--chans', chans, '--out', P], check=True)
if not os.path.exists(C + '.csv'):
    subprocess.run(['/usr/bin/python3', 'gen.py', '--clean', '--seed', str(seed), '--rate', rate, '--dur', dur, '--out', C] + tc, check=True)
M = f"{C}.{kind}.yaml"
t0 = time.time()
if not os.path.exists(M):
    r = subprocess.run([S, 'fit', C + '.csv', '--kind', kind, '-o', M, '-q', '--threads', '2'], capture_output=True, text=True, timeout=900)
    open(M + '.log', 'w').write(r.stdout + r.stderr)
    if r.returncode: print('FIT FAIL', r.stderr[-400:]); sys.exit(1)
tf = time.time() - t0
def diag(args, js):
    return subprocess.run([S, 'diagnose', P + '.csv', '--model', M, '--json', js, '--threads', '2'] + args, capture_output=True, text=True, timeout=900)
r = diag([], P + '.json'); open(P + '.txt', 'w').write(r.stdout + r.stderr)
out = dict(tag=P, effect=E, seed=seed, size=size, rate=rate, dur=dur, kind=kind, rc=r.returncode, tfit=round(tf, 1))
if r.returncode: out['err'] = r.stderr[-400:]; print(json.dumps(out)); open('fitresults.jsonl', 'a').write(json.dumps(out) + '\n'); sys.exit()
d = json.load(open(P + '.json')); tr = json.load(open(P + '.truth.json')); effch = tr['chans']; ch = {}
for a in d['axes']:
    ch[a['channel']] = dict(rep=[f['effect'] for f in a['findings'] if f['reported']], misfit=round(a['misfit'], 4), eff=a['channel'] in effch, kind=tr['base'][a['channel']]['kind'])
out['ch'] = ch; exp = EXP[E]
if exp and effch:
    r2 = diag(['--add'] + [f'{exp}:{c}' for c in effch] + ['-o', P + '.improved.yaml'], P + '.add.json'); open(P + '.add.txt', 'w').write(r2.stdout + r2.stderr)
    out['add_rc'] = r2.returncode
    if r2.returncode == 0:
        for a in json.load(open(P + '.add.json'))['axes']:
            if a['channel'] in effch: ch[a['channel']]['mb'] = round(a['misfit_before'], 4); ch[a['channel']]['ma'] = round(a['misfit_after'], 4)
    else: out['add_err'] = r2.stderr[-400:]
print(json.dumps(out)); open('fitresults.jsonl', 'a').write(json.dumps(out) + '\n')
