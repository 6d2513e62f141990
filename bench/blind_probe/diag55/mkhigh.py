#!/usr/bin/python3
"""mkhigh.py IN.model.yaml OUT.yaml FACTOR: multiply every white density by FACTOR (a model too high, e.g. a datasheet's conservative noise)"""
import re,sys
s=open(sys.argv[1]).read(); f=float(sys.argv[3])
s=re.sub(r'density: ([0-9.e-]+) ', lambda m: 'density: %.9g '%(float(m.group(1))*f), s)
open(sys.argv[2],'w').write(s)
