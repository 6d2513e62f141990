from eff import *
D=np.pi/180
M='gyro:\n  all:\n    - {type: bias, value: 0.1 deg/s}\n    - {type: white, density: 0.2 deg/sqrt(h)}\n    - {type: ramp, slope: 3600 deg/h^2}\naccel:\n  all:\n    - {type: bias, value: 1 mg}\n'
a=run('bw0',M,scen=STAT,dur=20); b=run('bw1',M,scen=STAT,dur=20,extra=['--bias-window','10 s'])
ea=arr(a,'w')-arr(a,'w','ideal'); eb=arr(b,'w')-arr(b,'w','ideal')
w0=ea[a['t_s']<=10+1e-9].mean(0)
print('window mean deg/s',w0/D, ' resid of b vs a - windowmean', np.abs(eb-(ea-w0)).max())
fa=arr(a,'f')-arr(a,'f','ideal'); fb=arr(b,'f')-arr(b,'f','ideal'); print('accel after window',np.abs(fb).max())
