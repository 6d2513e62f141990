#!/usr/bin/python3
"""zstates.py WORK t1 t2 ...: per-state mean (e/sigma)^2 over runs, and run-averaged NEES, at given epochs"""
import sys, numpy as np
d=np.load(sys.argv[1]+'/all.npz'); A=d['A']; n=list(d['names']); t=A[0,:,0]
st=['north_m','east_m','down_m','vn_mps','ve_mps','vd_mps','psi_n_rad','psi_e_rad','psi_d_rad']
print('t     NEES  diag  '+' '.join('%6s'%s[:6] for s in st))
for tt in map(float,sys.argv[2:]):
  i=np.argmin(abs(t-tt))
  z2=[np.mean((A[:,i,n.index(s)]/A[:,i,n.index('sigma_'+s)])**2) for s in st]
  print('%5.0f %5.2f %5.2f '%(t[i],A[:,i,n.index('nees')].mean(),sum(z2))+' '.join('%6.2f'%x for x in z2))
