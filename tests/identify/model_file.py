"""Reading what `sinsim fit` and `sinsim diagnose` wrote, per channel, for the tests that run them."""
import json


def effect_lines(model, section, axis):
    """The `- {type: ...}` lines written for one channel (section gyro/accel, axis x/y/z), in order."""
    lines, where = [], None
    for line in open(model):
        if not line.startswith(" "):
            where = line.split(":")[0]
        elif line.startswith("  ") and not line.startswith("   "):
            where = (where.split(".")[0] if where else "") + "." + line.strip().rstrip(":")
        elif where == section + "." + axis and line.strip().startswith("- {type:"):
            lines.append(line.strip())
    return lines


def written_effects(model, section, axis):
    """The effect types written for one channel, in order."""
    return [line.split("type: ")[1].split(",")[0].split("}")[0] for line in effect_lines(model, section, axis)]


def gm_taus(model, section, axis):
    """The `tau` [s] of each gauss_markov written for one channel."""
    return [float(line.split("tau: ")[1].split(" s")[0]) for line in effect_lines(model, section, axis)
            if line.startswith("- {type: gauss_markov")]


def reported_findings(report, channel):
    """The effects a `diagnose --json` report reports for one channel (gx .. az), in its order."""
    return [f["effect"] for ax in json.load(open(report))["axes"] if ax["channel"] == channel
            for f in ax["findings"] if f.get("reported")]
