#!/usr/bin/python3
"""Build the record list, inject (inject.py), diagnose each record (one sinsim at a time, --threads 1,
--add found), keep JSON in results/, delete the CSV. Resumable. Baselines: clean windows in results/null_wK.json."""
import sys, os, json, subprocess, time
sys.path.insert(0,'/tmp/probe_28/work'); import inject
W='/tmp/probe_28/work'; os.makedirs(W+'/results',exist_ok=True); os.makedirs(W+'/recs',exist_ok=True)
SS='/tmp/probe_bin28/sinsim'
def diag(csv,js,add=True):
    cmd=[SS,'diagnose',csv,'--model',W+'/run1-auto.yaml','--rate','100','--gyro-unit','deg/s','--accel-unit','g',
         '--threads','1','--realisations','16','--json',js]
    if add: cmd+=['--add','found','-o',js.replace('.json','.improved.yaml')]
    t=time.time(); r=subprocess.run(cmd,capture_output=True,text=True); return r.returncode,time.time()-t,r.stdout+r.stderr
recs=[]
cat=['step','ramp','warmup','sinusoid','random_walk','gauss_markov','outliers']; chs=['gx','gz','az','ax']
i=0
for e in cat:
    for k in (2,5):
        for s in range(2):
            recs.append(dict(name=f'{e}_k{k}_s{s}',win=(i%8),seed=100+i,eff=[(e,chs[i%4],k)])); i+=1
for e in ['telegraph','chirp','burst']:
    for k in (2,5):
        for s in range(2):
            recs.append(dict(name=f'ooc_{e}_k{k}_s{s}',win=(i%8),seed=100+i,eff=[(e,chs[i%4],k)])); i+=1
pairs=[('step','sinusoid'),('ramp','gauss_markov'),('warmup','outliers'),('random_walk','sinusoid'),('step','outliers')]
for a,b in pairs:
    for k in (2,5):
        c=chs[i%4]; recs.append(dict(name=f'two_{a}+{b}_k{k}',win=(i%8),seed=100+i,eff=[(a,c,k),(b,c,k)])); i+=1
for e in ['step','sinusoid','ramp','gauss_markov']:
    recs.append(dict(name=f'noround_{e}_k5',win=(i%8),seed=100+i,eff=[(e,chs[i%4],5)],noround=True)); i+=1
if __name__=='__main__':
    # baselines: clean windows (also the false-alarm rate on real clean data)
    for w in range(8):
        js=f'{W}/results/null_w{w}.json'
        if os.path.exists(js): continue
        csv=f'{W}/recs/null_w{w}.csv'; inject.make(csv,w,[],0)
        rc,dt,out=diag(csv,js,add=False); os.remove(csv)
        json.dump(dict(rc=rc,secs=dt,out=out[-3000:]),open(js.replace('.json','.meta.json'),'w')); print('null',w,rc,round(dt,1),flush=True)
    for r in recs:
        js=f'{W}/results/{r["name"]}.json'
        if os.path.exists(js.replace('.json','.meta.json')): continue
        csv=f'{W}/recs/{r["name"]}.csv'; info=inject.make(csv,r['win'],r['eff'],r['seed'],r.get('noround',False))
        rc,dt,out=diag(csv,js); os.remove(csv)
        json.dump(dict(rec=r,info=info,rc=rc,secs=dt,out=out),open(js.replace('.json','.meta.json'),'w'))
        print(r['name'],rc,round(dt,1),flush=True)
