import json,sys,numpy as np
sys.path.insert(0,'/tmp/probe_A'); from util import *
d=json.load(open('/tmp/probe_A/run1_a.json')); X=np.load('/tmp/probe_A/run1.npy')
for i,ch in enumerate(['gx','gy','gz','ax','ay','az']):
    x=np.radians(X[:,i]) if i<3 else X[:,i]*9.80665
    c=d['channels'][ch]; al=c['allan']
    e=max(abs(np.sqrt(oavar(x,m)[0])/a-1) for m,a in zip(al['m'],al['adev']))
    f,P=welch(x,100.,c['psd']['segment_length']); ep=np.max(np.abs(P/np.array(c['psd']['psd'])-1))
    lags=np.round(np.array(c['acf']['lag_s'])*100).astype(int); r=acf_biased(x,lags.max()); ea=np.max(np.abs(r[lags]-np.array(c['acf']['r'])))/r[0]
    print(ch,'ntau',len(al['m']),'adev',e,'psd seg',c['psd']['segment_length'],ep,'acf nl',len(lags),lags.max(),ea)
    if False:
        k=al['m'].index(100); print('  gx OADEV tau=1s deg/s',np.degrees(al['adev'][k]) if 100 in al['m'] else None)
print('gx OADEV m=100', np.degrees(np.sqrt(oavar(np.radians(X[:,0]),100)[0])))
