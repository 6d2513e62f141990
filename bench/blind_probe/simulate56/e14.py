from eff import *
D=np.pi/180
K=100*D/3600/60
r=[]
for seed in [1,2]:
    d=run('rwr','gyro:\n  all:\n    - {type: random_walk, K: 100 deg/h/sqrt(h), rate: 200 Hz}\naccel:\n  all:\n    - {type: white, sigma: 1 mg, rate: 150 Hz}\n',scen=STAT,dur=1000,rate=100,seed=seed)
    e=arr(d,'w')-arr(d,'w','ideal')
    for L in [100]:
        dd=np.diff(e[::L],axis=0); r.append(dd.var(0)/(K*K*L*0.01))
    ea=arr(d,'f')-arr(d,'f','ideal')
    print('white sigma 1mg @150Hz into 100Hz: sd/mg',ea.std(0)/9.80665e-3,' (each 100Hz interval covers 1.5 samples; expected sd 1/sqrt(1.5)=0.816 on average-ish)')
print('discrete RW var ratio',np.round(r,3))
