import numpy as np, sys, importlib.util
sys.argv=['x','x','--base','wgm','--seed','1']
src=open('/tmp/probe_59/work/scripts/gen.py').read().replace('\nmain()\n','\n')
g={}; exec(src,g)
fs=100; n=90000
for base in ['wgm','wrw','wfl','ar2']:
    out=[]
    for nm in ['ramp','sinusoid','bias_jumps','outliers','random_walk','gauss_markov','warmup','chirp','noiseburst','triangle','telegraph']:
        v=[]
        for s in range(3):
            rng=np.random.default_rng(100+s); b=g['base_noise'](base,n,fs,rng,0); e=g['effect'](nm,1.0,n,fs,rng,1e-3)
            tb,ab=g['adev'](b,fs); te,ae=g['adev'](e,fs); v.append(np.max(ae/ab))
        out.append(f"{nm}={np.median(v):.3g}")
    print(base,' '.join(out))
