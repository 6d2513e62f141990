from eff import *
D=np.pi/180
K=10*D/3600/60  # rad/s/sqrt(s)
Ka=0.01/60      # 0.01 m/s^2/sqrt(h) -> m/s^2/sqrt(s)?  (m/s^2)/sqrt(h) = (m/s^2)/60 /sqrt(s)
rate=20; dt=1/rate
res={'g':[],'a':[]}
for seed in [1,2]:
    d=run(f'rw{seed}','gyro:\n  all:\n    - {type: random_walk, K: 10 deg/h/sqrt(h)}\naccel:\n  all:\n    - {type: random_walk, K: 0.01 m/s^2/sqrt(h)}\n',scen=STAT,dur=2000,rate=rate,seed=seed)
    for key,kk,k in [('g','w',K),('a','f',Ka)]:
        e=arr(d,kk)-arr(d,kk,'ideal')
        for L in [20,200]:
            x=e[::L]; dd=np.diff(x,axis=0)
            exp=k*k*(L*dt)   # approx; interval-mean correction: minus dt/3*2... small
            exp_c=k*k*(L*dt - 2*dt/3 + dt/3*0)  # placeholder
            res[key].append((L, (dd.var(0)/exp)))
for k,v in res.items():
    for L,r in v: print(k,'L',L,'var(diff)/K^2 T',np.round(r,3))
# start value: RW starts at 0?
d=np.genfromtxt('o_e_rw1/imu.csv',delimiter=',',names=True,max_rows=3)
print('first sample gyro err', arr(d,'w')[0]-arr(d,'w','ideal')[0], 'K*sqrt(dt)=',K*np.sqrt(dt))
