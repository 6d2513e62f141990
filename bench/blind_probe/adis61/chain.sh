#!/bin/sh
# wait for run_all.py (pid in run_all.pid), then the second batch
while kill -0 $(cat /tmp/probe_28/work/run_all.pid) 2>/dev/null; do sleep 5; done
/usr/bin/python3 /tmp/probe_28/work/run_more.py > /tmp/probe_28/work/run_more.log 2>&1
