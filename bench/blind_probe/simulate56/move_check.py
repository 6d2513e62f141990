import wgs, numpy as np, subprocess, sys
BIN='/tmp/probe_bin3/sinsim'
S=lambda u: u-np.sin(2*np.pi*u)/(2*np.pi)
def mk(name, lat, h, speed, heading, seg, rate=100, extra=''):
    y=f"""name: {name}
start: {{latitude: {lat} deg, longitude: 7 deg, height: {h} m, speed: {speed} m/s, heading: {heading} deg}}
imu_rate: {rate} Hz
output_rate: {rate} Hz
vertical: held
{extra}
segments:
  - {seg}
"""
    open(name+'.yaml','w').write(y)
    out=subprocess.run([BIN,'run',name+'.yaml','-o','o_'+name,'--imu'],capture_output=True,text=True)
    if out.returncode: print(out.stderr); sys.exit(1)
    tr=np.genfromtxt('o_'+name+'/truth.csv',delimiter=',',names=True)
    im=np.genfromtxt('o_'+name+'/imu.csv',delimiter=',',names=True)
    return tr,im
def check(name, tr, im, prof, g0=None):
    # prof(t) -> s, psi, gamma, roll, pitch  (rad) ; numerical derivs
    errs_f=[];errs_w=[];errs_fm=[];errs_wm=[]
    dt=im['t_s'][1]-im['t_s'][0]
    def quantities(t, lat, h):
        e=1e-4
        s,psi,gam,ro,pi_=prof(t)
        def vn(tt):
            s,psi,gam,_,_=prof(tt); return s*np.array([np.cos(gam)*np.cos(psi),np.cos(gam)*np.sin(psi),-np.sin(gam)])
        v=vn(t); vdot=(vn(t-2*e)-8*vn(t-e)+8*vn(t+e)-vn(t+2*e))/(-12*e) * -1
        vdot=(-vn(t+2*e)+8*vn(t+e)-8*vn(t-e)+vn(t-2*e))/(12*e)
        M,N=wgs.radii(lat)
        wie=wgs.WE*np.array([np.cos(lat),0,-np.sin(lat)])
        wen=np.array([v[1]/(N+h),-v[0]/(M+h),-v[1]*np.tan(lat)/(N+h)])
        gn=wgs.gravity_ned(np.degrees(lat),h)
        C=wgs.Cnb(ro,pi_,psi)
        f=C.T@(vdot+np.cross(2*wie+wen,v)-gn)
        eul=lambda tt: np.array(prof(tt)[3:5]+(prof(tt)[1],))
        ed=(-eul(t+2*e)+8*eul(t+e)-8*eul(t-e)+eul(t-2*e))/(12*e)
        rd,pd,yd=ed
        wnb=np.array([rd-yd*np.sin(pi_), pd*np.cos(ro)+yd*np.sin(ro)*np.cos(pi_), -pd*np.sin(ro)+yd*np.cos(ro)*np.cos(pi_)])
        w=wnb+C.T@(wie+wen)
        return f,w
    idx=np.linspace(1,len(im)-1,25).astype(int)
    for k in idx:
        t=im['t_s'][k]; j=np.argmin(abs(tr['t_s']-t))
        lat=np.radians(tr['lat_deg'][j]); h=tr['h_m'][j]
        f,w=quantities(t,lat,h)
        fg=np.array([im['ideal_fx_mps2'][k],im['ideal_fy_mps2'][k],im['ideal_fz_mps2'][k]])
        wg=np.array([im['ideal_wx_radps'][k],im['ideal_wy_radps'][k],im['ideal_wz_radps'][k]])
        # interval mean via Simpson between t-dt and t (lat,h approx from truth j, j-1)
        latp=np.radians(tr['lat_deg'][j-1]); hp=tr['h_m'][j-1]
        fa,wa=quantities(t-dt,latp,hp); fm,wm=quantities(t-dt/2,(lat+latp)/2,(h+hp)/2)
        fmean=(fa+4*fm+f)/6; wmean=(wa+4*wm+w)/6
        errs_f.append(np.linalg.norm(fg-f)); errs_w.append(np.linalg.norm(wg-w))
        errs_fm.append(np.linalg.norm(fg-fmean)); errs_wm.append(np.linalg.norm(wg-wmean))
    print(f"{name}: vs instantaneous max|df|={max(errs_f):.2e} max|dw|={max(errs_w):.2e}; vs interval-mean max|df|={max(errs_fm):.2e} max|dw|={max(errs_wm):.2e}")
    return errs_fm,errs_wm
