#!/usr/bin/python3
"""Second batch: seeds 2-3 of every single catalogue and out-of-catalogue effect, on other channels/windows
(same protocol as run_all.py). Run after run_all.py."""
import sys, os, json
sys.path.insert(0,'/tmp/probe_28/work'); import inject, run_all
W=run_all.W; recs=[]; i=0
chs=['gy','ax','gx','az','gz']
for e in ['step','ramp','warmup','sinusoid','random_walk','gauss_markov','outliers','telegraph','chirp','burst']:
    for k in (2,5):
        for s in (2,3):
            pre='ooc_' if e in ('telegraph','chirp','burst') else ''
            recs.append(dict(name=f'{pre}{e}_k{k}_s{s}',win=(i*3+1)%8,seed=500+i,eff=[(e,chs[i%5],k)])); i+=1
if __name__=='__main__':
    for r in recs:
        js=f'{W}/results/{r["name"]}.json'
        if os.path.exists(js.replace('.json','.meta.json')): continue
        csv=f'{W}/recs/{r["name"]}.csv'; info=inject.make(csv,r['win'],r['eff'],r['seed'])
        rc,dt,out=run_all.diag(csv,js); os.remove(csv)
        json.dump(dict(rec=r,info=info,rc=rc,secs=dt,out=out),open(js.replace('.json','.meta.json'),'w'))
        print(r['name'],rc,round(dt,1),flush=True)
