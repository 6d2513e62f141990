#!/bin/sh
# wait for chain.sh (second batch), then the third
while kill -0 $(cat /tmp/probe_28/work/chain.pid) 2>/dev/null; do sleep 5; done
/usr/bin/python3 /tmp/probe_28/work/run_third.py > /tmp/probe_28/work/run_third.log 2>&1
