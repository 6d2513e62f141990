#!/usr/bin/python3
"""Write the reference record (rec/g.npy, rec/a.npy from gen_ref.py) in many vendor formats.
Writes rec/<name>.<ext> and variants.json: [{name, file, args, expect}]
expect: same (numbers equal to ref), refuse (exit!=0, clear message), warn (numbers same + warning),
        other (just look)."""
import numpy as np, json, gzip, os
g = np.load('rec/g.npy'); a = np.load('rec/a.npy'); N = len(g); rate = 100.0
G0 = 9.80665
V = []
def rows(tcol=None, gf='%.9f', af='%.9f', gs=1.0, as_=1.0, tf='%.2f'):
    out = []
    for i in range(N):
        vals = [gf % (x * gs) for x in g[i]] + [af % (x * as_) for x in a[i]]
        if tcol is not None:
            vals = [tf % tcol[i] if isinstance(tf, str) else tf(tcol[i])] + vals
        out.append(vals)
    return out
def write(name, header, data, sep=',', args=(), expect='same', eol='\n', pre='', post='', ext='csv', last_nl=True, note=''):
    path = 'rec/%s.%s' % (name, ext)
    lines = []
    if header is not None: lines.append(sep.join(header))
    lines += [sep.join(r) for r in data]
    txt = pre + eol.join(lines) + (eol if last_nl else '') + post
    if ext.endswith('gz'):
        with gzip.open(path, 'wt', newline='') as f: f.write(txt)
    else:
        with open(path, 'w', newline='') as f: f.write(txt)
    V.append(dict(name=name, file=path, args=list(args), expect=expect, note=note))
    return path
U = ['--gyro-unit', 'deg/s', '--accel-unit', 'g']
H = ['t', 'gx', 'gy', 'gz', 'ax', 'ay', 'az']
HU = ['t[s]', 'gx[deg/s]', 'gy[deg/s]', 'gz[deg/s]', 'ax[g]', 'ay[g]', 'az[g]']
ts = np.arange(N) / rate
base = rows(ts)
write('ref', H, base, args=U)
# ---- time
write('t_ms_hdr', ['t[ms]'] + H[1:], rows(np.arange(N) * 10, tf='%d'), args=U)
write('t_us_hdr', ['t[us]'] + H[1:], rows(np.arange(N) * 10000, tf='%d'), args=U)
write('t_ns_hdr', ['t[ns]'] + H[1:], rows(np.arange(N) * 10000000, tf='%d'), args=U)
write('t_ms_plain', H, rows(np.arange(N) * 10, tf='%d'), args=U, expect='refuse_or_warn', note='doc: read as 0.1 Hz with warning naming t[ms]')
write('t_us_plain', H, rows(np.arange(N) * 10000, tf='%d'), args=U, expect='refuse')
write('t_ns_plain', H, rows(np.arange(N) * 10000000, tf='%d'), args=U, expect='refuse')
write('t_epoch_s6', H, rows(1.7e9 + 0.123456 + ts, tf='%.6f'), args=U)
write('t_epoch_s3', H, rows(1.7e9 + ts, tf='%.3f'), args=U)
write('t_epoch_s9', H, rows(None, ) and [[('%d.%09d' % (1700000000 + (i // 100), (i % 100) * 10000000 + 123))] + r for i, r in enumerate(rows(None))], args=U)
write('t_epoch_ms', ['t[ms]'] + H[1:], [['%d' % (1700000000123 + i * 10)] + r for i, r in enumerate(rows(None))], args=U)
write('t_epoch_ms_frac', ['t[ms]'] + H[1:], [['%.3f' % (1700000000123 + i * 10 + 0.5)] + r for i, r in enumerate(rows(None))], args=U)
write('t_epoch_us', ['t[us]'] + H[1:], [['%d' % (1700000000123456 + i * 10000)] + r for i, r in enumerate(rows(None))], args=U)
write('t_epoch_ns', ['t[ns]'] + H[1:], [['%d' % (1700000000123456789 + i * 10000000)] + r for i, r in enumerate(rows(None))], args=U)
write('t_offset', H, rows(1234.5 + ts, tf='%.2f'), args=U)
write('t_negative_start', H, rows(-100.0 + ts, tf='%.2f'), args=U)
write('no_time_rate', H[1:], rows(None), args=U + ['--rate', '100'])
write('no_time_norate', H[1:], rows(None), args=U, expect='refuse')
write('t_rate_agree', H, base, args=U + ['--rate', '100'])
write('t_rate_disagree', H, base, args=U + ['--rate', '200'], expect='refuse')
write('t_rate_hz_text', H[1:], rows(None), args=U + ['--rate', '100 Hz'])
write('t_rate_close', H, base, args=U + ['--rate', '100.5'], expect='refuse', note='0.5% off')
# ---- units
write('hdr_units', HU, base)
write('hdr_units_space', ['t [s]', 'gx [deg/s]', 'gy [deg/s]', 'gz [deg/s]', 'ax [g]', 'ay [g]', 'az [g]'], base)
write('hdr_units_paren', ['t (s)', 'gx (deg/s)', 'gy (deg/s)', 'gz (deg/s)', 'ax (g)', 'ay (g)', 'az (g)'], base)
write('hdr_dps', ['t', 'gx[dps]', 'gy[dps]', 'gz[dps]', 'ax[g]', 'ay[g]', 'az[g]'], base, expect='same_or_refuse')
write('hdr_rad', ['t', 'gx[rad/s]', 'gy[rad/s]', 'gz[rad/s]', 'ax[m/s^2]', 'ay[m/s^2]', 'az[m/s^2]'], rows(ts, gf='%.12e', af='%.12e', gs=np.pi / 180, as_=G0), expect='same~')
write('hdr_mss_unicode', ['t', 'gx[rad/s]', 'gy[rad/s]', 'gz[rad/s]', 'ax[m/s²]', 'ay[m/s²]', 'az[m/s²]'], rows(ts, gf='%.12e', af='%.12e', gs=np.pi / 180, as_=G0), expect='same~_or_refuse')
write('hdr_mg_degh', ['t', 'gx[deg/h]', 'gy[deg/h]', 'gz[deg/h]', 'ax[mg]', 'ay[mg]', 'az[mg]'], rows(ts, gf='%.6f', af='%.9f', gs=3600, as_=1000), expect='same~')
write('opt_rad_mss', H, rows(ts, gf='%.12e', af='%.12e', gs=np.pi / 180, as_=G0), args=['--gyro-unit', 'rad/s', '--accel-unit', 'm/s^2'], expect='same~')
write('opt_mg_degh', H, rows(ts, gf='%.6f', af='%.9f', gs=3600, as_=1000), args=['--gyro-unit', 'deg/h', '--accel-unit', 'mg'], expect='same~')
write('opt_dps', H, base, args=['--gyro-unit', 'dps', '--accel-unit', 'g'], expect='same_or_refuse')
write('hdr_opt_agree', HU, base, args=U)
write('hdr_opt_agree_spelling', ['t', 'gx[deg/s]', 'gy[deg/s]', 'gz[deg/s]', 'ax[g]', 'ay[g]', 'az[g]'], base, args=['--gyro-unit', 'degree/s', '--accel-unit', 'g'], expect='same_or_refuse')
write('hdr_opt_disagree_g', HU, base, args=['--gyro-unit', 'rad/s'], expect='refuse')
write('hdr_opt_disagree_a', HU, base, args=['--accel-unit', 'm/s^2'], expect='refuse')
write('hdr_unit_wrongdim', ['t', 'gx[g]', 'gy[g]', 'gz[g]', 'ax[g]', 'ay[g]', 'az[g]'], base, expect='refuse')
write('hdr_unit_bogus', ['t', 'gx[furlong]', 'gy[deg/s]', 'gz[deg/s]', 'ax[g]', 'ay[g]', 'az[g]'], base, expect='refuse')
write('hdr_missing_units_noopt', H, base, expect='warn', note='deg/s read as rad/s: should warn forgot --gyro-unit')
# ---- delimiters and text forms
write('semicolon', H, base, sep=';', args=U)
write('tab', H, base, sep='\t', args=U)
write('spaces_aligned', ['%14s' % h for h in H], [['%14s' % v for v in r] for r in base], sep='  ', args=U)
write('spaces_lead', None, [], args=U, expect='skip')  # placeholder removed below
V.pop()
write('decimal_comma_semicolon', H, [[v.replace('.', ',') for v in r] for r in base], sep=';', args=U, expect='refuse')
write('decimal_comma_semicolon_delim', H, [[v.replace('.', ',') for v in r] for r in base], sep=';', args=U + ['--delimiter', 'semicolon'], expect='refuse')
write('quoted_header', ['"%s"' % h for h in H], base, args=U)
write('quoted_all', ['"%s"' % h for h in H], [['"%s"' % v for v in r] for r in base], args=U, expect='same_or_refuse')
write('crlf', H, base, eol='\r\n', args=U)
write('cr_only', H, base, eol='\r', args=U, expect='refuse')
write('bom', H, base, pre='\ufeff', args=U)
write('bom_crlf_semicolon', H, base, sep=';', eol='\r\n', pre='\ufeff', args=U)
write('trailing_delim', [h for h in H] + [''], [r + [''] for r in base], args=U)
write('trailing_delim_semicolon', H + [''], [r + [''] for r in base], sep=';', args=U)
write('comments_top', H, base, pre='# logger v1.2\n# rate 100 Hz\n#\n', args=U)
write('comments_top_crlf', H, base, pre='# logger v1.2\r\n# rate 100 Hz\r\n', eol='\r\n', args=U)
write('blank_lines_end', H, base, post='\n\n', args=U, expect='same_or_refuse')
write('blank_line_after_header', H, base, pre='', args=U, expect='same_or_refuse')
# fix: blank after header -> rewrite manually
with open('rec/blank_line_after_header.csv') as f: L = f.read().split('\n', 1)
open('rec/blank_line_after_header.csv', 'w').write(L[0] + '\n\n' + L[1])
write('blank_line_middle', H, base[:30000] + [[]] + base[30000:], args=U, expect='refuse')
write('no_final_newline', H, base, last_nl=False, args=U)
write('comment_line_middle', H, base[:30000] + [['# resync']] + base[30000:], args=U, expect='refuse', note='# line inside data')
# extra columns
cnt = np.arange(N)
ex = [['%d' % cnt[i], r[0], 'OK', r[1], r[2], r[3], '0x%02x' % (i % 256), r[4], r[5], r[6], '%.4f' % (0.2 + 1e-4 * i % 0.01), '%.4f' % -0.1, '%.4f' % 0.4, '%.2f' % 25.0] for i, r in enumerate(base)]
EH = ['counter', 't', 'status', 'gx', 'gy', 'gz', 'flags', 'ax', 'ay', 'az', 'mx', 'my', 'mz', 'temp']
write('extra_cols', EH, ex, args=U, expect='same', note='text status/flag columns')
exn = [['%d' % cnt[i], r[0], '1', r[1], r[2], r[3], '%d' % (i % 256), r[4], r[5], r[6], '%.4f' % 0.2, '%.4f' % -0.1, '%.4f' % 0.4, '%.2f' % 25.0] for i, r in enumerate(base)]
write('extra_cols_numeric', EH, exn, args=U)
perm = [6, 3, 0, 5, 1, 4, 2]
write('shuffled', [H[p] for p in perm], [[r[p] for p in perm] for r in base], args=U)
VH = ['Time[ms]', 'GyroX[deg/s]', 'GyroY[deg/s]', 'GyroZ[deg/s]', 'AccX[g]', 'AccY[g]', 'AccZ[g]']
vrows = rows(np.arange(N) * 10, tf='%d')
write('vendor_names_nomap', VH, vrows, expect='refuse')
write('vendor_names_map', VH, vrows, args=['--columns', 't=Time[ms],gx=GyroX[deg/s],gy=GyroY[deg/s],gz=GyroZ[deg/s],ax=AccX[g],ay=AccY[g],az=AccZ[g]'])
write('vendor_names_map_nounit', VH, vrows, args=['--columns', 't=Time,gx=GyroX,gy=GyroY,gz=GyroZ,ax=AccX,ay=AccY,az=AccZ'], note='units from header')
write('vendor_names_map_disagree', VH, vrows, args=['--columns', 't=Time[s],gx=GyroX,gy=GyroY,gz=GyroZ,ax=AccX,ay=AccY,az=AccZ'], expect='refuse')
write('vendor_map_case', VH, vrows, args=['--columns', 't=time,gx=gyrox,gy=gyroy,gz=gyroz,ax=accx,ay=accy,az=accz'])
write('map_by_number_headered', H, base, args=U + ['--columns', 't=1,gx=2,gy=3,gz=4,ax=5,ay=6,az=7'], expect='same_or_refuse', note='doc: all numbers => no header; header line then is data?')
write('headerless_map', None, base, args=U + ['--columns', 't=1,gx=2,gy=3,gz=4,ax=5,ay=6,az=7'])
write('headerless_map_units', None, base, args=['--columns', 't=1[s],gx=2[deg/s],gy=3[deg/s],gz=4[deg/s],ax=5[g],ay=6[g],az=7[g]'])
write('headerless_map_rate', None, rows(None), args=U + ['--rate', '100', '--columns', 'gx=1,gy=2,gz=3,ax=4,ay=5,az=6'])
write('headerless_nomap', None, base, args=U, expect='refuse')
write('headerless_shuffled_map', None, [[r[p] for p in perm] for r in base], args=U + ['--columns', 't=3,gx=5,gy=2,gz=7,ax=6,ay=4,az=1'])
write('map_col_out_of_range', None, base, args=U + ['--columns', 't=1,gx=2,gy=3,gz=4,ax=5,ay=6,az=9'], expect='refuse')
write('map_missing_name', H, base, args=U + ['--columns', 'gx=GyroX'], expect='refuse')
write('map_dup_column', H, base, args=U + ['--columns', 'gx=gx,gy=gx'], expect='refuse')
# gz
write('gz', H, base, args=U, ext='csv.gz')
write('gz_crlf_bom', H, base, args=U, ext='csv.gz', eol='\r\n', pre='\ufeff')
# values
sci = rows(ts, gf='%.9e', af='%.9e')
write('sci', H, sci, args=U)
write('sci_upper', H, [[v.upper() for v in r] for r in sci], args=U)
for bad in ['nan', 'NaN', 'inf', '-inf', '', ' ', '1e400', '1e300', 'abc', '0x10', '1.2.3', '--1']:
    b2 = [list(r) for r in base]; b2[4321][3] = bad
    nm = 'bad_%s' % {'': 'empty', ' ': 'space', '-inf': 'minf'}.get(bad, bad.replace('.', '_'))
    write(nm, H, b2, args=U, expect='refuse', note='row 4321 data (line 4323), col 4 gz')
b2 = [list(r) for r in base]; b2[100][0] = ''
write('bad_empty_time', H, b2, args=U, expect='refuse')
b2 = [list(r) for r in base]; b2[100] = b2[100][:5]
write('short_row', H, b2, args=U, expect='refuse')
b2 = [list(r) for r in base]; b2[100] = b2[100] + ['1.0']
write('long_row', H, b2, args=U, expect='refuse')
write('plus_sign', H, [[('+' + v) if not v.startswith('-') else v for v in r] for r in base], args=U)
write('leading_dot', H, [[v.replace('0.', '.', 1) if v.startswith('0.') else (v.replace('-0.', '-.', 1) if v.startswith('-0.') else v) for v in r] for r in base], args=U)
write('huge_all', H, rows(ts, gs=1e300), args=U, expect='refuse')
# integer counts with scale (LSB 1e-4 deg/s, 1e-6 g)
gq = np.round(g / 1e-4).astype(np.int64); aq = np.round(a / 1e-6).astype(np.int64)
qrows = [['%.2f' % ts[i]] + ['%d' % x for x in gq[i]] + ['%d' % x for x in aq[i]] for i in range(N)]
qref = [['%.2f' % ts[i]] + ['%.4f' % (x * 1e-4) for x in gq[i]] + ['%.6f' % (x * 1e-6) for x in aq[i]] for i in range(N)]
write('q_ref', H, qref, args=U, note='reference for counts')
write('q_counts_hdr', ['t', 'gx[0.0001 deg/s]', 'gy[0.0001 deg/s]', 'gz[0.0001 deg/s]', 'ax[ug]', 'ay[ug]', 'az[ug]'], qrows, expect='same_q_or_refuse')
write('q_counts_opt', H, qrows, args=['--gyro-unit', '1e-4 deg/s', '--accel-unit', 'ug'], expect='same_q_or_refuse')
write('q_counts_map', H, qrows, args=['--columns', 't=t,gx=gx[0.0001 deg/s],gy=gy[0.0001 deg/s],gz=gz[0.0001 deg/s],ax=ax[ug],ay=ay[ug],az=az[ug]'], expect='same_q_or_refuse')
# time problems
def trow(tt, tf='%.6f'): return [[tf % tt[i]] + r for i, r in enumerate(rows(None))]
tt = ts.copy(); tt[5000] = tt[4999]
write('t_dup', H, trow(tt, '%.2f'), args=U, expect='refuse')
write('t_dup_allow', H, trow(tt, '%.2f'), args=U + ['--allow-irregular-time'], expect='refuse_or_warn')
tt = ts.copy(); tt[5000], tt[5001] = tt[5001], tt[5000]
write('t_nonmono', H, trow(tt, '%.2f'), args=U, expect='refuse')
write('t_nonmono_allow', H, trow(tt, '%.2f'), args=U + ['--allow-irregular-time'], expect='refuse')
keep = np.ones(N, bool); keep[20000:20005] = False
gap_t = ts[keep]; gap_rows = [['%.2f' % ts[i]] + r for i, r in enumerate(rows(None)) if keep[i]]
write('t_gap', H, gap_rows, args=U, expect='refuse')
write('t_gap_allow', H, gap_rows, args=U + ['--allow-irregular-time'], expect='warn')
rng = np.random.default_rng(7)
for jp in [0.1, 0.4, 1.0, 3.0]:
    tt = ts + rng.uniform(-jp / 100, jp / 100, N) / rate
    write('t_jitter%g' % jp, H, trow(tt), args=U, expect='same_or_refuse')
    write('t_jitter%g_allow' % jp, H, trow(tt), args=U + ['--allow-irregular-time'], expect='warn')
tt = ts + rng.uniform(-0.01, 0.01, N) / rate + 1.7e9
write('t_jitter1_epoch_allow', H, trow(tt, '%.6f'), args=U + ['--allow-irregular-time'], expect='warn')
# one row / tiny
write('empty', None, [], args=U, expect='refuse', last_nl=False)
write('header_only', H, [], args=U, expect='refuse')
write('one_row', H, base[:1], args=U, expect='refuse')
write('two_rows', H, base[:2], args=U, expect='refuse')
write('three_rows', H, base[:3], args=U, expect='refuse')
write('ten_rows', H, base[:10], args=U, expect='other')
write('empty_gz', None, [], args=U, expect='refuse', last_nl=False, ext='csv.gz')
json.dump(V, open('variants.json', 'w'), indent=1)
print(len(V), 'variants')
