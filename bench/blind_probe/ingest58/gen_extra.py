#!/usr/bin/python3
"""gz oddities appended to variants.json"""
import json, shutil, os
V = json.load(open('variants.json'))
U = ['--gyro-unit', 'deg/s', '--accel-unit', 'g']
d = open('rec/gz.csv.gz', 'rb').read()
open('rec/gz_trunc.csv.gz', 'wb').write(d[:len(d) // 2]); V.append(dict(name='gz_trunc', file='rec/gz_trunc.csv.gz', args=U, expect='refuse', note=''))
open('rec/gz_trunc_tail.csv.gz', 'wb').write(d[:-4]); V.append(dict(name='gz_trunc_tail', file='rec/gz_trunc_tail.csv.gz', args=U, expect='refuse', note='only crc/isize cut'))
shutil.copy('rec/gz.csv.gz', 'rec/gz_named_csv.csv'); V.append(dict(name='gz_named_csv', file='rec/gz_named_csv.csv', args=U, expect='same_or_refuse', note='gzip content, .csv name'))
shutil.copy('rec/ref.csv', 'rec/plain_named_gz.csv.gz'); V.append(dict(name='plain_named_gz', file='rec/plain_named_gz.csv.gz', args=U, expect='same_or_refuse', note='plain content, .gz name'))
shutil.copy('rec/ref.csv', 'rec/ext_txt.txt'); V.append(dict(name='ext_txt', file='rec/ext_txt.txt', args=U, expect='same', note=''))
open('rec/gz_concat.csv.gz', 'wb').write(d + d); V.append(dict(name='gz_concat', file='rec/gz_concat.csv.gz', args=U, expect='refuse', note='two members: second header line'))
json.dump(V, open('variants.json', 'w'), indent=1)
