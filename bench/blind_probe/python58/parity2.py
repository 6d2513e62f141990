# Python vs CLI with times and bias_window (run and mc), aided scenario run
import sinsim, subprocess, os, filecmp, shutil, warnings
warnings.simplefilter("ignore"); os.chdir("/tmp/probe_58"); B = "/tmp/probe_bin58/sinsim"
O = "out/par2"; shutil.rmtree(O, ignore_errors=True); os.makedirs(O)
M = "scenarios/grade-consumer.yaml"; SC = "scenarios/car.yaml"
def cmpdir(a, b):
    return {f: filecmp.cmp(f"{a}/{f}", f"{b}/{f}", shallow=False) for f in sorted(os.listdir(b)) if os.path.isfile(f"{b}/{f}")}
sinsim.mc(SC, models=[M], runs=5, seed=2, times=["5 min", 900], bias_window="60 s", output=f"{O}/py")
subprocess.run([B, "mc", SC, "--model", M, "--runs", "5", "--seed", "2", "--times", "5 min,900", "--bias-window", "60 s", "-o", f"{O}/cli", "--no-progress"], capture_output=True)
print("mc times+bias_window:", cmpdir(f"{O}/py", f"{O}/cli"))
r = sinsim.run(SC, model=M, seed=2, bias_window=60, output=f"{O}/pyrun")
subprocess.run([B, "run", SC, "--model", M, "--seed", "2", "--bias-window", "60", "-o", f"{O}/clirun"], capture_output=True)
print("run bias_window:", cmpdir(f"{O}/pyrun", f"{O}/clirun"))
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    r = sinsim.run("scenarios/car-10min-aided.yaml", seed=4, output=f"{O}/pyaided")
    pw = [str(x.message) for x in w]
p = subprocess.run([B, "run", "scenarios/car-10min-aided.yaml", "--seed", "4", "-o", f"{O}/cliaided"], capture_output=True, text=True)
print("aided run:", cmpdir(f"{O}/pyaided", f"{O}/cliaided"))
print("  py warnings:", pw, "| summary warnings:", r["summary"].get("warnings"))
print("  cli stderr:", p.stderr.strip()[:300])
print("  outages py:", [(o["start"], o["end"], round(o["max_horizontal"], 3), round(o["filter_sigma_horizontal"], 3)) for o in r["summary"]["outages"]])
print("  cli:", p.stdout.strip()[-400:])
