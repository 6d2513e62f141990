#!/usr/bin/env python3
"""Writes a hostile input corpus for sinsim: scenarios, error models, records and command lines.

Independent of sinsim's code: it knows only the file formats as the README and docs/ describe
them, and tries what an attacker (or a very unlucky user) would: extreme, non-finite, negative and
huge values in every key and unit, wrong types, alias bombs and deep nesting, long lines and
fields, binary junk, truncated and bomb gzip, wrong delimiters, odd encodings, empty files,
directories and devices as paths, time columns that go backwards or repeat, absurd rates, huge AR
orders. Deterministic (fixed seed): the same corpus every time.

    make_corpus.py OUTDIR            # the whole corpus (several hundred inputs)
    make_corpus.py --fast OUTDIR     # only the fast slice (the ctest hostile_corpus)

OUTDIR/manifest.json lists every case: the command lines to run (with {IN}, {OUT}, {TMP}
placeholders), whether the input must be refused ("reject"), must succeed ("accept") or may do
either ("either"), and what an error message must name (the offending file, or option).
Run it with run_corpus.py.
"""
import gzip
import json
import math
import os
import random
import stat
import sys
import zlib

R = random.Random(15)

# ---------------------------------------------------------------------------------------------
# Building blocks

# Hostile scalars for a quantity (each written as the YAML value text). Those marked True are
# refused by any sane reader whatever the key (not finite, wrong type, beyond any physics); the
# others may be valid for some keys (then the outcome is "either" and the outputs are checked).
NUMERIC_ATTACKS = [
    (".nan", True), ("nan", True), (".inf", True), ("-.inf", True), ("inf", True),
    ("1e308", True), ("-1e308", True), ("1e400", True), ("-1e400", True),
    ("1e13", True), ("-1e13", True),
    ("1e-308", False), ("4.9e-324", False), ("0", False), ("-0", False), ("-1", False),
    ("''", True), ("~", False),  # an empty value: the key's default, if it has one ("[1, 2]", True), ("{a: 1}", True), ("true", True),
    ("abc", True), ("0x7fffffffffffffff", False), ("18446744073709551616", True),
    ("1" * 400, True), ("1e", True), ("--5", True), ("1..2", True), ("+", True),
]
UNIT_ATTACKS = [
    ("nan {u}", True), ("inf {u}", True), ("1e308 {u}", True), ("-1e308 {u}", True),
    ("1e300 {u}", True), ("5 furlong", True), ("5 {u}/{u}/{u}/{u}", False),
    ("5 (((((((((((((((((((((((((((((((m)))))))))))))))))))))))))))))))", True),
    ("5 m^99999999999", True), ("5 m^-99999999999", True), ("5 {u}^0", False),
    ("5 " + "m*" * 2000 + "m", True), ("5 {u} extra words", True), ("5{u}", False),
    ("  5   {u}  ", False), ("5 \u00b5{u}", False), ("5 \u2212{u}", True),
    ("5,5 {u}", True), ("1e-300 {u}", False), ("-5 {u}", False), ("5 " + "k" * 100 + "{u}", True),
]


def pick(seq, k):
    """k items of seq, deterministic, without repetition."""
    if k >= len(seq):
        return list(seq)
    return R.sample(list(seq), k)


class Corpus:
    def __init__(self, root, fast_only=False):
        self.root = root
        self.fast_only = fast_only
        self.cases = []
        self.names = set()
        self.pending = []  # files written by the next add() (data or a function making it)
        for d in ("scenario", "model", "record", "path", "cli", "base"):
            os.makedirs(os.path.join(root, d), exist_ok=True)

    def path(self, kind, name):
        assert (kind, name) not in self.names, name
        self.names.add((kind, name))
        return os.path.join(self.root, kind, name)

    def write(self, kind, name, data):
        """Queues a file for the next case (written when that case is in the corpus)."""
        p = self.path(kind, name)
        self.pending.append((p, data))
        return p

    def flush(self, keep=True):
        for p, data in self.pending if keep else []:
            data = data() if callable(data) else data
            mode = "wb" if isinstance(data, bytes) else "w"
            with open(p, mode, **({} if mode == "wb" else {"encoding": "utf-8", "newline": ""})) as f:
                f.write(data)
        self.pending = []

    def add(self, kind, name, commands, expect, names=None, fast=False, note=""):
        """A case: run every command (a list of argv templates) on the input."""
        keep = fast or not self.fast_only
        self.flush(keep)
        if not keep:
            return
        self.cases.append({"kind": kind, "name": name, "commands": commands, "expect": expect,
                           "names": names, "fast": fast, "note": note})


# ---------------------------------------------------------------------------------------------
# Valid bases (small: a run takes well under a second)

BASE_SCENARIO = {
    "name": "base",
    "start": {"latitude": "45 deg", "longitude": "7 deg", "height": "100 m", "heading": "30 deg",
              "speed": "0 m/s"},
    "imu_rate": "100 Hz",
    "output_rate": "1 Hz",
    "vertical": {"channel": "damped", "time_constant": "100 s"},
    "temperature": {"start": "20 degC", "rate": "0.01 degC/s"},
    "seed": "3",
    "segments": [
        {"type": "static", "duration": "2 s"},
        {"type": "accelerate", "speed": "15 m/s", "duration": "2 s"},
        {"type": "turn", "heading_change": "90 deg", "bank": "auto", "duration": "2 s"},
        {"type": "climb", "height_change": "20 m", "duration": "5 s"},
        {"type": "descend", "height": "100 m", "duration": "5 s"},
        {"type": "pitch", "angle": "5 deg", "duration": "1 s"},
        {"type": "roll", "angle": "-5 deg", "duration": "1 s"},
        {"type": "cruise", "duration": "2 s"},
        {"type": "decelerate", "speed": "5 m/s", "duration": "2 s"},
        {"type": "repeat", "count": "2", "segments": [{"type": "cruise", "duration": "1 s"}]},
    ],
}

AIDING = {
    "initial_errors": {"position": {"sigma": ["2 m", "2 m", "3 m"]},
                       "velocity": ["0.1 m/s", "0 m/s", "0 m/s"],
                       "attitude": {"sigma": ["0.3 deg", "0.3 deg", "2 deg"]}},
    "gnss": {"rate": "1 Hz", "position_sigma": ["1 m", "1 m", "2 m"], "velocity_sigma": "0.05 m/s",
             "lever_arm": ["0.5 m", "0 m", "-1 m"], "outages": [["5 s", "8 s"]]},
    "filter": {"model": {"gyro": {"all": [{"type": "white", "density": "0.15 deg/sqrt(h)"},
                                          {"type": "bias", "sigma": "10 deg/h"}]},
                         "accel": {"all": [{"type": "white", "density": "0.1 mg/sqrt(Hz)"},
                                           {"type": "bias", "sigma": "1 mg"}]}}},
}

# Every effect with its keys (docs/error-models.md), small values.
EFFECTS = {
    "white": {"density": "0.2 deg/sqrt(h)"},
    "white_rate": {"type": "white", "sigma": "0.01 deg/s", "rate": "100 Hz"},
    "bias": {"value": "10 deg/h", "sigma": "1 deg/h"},
    "random_walk": {"K": "0.1 deg/h/sqrt(h)"},
    "gauss_markov": {"sigma": "5 deg/h", "tau": "300 s"},
    "bias_instability": {"B": "1 deg/h", "tau_range": ["1 s", "1000 s"]},
    "quantization": {"lsb": "0.05 deg/s"},
    "outliers": {"rate": "0.01 Hz", "amplitude": "1 deg/s"},
    "bias_jumps": {"rate": "0.01 Hz", "size": "0.1 deg/s", "telegraph": "yes"},
    "ar": {"a": ["-0.5", "0.2"], "sigma": "0.01 deg/s", "rate": "100 Hz"},
    "sinusoid": {"amplitude": "0.01 deg/s", "frequency": "3 Hz", "phase": "10 deg"},
    "temperature": {"T0": "25 degC", "coefficients": ["0.1 deg/h/K", "0.01 deg/h/K^2"]},
    "ramp": {"slope": "1 deg/h/h"},
    "warmup": {"amplitude": "2 deg/h", "tau": "120 s"},
}
TRIAD_EFFECTS = {
    "misalignment": {"matrix": [["0", "0.1 mrad", "0"], ["0", "0", "-0.2 mrad"],
                                ["0.05 mrad", "0", "0"]]},
    "g_sensitivity": {"matrix": [["1 deg/h/g", "0", "0"], ["0", "1 deg/h/g", "0"],
                                 ["0", "0", "1 deg/h/g"]]},
    "scale_factor": {"diagonal": ["300 ppm", "-200 ppm", "100 ppm"]},
}


def effect(name):
    keys = dict(EFFECTS[name])
    typ = keys.pop("type", name)
    return dict({"type": typ}, **keys)


def base_model():
    return {"gyro": {"all": [effect("white"), effect("bias")], "x": [effect("ar")]},
            "accel": {"all": [{"type": "white", "sigma": "1 mg", "rate": "100 Hz"}],
                      "triad": [{"type": "scale_factor",
                                 **TRIAD_EFFECTS["scale_factor"]}]}}


def yaml(value, indent=0):
    """Block YAML of nested dicts/lists whose leaves are already YAML text."""
    pad = "  " * indent
    if isinstance(value, dict):
        if not value:
            return pad + "{}\n"
        out = ""
        for k, v in value.items():
            if isinstance(v, (dict, list)) and v:
                out += f"{pad}{k}:\n" + yaml(v, indent + 1)
            else:
                out += f"{pad}{k}: {flow(v)}\n"
        return out
    if isinstance(value, list):
        if not value:
            return pad + "[]\n"
        out = ""
        for v in value:
            out += f"{pad}- {flow(v)}\n"
        return out
    return pad + str(value) + "\n"


def flow(v):
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {flow(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(flow(x) for x in v) + "]"
    return str(v)


def record_text(n=2000, rate=100.0, header=None, seed=1, t0=0.0):
    """A plausible static IMU record: white noise plus a slow drift, SI units."""
    rr = random.Random(seed)
    header = header or "t [s],gx [rad/s],gy [rad/s],gz [rad/s],ax [m/s^2],ay [m/s^2],az [m/s^2],temp [degC]"
    lines = [header]
    drift = 0.0
    for k in range(n):
        drift += rr.gauss(0, 1e-6)
        g = [rr.gauss(0, 1e-3) + drift for _ in range(3)]
        a = [rr.gauss(0, 1e-2), rr.gauss(0, 1e-2), -9.81 + rr.gauss(0, 1e-2)]
        lines.append(",".join(f"{x:.9g}" for x in [t0 + k / rate] + g + a + [25 + k * 1e-4]))
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# Command templates. {IN} is the input, {OUT} a fresh output path (must not exist after an
# error), {TMP} a scratch folder, {BASE_*} the valid bases.

def scenario_cmds(mc=False):
    cmds = [["run", "{IN}", "-o", "{OUT}"]]
    if mc:
        cmds.append(["mc", "{IN}", "--runs", "2", "--threads", "1", "--no-progress", "-o", "{OUT}"])
    return cmds


def model_cmds(diagnose=False, run=True):
    cmds = [["synth", "{IN}", "--rate", "100", "--duration", "5", "-o", "{OUT}.csv"]]
    if run:
        cmds.append(["run", "{BASE_SCENARIO}", "--model", "{IN}", "-o", "{OUT}"])
    if diagnose:
        cmds.append(["diagnose", "{BASE_RECORD}", "--model", "{IN}", "--realisations", "8",
                     "--threads", "1", "--channels", "gx", "--json", "{OUT}.json",
                     "-o", "{OUT}.yaml"])
    return cmds


def record_cmds(rate=None, fit=True, diagnose=False, measured=False):
    extra = ["--rate", str(rate)] if rate else []
    cmds = [["analyze", "{IN}", *extra, "--json", "{OUT}.json"]]
    if fit:
        cmds.append(["fit", "{IN}", *extra, "--kind", "ar", "--max-order", "4", "-q",
                     "-o", "{OUT}.yaml"])
    if diagnose:
        cmds.append(["diagnose", "{IN}", *extra, "--model", "{BASE_MODEL}", "--realisations", "8",
                     "--threads", "1", "--json", "{OUT}.json", "-o", "{OUT}.yaml"])
    if measured:
        cmds.append(["mc", "--measured", "{IN}", *extra, "--model", "{BASE_MODEL}", "--runs", "2",
                     "--threads", "1", "--no-progress", "-o", "{OUT}"])
    return cmds


# ---------------------------------------------------------------------------------------------
# Scenarios

SCENARIO_KEYS = [
    ("start", "latitude", "deg"), ("start", "longitude", "deg"), ("start", "height", "m"),
    ("start", "heading", "deg"), ("start", "speed", "m/s"), (None, "imu_rate", "Hz"),
    (None, "output_rate", "Hz"), ("vertical", "time_constant", "s"),
    ("temperature", "start", "degC"), ("temperature", "rate", "degC/s"), (None, "seed", ""),
]
SEGMENT_KEYS = [  # (segment index in BASE_SCENARIO, key, unit)
    (0, "duration", "s"), (1, "speed", "m/s"), (1, "duration", "s"), (2, "heading_change", "deg"),
    (2, "bank", "deg"), (3, "height_change", "m"), (4, "height", "m"), (5, "angle", "deg"),
    (6, "angle", "deg"), (8, "speed", "m/s"), (9, "count", ""),
]


def deep_copy(x):
    return json.loads(json.dumps(x))


def scenarios(c):
    base = c.write("base", "scenario.yaml", yaml(BASE_SCENARIO))
    c.flush()
    # Per key: a sample of the numeric and unit attacks.
    n = 0
    for group, key, unit in SCENARIO_KEYS:
        attacks = pick(NUMERIC_ATTACKS, 9) + ([(a.format(u=unit), bad) for a, bad in
                                                pick(UNIT_ATTACKS, 6)] if unit else [])
        for value, bad in attacks:
            s = deep_copy(BASE_SCENARIO)
            (s[group] if group else s)[key] = value
            name = f"key-{group or 'top'}-{key}-{n:03d}.yaml"
            n += 1
            c.write("scenario", name, yaml(s))
            c.add("scenario", name, scenario_cmds(mc=n % 7 == 0), "reject" if bad else "either",
                  fast=n % 9 == 0, note=f"{key}: {value[:40]}")
    for idx, key, unit in SEGMENT_KEYS:
        attacks = pick(NUMERIC_ATTACKS, 8) + ([(a.format(u=unit), bad) for a, bad in
                                                pick(UNIT_ATTACKS, 5)] if unit else [])
        for value, bad in attacks:
            s = deep_copy(BASE_SCENARIO)
            s["segments"][idx][key] = value
            name = f"seg-{idx}-{key}-{n:03d}.yaml"
            n += 1
            c.write("scenario", name, yaml(s))
            c.add("scenario", name, scenario_cmds(mc=n % 7 == 0), "reject" if bad else "either",
                  fast=n % 9 == 0, note=f"segments[{idx}].{key}: {value[:40]}")
    # Aiding keys.
    aid_targets = [("gnss", "rate", "Hz"), ("gnss", "velocity_sigma", "m/s"),
                   ("alignment", "duration", "s")]
    for group, key, unit in aid_targets:
        for value, bad in pick(NUMERIC_ATTACKS, 5) + [(a.format(u=unit), b) for a, b in
                                                       pick(UNIT_ATTACKS, 3)]:
            s = dict(deep_copy(BASE_SCENARIO), **deep_copy(AIDING))
            if group == "alignment":
                s["alignment"] = {"type": "coarse", "duration": "1 s"}
            s[group][key] = value
            name = f"aid-{group}-{key}-{n:03d}.yaml"
            n += 1
            c.write("scenario", name, yaml(s))
            c.add("scenario", name, scenario_cmds(), "reject" if bad else "either",
                  fast=n % 9 == 0, note=f"{group}.{key}: {value[:40]}")
    aid_struct = {
        "outage-backwards": {"outages": [["8 s", "5 s"]]},
        "outage-nan": {"outages": [[".nan s", "5 s"]]},
        "outage-huge": {"outages": [["0 s", "1e308 s"]]},
        "outage-many": {"outages": [[f"{k} s", f"{k}.5 s"] for k in range(3000)]},
        "lever-huge": {"lever_arm": ["1e300 m", "0 m", "0 m"]},
        "lever-short": {"lever_arm": ["1 m"]},
        "sigma-negative": {"position_sigma": ["-1 m", "1 m", "1 m"]},
        "sigma-zero": {"position_sigma": ["0 m", "0 m", "0 m"]},
        "sigma-tiny": {"position_sigma": ["1e-300 m", "1e-300 m", "1e-300 m"]},
        "rate-1e5": {"rate": "100 kHz"},
    }
    for nm, change in aid_struct.items():
        s = dict(deep_copy(BASE_SCENARIO), **deep_copy(AIDING))
        s["gnss"].update(change)
        name = f"aid-{nm}.yaml"
        c.write("scenario", name, yaml(s))
        c.add("scenario", name, scenario_cmds(), "either" if nm in ("sigma-zero", "sigma-tiny")
              else "reject", fast=nm in ("outage-nan", "sigma-tiny"), note=nm)
    for nm, init in {"init-huge": {"position": ["1e300 m", "0 m", "0 m"]},
                     "init-nan": {"velocity": [".nan m/s", "0 m/s", "0 m/s"]},
                     "init-sigma-huge": {"attitude": {"sigma": ["1e300 deg", "0 deg", "0 deg"]}},
                     "init-sigma-neg": {"attitude": {"sigma": ["-1 deg", "0 deg", "0 deg"]}}}.items():
        s = dict(deep_copy(BASE_SCENARIO), **deep_copy(AIDING))
        s["initial_errors"] = init
        c.write("scenario", nm + ".yaml", yaml(s))
        c.add("scenario", nm + ".yaml", scenario_cmds(), "reject", note=nm)
    for nm, fm in {"filter-empty": "{}", "filter-null": "~", "filter-self": "{model: base.yaml}",
                   "filter-dir": "{model: /tmp}", "filter-dev": "{model: /dev/urandom}",
                   "filter-ar-huge": "{model: {gyro: {all: [{type: ar, a: [" +
                   ", ".join(["0.001"] * 400) + "], sigma: 1 deg/s, rate: 100 Hz}]}}}"}.items():
        s = dict(deep_copy(BASE_SCENARIO), **deep_copy(AIDING))
        s["filter"] = fm
        c.write("scenario", nm + ".yaml", yaml(s))
        c.add("scenario", nm + ".yaml", scenario_cmds(), "reject", note=nm)

    # Combinations whose product explodes while each factor is inside its range.
    combos = {
        "rate-max-long": {"imu_rate": "100 kHz", "segments": [{"type": "static",
                                                                "duration": "864000 s"}]},
        "rate-min": {"imu_rate": "0.001 Hz", "segments": [{"type": "static", "duration": "1 s"}]},
        "output-faster-than-imu": {"imu_rate": "10 Hz", "output_rate": "100 kHz"},
        "speed-orbit-turn": {"segments": [{"type": "accelerate", "speed": "11 km/s",
                                           "duration": "1 s"},
                                          {"type": "turn", "heading_change": "1e6 deg",
                                           "duration": "1 s"}]},
        "climb-space": {"segments": [{"type": "climb", "height_change": "99 km",
                                      "duration": "0.001 s"}]},
        "descend-core": {"segments": [{"type": "descend", "height_change": "6000 km",
                                       "duration": "10 s"}]},
        "pole": {"start": {"latitude": "90 deg", "longitude": "0 deg", "height": "0 m",
                           "heading": "0 deg", "speed": "50 m/s"}},
        "beyond-pole": {"start": {"latitude": "90.0000001 deg", "longitude": "0 deg"}},
        "lat-rad": {"start": {"latitude": "1e10 rad", "longitude": "0 deg"}},
        "bank-90": {"segments": [{"type": "turn", "heading_change": "90 deg", "bank": "90 deg"}]},
        "bank-89.999": {"segments": [{"type": "turn", "heading_change": "90 deg",
                                      "bank": "89.999 deg"}]},
        "bank-zero-speed": {"start": {"latitude": "45 deg", "longitude": "7 deg", "speed": "0 m/s"},
                            "segments": [{"type": "turn", "heading_change": "90 deg",
                                          "bank": "auto"}]},
        "tiny-durations": {"segments": [{"type": "static", "duration": "1e-5 s"}] * 50},
        "pitch-180": {"segments": [{"type": "pitch", "angle": "180 deg", "duration": "1 s"}]},
        "pitch-90-roll": {"segments": [{"type": "pitch", "angle": "90 deg", "duration": "1 s"},
                                       {"type": "roll", "angle": "720 deg", "duration": "1 s"}]},
        "decelerate-negative": {"segments": [{"type": "decelerate", "speed": "-5 m/s",
                                              "duration": "1 s"}]},
        "repeat-zero": {"segments": [{"type": "repeat", "count": "0", "segments":
                                      [{"type": "static", "duration": "1 s"}]}]},
        "repeat-empty": {"segments": [{"type": "repeat", "count": "5", "segments": []}]},
        "repeat-huge": {"segments": [{"type": "repeat", "count": "1000000000000",
                                      "segments": [{"type": "static", "duration": "1 s"}]}]},
        "repeat-nested-product": {"segments": [{"type": "repeat", "count": "1000", "segments": [
            {"type": "repeat", "count": "1000", "segments": [
                {"type": "repeat", "count": "1000", "segments": [
                    {"type": "static", "duration": "1e-5 s"}]}]}]}]},
        "repeat-fraction": {"segments": [{"type": "repeat", "count": "2.5", "segments":
                                          [{"type": "static", "duration": "1 s"}]}]},
        "no-segments": {"segments": []},
        "segments-map": {"segments": {"type": "static", "duration": "1 s"}},
        "unknown-segment": {"segments": [{"type": "teleport", "duration": "1 s"}]},
        "segment-no-type": {"segments": [{"duration": "1 s"}]},
        "unknown-key": {"imu_rat": "100 Hz"},
        "seed-negative": {"seed": "-1"},
        "seed-huge": {"seed": "99999999999999999999999"},
        "errors-dir": {"errors": "/tmp"},
        "errors-dev": {"errors": "/dev/zero"},
        "errors-urandom": {"errors": "/dev/urandom"},
        "errors-self": {"errors": "SELF"},
        "errors-missing": {"errors": "no/such/model.yaml"},
        "errors-empty-string": {"errors": "''"},
        "errors-list": {"errors": "[a, b]"},
        "vertical-unknown": {"vertical": {"channel": "wormhole"}},
        "vertical-tc-zero": {"vertical": {"channel": "damped", "time_constant": "0 s"}},
        "temperature-end-nan": {"temperature": {"start": "20 degC", "end": ".nan degC"}},
        "temperature-absolute-zero": {"temperature": {"start": "-300 degC", "rate": "0 degC/s"}},
        "temperature-runaway": {"temperature": {"start": "20 degC", "rate": "1e10 degC/s"}},
    }
    for nm, change in combos.items():
        s = deep_copy(BASE_SCENARIO)
        s.update(deep_copy(change))
        if nm == "errors-self":
            s["errors"] = f"combo-{nm}.yaml"
        text = yaml(s)
        c.write("scenario", f"combo-{nm}.yaml", text)
        either = nm in ("pole", "bank-89.999", "pitch-180", "pitch-90-roll", "repeat-zero",
                        "seed-negative", "temperature-absolute-zero", "bank-zero-speed",
                        "tiny-durations", "rate-min")
        c.add("scenario", f"combo-{nm}.yaml", scenario_cmds(mc=nm in ("tiny-durations", "pole")),
              "either" if either else "reject", fast=nm in ("rate-max-long", "errors-dev",
                                                            "repeat-nested-product"), note=nm)
    syntax(c, "scenario", yaml(BASE_SCENARIO), scenario_cmds())
    return base


# ---------------------------------------------------------------------------------------------
# Structure and encoding attacks shared by every YAML input

def alias_bomb(levels, width):
    lines = ["a0: &a0 [{type: static, duration: 1 s}]"]
    for k in range(1, levels):
        lines.append(f"a{k}: &a{k} [" + ", ".join([f"*a{k-1}"] * width) + "]")
    return "\n".join(lines) + "\n"


def syntax(c, kind, valid, cmds):
    """Attacks on the YAML layer, applied to a valid file `valid`."""
    head = valid.split("\n")
    cases = {
        "empty": ("", "reject"),
        "whitespace": ("   \n\t\n  \n", "reject"),
        "comments": ("# nothing here\n# at all\n", "reject"),
        "null-doc": ("~\n", "reject"),
        "scalar-doc": ("42\n", "reject"),
        "list-doc": ("- a\n- b\n", "reject"),
        "dup-top": (valid + head[1] + "\n", "reject"),
        "two-docs": (valid + "---\n" + valid, "reject"),
        "doc-end-junk": (valid + "...\n}}}\n", "reject"),
        "nul-byte": (valid.replace("\n", "\n\x00", 1), "reject"),
        "utf8-bom": ("\ufeff" + valid, "either"),
        "utf16": (None, "reject"),
        "latin1": (None, "either"),
        "crlf": (valid.replace("\n", "\r\n"), "either"),
        "cr-only": (valid.replace("\n", "\r"), "reject"),
        "tabs": (valid.replace("  ", "\t"), "reject"),
        "unclosed-flow": (valid + "x: [1, 2\n", "reject"),
        "unclosed-quote": (valid + 'x: "abc\n', "reject"),
        "deep-list": ("x: " + "[" * 100000 + "]" * 100000 + "\n" + valid, "reject"),
        "deep-map": ("x: " + "{a: " * 20000 + "1" + "}" * 20000 + "\n" + valid, "reject"),
        "deep-block": ("".join("  " * k + f"k{k}:\n" for k in range(3000)) + "  " * 3000 + "v\n",
                       "reject"),
        "long-line": ("description: " + "x" * (3 << 20) + "\n" + valid, "either"),
        "huge-file": ("description: " + "x" * (6 << 20) + "\n" + valid, "reject"),
        "long-key": (valid + "k" * 100000 + ": 1\n", "reject"),
        "many-keys": (valid + "".join(f"k{k}: {k}\n" for k in range(200000)), "reject"),
        "alias-bomb": (alias_bomb(12, 10) + valid, "reject"),
        "alias-undefined": (valid + "x: *nothere\n", "reject"),
        "anchor-redefined": ("x: &a 1\ny: &a 2\n" + valid, "either"),
        "merge-key": ("base: &b {a: 1}\nx: {<<: *b, c: 2}\n" + valid, "reject"),
        "tag-python": (valid + "x: !!python/object:os.system ls\n", "reject"),
        "tag-binary": (valid + "x: !!binary aGVsbG8=\n", "reject"),
        "complex-key": (valid + "? [a, b]\n: 1\n", "reject"),
        "binary-junk": (None, "reject"),
        "control-chars": (valid.replace("deg", "d\x1beg", 1), "reject"),
        "rtl-override": (valid.replace("deg", "d\u202eeg", 1), "reject"),
        "emoji-unit": (valid.replace("deg", "\U0001F600", 1), "reject"),
        "overlong-utf8": (None, "reject"),
        "directive": ("%YAML 1.1\n%TAG ! tag:x,2000:\n---\n" + valid, "either"),
        "bad-directive": ("%YAML 9.9\n---\n" + valid, "reject"),
    }
    for nm, (text, expect) in cases.items():
        name = f"syntax-{nm}.yaml"
        if nm == "utf16":
            data = valid.encode("utf-16")
        elif nm == "latin1":
            data = ("# caf\xe9 \xb0\n" + valid).encode("latin-1")
        elif nm == "binary-junk":
            data = bytes(R.randrange(256) for _ in range(5000))
        elif nm == "overlong-utf8":
            data = b"name: \xc0\xaf\xe0\x80\xaf\n" + valid.encode()
        else:
            data = text.encode("utf-8")
        c.write(kind, name, data)
        c.add(kind, name, cmds, expect, fast=nm in ("alias-bomb", "deep-list", "two-docs",
                                                     "nul-byte", "binary-junk", "dup-top"),
              note=nm)


# ---------------------------------------------------------------------------------------------
# Models

def models(c):
    base = c.write("base", "model.yaml", yaml(base_model()))
    c.flush()
    n = 0
    for eff, keys in EFFECTS.items():
        for key in keys:
            if key == "type":
                continue
            unit_guess = {"density": "deg/sqrt(h)", "sigma": "deg/h", "value": "deg/h",
                          "K": "deg/h/sqrt(h)", "tau": "s", "B": "deg/h", "lsb": "deg/s",
                          "rate": "Hz", "amplitude": "deg/s", "frequency": "Hz", "phase": "deg",
                          "T0": "degC", "slope": "deg/h/h"}.get(key, "")
            attacks = pick(NUMERIC_ATTACKS, 5)
            if unit_guess:
                attacks += [(a.format(u=unit_guess), b) for a, b in pick(UNIT_ATTACKS, 3)]
            if isinstance(keys[key], list):
                attacks = [("[]", True), ("[" + ", ".join(["1e308"] * 3) + "]", True),
                           (f"[{keys[key][0]}]", eff not in ("ar", "temperature")),
                           ("[.nan, .nan]", True), ("'" + str(keys[key]) + "'", True)]
            for value, bad in attacks:
                e = effect(eff)
                e[key] = value
                name = f"eff-{eff}-{key}-{n:03d}.yaml"
                n += 1
                c.write("model", name, yaml({"gyro": {"x": [e]}}))
                c.add("model", name, model_cmds(diagnose=n % 11 == 0, run=n % 3 == 0),
                      "reject" if bad else "either", fast=n % 10 == 0,
                      note=f"{eff}.{key}: {value[:40]}")
    for eff, keys in TRIAD_EFFECTS.items():
        key = next(iter(keys))
        for nm, value in {"nan": [[".nan"] * 3] * 3 if key == "matrix" else [".nan"] * 3,
                          "huge": [["1e308"] * 3] * 3 if key == "matrix" else ["1e308 ppm"] * 3,
                          "short": [["0", "0"]] if key == "matrix" else ["1 ppm"],
                          "scalar": "5", "singular": [["-1e6 ppm"] * 3] * 3 if key == "matrix"
                          else ["-1e6 ppm"] * 3}.items():
            name = f"triad-{eff}-{nm}.yaml"
            c.write("model", name, yaml({"gyro": {"triad": [dict({"type": eff}, **{key: value})]}}))
            c.add("model", name, model_cmds(), "either" if nm == "singular" else "reject",
                  note=f"{eff}.{key} {nm}")
    # AR specials.
    ar = {
        "order-1000": (["0.0001"] * 1000, "either"),
        "order-100000": (["0"] * 100000, "reject"),
        "unit-root": (["-1"], "reject"),
        "near-unit": (["-0.9999999999"], "either"),
        "explosive": (["-2.5", "1.6"], "reject"),  # complex poles of modulus 1.26
        "all-zero": (["0", "0", "0"], "either"),
        "empty": ([], "reject"),
        "strings": (["a", "b"], "reject"),
        "nested": ([["0.1"]], "reject"),
        "denormal": (["4.9e-324"], "either"),
    }
    for nm, (coeffs, expect) in ar.items():
        name = f"ar-{nm}.yaml"
        c.write("model", name, yaml({"gyro": {"x": [{"type": "ar", "a": flow(coeffs),
                                                     "sigma": "0.01 deg/s", "rate": "100 Hz"}]}}))
        c.add("model", name, model_cmds(diagnose=nm == "order-1000"), expect,
              fast=nm in ("order-100000", "unit-root"), note=nm)
    odd = {
        "perfect": ("gyro: {}\n", "either"),
        "no-sensors": ("description: nothing\n", "reject"),
        "gyro-null": ("gyro: ~\n", "reject"),
        "gyro-list": ("gyro: [1, 2]\n", "reject"),
        "axis-unknown": ("gyro: {w: [{type: white, density: 1 deg/sqrt(h)}]}\n", "reject"),
        "sensor-unknown": ("magnetometer: {x: []}\n", "reject"),
        "type-unknown": ("gyro: {x: [{type: wormhole}]}\n", "reject"),
        "type-missing": ("gyro: {x: [{density: 1 deg/sqrt(h)}]}\n", "reject"),
        "type-list": ("gyro: {x: [{type: [white]}]}\n", "reject"),
        "key-unknown": ("gyro: {x: [{type: white, density: 1 deg/sqrt(h), densty: 2}]}\n",
                        "reject"),
        "wrong-dimension": ("gyro: {x: [{type: white, density: 1 m}]}\n", "reject"),
        "accel-unit-on-gyro": ("gyro: {x: [{type: bias, value: 1 mg}]}\n", "reject"),
        "enabled-junk": ("gyro: {x: [{type: white, density: 1 deg/sqrt(h), enabled: maybe}]}\n",
                         "reject"),
        "dup-density": ("gyro:\n  x:\n    - type: white\n      density: 1 deg/sqrt(h)\n"
                        "      density: 2 deg/sqrt(h)\n", "reject"),
        "dup-axis": ("gyro:\n  x: []\n  x: []\n", "reject"),
        "many-effects": ("gyro:\n  x:\n" + "".join(
            "    - {type: white, density: 0.1 deg/sqrt(h)}\n" for _ in range(20000)), "either"),
        "many-bad": ("gyro:\n  x:\n" + "".join(
            f"    - {{type: white, density: -{k} deg/sqrt(h)}}\n" for k in range(1, 100001)),
            "reject"),
        "temp-degree-300": ("gyro: {x: [{type: temperature, T0: 25 degC, coefficients: [" +
                            ", ".join(f"1 deg/h/K^{k}" for k in range(1, 301)) + "]}]}\n", "either"),
        "bi-range-wide": ("gyro: {x: [{type: bias_instability, B: 1 deg/h, "
                          "tau_range: [1e-5 s, 864000 s]}]}\n", "either"),
        "bi-range-backwards": ("gyro: {x: [{type: bias_instability, B: 1 deg/h, "
                               "tau_range: [100 s, 1 s]}]}\n", "reject"),
        "outliers-every-sample": ("gyro: {x: [{type: outliers, rate: 100 kHz, amplitude: "
                                  "1 deg/s}]}\n", "either"),
        "jumps-every-sample": ("gyro: {x: [{type: bias_jumps, rate: 1e300 Hz, size: 1 deg/s}]}\n",
                               "either"),
        "jumps-size-huge": ("gyro: {x: [{type: bias_jumps, rate: 1 kHz, size: 1e300 deg/s}]}\n",
                            "either"),
        "sinusoid-nyquist": ("gyro: {x: [{type: sinusoid, amplitude: 1 deg/s, frequency: 100 kHz,"
                             " phase: 0 deg}]}\n", "either"),
        "white-rate-1e12": ("gyro: {x: [{type: white, sigma: 1 deg/s, rate: 1e12 Hz}]}\n",
                            "reject"),
        "gm-rate-max": ("gyro: {x: [{type: gauss_markov, sigma: 1 deg/s, tau: 1 s, "
                        "rate: 100 kHz}]}\n", "either"),
        "density-1e308": ("gyro: {x: [{type: white, density: 1e308 deg/sqrt(h)}]}\n", "reject"),
        "density-1e11": ("gyro: {x: [{type: white, density: 1e11 rad/sqrt(s)}]}\n", "either"),
        "sum-overflow": ("gyro:\n  x:\n" + "".join(
            "    - {type: bias, value: 9e11 rad/s}\n" for _ in range(1000)), "either"),
        "ramp-overflow": ("gyro: {x: [{type: ramp, slope: 1e11 rad/s/s}]}\n", "either"),
        "warmup-tau-tiny": ("gyro: {x: [{type: warmup, amplitude: 1 deg/s, tau: 1e-300 s}]}\n",
                            "either"),
        "gm-tau-tiny": ("gyro: {x: [{type: gauss_markov, sigma: 1 deg/s, tau: 1e-300 s}]}\n",
                        "either"),
        "gm-tau-huge": ("gyro: {x: [{type: gauss_markov, sigma: 1 deg/s, tau: 1e12 s}]}\n",
                        "either"),
        "quant-lsb-tiny": ("gyro: {x: [{type: quantization, lsb: 1e-300 deg/s}]}\n", "either"),
        "quant-lsb-zero": ("gyro: {x: [{type: quantization, lsb: 0 deg/s}]}\n", "reject"),
    }
    for nm, (text, expect) in odd.items():
        name = f"odd-{nm}.yaml"
        c.write("model", name, text)
        c.add("model", name, model_cmds(diagnose=nm in ("temp-degree-300", "many-effects")),
              expect, fast=nm in ("perfect", "dup-density", "many-bad", "white-rate-1e12",
                                  "temp-degree-300"), note=nm)
    syntax(c, "model", yaml(base_model()), model_cmds(run=False))
    return base


# ---------------------------------------------------------------------------------------------
# Records

def gz(data, level=6):
    return gzip.compress(data if isinstance(data, bytes) else data.encode(), level)


def gzip_bomb(size, byte=b"0", chunk=1 << 24):
    """A gzip stream of `size` copies of `byte`, made in chunks (small memory)."""
    comp = zlib.compressobj(9, zlib.DEFLATED, 31)
    out = [comp.compress(b"t,gx\n")]
    block = byte * chunk
    left = size
    while left > 0:
        out.append(comp.compress(block[:min(chunk, left)]))
        left -= chunk
    out.append(comp.flush())
    return b"".join(out)


def records(c):
    good = record_text()
    base = c.write("base", "record.csv", good)
    c.flush()
    lines = good.split("\n")
    header, rows = lines[0], [l for l in lines[1:] if l]
    cases = {}

    def put(nm, data, expect, **kw):
        cases[nm] = (data, expect, kw)

    put("valid", good, "accept", diagnose=True, measured=True)
    put("valid-norate-header", record_text(header="t,gx,gy,gz,ax,ay,az,temp"), "accept")
    put("empty", "", "reject")
    put("whitespace", "  \n\n\t\n", "reject")
    put("header-only", header + "\n", "reject")
    for k in (1, 2, 3, 4, 8):
        put(f"rows-{k}", "\n".join([header] + rows[:k]) + "\n", "reject" if k < 3 else "either")
    put("bom", "\ufeff" + good, "either")
    put("utf16", None, "reject")
    put("crlf", good.replace("\n", "\r\n"), "either")
    put("cr-only", good.replace("\n", "\r"), "reject")
    put("no-final-newline", good.rstrip("\n"), "either")
    for nm, sep in {"semicolon": ";", "tab": "\t", "space": " ", "pipe": "|"}.items():
        put(f"delim-{nm}", good.replace(",", sep), "either")
    put("decimal-comma", "\n".join([header.replace(",", ";")] +
                                   [r.replace(",", ";").replace(".", ",") for r in rows]) + "\n",
        "reject")
    put("quoted", "\n".join(['"' + h + '"' for h in [header]] +
                            [",".join(f'"{x}"' for x in r.split(",")) for r in rows]) + "\n",
        "either")
    put("no-header", "\n".join(rows) + "\n", "reject")
    put("header-dup", header.replace("gy [rad/s]", "gx [rad/s]") + "\n" + "\n".join(rows) + "\n",
        "reject")
    put("header-unknown-unit", header.replace("[rad/s]", "[furlong/fortnight]") + "\n" +
        "\n".join(rows) + "\n", "reject")
    put("header-wrong-dim", header.replace("gx [rad/s]", "gx [m]") + "\n" + "\n".join(rows) + "\n",
        "reject")
    put("header-unit-bomb", header.replace("[rad/s]", "[" + "(" * 5000 + "rad" + ")" * 5000 + "]")
        + "\n" + "\n".join(rows) + "\n", "reject")
    put("header-only-time", "t\n" + "\n".join(str(k / 100) for k in range(500)) + "\n", "reject")
    put("header-only-temp", "temp\n" + "\n".join("25" for _ in range(500)) + "\n", "reject")
    put("columns-65", ",".join(f"c{k}" for k in range(65)) + "\n" +
        ("0," * 64 + "0\n") * 10, "reject")
    put("columns-1e6", ",".join("gx" for _ in range(1000000)) + "\n1\n", "reject")
    put("field-long", header + "\n" + rows[0].replace(",", "," + "1" * 100000, 1) + "\n" +
        "\n".join(rows[1:]) + "\n", "reject")
    put("field-zeros", header + "\n" + "\n".join(
        r.replace(",", ",0000000000000000000000000000000000000000000000000000000000000", 1)
        for r in rows) + "\n", "either")
    put("line-50MB", header + "\n" + "9" * (50 << 20) + "\n", "reject")
    put("ragged-short", header + "\n" + "\n".join(r if k % 5 else ",".join(r.split(",")[:3])
                                                  for k, r in enumerate(rows)) + "\n", "reject")
    put("ragged-long", header + "\n" + "\n".join(r + ",1,2" if k == 7 else r
                                                 for k, r in enumerate(rows)) + "\n", "reject")
    put("empty-fields", header + "\n" + "\n".join(r.replace(",", ",,", 1) if k == 3 else r
                                                  for k, r in enumerate(rows)) + "\n", "reject")
    put("blank-lines", header + "\n\n" + "\n\n".join(rows) + "\n\n", "either")
    put("comment-lines", "# exported\n" + good, "either")
    for nm, val in {"nan": "nan", "NaN": "NaN", "inf": "inf", "-inf": "-inf", "1e308": "1e308",
                    "-1e308": "-1e308", "1e400": "1e400", "denormal": "4.9e-324",
                    "hex": "0x1p3", "text": "abc", "plus": "+", "1e13": "1e13"}.items():
        bad_rows = [",".join([r.split(",")[0], val] + r.split(",")[2:]) if k == 100 else r
                    for k, r in enumerate(rows)]
        put(f"value-{nm}", header + "\n" + "\n".join(bad_rows) + "\n",
            "either" if nm in ("denormal",) else "reject", fast=nm in ("nan", "1e308"))
    allbig = [",".join([r.split(",")[0]] + ["1e300"] * 7) for r in rows]
    put("values-all-1e300", header + "\n" + "\n".join(allbig) + "\n", "reject")
    allbig11 = [",".join([r.split(",")[0]] + [f"{9e11 * (1 if k % 2 else -1):g}"] * 7)
                for k, r in enumerate(rows)]
    put("values-all-9e11", header + "\n" + "\n".join(allbig11) + "\n", "either", fast=True)
    # A constant or zero channel: analyze may describe it (zero variance), fit must refuse it.
    put("constant", header + "\n" + "\n".join(
        ",".join([r.split(",")[0]] + ["0.25"] * 7) for r in rows) + "\n", "either")
    put("zero", header + "\n" + "\n".join(
        ",".join([r.split(",")[0]] + ["0"] * 7) for r in rows) + "\n", "either")
    put("denormals", header + "\n" + "\n".join(
        ",".join([r.split(",")[0]] + [f"{R.random() * 1e-310:.3g}" for _ in range(7)])
        for r in rows) + "\n", "either")

    def with_time(ts, nm, expect, **kw):
        body = [",".join([f"{t!r}"] + r.split(",")[1:]) for t, r in zip(ts, rows)]
        put(nm, header + "\n" + "\n".join(body) + "\n", expect, **kw)

    n = len(rows)
    with_time([(n - k) / 100 for k in range(n)], "time-backwards", "reject", fast=True)
    with_time([k // 2 / 100 for k in range(n)], "time-repeats", "reject")
    with_time([0.0] * n, "time-constant", "reject")
    with_time([k / 100 + (5 if k > 1000 else 0) for k in range(n)], "time-gap", "either")
    with_time([k / 100 if k != 500 else 4.0 for k in range(n)], "time-one-back", "reject")
    with_time([1e300 + k for k in range(n)], "time-1e300", "reject")
    with_time([k * 1e6 for k in range(n)], "time-1e6-step", "reject")
    with_time([k * 1e300 for k in range(n)], "time-1e300-step", "reject", fast=True)
    with_time([k * 1e-12 for k in range(n)], "time-1e-12-step", "reject")
    with_time([k * 1e-308 for k in range(n)], "time-denormal-step", "reject")
    with_time([k / 100 + R.uniform(-0.004, 0.004) for k in range(n)], "time-jitter", "either")
    with_time([float("nan") if k == 10 else k / 100 for k in range(n)], "time-nan", "reject")
    with_time([k / 100 * (1 if k < 1000 else 100) for k in range(n)], "time-rate-change",
              "either")
    with_time([-1e12 + k / 100 for k in range(n)], "time-negative-start", "either")
    with_time([1e9 + k / 100 for k in range(n)], "time-epoch-ns-precision", "either")
    put("rate-1e-300", good, "reject", rate="1e-300")
    put("rate-1e12", good, "reject", rate="1e12")
    put("rate-nan", good, "reject", rate="nan")
    put("rate-negative", good, "reject", rate="-100")
    put("rate-zero", good, "reject", rate="0")
    put("rate-with-unit", good, "either", rate="100 Hz")
    put("rate-conflicts-time", good, "either", rate="1000")
    long_rows = record_text(n=200000, rate=1000)
    put("long-200k", long_rows, "either", fit=False)
    put("binary-junk", bytes(R.randrange(256) for _ in range(20000)), "reject")
    put("nul-bytes", good.replace("\n", "\x00\n", 5), "reject")
    put("latin1-header", None, "reject")
    for nm, data in {"gz-valid": gz(good), "gz-truncated": gz(good)[:-200],
                     "gz-header-only": gz(good)[:10], "gz-junk-tail": gz(good) + b"\x00junk" * 10,
                     "gz-concat": gz(good) + gz("\n".join(rows[:10]) + "\n"),
                     "gz-of-junk": gz(bytes(R.randrange(256) for _ in range(20000))),
                     "gz-not-gzip": good.encode(), "gz-bad-crc": None,
                     "gz-bomb-line": None, "gz-bomb-lines": None, "gz-empty": gz(b"")}.items():
        if nm == "gz-bad-crc":
            b = bytearray(gz(good))
            b[-6] ^= 0xFF
            data = bytes(b)
        elif nm == "gz-bomb-line":  # one line of 1e9 digits (just under the 1 GiB text limit)
            data = lambda: gzip_bomb(1000000000)
        elif nm == "gz-bomb-lines":  # 2 GB of "1\n" rows
            data = lambda: gzip_bomb(2000000000, b"1\n")
        # zlib reads a plain file through gzopen as is, and stops at junk after the last member.
        put(nm, data, "either" if nm in ("gz-valid", "gz-concat", "gz-not-gzip", "gz-junk-tail")
            else "reject",
            gz=True, fit=not nm.startswith("gz-bomb"), fast=nm in ("gz-truncated",))
    for nm, (data, expect, kw) in cases.items():
        gzipped = kw.pop("gz", False)
        name = f"rec-{nm}.csv" + (".gz" if gzipped else "")
        if nm == "utf16":
            data = good.encode("utf-16")
        elif nm == "latin1-header":
            data = ("t,gx [\xb0/s]\n" + "\n".join(f"{k/100},{R.random()}" for k in range(500))
                    + "\n").encode("latin-1")
        c.write("record", name, data)
        rate = kw.pop("rate", None)
        fast = kw.pop("fast", False)
        c.add("record", name, record_cmds(rate=rate, **kw), expect, fast=fast, note=nm)
    return base


# ---------------------------------------------------------------------------------------------
# Paths that are not regular files, and command-line options

def paths(c):
    fifo = c.path("path", "fifo")
    os.mkfifo(fifo)
    link = c.path("path", "link-to-zero")
    os.symlink("/dev/zero", link)
    loop = c.path("path", "link-loop")
    os.symlink(loop, loop)
    d = c.path("path", "a-dir.yaml")
    os.makedirs(d)
    targets = {"dev-zero": "/dev/zero", "dev-null": "/dev/null", "dev-urandom": "/dev/urandom",
               "proc-self-mem": "/proc/self/mem", "dir": d, "root": "/", "fifo": fifo,
               "link-zero": link, "link-loop": loop, "missing": os.path.join(c.root, "no/such"),
               "empty-name": "", "long-name": "x" * 5000, "newline-name": "a\nb.yaml"}
    for nm, p in targets.items():
        for kind, cmds in (("scenario", scenario_cmds()), ("model", model_cmds(run=False)),
                           ("record", record_cmds(fit=False))):
            cmd = [[p if a == "{IN}" else a for a in cmd] for cmd in cmds]
            c.add("path", f"{nm}-as-{kind}", cmd, "reject", names=[p] if p else ["argument"],
                  fast=nm in ("fifo", "dev-zero", "dir") and kind != "record", note=p[:60])
    # Output paths that cannot be written. The devices are the corpus's own copies (never
    # /dev/*: a writer that renames a temporary onto its target would replace the system's node).
    outs = {"out-fifo": fifo, "out-dir": d, "out-missing": "/no/such/dir/x",
            "out-proc": "/proc/version", "out-link-zero": link}
    try:
        null = c.path("path", "null-device")
        os.mknod(null, 0o666 | stat.S_IFCHR, os.makedev(1, 3))  # a /dev/null of our own
        outs["out-null-device"] = null
    except (PermissionError, OSError):
        pass
    for nm, out in outs.items():
        c.add("path", nm, [["synth", "{BASE_MODEL}", "--rate", "100", "--duration", "1",
                            "-o", out],
                           ["fit", "{BASE_RECORD}", "--kind", "ar", "--max-order", "2", "-q",
                            "-o", out]],
              "either" if nm == "out-missing" else "reject",  # synth creates folders, as run
              names=[out], note=out)


def cli(c):
    S, M, D = "{BASE_SCENARIO}", "{BASE_MODEL}", "{BASE_RECORD}"
    bad_numbers = ["nan", "inf", "-inf", "-1", "0", "1e308", "1e-308", "", "abc", "1e400",
                   "18446744073709551617", " 5", "5 parsecs"]
    opts = {
        ("synth", "--rate"): ["synth", M, "--duration", "1", "-o", "{OUT}.csv", "--rate"],
        ("synth", "--duration"): ["synth", M, "--rate", "100", "-o", "{OUT}.csv", "--duration"],
        ("synth", "--seed"): ["synth", M, "--rate", "100", "--duration", "1", "-o", "{OUT}.csv",
                              "--seed"],
        ("synth", "--temperature"): ["synth", M, "--rate", "100", "--duration", "1", "-o",
                                     "{OUT}.csv", "--temperature"],
        ("synth", "--latitude"): ["synth", M, "--rate", "100", "--duration", "1", "-o",
                                  "{OUT}.csv", "--latitude"],
        ("mc", "--runs"): ["mc", S, "--threads", "1", "--no-progress", "-o", "{OUT}", "--runs"],
        ("mc", "--threads"): ["mc", S, "--runs", "2", "--no-progress", "-o", "{OUT}",
                              "--threads"],
        ("mc", "--times"): ["mc", S, "--runs", "2", "--threads", "1", "--no-progress", "-o",
                            "{OUT}", "--times"],
        ("mc", "--seed"): ["mc", S, "--runs", "2", "--threads", "1", "--no-progress", "-o",
                           "{OUT}", "--seed"],
        ("run", "--seed"): ["run", S, "-o", "{OUT}", "--seed"],
        ("run", "--bias-window"): ["run", S, "-o", "{OUT}", "--bias-window"],
        ("analyze", "--max-lag"): ["analyze", D, "--json", "{OUT}.json", "--max-lag"],
        ("analyze", "--segment"): ["analyze", D, "--json", "{OUT}.json", "--segment"],
        ("analyze", "--confidence"): ["analyze", D, "--json", "{OUT}.json", "--confidence"],
        ("analyze", "--rate"): ["analyze", D, "--json", "{OUT}.json", "--rate"],
        ("fit", "--order"): ["fit", D, "--kind", "ar", "-q", "-o", "{OUT}.yaml", "--order"],
        ("fit", "--max-order"): ["fit", D, "--kind", "ar", "-q", "-o", "{OUT}.yaml",
                                 "--max-order"],
        ("fit", "--denoise-level"): ["fit", D, "--kind", "ar", "--max-order", "3",
                                     "--denoise", "db5", "-q", "-o", "{OUT}.yaml",
                                     "--denoise-level"],
        ("fit", "--nav-step"): ["fit", D, "--kind", "ar", "--criterion", "paper", "-q",
                                "-o", "{OUT}.yaml", "--nav-step"],
        ("diagnose", "--realisations"): ["diagnose", D, "--model", M, "--threads", "1",
                                         "--channels", "gx", "--json", "{OUT}.json",
                                         "-o", "{OUT}.yaml", "--realisations"],
        ("diagnose", "--threshold"): ["diagnose", D, "--model", M, "--threads", "1",
                                      "--realisations", "8", "--channels", "gx",
                                      "--json", "{OUT}.json", "-o", "{OUT}.yaml", "--threshold"],
        ("diagnose", "--threads"): ["diagnose", D, "--model", M, "--realisations", "8",
                                    "--channels", "gx", "--json", "{OUT}.json",
                                    "-o", "{OUT}.yaml", "--threads"],
    }
    n = 0
    for (cmd, opt), argv in opts.items():
        for v in bad_numbers:
            valid_maybe = v == " 5" or (v in ("0", "-1", "1e-308") and opt != "--rate") or (
                opt == "--threshold" and v in ("1e308", "18446744073709551617"))  # report nothing
            c.add("cli", f"{cmd}{opt}-{n:03d}", [argv + [v]], "either" if valid_maybe
                  else "reject", names=[opt], fast=n % 16 == 0, note=f"{cmd} {opt} {v!r}")
            n += 1
    for nm, argv in {"fit-axes-bogus": ["fit", D, "--axes", "gq", "-q", "-o", "{OUT}.yaml"],
                     "fit-kind-bogus": ["fit", D, "--kind", "neural", "-q", "-o", "{OUT}.yaml"],
                     "diag-channels-bogus": ["diagnose", D, "--model", M, "--channels", "zz",
                                             "--realisations", "8", "--threads", "1"],
                     "analyze-tau-bogus": ["analyze", D, "--tau", "weekly", "--json",
                                           "{OUT}.json"],
                     "mc-measured-att": ["mc", "--measured", D, "--model", M, "--runs", "2",
                                         "--attitude", "nan deg, 0 deg, 0 deg", "-o", "{OUT}"],
                     "mc-runs-4e9": ["mc", S, "--runs", "4000000000", "-o", "{OUT}"],
                     "mc-resume-fresh": ["mc", S, "--runs", "2", "--resume", "--threads", "1",
                                         "--no-progress", "-o", "{OUT}"],
                     "run-model-and-imu": ["run", S, "--imu", "--model", "/dev/zero",
                                           "-o", "{OUT}"]}.items():
        c.add("cli", nm, [argv], "either" if nm == "mc-resume-fresh" else "reject",
              names=["/dev/zero"] if nm == "run-model-and-imu" else None, note=nm)


def main():
    args = [a for a in sys.argv[1:] if a != "--fast"]
    if len(args) != 1:
        sys.exit(__doc__)
    c = Corpus(args[0], fast_only="--fast" in sys.argv)
    bases = {"BASE_SCENARIO": scenarios(c), "BASE_MODEL": models(c), "BASE_RECORD": records(c)}
    paths(c)
    cli(c)
    with open(os.path.join(c.root, "manifest.json"), "w") as f:
        json.dump({"bases": bases, "cases": c.cases}, f, indent=0)
    runs = sum(len(x["commands"]) for x in c.cases)
    print(f"{len(c.cases)} cases, {runs} command runs, "
          f"{sum(1 for x in c.cases if x['fast'])} in the fast slice -> {c.root}")


if __name__ == "__main__":
    main()
