# Bad model files: CLI (synth) exit code + message, Python Model() exception type + diagnostics.
import sinsim, subprocess, os, sys
os.chdir("/tmp/probe_58")
H = "gyro:\n  all:\n"
cases = {
 "missing_unit":  H + "    - {type: white, density: 0.3}\n",
 "wrong_unit":    H + "    - {type: white, density: 0.3 m/sqrt(h)}\n",
 "unknown_unit":  H + "    - {type: white, density: 0.3 furlong/sqrt(h)}\n",
 "neg_sigma":     H + "    - {type: gauss_markov, sigma: -1 deg/s, tau: 10 s}\n",
 "zero_tau":      H + "    - {type: gauss_markov, sigma: 1 deg/s, tau: 0 s}\n",
 "nan":           H + "    - {type: white, density: nan deg/sqrt(h)}\n",
 "dotnan":        H + "    - {type: white, density: .nan deg/sqrt(h)}\n",
 "nan_bare":      H + "    - {type: bias, value: .nan}\n",
 "inf":           H + "    - {type: bias, value: inf deg/s}\n",
 "huge":          H + "    - {type: bias, value: 1e300 deg/s}\n",
 "unknown_key":   H + "    - {type: white, density: 0.3 deg/sqrt(h), densty: 1 deg/sqrt(h)}\n",
 "unknown_type":  H + "    - {type: whit, density: 0.3 deg/sqrt(h)}\n",
 "dup_key_flow":  H + "    - {type: white, density: 0.3 deg/sqrt(h), density: 0.5 deg/sqrt(h)}\n",
 "dup_key_top":   "gyro:\n  all: [{type: white, density: 0.3 deg/sqrt(h)}]\ngyro:\n  all: []\n",
 "dup_key_block": H + "    - type: white\n      density: 0.3 deg/sqrt(h)\n      density: 0.4 deg/sqrt(h)\n",
 "both_sigma_density": H + "    - {type: white, density: 0.3 deg/sqrt(h), sigma: 1 deg/s, rate: 100 Hz}\n",
 "sigma_no_rate": H + "    - {type: white, sigma: 1 deg/s}\n",
 "triad_in_axis": H + "    - {type: scale_factor, value: 100 ppm}\n",
 "axis_in_triad": "gyro:\n  triad:\n    - {type: white, density: 0.3 deg/sqrt(h)}\n",
 "unstable_ar":   H + "    - {type: ar, a: [-1.05], sigma: 1 deg/s, rate: 1 kHz}\n",
 "empty_ar":      H + "    - {type: ar, a: [], sigma: 1 deg/s, rate: 1 kHz}\n",
 "bad_enabled":   H + "    - {type: white, density: 0.3 deg/sqrt(h), enabled: maybe}\n",
 "accel_unit_on_gyro": H + "    - {type: bias, value: 1 mg}\n",
 "empty":         "# nothing\n",
 "syntax":        H + "    - {type: white, density: 0.3 deg/sqrt(h)\n",
 "unknown_sensor": "gyros:\n  all: []\n",
 "unknown_list":  "gyro:\n  alll: []\n",
 "bi_range_rev":  H + "    - {type: bias_instability, B: 1 deg/h, tau_range: [100 s, 1 s]}\n",
 "sf_percent_neg_sigma": "gyro:\n  triad:\n    - {type: scale_factor, value: 1 %, sigma: -5 ppm}\n",
 "temp_T0_neg":   H + "    - {type: temperature, T0: -300 degC, coefficients: [1 deg/s/degC]}\n",
 "misalign_diag": "gyro:\n  triad:\n    - {type: misalignment, matrix: [[1 deg, 0, 0], [0, 0, 0], [0, 0, 0]]}\n",
 "string_list":   H + "    - {type: white, density: [0.3 deg/sqrt(h)]}\n",
 "many_problems": H + "    - {type: white, density: 0.3}\n    - {type: gauss_markov, sigma: -1 deg/s, tau: 1 s}\n    - {type: foo}\n",
 "rate_slow":     H + "    - {type: gauss_markov, sigma: 1 deg/s, tau: 1 s, rate: 10 Hz}\n",
}
for name, text in cases.items():
    f = f"bad/{name}.yaml"; open(f, "w").write(text)
    p = subprocess.run(["/tmp/probe_bin58/sinsim", "synth", f, "--rate", "100", "--duration", "1", "-o", f"bad/{name}.csv"], capture_output=True, text=True)
    cli = f"rc={p.returncode} {p.stderr.strip()!r}"[:260]
    try:
        m = sinsim.Model(f); py = f"NO EXCEPTION: {m}"
        try:
            sinsim.synth(m, 100, 1, f"bad/{name}.py.csv"); py += " ; synth OK"
        except Exception as e: py += f" ; synth raised {type(e).__name__}: {e}"
    except sinsim.ConfigError as e: py = f"ConfigError diag={e.diagnostics}"[:260]
    except Exception as e: py = f"{type(e).__mro__[:3]}: {e}"[:260]
    print(f"[{name}]\n   CLI: {cli}\n   PY : {py}\n   leftover csv: {os.path.exists(f'bad/{name}.csv')}")
