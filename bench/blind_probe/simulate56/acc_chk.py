import numpy as np, subprocess, sys
S=lambda u: u-np.sin(2*np.pi*u)/(2*np.pi)
for T,rate,lat,hdg in [(1.0,100,45,0),(1.005,100,45,0),(1.005,100,0,0),(1.0,100,45,90),(10,100,45,0),(1.0,1000,45,0)]:
    open('ak.yaml','w').write(f"""start: {{latitude: {lat} deg, longitude: 7 deg, heading: {hdg} deg}}
imu_rate: {rate} Hz
output_rate: {rate} Hz
segments:
  - {{type: accelerate, speed: 10 m/s, duration: {T} s}}
  - {{type: cruise, duration: 1 s}}
""")
    subprocess.run(['/tmp/probe_bin3/sinsim','run','ak.yaml','-o','o_ak','--imu'],capture_output=True)
    d=np.genfromtxt('o_ak/imu.csv',delimiter=',',names=True); dt=1/rate
    s=np.vectorize(lambda t: 10*S(min(t/T,1)))
    t=d['t_s']; e=(s(t)-s(t-dt))/dt
    r=d['ideal_fx_mps2']-e
    print(T,rate,lat,hdg,'max|resid fx|',np.abs(r).max(),' resid at first',r[0])
