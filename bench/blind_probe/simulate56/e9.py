from eff import *
D=np.pi/180
rate=5; dt=1/rate
d=run('bi','gyro:\n  all:\n    - {type: bias_instability, floor: 10 deg/h, tau_range: [1 s, 100 s]}\naccel:\n  all:\n    - {type: bias_instability, B: 0.1 mg, tau_range: [1 s, 100 s]}\n',scen=STAT,dur=20000,rate=rate)
def adev(y,m):
    c=np.cumsum(np.r_[0,y])*dt; tau=m*dt
    n=len(y); v=(c[2*m:]-2*c[m:n-m+1]+c[:n-2*m+1]) if False else None
    x=c
    d2=x[2*m:]-2*x[m:-m]+x[:-2*m]
    return np.sqrt(np.mean(d2**2)/(2*tau**2))
e=arr(d,'w')-arr(d,'w','ideal'); ea=arr(d,'f')-arr(d,'f','ideal')
for m in [5,10,25,50,100,250,500]:
    print('tau',m*dt,' gyro adev/floor',np.round([adev(e[:,i],m)/(10*D/3600) for i in range(3)],3), ' accel adev/(0.664B)',np.round([adev(ea[:,i],m)/(0.664*0.1e-3*9.80665) for i in range(3)],3))
