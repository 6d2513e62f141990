import json,sys,numpy as np
sys.path.insert(0,'/tmp/probe_A'); from util import *; from wav import denoise
b=json.load(open('/tmp/probe_A/a_dn.json')); X=np.loadtxt('/tmp/probe_A/syn.csv',delimiter=',',skiprows=1)
for ch,col in [('gx',0),('gy',1),('gz',2),('ax',3)]:
    x=X[:,col]; y,sig,thr,lev=denoise(x)
    B=b['channels'][ch]; dn=B['denoise']
    print(ch,'sigma',sig,dn['sigma'],'thr',thr,dn['threshold'],'lev',lev,dn['level'])
    r=acf_biased(y,20000); print('  acf r0 mine',r[0],'tool',B['acf']['r'][0],'max|dr|/r0',np.max(np.abs(r-np.array(B['acf']['r'])))/r[0])
    f,P=welch(y,100.,16384); print('  psd maxrel',np.max(np.abs(P/np.array(B['psd']['psd'])-1)))
    print('  psd max|dP|/mean(P)',np.max(np.abs(P-np.array(B['psd']['psd'])))/np.mean(P), 'min P',P.min())
