#!/usr/bin/python3
"""Third batch: fixed-size spikes (8 and 15 sample sd, not ADEV-sized), slow telegraph (dwell 200 s),
and three full-length records (run 2 after 10 min, 9400 s, 32 realisations; baseline null_run2_full.json)."""
import sys, os, json, subprocess, time
sys.path.insert(0,'/tmp/probe_28/work'); import inject, run_all
W=run_all.W; recs=[]
for i,(c,k) in enumerate([('gx',8),('gz',15),('ax',8),('az',15),('gy',8),('gx',15)]):
    recs.append(dict(name=f'spikes_sd{k}_{c}',win=(i*5)%8,seed=900+i,eff=[('spikes',c,k)]))
for i,(c,k) in enumerate([('gx',2),('gz',5),('az',5)]):
    recs.append(dict(name=f'ooc_slowtelegraph_k{k}_{c}',win=(i*3+2)%8,seed=950+i,eff=[('slowtelegraph',c,k)]))
full=[dict(name='full_step_k2_gx',seed=990,eff=[('step','gx',2)]),dict(name='full_sinusoid_k2_gz',seed=991,eff=[('sinusoid','gz',2)]),
      dict(name='full_ooc_telegraph_k2_gx',seed=992,eff=[('telegraph','gx',2)])]
def diag_full(csv,js):
    cmd=[run_all.SS,'diagnose',csv,'--model',W+'/run1-auto.yaml','--rate','100','--gyro-unit','deg/s','--accel-unit','g',
         '--threads','1','--realisations','32','--json',js,'--add','found','-o',js.replace('.json','.improved.yaml')]
    t=time.time(); r=subprocess.run(cmd,capture_output=True,text=True); return r.returncode,time.time()-t,r.stdout+r.stderr
if __name__=='__main__':
    for r in recs+full:
        js=f'{W}/results/{r["name"]}.json'
        if os.path.exists(js.replace('.json','.meta.json')): continue
        csv=f'{W}/recs/{r["name"]}.csv'
        if r['name'].startswith('full'):
            info=inject.make(csv,-1,r['eff'],r['seed'],full=True); info['win']='full'; rc,dt,out=diag_full(csv,js)
        else:
            info=inject.make(csv,r['win'],r['eff'],r['seed']); rc,dt,out=run_all.diag(csv,js)
        os.remove(csv)
        json.dump(dict(rec=r,info=info,rc=rc,secs=dt,out=out),open(js.replace('.json','.meta.json'),'w'))
        print(r['name'],rc,round(dt,1),flush=True)
