#!/bin/sh
# fit --criterion paper --denoise db5: denoised T_c is huge -> paper order enormous -> runs for minutes
cd "${WORK:-.}"
/usr/bin/time -f "%e s wall, rc" timeout -k 10 -s INT 20 ${SINSIM:-sinsim} fit syn.csv --rate 100 --axes gx --kind ar --criterion paper --denoise db5 --threads 1 -q -o syn_paper_db5.yaml
echo "rc=$?"; ls syn_paper_db5.yaml* 2>&1
