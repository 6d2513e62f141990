"""The table the aided examples print (examples/scale-factor, examples/known-errors): per cell, an
`mc` output folder OUT/CELL, the run-averaged NEES's epochs inside its 99 % band while aided and in
outages (with the mean), and each outage's largest horizontal error (median / 95 %) beside the
filter's 1-sigma then (median), from summary.json's "aided".

    python3 examples/aided_cells.py OUT CELL [CELL ...]
"""
import json
import sys


def main(out, cells):
    print("| cell | NEES inside, aiding / outage (mean) | outage max horizontal p50 / p95 (sigma p50) [m] |")
    print("|---|---|---|")
    for cell in cells:
        with open(f"{out}/{cell}/summary.json") as f:
            m = json.load(f)["aided"]["models"][0]
        n = m["nees"]
        nees = " / ".join(f"{n[c]['inside_99']}/{n[c]['epochs']} ({n[c]['mean_of_run_averages']:.2f})"
                          for c in ("aiding", "outage"))
        drift = "; ".join(f"{o['max_horizontal_m']['p50']:.1f} / {o['max_horizontal_m']['p95']:.1f} "
                          f"({o['sigma_horizontal_m']['p50']:.1f})" for o in m["outages"])
        print(f"| {cell} | {nees} | {drift} |")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
