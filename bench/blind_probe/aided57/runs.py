#!/usr/bin/python3
"""runs.py SCEN N WORK [first_seed]: sinsim run --seed k for k=first..first+N-1, collect filter.csv
and summary.json outages into WORK/all.npz; print per-state coverage at outage ends and per-epoch NEES."""
import sys, os, subprocess, json, csv, numpy as np, shutil
S='/tmp/probe_bin57/sinsim'
scen, N, work = sys.argv[1], int(sys.argv[2]), sys.argv[3]
first = int(sys.argv[4]) if len(sys.argv) > 4 else 1
os.makedirs(work, exist_ok=True)
F=[]; outs=[]
for k in range(first, first+N):
    d=os.path.join(work,'r'); 
    p=subprocess.run([S,'run',scen,'-o',d,'--seed',str(k)],capture_output=True,text=True)
    if p.returncode: print(p.stderr); sys.exit(1)
    a=np.genfromtxt(os.path.join(d,'filter.csv'),delimiter=',',names=True)
    F.append(a)
    outs.append(json.load(open(os.path.join(d,'summary.json')))['outages'])
names=F[0].dtype.names
A=np.stack([np.column_stack([f[n] for n in names]) for f in F])  # runs, epochs, cols
np.savez(os.path.join(work,'all.npz'),A=A,names=np.array(names),outs=json.dumps(outs))
ix={n:i for i,n in enumerate(names)}
st=['north_m','east_m','down_m','vn_mps','ve_mps','vd_mps','psi_n_rad','psi_e_rad','psi_d_rad']
t=A[0,:,ix['t_s']]; out=A[0,:,ix['outage']]
nees=A[:,:,ix['nees']].mean(0)
from scipy.stats import chi2
R=N; lo,hi=chi2.ppf(0.005,9*R)/R, chi2.ppf(0.995,9*R)/R
aid=A[0,:,ix['aiding']]==1
print(f'{N} runs; NEES run-avg: aiding mean {nees[aid].mean():.3f} inside {np.sum((nees[aid]>lo)&(nees[aid]<hi))}/{aid.sum()}; outage mean {nees[out==1].mean():.3f} inside {np.sum((nees[out==1]>lo)&(nees[out==1]<hi))}/{(out==1).sum()} band [{lo:.2f},{hi:.2f}]')
nis=A[:,:,ix['nis']]; 
if aid.any(): print('NIS mean over aiding', np.nanmean(nis[:,aid]), 'dof', A[0,aid,ix['nis_dof']][0])
# outage ends: last outage epoch of each contiguous block
ends=[i for i in range(len(t)) if out[i]==1 and (i+1==len(t) or out[i+1]==0)]
for i in ends:
    z=np.array([A[:,i,ix[s]]/A[:,i,ix['sigma_'+s]] for s in st])  # 9 x runs
    cov=[[np.mean(np.abs(z[j])<m) for m in (1,2,3)] for j in range(9)]
    print(f't={t[i]:.0f}s (last outage epoch): per-state |e|/sigma within 1/2/3 sigma; mean z^2')
    for j,s in enumerate(st): print(f'   {s:10s} {cov[j][0]:.3f} {cov[j][1]:.3f} {cov[j][2]:.3f}   z2={np.mean(z[j]**2):.3f}')
    h=np.hypot(A[:,i,ix['north_m']],A[:,i,ix['east_m']]); sh=np.hypot(A[:,i,ix['sigma_north_m']],A[:,i,ix['sigma_east_m']])
    print(f'   horizontal: median err {np.median(h):.2f} m, median sigma_h {np.median(sh):.2f} m, frac h<sigma_h {np.mean(h<sh):.3f} (2D gauss equal sig: 0.632)')
shutil.rmtree(os.path.join(work,'r'),ignore_errors=True)
