from eff import *
vals=[]
for s in range(100,250):
    d=run('sfs2','gyro:\n  triad:\n    - {type: scale_factor, value: 0, sigma: 1000 ppm}\naccel: {}\n',seed=s,scen=DYN)
    wi,wm=arr(d,'w','ideal'),arr(d,'w')
    vals.append([np.polyfit(wi[:,i],wm[:,i]-wi[:,i],1)[0] for i in range(3)])
v=np.array(vals)*1e6; print('n',len(v),'sd',v.std(0),'mean',v.mean(0),'se',v.std(0)/np.sqrt(len(v)), 'corr', np.corrcoef(v.T)[0,1:], np.corrcoef(v.T)[1,2])
