"""Per-state consistency of an aided filter over many `sinsim run`s (bench/outage_nees/run.sh):
for every epoch class (aiding; outage, and outage split in 10-s phases from its start) the
run-averaged NEES (filter.csv `nees`, full 9 x 9 covariance) and, per state, the mean of
e_i^2 / sigma_i^2 (1 when the state's own variance is right). The sum of the nine per-state means
is the NEES a diagonal covariance would give: when the NEES exceeds it, the excess comes through
the covariance's correlations. The first 60 s (alignment of the filter) are left out.

    python3 bench/outage_nees/components.py DIR     (DIR/s*/filter.csv)
"""
import csv
import glob
import sys

NAMES = ["N", "E", "D", "vN", "vE", "vD", "psiN", "psiE", "psiD"]


def main(d):
    files = sorted(glob.glob(f"{d}/s*/filter.csv"))
    acc = {}
    for fn in files:
        with open(fn) as f:
            rows = csv.reader(f)
            next(rows)
            start = None
            for row in rows:
                t = float(row[0])
                if t < 60:
                    continue
                outage = row[23] == "1"
                classes = ["aiding"]
                if outage:
                    start = t if start is None else start
                    classes = ["outage", f"outage {int(t - start) // 10 * 10:2d}-{int(t - start) // 10 * 10 + 10} s"]
                else:
                    start = None
                e = [float(x) for x in row[1:10]]
                s = [float(x) for x in row[10:19]]
                for c in classes:
                    a = acc.setdefault(c, [[0.0] * 9, 0, 0.0])
                    for i in range(9):
                        a[0][i] += (e[i] / s[i]) ** 2
                    a[1] += 1
                    a[2] += float(row[19])
    print(f"{d}: {len(files)} runs")
    print("class            epochs   NEES  diag-sum  " + " ".join(f"{n:>5s}" for n in NAMES))
    for c in sorted(acc):
        z, k, nees = acc[c]
        print(f"{c:15s} {k:7d} {nees / k:6.2f} {sum(z) / k:8.2f}  " + " ".join(f"{v / k:5.2f}" for v in z))


if __name__ == "__main__":
    main(sys.argv[1])
