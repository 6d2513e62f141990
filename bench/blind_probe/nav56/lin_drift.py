# linear-kernel drift at T=600 s: (1) from each synth record (vs tool's replay), (2) Monte Carlo of the model T
import numpy as np,glob,json
lat=np.radians(45); ge=9.7803253359*(1+0.00193185265241*np.sin(lat)**2)/np.sqrt(1-0.00669437999013*np.sin(lat)**2)
a=6378137.0; e2=0.00669437999013; RN=a*(1-e2)/(1-e2*np.sin(lat)**2)**1.5; RE=a/np.sqrt(1-e2*np.sin(lat)**2)
ws=np.sqrt(ge/np.sqrt(RN*RE)); T=600.; W=60.; dt=0.01
t=np.arange(1,60001)*dt-dt/2
Ka=np.sin(ws*(T-t))/ws; Kg=(1-np.cos(ws*(T-t)))/ws**2
def drift(g,acc):
    g=g-g[:int(W/dt)].mean(0); acc=acc-acc[:int(W/dt)].mean(0)
    pn=np.sum(acc[:,0]*Ka - ge*g[:,1]*Kg)*dt; pe=np.sum(acc[:,1]*Ka + ge*g[:,0]*Kg)*dt
    return np.hypot(pn,pe)
rec=[];tool=[]
for f in sorted(glob.glob('rec10_T_*.csv'))[:100]:
    x=np.loadtxt(f,delimiter=',',skiprows=1,usecols=range(1,7))
    rec.append(drift(x[:,:3],x[:,3:])); s=f.split('_')[-1][:-4]
    J=json.load(open(f'mw_{s}/summary.json'))['measured']['models'][0]
    tool.append([q['measured_horizontal_m'] for q in J['at'] if q['t_s']==600][0])
rec=np.array(rec); tool=np.array(tool)
print("record: linear vs tool replay ratio median %.4f min %.4f max %.4f"%(np.median(rec/tool),(rec/tool).min(),(rec/tool).max()))
rng=np.random.default_rng(1); K=30*np.pi/180/3600/60; N=0.3*np.pi/180/60; Q=0.05/60
sims=[]
for i in range(2000):
    g=np.cumsum(rng.standard_normal((60000,2))*K*np.sqrt(dt),0)+rng.standard_normal((60000,2))*N/np.sqrt(dt)
    acc=rng.standard_normal((60000,2))*Q/np.sqrt(dt)
    sims.append(drift(g,acc))
sims=np.array(sims)
print("linear MC of model T (2000): median %.0f rms %.0f p95 %.0f ; records(100) median %.0f rms %.0f"%(np.median(sims),np.sqrt(np.mean(sims**2)),np.percentile(sims,95),np.median(rec),np.sqrt(np.mean(rec**2))))
