import json,sys,numpy as np
sys.path.insert(0,'/tmp/probe_A'); from util import *
js=sys.argv[1]; d=json.load(open(js)); fs=d['rate_hz']
data=dict(np.load(sys.argv[2])) if sys.argv[2].endswith('npz') else None
names=sys.argv[3].split(',')  # mapping channel=key
for mp in names:
    ch,key=mp.split('=')
    x=data[key]; c=d['channels'][ch]
    al=c['allan']; worst=0; 
    for m,a,cnt in zip(al['m'],al['adev'],al['count']):
        v,n=oavar(x,m); r=abs(np.sqrt(v)/a-1); worst=max(worst,r)
        if n!=cnt: print(ch,'count mismatch',m,n,cnt)
    print(ch,'ADEV n_tau',len(al['m']),'max m',max(al['m']),'N/4',len(x)//4,'max rel err',worst)
    ps=c['psd']; f,P=welch(x,fs,ps['segment_length'])
    fj=np.array(ps['f_hz']); pj=np.array(ps['psd'])
    idx=np.searchsorted(f,fj); 
    print(ch,'PSD nbins',len(fj),'max rel err',np.max(np.abs(pj/P[idx]-1)),'f err',np.max(np.abs(f[idx]-fj)))
    ac=c['acf']; lags=np.round(np.array(ac['lag_s'])*fs).astype(int); r=acf_biased(x,lags.max())
    print(ch,'ACF nlags',len(lags),'max abs err/r0',np.max(np.abs(np.array(ac['r'])-r[lags]))/r[0])
