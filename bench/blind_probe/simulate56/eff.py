import numpy as np, subprocess, sys, os
BIN='/tmp/probe_bin3/sinsim'
DYN="""name: dyn
start: {latitude: 45 deg, longitude: 7 deg, height: 100 m, speed: 20 m/s, heading: 10 deg}
imu_rate: 100 Hz
output_rate: 1 Hz
vertical: held
TEMP
segments:
  - {type: repeat, count: 5, segments: [{type: roll, angle: 30 deg, duration: 2 s}, {type: pitch, angle: -20 deg, duration: 2 s}, {type: turn, heading_change: 45 deg, duration: 2 s, bank: auto}, {type: accelerate, speed: 30 m/s, duration: 2 s}, {type: decelerate, speed: 20 m/s, duration: 2 s}]}
"""
STAT="""name: stat
start: {latitude: 45 deg, longitude: 7 deg, height: 100 m}
imu_rate: RATE Hz
output_rate: 1 Hz
vertical: held
TEMP
segments:
  - {type: static, duration: DUR s}
"""
def run(tag, model, scen=DYN, rate=100, dur=10, seed=1, temp='', extra=[]):
    sc=scen.replace('RATE',str(rate)).replace('DUR',str(dur)).replace('TEMP',temp)
    open(f'e_{tag}.yaml','w').write(sc); open(f'm_{tag}.yaml','w').write(model)
    r=subprocess.run([BIN,'run',f'e_{tag}.yaml','--model',f'm_{tag}.yaml','-o',f'o_e_{tag}','--imu','--seed',str(seed)]+extra,capture_output=True,text=True)
    if r.returncode: print(tag,'FAILED',r.stderr); return None
    d=np.genfromtxt(f'o_e_{tag}/imu.csv',delimiter=',',names=True)
    return d
def arr(d,kind,which='meas'):
    if kind=='w': return np.c_[d[f'{which}_wx_radps'],d[f'{which}_wy_radps'],d[f'{which}_wz_radps']]
    if kind=='f': return np.c_[d[f'{which}_fx_mps2'],d[f'{which}_fy_mps2'],d[f'{which}_fz_mps2']]
    if kind=='th': return np.c_[d[f'{which}_dthx_rad'],d[f'{which}_dthy_rad'],d[f'{which}_dthz_rad']]
    if kind=='v': return np.c_[d[f'{which}_dvx_mps'],d[f'{which}_dvy_mps'],d[f'{which}_dvz_mps']]
