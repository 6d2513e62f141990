#!/usr/bin/python3
"""Injector: cut 1000-s windows of ADIS16405 run 2 and add effects (NumPy only).
Sizing: effect's own overlapping ADEV at the tau where effect/clean ratio peaks = k x clean ADEV there.
Lattice: each sample placed at a uniform point of its LSB cell, effect added, rounded back (--noround: no re-rounding)."""
import numpy as np, gzip, json, sys, os
FS=100.0; LSB={'gx':0.05,'gy':0.05,'gz':0.05,'ax':0.00333,'ay':0.00333,'az':0.00333}
CH=['gx','gy','gz','ax','ay','az']
_RUN2=None
def run2():
    global _RUN2
    if _RUN2 is None:
        c='/tmp/probe_28/work/run2.npy'
        if os.path.exists(c): _RUN2=np.load(c)
        else:
            _RUN2=np.loadtxt('/work/shared/data/adis16405/run2.csv.gz',delimiter=',',skiprows=1); np.save(c,_RUN2)
    return _RUN2
def taus(N):
    ms=sorted(set(int(round(2**(j/2))) for j in range(0,60) if round(2**(j/2))<=N//8)); return np.array(ms)
def oadev(x,ms):
    c=np.concatenate([[0],np.cumsum(x)]); out=[]
    for m in ms:
        a=(c[m:]-c[:-m])/m; d=a[m:]-a[:-m]; out.append(np.sqrt(0.5*np.mean(d*d)))
    return np.array(out)
def effect_shape(kind,N,rng,p):
    t=np.arange(N)/FS; T=N/FS
    if kind=='step': t0=p.setdefault('t0',rng.uniform(0.2,0.8)*T); return (t>=t0).astype(float)
    if kind=='ramp': return (t-T/2)/T
    if kind=='warmup': tau=p.setdefault('tau',rng.uniform(40,150)); return np.exp(-t/tau)
    if kind=='sinusoid':
        f=p.setdefault('f',float(rng.choice([0.02,0.05,0.13,0.3,0.9,2.3,7.1])*rng.uniform(0.9,1.1)))
        return np.sin(2*np.pi*f*t+rng.uniform(0,2*np.pi))
    if kind=='random_walk': return np.cumsum(rng.standard_normal(N))/np.sqrt(FS)
    if kind=='gauss_markov':
        tau=p.setdefault('tau',float(rng.choice([2.,10.,30.]))); phi=np.exp(-1/(FS*tau)); e=rng.standard_normal(N)*np.sqrt(1-phi**2)
        x=np.empty(N); x[0]=rng.standard_normal()
        for i in range(1,N): x[i]=phi*x[i-1]+e[i]
        return x
    if kind=='outliers':
        rate=p.setdefault('rate',0.02); s=np.zeros(N); k=rng.random(N)<rate/FS; s[k]=rng.choice([-1,1],k.sum()); return s
    if kind in ('telegraph','slowtelegraph'):  # OOC: two-level random telegraph, mean dwell
        dw=p.setdefault('dwell',float(rng.choice([5.,20.,60.])) if kind=='telegraph' else 200.); sw=rng.random(N)<1/(dw*FS); return (np.cumsum(sw)%2).astype(float)-0.5
    if kind=='chirp':  # OOC: slow linear chirp 0.01->0.2 Hz
        f0,f1=0.01,0.2; ph=2*np.pi*(f0*t+(f1-f0)*t*t/(2*T)); return np.sin(ph)
    if kind=='burst':  # OOC: noise burst, white noise in a 100-s segment
        dur=p.setdefault('dur',100.); t0=p.setdefault('t0',rng.uniform(0.1,0.8)*T); s=np.zeros(N); m=(t>=t0)&(t<t0+dur); s[m]=rng.standard_normal(m.sum()); return s
    raise ValueError(kind)
def make(out,win,effects,seed,noround=False,full=False):
    """effects: list of (kind,channel,k)"""
    rng=np.random.default_rng(seed); X=(run2()[60000:].copy() if full else run2()[60000+win*100000:60000+(win+1)*100000].copy()); N=len(X)
    ms=taus(N); info=[]
    U=rng.uniform(-0.5,0.5,size=X.shape)
    Y=X.copy()
    for kind,ch,k in effects:
        j=CH.index(ch); p={}
        if kind.startswith('spikes'):  # fixed-size spikes: k = multiples of the clean sample sd (not ADEV-sized)
            s=effect_shape('outliers',N,rng,p); a0=oadev(X[:,j],ms); ae=oadev(s,ms); r=ae/a0; i=int(np.nanargmax(r)); amp=k*X[:,j].std()
        else:
            s=effect_shape(kind,N,rng,p)
            a0=oadev(X[:,j],ms); ae=oadev(s,ms); r=ae/a0; i=int(np.nanargmax(r)); amp=k/r[i]
        Y[:,j]+=amp*s; p.update(kind=kind,channel=ch,k=k,amp=float(amp),tau_peak=float(ms[i]/FS),adev_ratio_at_peak=float(amp*r[i])); info.append(p)
    for j,ch in enumerate(CH):
        if np.any(Y[:,j]!=X[:,j]) and not noround:
            l=LSB[ch]; Y[:,j]=np.round((Y[:,j]+U[:,j]*l)/l)*l  # uniform point of the cell, effect, re-round
            # NB: the effect was added to X before; X+U*l rounds back to X
    fmt=['%.2f']*3+['%.5f']*3 if not noround else ['%.7g']*6
    np.savetxt(out,Y,delimiter=',',header=','.join(CH),comments='',fmt=fmt)
    return dict(file=out,win=win,seed=seed,noround=noround,effects=info)
if __name__=='__main__':
    print(json.dumps(make(sys.argv[1],int(sys.argv[2]),[tuple(e.split(':')[:2])+(float(e.split(':')[2]),) for e in sys.argv[4:]],int(sys.argv[3]))))
