"""Compare the tables in report.html with summary.json (drift table, paired table, budget table). usage: check_html.py OUTDIR"""
import re, html, sys, json
d = sys.argv[1]; js = json.load(open(f'{d}/summary.json')); s = open(f'{d}/report.html').read()
U = {'µm':1e-6,'mm':1e-3,'m':1,'km':1e3}
def val(x):
    x = x.strip().replace('−','-')
    m = re.fullmatch(r'(-?[\d.]+(?:e[-+]?\d+)?)\s*(µm|mm|km|m)?', x)
    if not m: return None
    return float(m.group(1))*U.get(m.group(2) or '', 1)
def tsec(x):
    m = re.fullmatch(r'([\d.]+)\s*(s|min|h)', x.strip()); return float(m.group(1))*{'s':1,'min':60,'h':3600}[m.group(2)]
rows = [[html.unescape(re.sub('<[^>]+>','',c)).strip() for c in re.findall(r'<t[dh][^>]*>(.*?)</t[dh]>', r, flags=re.S)] for r in re.findall(r'<tr.*?</tr>', s, flags=re.S)]
models = {m['label']: m for m in js['models']}
bad = 0; n = 0
def chk(what, shown, exp, digits=4):
    global bad, n; n += 1
    v = val(shown)
    if v is None: print('UNPARSED', what, shown); bad += 1; return
    tol = 0.5*10**(-(digits-1))*max(abs(exp),1e-300)*1.01 + 1e-12
    # shown has ~digits significant digits
    if abs(v-exp) > max(tol, 0.51*10**(len(str(abs(val(shown.split()[0])) if False else 0))-99)) and abs(v-exp) > abs(exp)*2e-3:
        print(f'MISMATCH {what}: shown {shown!r} json {exp:.6g}'); bad += 1
for r in rows:
    if len(r) == 8 and r[0] in models:
        t = tsec(r[1]); a = [x for x in models[r[0]]['at'] if abs(x['t_s']-t) < 1e-6]
        if not a: print('no json entry', r); bad += 1; continue
        a = a[0]
        for k,(col,exp) in enumerate([('CEP',a['cep_m']),('R95',a['r95_m']),('99%',a['horizontal_m']['p99']),('RMS',a['horizontal_m']['rms']),('vert95',a['vertical_m']['p95']),('velRMS',a['velocity_mps']['rms'])]):
            chk(f'{r[0]} {r[1]} {col}', r[2+k], exp)
    if len(r) == 10 and r[0] in models and r[1] in models:
        t = tsec(r[2]); c = [c for c in js['comparisons'] if c['a']==r[0] and c['b']==r[1]][0]
        a = [x for x in c['at'] if abs(x['t_s']-t) < 1e-6][0]
        lo, hi = r[6].strip('[]').split(',')
        for col, shown, exp in [('mean a', r[3], a['mean_a_m']), ('mean b', r[4], a['mean_b_m']), ('diff', r[5], a['mean_difference_m']), ('ci lo', lo, a['ci95_difference_m'][0]), ('ci hi', hi, a['ci95_difference_m'][1]), ('t', r[7], a['t']), ('p_t', r[8], a['p_t']), ('p_w', r[9], a['p_wilcoxon'])]:
            chk(f'{r[0]}-{r[1]} {r[2]} {col}', shown, exp, 1 if col.startswith('p') else 3)
print(f'{n} numbers compared, {bad} problems')
