# KeyboardInterrupt during a long sinsim.mc: time to stop, exception type, leftovers, interpreter still usable.
import sinsim, os, signal, threading, time, tempfile, glob, sys
os.chdir("/tmp/probe_58")
out = sys.argv[1] if len(sys.argv) > 1 else ""
before = set(glob.glob(tempfile.gettempdir() + "/*"))
threading.Timer(3.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
t0 = time.time()
try:
    sinsim.mc("scenarios/car.yaml", models=["scenarios/adis16355-ar5.yaml"], runs=3000, seed=1, threads=2, output=out)
    print("mc finished without interrupt?!", time.time() - t0)
except KeyboardInterrupt as e:
    print(f"KeyboardInterrupt after {time.time()-t0:.2f} s (signal at 3.0 s): {e!r}")
except BaseException as e:
    print(f"other {type(e).__name__} after {time.time()-t0:.2f}: {e}")
time.sleep(0.5)
new = set(glob.glob(tempfile.gettempdir() + "/*")) - before
print("new entries in", tempfile.gettempdir(), ":", sorted(new))
if out: print("output folder:", sorted(os.listdir(out)) if os.path.isdir(out) else "absent")
print("threads alive:", threading.active_count())
t0 = time.time()
b = sinsim.mc("scenarios/static.yaml", models=["scenarios/grade-tactical.yaml"], runs=4, seed=2)
print(f"after interrupt, a new mc works: {b['headline']} in {time.time()-t0:.2f} s")
