# Does Ctrl-C stop sinsim.synth / sinsim.fit early, or only after completion? (timed back to back)
import sinsim, os, signal, threading, time, warnings
warnings.simplefilter("ignore"); os.chdir("/tmp/probe_58")
for f in ["out/s_int.csv"]:
    if os.path.exists(f): os.remove(f)
def timed(fn, interrupt):
    if interrupt: threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    t0 = time.time()
    try: fn(); r = "completed"
    except KeyboardInterrupt: r = "KeyboardInterrupt"
    return f"{r} after {time.time()-t0:.2f} s"
print("synth interrupted at 1 s:", timed(lambda: sinsim.synth("scenarios/adis16355-ar5.yaml", 1000, 3600, "out/s_int.csv"), True))
if os.path.exists("out/s_int.csv"):
    n = sum(1 for _ in open("out/s_int.csv")); print("   out/s_int.csv exists with", n, "lines (complete = 3600001)")
print("synth not interrupted:", timed(lambda: sinsim.synth("scenarios/adis16355-ar5.yaml", 1000, 3600, "out/s_full.csv"), False))
rec = sinsim.load_record("/work/shared/data/adis16405/run1.csv.gz", gyro_unit="deg/s", accel_unit="g", rate=100)
print("fit gm interrupted at 1 s:", timed(lambda: sinsim.fit(rec, kind="gm", axes=["gx","gy","gz"]), True))
print("fit gm not interrupted:", timed(lambda: sinsim.fit(rec, kind="gm", axes=["gx","gy","gz"]), False))
