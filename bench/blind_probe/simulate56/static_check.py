import wgs, numpy as np, subprocess, sys, csv, os
BIN='/tmp/probe_bin3/sinsim'
def run(name, lat, h, r,p,y, rate=100):
    y_=f"""name: {name}
start: {{latitude: {lat} deg, longitude: 7 deg, height: {h} m, attitude: {{roll: {r} deg, pitch: {p} deg, yaw: {y} deg}}}}
imu_rate: {rate} Hz
output_rate: 1 Hz
vertical: held
segments:
  - {{type: static, duration: 2 s}}
"""
    open(name+'.yaml','w').write(y_)
    out=subprocess.run([BIN,'run',name+'.yaml','-o','o_'+name,'--imu'],capture_output=True,text=True)
    if out.returncode: print(out.stderr); return
    d=np.genfromtxt('o_'+name+'/imu.csv',delimiter=',',names=True)
    w=np.array([d['ideal_wx_radps'][-1],d['ideal_wy_radps'][-1],d['ideal_wz_radps'][-1]])
    fb=np.array([d['ideal_fx_mps2'][-1],d['ideal_fy_mps2'][-1],d['ideal_fz_mps2'][-1]])
    L=np.radians(lat)
    C=wgs.Cnb(*np.radians([r,p,y]))
    gn=wgs.gravity_ned(lat,h)
    f_t=-C.T@gn; w_t=C.T@np.array([wgs.WE*np.cos(L),0,-wgs.WE*np.sin(L)])
    print(f"{name}: lat {lat} h {h} rpy {r},{p},{y}: |df|={np.linalg.norm(fb-f_t):.2e} rel {np.linalg.norm(fb-f_t)/np.linalg.norm(f_t):.1e}  |dw|={np.linalg.norm(w-w_t):.2e} rel {np.linalg.norm(w-w_t)/wgs.WE:.1e}  somig-vs-exact {wgs.somigliana(lat,h)-np.linalg.norm(gn):.1e}")
    if np.linalg.norm(fb-f_t)/9.8>1e-9 or np.linalg.norm(w-w_t)/wgs.WE>1e-9:
        print('  got f',fb,'exp',f_t); print('  got w',w,'exp',w_t)
cases=[('s1',45,250,0,0,0),('s2',0,0,0,0,90),('s3',-60,5000,10,-20,135),('s4',89,0,0,0,0),('s5',30,-100,0,80,0),('s6',-33.3,30000,-45,30,-170),('s7',60,99000,180,0,0),('s8',10,-11000,5,5,359)]
for c in cases: run(*c)
