from eff import *
D=np.pi/180
vals=[]
for s in range(1,31):
    d=run('sfs','gyro:\n  triad:\n    - {type: scale_factor, value: 0, sigma: 1000 ppm}\naccel:\n  triad:\n    - {type: scale_factor, diagonal: [100 ppm, 0, 0], sigma: 500 ppm}\n',seed=s)
    wi,wm=arr(d,'w','ideal'),arr(d,'w'); fi,fm=arr(d,'f','ideal'),arr(d,'f')
    sg=[np.polyfit(wi[:,i],wm[:,i]-wi[:,i],1)[0] for i in range(3)]
    sa=[np.polyfit(fi[:,i],fm[:,i]-fi[:,i],1)[0] for i in range(3)]
    # off-diagonal check
    if s==1:
        Sfit=np.linalg.lstsq(wi,wm-wi,rcond=None)[0].T; print('fitted S (ppm)\n',np.round(Sfit*1e6,3))
    vals.append(sg+sa)
v=np.array(vals)*1e6; print('gyro SF sd ppm',v[:,:3].std(0),'mean',v[:,:3].mean(0)); print('accel SF sd',v[:,3:].std(0),'mean',v[:,3:].mean(0))
# AR
d=run('ar','gyro:\n  x:\n    - {type: ar, a: [-0.9], output_sigma: 0.1 deg/s, rate: 100 Hz}\n  y:\n    - {type: ar, a: [-0.9], sigma: 0.1 deg/s, rate: 100 Hz}\naccel: {}\n',scen=STAT,dur=500)
e=arr(d,'w')-arr(d,'w','ideal')
print('AR(1) output_sigma sd/exp',e[:,0].std()/(0.1*D),' lag1',np.corrcoef(e[:-1,0],e[1:,0])[0,1],'(0.9)')
print('AR(1) driving sigma sd/exp',e[:,1].std()/(0.1*D/np.sqrt(1-0.81)),' lag1',np.corrcoef(e[:-1,1],e[1:,1])[0,1])
d=run('arslow','gyro:\n  x:\n    - {type: ar, a: [-0.9], sigma: 0.1 deg/s, rate: 50 Hz}\naccel: {}\n',scen=STAT,dur=5)
d=run('gmslow','gyro:\n  x:\n    - {type: gauss_markov, sigma: 0.1 deg/s, tau: 1 s, rate: 50 Hz}\naccel: {}\n',scen=STAT,dur=5)
# bias jumps
d=run('bj','gyro:\n  x:\n    - {type: bias_jumps, rate: 0.5 Hz, size: 0.1 deg/s}\n  y:\n    - {type: bias_jumps, rate: 0.5 Hz, size: 0.1 deg/s, telegraph: yes}\n  z:\n    - {type: outliers, rate: 2 Hz, amplitude: 1 deg/s}\naccel: {}\n',scen=STAT,dur=2000)
e=arr(d,'w')-arr(d,'w','ideal'); dx=np.diff(e[:,0]); 
jumps=np.abs(dx)>1e-12; print('bias_jumps: n jumps',jumps.sum(),'exp',0.5*2000,' (jump sd incl split across interval)')
lv=np.unique(np.round(e[:,1]/D,6)); print('telegraph levels (deg/s, first few)',lv[:3],lv[-3:], 'count', len(lv))
nz=np.abs(e[:,2])>1e-12; print('outliers: n',nz.sum(),'exp',2*2000, ' values(deg/s) ',np.unique(np.round(e[nz,2]/D,6))[:5])
