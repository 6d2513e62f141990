from eff import *
D=np.pi/180
d=run('ar1k','gyro:\n  x:\n    - {type: ar, a: [-0.9], output_sigma: 0.1 deg/s, rate: 1 kHz}\n  y:\n    - {type: ar, a: [-1.2, 0.5], sigma: 0.01 deg/s, rate: 1 kHz}\naccel: {}\n',scen=STAT,dur=1000)
e=arr(d,'w')-arr(d,'w','ideal')
# theory for x: AR(1) rho=0.9, mean of 10
r=0.9; idx=np.arange(10); V=(0.1*D)**2*np.mean(r**np.abs(idx[:,None]-idx[None,:]))
print('AR1 1kHz->100Hz var ratio',e[:,0].var()/V)
# AR2 theory via impulse response
a=[1,-1.2,0.5]; h=np.zeros(20000); h[0]=1
for n in range(1,20000): h[n]=-(a[1]*h[n-1]+(a[2]*h[n-2] if n>=2 else 0))
acf=lambda k: np.sum(h[:20000-k]*h[k:])*(0.01*D)**2
c=np.array([acf(k) for k in range(12)])
V2=np.mean([[c[abs(i-j)] for j in range(10)] for i in range(10)])
print('AR2 var ratio',e[:,1].var()/V2)
d=run('whslow','gyro:\n  x:\n    - {type: white, density: 0.1 deg/sqrt(h), rate: 50 Hz}\naccel: {}\n',scen=STAT,dur=2)
d=run('rwslow','gyro:\n  x:\n    - {type: random_walk, K: 1 deg/h/sqrt(h), rate: 50 Hz}\naccel: {}\n',scen=STAT,dur=2)
d=run('bislow','gyro:\n  x:\n    - {type: bias_instability, B: 1 deg/h, tau_range: [1 s, 100 s], rate: 50 Hz}\naccel: {}\n',scen=STAT,dur=2)
