from eff import *
D=np.pi/180
tests=[('gyro','10 dph',10*D/3600),('gyro','10 deg/hr',10*D/3600),('gyro','1 rev/min',2*np.pi/60),('gyro','100 urad/s',1e-4),('gyro','1 arcsec/s',D/3600),('gyro','1 mrad/s',1e-3),
('accel','1 g',9.80665),('accel','1000 mg',9.80665),('accel','100 Gal',1.0),('accel','1 ft/s^2',0.3048),('accel','100 µg',9.80665e-4),('accel','1 m/s/s',1.0),('accel','3.6 km/h/s',1.0),('accel','1 kn/s',1852/3600)]
for sen,val,exp in tests:
    m=f'{sen}:\n  x:\n    - {{type: bias, value: {val}}}\n'
    d=run('u',m,scen=STAT,dur=0.1)
    if d is None: continue
    k='w' if sen=='gyro' else 'f'
    got=(arr(d,k)-arr(d,k,'ideal'))[0,0]; print(sen,val,'got',got,'exp',exp,'ok' if abs(got/exp-1)<1e-9 else 'MISMATCH')
