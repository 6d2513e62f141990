#!/usr/bin/python3
"""A fitted model with each warned ramp replaced by the random walk its drift comment names
(`fit` warns where a walk explains the trend nearly as well; sixty-fourth session).

usage: walk_for_ramp.py MODEL.yaml OUT.yaml [--drop]

The walk's K is the whole walk of the channel, so a random_walk line the channel already has is
replaced too. --drop writes the model without the warned ramps and without the walk (the third
model of the comparison in docs/fitting.md, "A ramp or a walk?")."""
import re, sys


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    drop = "--drop" in sys.argv
    if len(args) != 2:
        sys.exit(__doc__)
    lines = open(args[0]).read().split("\n")
    out, i = [], 0
    while i < len(lines):
        m = re.search(r"a random_walk of K (\S+ \S+) explains this trend", lines[i])
        if m and i + 1 < len(lines) and "type: ramp" in lines[i + 1]:
            indent = lines[i + 1][: lines[i + 1].index("-")]
            if not drop:
                j = len(out) - 1  # this channel's earlier lines, up to its "  x:" key
                while j >= 0 and not re.match(r"^  [xyz]:", out[j]):
                    if "type: random_walk" in out[j]:
                        del out[j]
                    j -= 1
            out.append(lines[i])
            if not drop:
                out.append(f"{indent}- {{type: random_walk, K: {m.group(1)}}}")
            i += 2
            continue
        out.append(lines[i])
        i += 1
    open(args[1], "w").write("\n".join(out))


if __name__ == "__main__":
    main()
