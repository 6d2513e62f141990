# concurrency (threads calling run/analyze/synth at once), huge noise through run/mc, budget parity, KeyboardInterrupt in diagnose
import sinsim, numpy as np, threading, os, subprocess, filecmp, warnings, time, signal
warnings.simplefilter("ignore"); os.chdir("/tmp/probe_58")
M = "scenarios/grade-tactical.yaml"; SC = "scenarios/static.yaml"
ref = sinsim.run(SC, model=M, seed=5)["horizontal"]
res, errs = {}, []
def work(i):
    try:
        res[i] = sinsim.run(SC, model=M, seed=5)["horizontal"]
        sinsim.synth(M, 100, 30, f"out/thr_{i}.csv", seed=i)
        sinsim.analyze(f"out/thr_{i}.csv")
    except Exception as e: errs.append(repr(e))
ts = [threading.Thread(target=work, args=(i,)) for i in range(6)]; [t.start() for t in ts]; [t.join() for t in ts]
print("6 concurrent threads: errors", errs, "| all run results identical to serial:", all(np.array_equal(ref, v) for v in res.values()))
for dens in ["1e11 rad/s/sqrt(Hz)", "1e5 deg/sqrt(h)"]:
    d = {"gyro": {"all": [{"type": "white", "density": dens}]}}
    for fn in ["run", "mc"]:
        try:
            r = sinsim.run(SC, model=d, seed=1) if fn == "run" else sinsim.mc(SC, models=[d], runs=2)
            print(f"huge {dens} {fn}: ok", r["summary"]["line"] if fn == "run" else r["headline"])
        except Exception as e: print(f"huge {dens} {fn}: {type(e).__name__}: {str(e)[:200]}")
b = sinsim.mc(SC, models=[M], runs=4, seed=3, budget=True, output="out/pybudget")
p = subprocess.run(["/tmp/probe_bin58/sinsim", "mc", SC, "--model", M, "--runs", "4", "--seed", "3", "--budget", "-o", "out/clibudget", "--no-progress"], capture_output=True, text=True)
print("budget labels:", b["labels"])
for f in sorted(os.listdir("out/clibudget")):
    if os.path.isfile(f"out/clibudget/{f}"): print("  ", f, "identical" if filecmp.cmp(f"out/clibudget/{f}", f"out/pybudget/{f}", shallow=False) else "DIFFERENT")
