#!/usr/bin/python3
"""Score results/*.json against the clean-window baselines results/null_wK.json."""
import json, glob, os, collections, gzip
_open=open
def open(p,*a):
    return gzip.open(p+'.gz','rt') if p.endswith('.json') and not p.endswith('meta.json') and not os.path.exists(p) else _open(p,*a)
W='/tmp/probe_28/work/results'
EQ={'step':{'bias_jumps'},'ramp':{'ramp'},'warmup':{'warmup'},'sinusoid':{'sinusoid'},'random_walk':{'random_walk'},
    'gauss_markov':{'gauss_markov'},'outliers':{'outliers'},
    'telegraph':{'gauss_markov','bias_jumps','unexplained'},'chirp':{'sinusoid','gauss_markov','unexplained'},
    'burst':{'outliers','unexplained'},'spikes':{'outliers'},'slowtelegraph':{'gauss_markov','bias_jumps','unexplained'}}
def rep(a): return [f['effect'] for f in a['findings'] if f['reported']]
def unexp(a): return bool(a.get('unexplained') or a.get('unexplained_steps') or a.get('noise_level_change'))
base={}
for w in range(8):
    d=json.load(open(f'{W}/null_w{w}.json')); base[w]={a['channel']:a for a in d['axes']}
base['full']={a['channel']:a for a in json.load(open('/tmp/probe_28/work/null_run2_full.json'))['axes']}
rows=[]; S=collections.defaultdict(lambda:[0,0])
for mf in sorted(glob.glob(W+'/*.meta.json')):
    if os.path.basename(mf).startswith('null'): continue
    m=json.load(open(mf)); js=mf.replace('.meta.json','.json')
    if m['rc']!=0 or not os.path.exists(js+'.gz'): rows.append((m['rec']['name'],'CRASH rc=%d'%m['rc'])); continue
    d=json.load(open(js)); ax={a['channel']:a for a in d['axes']}; w=m['info']['win']
    effs=m['info']['effects']; ch=effs[0]['channel']; B=rep(base[w][ch]); R=rep(ax[ch])
    new=[e for e in R if e not in B] + ([R[0]] if R and B and R[0]!=B[0] and R[0] in B else [])
    bs={f['effect']:f['score'] for f in base[w][ch]['findings'] if f['reported']}
    rs={f['effect']:f['score'] for f in ax[ch]['findings'] if f['reported']}
    # credited: a finding the clean window lacks, one that now leads, or one whose score rose >=10 and >=2x
    new=[e for i,e in enumerate(R) if (e not in B) or (i==0 and B and B[0]!=e) or (rs[e]>=bs[e]+10 and rs[e]>=2*bs[e])]
    first=new[0] if new else ('unexplained' if unexp(ax[ch]) else 'nothing')
    kinds=[e['kind'] for e in effs]; k=effs[0]['k']; name=m['rec']['name']
    grp='two' if len(effs)==2 else ('ooc' if kinds[0] in ('telegraph','chirp','burst','slowtelegraph') else ('noround' if name.startswith('noround') else ('full' if name.startswith('full') else ('spikes' if name.startswith('spikes') else 'single'))))
    a=ax[ch]; mb,ma=a.get('misfit_before'),a.get('misfit_after')
    if grp=='two':
        ok1=first in EQ[kinds[0]]|EQ[kinds[1]]; both=all(any(e in EQ[kd] for e in new) for kd in kinds)
        S[f'two k{k:g}: first is one of the two'][0]+=ok1; S[f'two k{k:g}: first is one of the two'][1]+=1
        S[f'two k{k:g}: both named'][0]+=both; S[f'two k{k:g}: both named'][1]+=1
    else:
        ok=first in EQ[kinds[0]]
        S[f'{grp} k{k:g}: right first'][0]+=ok; S[f'{grp} k{k:g}: right first'][1]+=1
        S[f'{grp} {kinds[0]}: right first'][0]+=ok; S[f'{grp} {kinds[0]}: right first'][1]+=1
    if mb is not None and mb>0:
        S['misfit halved after --add found (inj. ch, misfit_before>0)'][0]+= (ma<=0.5*mb); S['misfit halved after --add found (inj. ch, misfit_before>0)'][1]+=1
    alarms=[]
    for c,a2 in ax.items():
        if c==ch: continue
        nb=[e for e in rep(a2) if e not in rep(base[w][c])]
        S['clean channels with a finding the clean window lacks'][1]+=1
        if nb: S['clean channels with a finding the clean window lacks'][0]+=1; alarms.append(c+':'+','.join(nb))
    fs=[f for f in a['findings'] if f['reported']]
    rows.append((name,ch,'w%s'%w,'k=%g'%k,'tau*=%s'%','.join('%g'%e['tau_peak'] for e in effs),'base='+','.join(B),
                 'found='+','.join('%s(%.1f)'%(f['effect'],f['score']) for f in fs),'FIRST_NEW='+first,
                 'U' if unexp(a) else '', 'misfit %.3f->%s'%(mb or 0, '%.3f'%ma if ma is not None else '-'),
                 'alarms='+';'.join(alarms), '%.0fs'%m['secs']))
for r in rows: print(' '.join(map(str,r)))
print()
for k in sorted(S): print('%-60s %d/%d'%(k,S[k][0],S[k][1]))
