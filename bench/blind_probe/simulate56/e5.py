from eff import *
D=np.pi/180
rate=20; dt=1/rate
def acf(x,maxlag):
    x=x-x.mean(); n=len(x); v=x.var()
    return np.array([np.mean(x[:n-k]*x[k:])/v for k in range(maxlag+1)]), v
def fac(tau): r=dt/tau; return 2/r**2*(r-1+np.exp(-r))
out=[]
for seed in [1,2,3]:
    d=run(f'gm{seed}','gyro:\n  all:\n    - {type: gauss_markov, sigma: 0.01 deg/s, tau: 2 s}\naccel:\n  all:\n    - {type: gauss_markov, sigma: 1 mg, tau: 0.01 s}\n  x:\n    - {type: gauss_markov, sigma: 1 mg, tau: 1 s, rate: 20 Hz}\n',scen=STAT,dur=2000,rate=rate,seed=seed)
    e=arr(d,'w')-arr(d,'w','ideal'); s=0.01*D
    for i in range(3):
        r,v=acf(e[:,i],80)
        k=np.arange(1,41); tau_fit=-np.sum(k*dt*k*dt)/np.sum(k*dt*np.log(np.clip(r[1:41],1e-9,None)))
        out.append(('gyro tau2',v/(s*s*fac(2)),tau_fit, r[1], np.exp(-dt/2)))
    e=arr(d,'f')-arr(d,'f','ideal'); s=9.80665e-3
    for i in range(1,3):
        r,v=acf(e[:,i],3); out.append(('acc tau0.01',v/(s*s*fac(0.01)),None,r[1],None))
    r,v=acf(e[:,0],40); k=np.arange(1,21); tau_fit=-np.sum((k*dt)**2)/np.sum(k*dt*np.log(np.clip(r[1:21],1e-9,None)))
    out.append(('acc x: tau0.01 cont + tau1 @20Hz discrete', v/(s*s*(fac(0.01)+1)), tau_fit, r[1], None))
for o in out: print(o)
