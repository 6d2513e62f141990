#!/bin/sh
# MDL selects order 0 but an AR(1) is written (file says both)
cd "${WORK:-.}"
${SINSIM:-sinsim} fit syn.csv --rate 100 --axes gx --kind ar --threads 1 -q -o white_ar.yaml 2>/dev/null
grep -E "AR\(|selected|type: ar" white_ar.yaml
