#!/usr/bin/python3
"""Second batch of small odd formats (rec2/), from rec/ref.csv text."""
import re
L = open('rec/ref.csv').read().split('\n')[:-1]
H, D = L[0], L[1:]
def w(name, txt): open('rec2/' + name, 'w', newline='').write(txt)
w('cr_small.csv', '\r'.join(L[:2001]) + '\r')
w('comma_space.csv', '\n'.join(l.replace(',', ', ') for l in L) + '\n')
w('trail_ws.csv', '\n'.join(l + '  ' for l in L) + '\n')
w('lead_ws_comma.csv', '\n'.join('  ' + l for l in L) + '\n')
w('tab_trailing.csv', '\n'.join(l.replace(',', '\t') + '\t' for l in L) + '\n')
w('time_name.csv', '\n'.join(['time' + H[1:]] + D) + '\n')
w('Time_cap.csv', '\n'.join(['Time' + H[1:]] + D) + '\n')
w('timestamp_name.csv', '\n'.join(['timestamp' + H[1:]] + D) + '\n')
w('upper_names.csv', '\n'.join([H.upper()] + D) + '\n')
w('comment_pct.csv', '% exported by logger\n' + '\n'.join(L) + '\n')
w('comment_slash.csv', '// exported by logger\n' + '\n'.join(L) + '\n')
w('meta_lines.csv', 'Device: XYZ-IMU\nSerial: 1234\n' + '\n'.join(L) + '\n')
w('comment_after_header.csv', '\n'.join([H, '# units: s, deg/s, g'] + D) + '\n')
w('comment_end.csv', '\n'.join(L) + '\n# end of log\n')
w('ws_line_end.csv', '\n'.join(L) + '\n   \n')
w('units_row.csv', '\n'.join([H, 's,deg/s,deg/s,deg/s,g,g,g'] + D) + '\n')
w('dup_header_name.csv', '\n'.join(['t,gx,gx,gz,ax,ay,az'] + D) + '\n')
w('crlf_blank_end.csv', '\r\n'.join(L) + '\r\n\r\n')
w('semicolon_trailing_comma_dec.csv', '\n'.join(l.replace(',', ';') for l in L) + '\n')
w('mixed_tab_space.csv', '\n'.join(l.replace(',', ' \t ') for l in L) + '\n')
w('nul.csv', '\n'.join(L[:100]) + '\n\x00\x00\n')
w('temp_col.csv', '\n'.join([H + ',temp'] + [d + ',25.5' for d in D]) + '\n')
w('temp_F.csv', '\n'.join([H + ',temp[degF]'] + [d + ',77' for d in D]) + '\n')
w('latin1_hdr.csv', '')
open('rec2/latin1_hdr.csv', 'wb').write(('\n'.join([H + ',temp\xe9rature'] + [d + ',1' for d in D]) + '\n').encode('latin-1'))
w('utf16.csv', '')
open('rec2/utf16.csv', 'wb').write(('\n'.join(L[:1000]) + '\n').encode('utf-16'))
# 400 Hz stamps rounded to ms
import numpy as np
n = 40000; t = np.arange(n) / 400.0
rows = D[:n] if len(D) >= n else None
w('r400_ms.csv', '\n'.join(['t,gx,gy,gz,ax,ay,az'] + ['%.3f,%s' % (t[i], D[i].split(',', 1)[1]) for i in range(n)]) + '\n')
w('r400_exact.csv', '\n'.join(['t,gx,gy,gz,ax,ay,az'] + ['%.7f,%s' % (t[i], D[i].split(',', 1)[1]) for i in range(n)]) + '\n')
