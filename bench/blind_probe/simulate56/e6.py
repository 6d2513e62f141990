from eff import *
D=np.pi/180
d=run('q1','gyro:\n  all:\n    - {type: quantization, lsb: 0.07326 deg/s}\n    - {type: bias, value: 0.01 deg/s}\naccel:\n  all:\n    - {type: quantization, lsb: 0.001 m/s}\n')
wi,wm=arr(d,'w','ideal'),arr(d,'w'); L=0.07326*D
print('gyro rate LSB: on lattice', np.abs(wm/L-np.round(wm/L)).max(), ' resid vs round(ideal+bias)', np.abs(wm-np.round((wi+0.01*D)/L)*L).max(), ' vs round(ideal)+bias',np.abs(wm-(np.round(wi/L)*L+0.01*D)).max())
thm=arr(d,'th'); print('gyro increments on lattice of L*dt?', np.abs(thm/(L*0.01)-np.round(thm/(L*0.01))).max())
vi,vm=arr(d,'v','ideal'),arr(d,'v')
print('accel inc LSB: on lattice',np.abs(vm/0.001-np.round(vm/0.001)).max(),' cum drift max',np.abs(np.cumsum(vm-vi,0)).max(),'(<=0.0005?)', ' per-sample max err',np.abs(vm-vi).max())
print('accel rate col = inc/dt?',np.abs(arr(d,'f')-vm/0.01).max())
d=run('q2','gyro:\n  all:\n    - {type: quantization, lsb: 0.07326 deg/s, carry: yes}\naccel:\n  all:\n    - {type: quantization, lsb: 0.001 m/s, carry: no}\n')
wi,wm=arr(d,'w','ideal'),arr(d,'w'); vi,vm=arr(d,'v','ideal'),arr(d,'v')
print('gyro rate LSB carried: cum err max (rad)',np.abs(np.cumsum((wm-wi)*0.01,0)).max(),' LSB*dt/2=',L*0.01/2, ' on lattice',np.abs(wm/L-np.round(wm/L)).max())
print('accel inc LSB not carried: resid vs round',np.abs(vm-np.round(vi/0.001)*0.001).max())
d=run('q3','gyro:\n  all:\n    - {type: quantization, lsb: 0.07326 deg/s, dithered: true}\naccel:\n  all:\n    - {type: quantization, lsb: 0.001 m/s, dithered: true}\n',scen=STAT,dur=100)
e=arr(d,'w')-arr(d,'w','ideal'); print('dithered rate LSB: sd/(L/sqrt12)',e.std(0)/(L/np.sqrt(12)), 'max |e|/L',np.abs(e).max()/L)
ev=arr(d,'v')-arr(d,'v','ideal'); c=np.cumsum(ev,0); print('dithered inc LSB carried: sd per sample/(L/sqrt12)... cum max',np.abs(c).max(), ' sd of cum',c.std(0)/(0.001/np.sqrt(12)), 'sd e',ev.std(0)/(0.001/np.sqrt(12)))
