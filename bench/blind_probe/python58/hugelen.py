# a record dict of 4e8 values as a zero-memory broadcast view: refused quickly, or copied first?
import sinsim, numpy as np, time
x = np.broadcast_to(np.float64(1.0), (400_000_000,)); t = time.time()
try: sinsim.analyze({'rate': 100, 'gx': x})
except Exception as e: print(type(e).__name__, str(e)[:200])
print(f"{time.time()-t:.1f} s")
