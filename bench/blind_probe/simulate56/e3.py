from eff import *
D=np.pi/180
def stats(e):
    c1=[np.corrcoef(e[:-1,i],e[1:,i])[0,1] for i in range(3)]
    return e.std(0), np.round(c1,3), np.round(np.corrcoef(e[:,0],e[:,1])[0,1],3)
for rate in [100,400]:
    d=run(f'wh{rate}','gyro:\n  all:\n    - {type: white, density: 0.2 deg/sqrt(h)}\naccel:\n  all:\n    - {type: white, density: 120 ug/sqrt(Hz)}\n',scen=STAT,dur=200,rate=rate)
    e=arr(d,'w')-arr(d,'w','ideal'); sd,c1,cxy=stats(e)
    N=0.2*D/60; print(rate,'Hz gyro white sd/expected',sd/(N*np.sqrt(rate)),'lag1',c1,'xy',cxy, 'mean/(sd/sqrtn)',e.mean(0)/(sd/np.sqrt(len(e))))
    e=arr(d,'f')-arr(d,'f','ideal'); sd,c1,cxy=stats(e)
    N=120e-6*9.80665; print(rate,'Hz accel white sd/expected',sd/(N*np.sqrt(rate)),'lag1',c1,'xy',cxy)
d=run('whs','gyro:\n  all:\n    - {type: white, sigma: 0.1 deg/s, rate: 1 kHz}\naccel:\n  all:\n    - {type: white, density: 0.05 m/s/sqrt(h), rate: 1 kHz}\n',scen=STAT,dur=200,rate=100)
e=arr(d,'w')-arr(d,'w','ideal'); sd,c1,cxy=stats(e); print('sigma 0.1deg/s@1kHz into 100Hz sd/exp',sd/(0.1*D/np.sqrt(10)),c1)
e=arr(d,'f')-arr(d,'f','ideal'); sd,c1,cxy=stats(e); print('density+rate 1k accel sd/exp',sd/(0.05/60*np.sqrt(100)),c1)
d=run('whs2','gyro:\n  all:\n    - {type: white, sigma: 0.1 deg/s, rate: 250 Hz}\naccel: {}\n',scen=STAT,dur=200,rate=100)
e=arr(d,'w')-arr(d,'w','ideal'); sd,c1,cxy=stats(e)
# ZOH of 250Hz samples into 100Hz intervals: each interval covers 2.5 samples. variance = sigma^2 * sum(w_i^2), w fractions
print('sigma@250Hz into 100Hz sd/sigma',sd/(0.1*D),' lag1',c1)
