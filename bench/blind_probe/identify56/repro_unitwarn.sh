#!/bin/sh
# unit warning suggests --gyro-unit deg/s although it was given (file header also says deg/s)
cd "${WORK:-.}"
${SINSIM:-sinsim} analyze syn_deg.csv --gyro-unit deg/s --json /dev/null 2>&1 >/dev/null | grep "forget"
${SINSIM:-sinsim} analyze syn_deg.csv --gyro-unit deg/s --json r.json 2>&1 >/dev/null | grep "forget"
