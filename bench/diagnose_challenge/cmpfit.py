#!/usr/bin/python3
"""cmpfit.py WORK OLD_BINARY: refit each kept fitted-null record (same and next modes) with the old
binary, as fitted_null.py did with the new one, and count the models whose written lines differ.

  fitted_null.py --generator alt --records 20 --seed 3 --jobs 2 --keep --work /tmp/fn_alt --sinsim NEW
  cmpfit.py /tmp/fn_alt OLD

A fit rule's regression check: which written models it changes (comments are not compared)."""
import sys, glob, subprocess, os
work, old = sys.argv[1], sys.argv[2]
changed = total = 0
for csv in sorted(glob.glob(os.path.join(work, "r*.csv"))):
    with open(csv) as f:
        f.readline(); t0 = float(f.readline().split(",")[0]); t1 = float(f.readline().split(",")[0])
        n = 2 + sum(1 for _ in f)
    rate = 1.0 / (t1 - t0)
    for mode in ("same", "next"):
        new = csv[:-4] + "." + mode + ".fit.yaml"
        if not os.path.exists(new): continue
        opts = [] if mode == "same" else ["--duration", f"{0.5 * n / rate:.6f} s"]
        out = "/tmp/cmpfit_old.yaml"
        subprocess.run([old, "fit", csv, "--kind", "auto", "-q", "-o", out] + opts, capture_output=True, check=True)
        strip = lambda p: [l for l in open(p) if not l.lstrip().startswith("#")]
        a, b = strip(new), strip(out)
        total += 1
        if a != b:
            changed += 1
            print(os.path.basename(new), "differs:", [l.strip() for l in b if l not in a][:3], "->", [l.strip() for l in a if l not in b][:3])
print(f"{changed}/{total} model files changed")
