from eff import *
D=np.pi/180
d=run('bias','gyro:\n  all:\n    - {type: bias, value: 10 deg/h}\n  z:\n    - {type: bias, value: -5 deg/h}\naccel:\n  x:\n    - {type: bias, value: 100 ug}\n',scen=STAT,dur=5)
e=arr(d,'w')-arr(d,'w','ideal'); print('gyro bias per axis deg/h',e.mean(0)/D*3600, 'sd',e.std(0))
e=arr(d,'f')-arr(d,'f','ideal'); print('accel bias ug',e.mean(0)/9.80665e-6)
# turn-on bias sigma: many seeds
vals=[]
for s in range(1,41):
    d=run('tb','gyro:\n  all:\n    - {type: bias, sigma: 100 deg/h}\naccel:\n  all:\n    - {type: bias, sigma: 1 mg}\n',scen=STAT,dur=1,seed=s)
    e=arr(d,'w')-arr(d,'w','ideal'); ea=arr(d,'f')-arr(d,'f','ideal')
    vals.append(np.r_[e.mean(0)/D*3600, ea.mean(0)/9.80665e-3]); 
    if s==1: print('within-run sd (should be 0)',e.std(0), ea.std(0))
v=np.array(vals); print('turn-on gyro sd deg/h',v[:,:3].std(0),' accel sd mg',v[:,3:].std(0),' corr xy',np.corrcoef(v[:,0],v[:,1])[0,1], 'gyro-x vs accel-x corr',np.corrcoef(v[:,0],v[:,3])[0,1])
