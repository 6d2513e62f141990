from eff import *
D=np.pi/180
TT='temperature: {start: 20 degC, end: 40 degC}'
d=run('tc','gyro:\n  all:\n    - {type: temperature, T0: 25 degC, coefficients: [0.01 deg/s/degC, 0.001 deg/s/degC^2]}\naccel:\n  x:\n    - {type: temperature, T0: 25 degC, coefficients: [0.1 mg/degC]}\n',scen=STAT,dur=100,temp=TT)
t=d['t_s']; e=(arr(d,'w')-arr(d,'w','ideal'))[:,0]
b=lambda T: (0.01*(T-25)+0.001*(T-25)**2)*D
T=lambda tt: 20+20*tt/100
dt=0.01; bend=b(T(t)); bmid=b(T(t-dt/2)); bmean=(b(T(t-dt))+4*bmid+bend)/6
print('temp gyro: resid vs interval mean',np.abs(e-bmean).max(),' vs end',np.abs(e-bend).max(),' vs start',np.abs(e-b(T(t-dt))).max(), 'size',np.abs(e).max())
ea=(arr(d,'f')-arr(d,'f','ideal'))[:,0]; ba=0.1e-3*9.80665*(T(t-dt/2)-25)
print('temp accel: resid vs mid',np.abs(ea-ba).max())
d=run('tc2','gyro:\n  all:\n    - {type: temperature, T0: 25 degC, coefficients: [0.01 deg/s/degC]}\naccel: {}\n',scen=STAT,dur=10,temp='temperature: {start: 20 degC, rate: 1 K/min}')
t=d['t_s']; e=(arr(d,'w')-arr(d,'w','ideal'))[:,0]; print('rate 1K/min resid', np.abs(e-0.01*D*(20+(t-0.005)/60-25)).max())
d=run('tc3','gyro:\n  all:\n    - {type: temperature, T0: 25 degC, coefficients: [0.01 deg/s/degC]}\naccel: {}\n',scen=STAT,dur=10,temp='temperature: 30 degC')
e=(arr(d,'w')-arr(d,'w','ideal'))[:,0]; print('const 30degC resid', np.abs(e-0.05*D).max())
d=run('tc4','gyro:\n  all:\n    - {type: temperature, T0: 77 degF, coefficients: [0.01 deg/s/K]}\naccel: {}\n',scen=STAT,dur=10,temp='temperature: 303.15 K')
if d is not None: e=(arr(d,'w')-arr(d,'w','ideal'))[:,0]; print('T0 77 degF, T 303.15 K, 0.01 deg/s/K resid', np.abs(e-0.05*D).max())
d=run('tc5','gyro:\n  all:\n    - {type: temperature, T0: 25 degC, coefficients: [0.01 deg/s/degC]}\naccel: {}\n',scen=STAT,dur=10)
if d is not None: print('no temperature: meas gyro first', arr(d,'w')[0])
# sinusoid ramp warmup
d=run('srw','gyro:\n  x:\n    - {type: sinusoid, amplitude: 0.1 deg/s, frequency: 2 Hz, phase: 30 deg}\n  y:\n    - {type: ramp, slope: 36 deg/h^2}\n  z:\n    - {type: warmup, amplitude: 0.5 deg/s, tau: 3 s}\naccel: {}\n',scen=STAT,dur=10)
t=d['t_s']; e=arr(d,'w')-arr(d,'w','ideal'); A=0.1*D; f=2; ph=np.radians(30)
sm=A*(np.cos(2*np.pi*f*(t-dt)+ph)-np.cos(2*np.pi*f*t+ph))/(2*np.pi*f*dt)
print('sinusoid resid vs interval mean',np.abs(e[:,0]-sm).max(),' vs end sample',np.abs(e[:,0]-A*np.sin(2*np.pi*f*t+ph)).max())
R=36*D/3600**2; print('ramp resid vs R*(t-dt/2)',np.abs(e[:,1]-R*(t-dt/2)).max(),'size',R*10)
wm_=0.5*D*3*(np.exp(-(t-dt)/3)-np.exp(-t/3))/dt; print('warmup resid vs interval mean',np.abs(e[:,2]-wm_).max())
