#!/usr/bin/python3
"""Ramps `fit --kind auto` writes on helper-29's drift-free records, and how many of them carry
the warning that a random walk explains the trend nearly as well (sixty-fourth session).

usage: ramps.py --sinsim BIN --work DIR [--seeds 30] [--sensors S1,S2,S4] [--seconds 2400] [--jobs 2]

Records: gen.py (this folder) SENSOR SEED SECONDS, cached in DIR/rec. Prints per sensor and sensor
kind (g, a) the channels with a ramp written and the warned ones among them, then the total."""
import argparse, collections, concurrent.futures, os, re, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))


def one(args, sensor, seed):
    rec = os.path.join(args.work, "rec", f"{sensor}_s{seed}_{int(args.seconds)}.csv")
    if not os.path.exists(rec):
        tmp = os.path.join(args.work, "rec", f"tmp_{sensor}_{seed}")
        os.makedirs(tmp, exist_ok=True)
        subprocess.run([sys.executable, os.path.join(HERE, "gen.py"), sensor, str(seed), str(args.seconds), tmp],
                       check=True, stdout=subprocess.DEVNULL)
        os.replace(os.path.join(tmp, f"{sensor}_s{seed}.csv"), rec)
    out = os.path.join(args.work, "models", f"{sensor}_s{seed}.yaml")
    r = subprocess.run([args.sinsim, "fit", rec, "--kind", "auto", "--threads", "1", "-o", out],
                       capture_output=True, text=True, check=True)
    ramps = [m.group(1) for m in re.finditer(r"^\s+([ga][xyz]): latent: [^(]*drift", r.stdout, re.M)]
    warned = set(re.findall(r"^fit: warning: ([ga][xyz]): drift: a random walk explains", r.stderr, re.M))
    return sensor, ramps, warned


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--sinsim", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--seeds", type=int, default=30)
    p.add_argument("--sensors", default="S1,S2,S4")
    p.add_argument("--seconds", type=float, default=2400.0)
    p.add_argument("--jobs", type=int, default=2)
    args = p.parse_args()
    for d in ("rec", "models"):
        os.makedirs(os.path.join(args.work, d), exist_ok=True)
    ramps, warned, channels = collections.Counter(), collections.Counter(), collections.Counter()
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as ex:
        jobs = [ex.submit(one, args, s, k) for s in args.sensors.split(",") for k in range(1, args.seeds + 1)]
        for j in jobs:
            sensor, r, w = j.result()
            for kind in "ga":
                channels[(sensor, kind)] += 3
            for ch in r:
                ramps[(sensor, ch[0])] += 1
                warned[(sensor, ch[0])] += ch in w
    for key in sorted(channels):
        print(f"{key[0]} {'gyro' if key[1] == 'g' else 'accel'}: ramp on {ramps[key]}/{channels[key]} channels, "
              f"warned {warned[key]}")
    print(f"total: ramp on {sum(ramps.values())}/{sum(channels.values())}, warned {sum(warned.values())}")


if __name__ == "__main__":
    main()
