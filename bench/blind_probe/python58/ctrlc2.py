# KeyboardInterrupt during other long calls (fit, diagnose, analyze, run, synth): how long until control returns?
import sinsim, os, signal, threading, time, warnings, sys
warnings.simplefilter("ignore"); os.chdir("/tmp/probe_58")
R = "/work/shared/data/adis16405/run1.csv.gz"
rec = sinsim.load_record(R, gyro_unit="deg/s", accel_unit="g", rate=100)
calls = {
 "fit latent 1M x 6": lambda: sinsim.fit(rec, kind="latent"),
 "diagnose 1M x 2, 32 real.": lambda: sinsim.diagnose(rec, "out/parr/cli_gm.yaml", channels=["gx", "ay"]),
 "run car.yaml x1 (short)": lambda: sinsim.run("scenarios/car.yaml", model="scenarios/adis16355-ar5.yaml"),
 "synth 1 kHz 2 h": lambda: sinsim.synth("scenarios/adis16355-ar5.yaml", 1000, 7200, "out/big_synth.csv"),
}
for name, f in calls.items():
    if len(sys.argv) > 1 and sys.argv[1] not in name: continue
    threading.Timer(1.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    t0 = time.time()
    try: f(); print(f"{name}: completed in {time.time()-t0:.2f} s, then ", end="")
    except KeyboardInterrupt: print(f"{name}: KeyboardInterrupt after {time.time()-t0:.2f} s (signal at 1.5 s)"); continue
    except Exception as e: print(f"{name}: {type(e).__name__} {e}"); continue
    try: time.sleep(0.5); print("interrupt delivered later (after the call)")
    except KeyboardInterrupt: print("KeyboardInterrupt raised only after the call returned")
print("big_synth.csv exists:", os.path.exists("out/big_synth.csv"), [f for f in os.listdir("out") if "big_synth" in f])
