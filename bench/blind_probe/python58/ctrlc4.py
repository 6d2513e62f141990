# Ctrl-C latency for sinsim.fit (latent) and sinsim.diagnose, interrupted at 1 s vs uninterrupted, back to back
import sinsim, os, signal, threading, time, warnings
warnings.simplefilter("ignore"); os.chdir("/tmp/probe_58")
def timed(fn, interrupt):
    if interrupt: threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    t0 = time.time()
    try: fn(); r = "completed"
    except KeyboardInterrupt: r = "KeyboardInterrupt"
    return f"{r} after {time.time()-t0:.2f} s"
rec = sinsim.load_record("/work/shared/data/adis16405/run1.csv.gz", gyro_unit="deg/s", accel_unit="g", rate=100)
r = {"rate": 100, "gx": rec["gx"], "gy": rec["gy"]}
for i in range(2):
    print("fit latent gx,gy interrupted:", timed(lambda: sinsim.fit(r, kind="latent"), True))
    print("fit latent gx,gy uninterrupted:", timed(lambda: sinsim.fit(r, kind="latent"), False))
print("diagnose gx interrupted:", timed(lambda: sinsim.diagnose(r, "out/parr/cli_gm.yaml", channels=["gx"]), True))
print("diagnose gx uninterrupted:", timed(lambda: sinsim.diagnose(r, "out/parr/cli_gm.yaml", channels=["gx"]), False))
