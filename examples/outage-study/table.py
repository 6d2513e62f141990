"""The outage study's table (examples/outage-study/run.sh) from each cell's mc outputs.

Per cell: the maximum horizontal error inside the outages of each length (median and 95 % over
runs x outages, from outages.csv), the median of the filter's horizontal sigma at that moment, and
the NEES consistency from summary.json's "aided" block: the share of epochs whose run-averaged
NEES lies inside its two-sided 99 % chi-square band, aiding and outage epochs apart.

    python3 examples/outage-study/table.py OUT
"""
import csv
import json
import sys


def percentile(values, p):
    """Type-7 percentile (numpy's default), the one mc's own outputs use."""
    v = sorted(values)
    h = (len(v) - 1) * p / 100.0
    lo = int(h)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (h - lo) * (v[hi] - v[lo])


def cell(out, truth, filt):
    d = f"{out}/truth-{truth}-filter-{filt}"
    by_length = {}
    with open(f"{d}/outages.csv") as f:
        for row in csv.DictReader(f):
            if not row["max_horizontal_m"]:  # empty: the filter never ran in that window
                continue
            length = round(float(row["end_s"]) - float(row["start_s"]))
            by_length.setdefault(length, []).append(
                (float(row["max_horizontal_m"]), float(row["sigma_horizontal_m"])))
    s = json.load(open(f"{d}/summary.json"))
    m = s["aided"]["models"][0]
    nees = m["nees"]
    cols = []
    for length in (30, 60):
        mx = [a for a, _ in by_length[length]]
        sg = [b for _, b in by_length[length]]
        cols.append(f"{percentile(mx, 50):.1f} / {percentile(mx, 95):.1f} ({percentile(sg, 50):.1f})")
    cons = " / ".join(
        f'{nees[c]["inside_99"]}/{nees[c]["epochs"]} ({nees[c]["mean_of_run_averages"]:.3g})'
        for c in ("aiding", "outage"))
    return s["runs_per_model"], cols, cons


def main():
    out = sys.argv[1]
    print("| truth | filter | runs | 30 s outages: max horizontal median / 95 % (filter sigma) [m] "
          "| 60 s outages: same [m] | NEES inside 99 % band, aiding / outage epochs (mean NEES) |")
    print("|---|---|---|---|---|---|")
    for truth in ("ar5", "gm"):
        for filt in ("ar5", "gm", "white"):
            runs, cols, cons = cell(out, truth, filt)
            name = {"ar5": "AR(5)", "gm": "GM", "white": "white"}
            print(f"| {name[truth]} | {name[filt]} | {runs} | {cols[0]} | {cols[1]} | {cons} |")


if __name__ == "__main__":
    main()
