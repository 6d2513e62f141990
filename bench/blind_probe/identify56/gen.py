import numpy as np, sys
sys.path.insert(0,'/tmp/probe_A'); from util import lfilter_ar
rng=np.random.default_rng(1)
fs=100.0; N=200000; dt=1/fs
w=rng.standard_normal(N)*0.01
ar2=lfilter_ar([1,-1.5,0.7],rng.standard_normal(N)*0.02)
a5=[1,-2.2,2.1,-1.2,0.45,-0.08]
print("AR5 |roots|",np.abs(np.roots(a5)))
ar5=lfilter_ar(a5,rng.standard_normal(N)*0.01)
tau=2.0; phi=np.exp(-dt/tau); sg=0.05
gm=lfilter_ar([1,-phi],rng.standard_normal(N)*sg*np.sqrt(1-phi**2))
K=1e-3; rw=np.cumsum(rng.standard_normal(N)*K*np.sqrt(dt))
acc=9.81+rng.standard_normal(N)*0.01
np.savetxt("syn.csv",np.c_[w,ar2,ar5,gm,rw,acc],delimiter=",",header="gx,gy,gz,ax,ay,az",comments="",fmt="%.12g")
np.savez("syn.npz",w=w,ar2=ar2,ar5=ar5,gm=gm,rw=rw,acc=acc)
