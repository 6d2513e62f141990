# sinsim.analyze on an N-sample dict channel (random values): under an address-space limit, MemoryError or abort?
import sinsim, numpy as np, sys, time, warnings
warnings.simplefilter("ignore")
n = int(float(sys.argv[1])); x = np.random.default_rng(0).standard_normal(n) * 1e-3
t = time.time()
try: a = sinsim.analyze({'rate': 1000, 'gx': x}); print("completed")
except BaseException as e: print(type(e).__name__, str(e)[:200])
print(f"{time.time()-t:.1f} s")
