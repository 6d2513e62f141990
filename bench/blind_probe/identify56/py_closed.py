import sinsim,numpy as np,warnings,time,sys
warnings.simplefilter('ignore')
s=np.load('/tmp/probe_A/syn.npz'); fs=100.; dt=0.01
R=int(sys.argv[1]) if len(sys.argv)>1 else 32
rec={'rate':fs,'gx':s['w'],'gy':s['rw'],'gz':s['gm']}
N=0.001; K=1e-3; sg=0.05; T=2.0
model={'gyro':{'x':[{'type':'white','density':f'{N} rad/s/sqrt(Hz)'}],
               'y':[{'type':'random_walk','K':f'{K} rad/s/sqrt(s)'}],
               'z':[{'type':'gauss_markov','sigma':f'{sg} rad/s','tau':f'{T} s'}]}}
t0=time.time()
d=sinsim.diagnose(rec,model,realisations=R,threads=1)
print('diagnose R=%d %.1fs'%(R,time.time()-t0))
def gm_avar(tau):
    x=tau/T; 
    return 2*sg**2*T**2/tau**2*(x-1.5+2*np.exp(-x)-0.5*np.exp(-2*x))
for ch,f in [('gx',lambda t:N**2/t),('gy',lambda t:K**2*t/3),('gz',gm_avar)]:
    a=d[ch]['adev']; tau=np.asarray(a['tau']); mod=np.asarray(a['model'])
    ref=np.sqrt(f(tau)); rel=mod/ref-1; meas=np.asarray(a['meas'])
    print(ch,'tau',np.round(tau[:29:4],3))
    print('   model/closed-1',np.round(rel[:29:4],4))
    print('   meas/closed-1 ',np.round((meas/ref-1)[:29:4],4))
    print('   band lo/model, hi/model at tau0',a['lo'][0]/mod[0],a['hi'][0]/mod[0])
