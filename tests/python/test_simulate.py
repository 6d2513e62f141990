"""sinsim.run / sinsim.mc / Scenario / Model against truth from outside the module: the
stationary INS (closed form: no drift with a perfect IMU), linearity of the INS error equations,
and the command line's own output files for the same seed."""
import csv
import math
import os
import subprocess

import numpy as np
import pytest

import sinsim
from conftest import static_scenario

WHITE_GYRO = {"gyro": {"all": [{"type": "white", "density": "0.2 deg/sqrt(h)"}]},
              "accel": {"all": [{"type": "white", "density": "0.05 m/s/sqrt(h)"}]}}


def test_perfect_imu_at_rest_stays_put():
    # Stationary INS with a perfect IMU: the exact solution is zero error. 1 mm after 1 h is the
    # project's bound for the integration error (issue 2, scenarios/static.yaml).
    r = sinsim.run(static_scenario(60), model="none")
    assert r["t"].shape == (3601,)  # t = 0 and every second of 1 h at output_rate 1 Hz
    assert r["pos_error_ned"].shape == (3601, 3)
    assert np.max(r["horizontal"]) < 1e-3
    assert r["summary"]["final_horizontal"] == pytest.approx(r["horizontal"][-1], abs=1e-12)


def test_dict_and_file_scenarios_run_alike(source_dir):
    # scenarios/static.yaml and its dict form (1 h): the same scenario, so bit-identical errors.
    from_file = sinsim.run(os.path.join(source_dir, "scenarios/static.yaml"), model=WHITE_GYRO,
                           seed=4)
    from_dict = sinsim.run(static_scenario(60), model=WHITE_GYRO, seed=4)
    assert np.array_equal(from_file["pos_error_ned"], from_dict["pos_error_ned"])
    assert np.max(from_file["horizontal"]) > 1.0  # the noise does show: 0.2 deg/sqrt(h) for 1 h


def test_drift_is_linear_in_the_noise_density():
    # To first order the INS error equations are linear in the sensor errors (Savage 2000,
    # ch. 12): with the same random streams, doubling every density doubles the error. The
    # second-order terms are, relative to it, of the order of the attitude error (~1e-3 rad after
    # 10 min of 0.2 deg/sqrt(h); the ratio measured 2 - 1.5e-4).
    model = sinsim.Model(WHITE_GYRO)
    double = model.scaled("gyro", "all", 0, "density", 2.0).scaled("accel", "all", 0, "density", 2.0)
    a = sinsim.run(static_scenario(10), model=model, seed=3)
    b = sinsim.run(static_scenario(10), model=double, seed=3)
    ratio = b["horizontal"][-1] / a["horizontal"][-1]
    assert ratio == pytest.approx(2.0, rel=1e-3)


def test_bad_scenario_key_names_the_key():
    sc = static_scenario()
    sc["segmnts"] = sc.pop("segments")
    with pytest.raises(sinsim.ConfigError) as e:
        sinsim.Scenario(sc)
    assert "segmnts" in str(e.value)
    assert isinstance(e.value, ValueError) and isinstance(e.value, sinsim.InputError)
    assert any(d[2] == "segmnts" for d in e.value.diagnostics)


def test_bad_scenario_value_names_its_key_path():
    sc = static_scenario()
    sc["segments"][0]["duration"] = "-3 s"
    with pytest.raises(sinsim.ConfigError, match=r"segments\[0\]\.duration"):
        sinsim.run(sc)


def test_model_file_error_names_file_and_line(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("gyro:\n  x:\n    - {type: white, density: 0.1 furlong}\n")
    with pytest.raises(sinsim.ConfigError) as e:
        sinsim.Model(str(path))
    assert f"{path}:3" in str(e.value)
    assert "gyro.x[0].density" in str(e.value)


def test_model_record_duration_reads_in_seconds_and_is_kept(tmp_path):
    path = tmp_path / "fitted.yaml"
    path.write_text("record_duration: 40 min\ngyro:\n  x:\n    - {type: white, density: 0.1 deg/sqrt(h)}\n")
    model = sinsim.Model(str(path))
    assert model.record_duration == 2400.0
    again = tmp_path / "again.yaml"
    model.write(str(again))
    assert sinsim.Model(str(again)).record_duration == 2400.0
    assert sinsim.Model(WHITE_GYRO).record_duration is None


def scenario_file(tmp_path):
    path = tmp_path / "static5.yaml"
    path.write_text(
        "name: static5\n"
        "start: {latitude: 45 deg, longitude: 7 deg, height: 250 m, heading: 0 deg}\n"
        "imu_rate: 100 Hz\noutput_rate: 1 Hz\nvertical: {channel: damped, time_constant: 100 s}\n"
        "segments:\n  - {type: static, duration: 5 min}\n")
    model = tmp_path / "white.yaml"
    sinsim.Model(WHITE_GYRO).write(str(model))
    return str(path), str(model)


def stats_row(path, label, t):
    with open(path) as f:
        for row in csv.DictReader(f):
            if row["model"] == label and math.isclose(float(row["t_s"]), t):
                return row
    raise AssertionError(f"no row {label} at {t} s in {path}")


def test_mc_per_run_values_match_the_cli(tmp_path, binary_dir):
    sc, model = scenario_file(tmp_path)
    cli = tmp_path / "cli"
    subprocess.run([os.path.join(binary_dir, "sinsim"), "mc", sc, "--runs", "16", "--model", model,
                    "--seed", "7", "--threads", "2", "--no-progress", "-o", str(cli)], check=True,
                   capture_output=True)
    r = sinsim.mc(sc, models=[model], runs=16, seed=7, threads=1)
    assert r["labels"] == ["white"]
    h = r["final"]["white"]["horizontal_m"]
    assert h.shape == (16,)
    row = stats_row(cli / "stats.csv", "white", r["t"][-1])
    # stats.csv prints 9 significant digits: 1e-8 relative covers the rounding. numpy's default
    # percentile is the same type-7 definition sinsim documents (sim/mc_stats.hpp).
    assert float(row["horizontal_m_mean"]) == pytest.approx(np.mean(h), rel=1e-8)
    assert float(row["horizontal_m_sd"]) == pytest.approx(np.std(h, ddof=1), rel=1e-8)
    for p in (50, 95):
        assert float(row[f"horizontal_m_p{p}"]) == pytest.approx(np.percentile(h, p), rel=1e-8)
    assert r["headline"]["white"]["cep"] == pytest.approx(np.percentile(h, 50), rel=1e-12)
    # the per-run array is the error array's last epoch
    e = r["errors"]["white"]
    assert e.shape == (16, len(r["t"]), 9)
    assert np.allclose(h, np.hypot(e[:, -1, 0], e[:, -1, 1]), rtol=1e-6)


def test_mc_is_repeatable_and_typed_models_equal_files(tmp_path):
    sc, model = scenario_file(tmp_path)
    a = sinsim.mc(sc, models=[model, "none"], runs=8, seed=11, threads=2)
    b = sinsim.mc(sc, models=[sinsim.Model(model), "none"], runs=8, seed=11, threads=1)
    assert a["labels"] == b["labels"] == ["white", "none"]
    for label in a["labels"]:
        assert np.array_equal(a["errors"][label], b["errors"][label])  # bit-identical
    assert np.all(a["final"]["none"]["horizontal_m"] < 1e-3)  # perfect IMU, 5 min at rest


def test_mc_takes_one_model_or_one_time_as_itself(tmp_path):
    # A string was iterated by its characters: models="m.yaml" opened "m", times="300 s" read "3".
    sc, model = scenario_file(tmp_path)
    a = sinsim.mc(sc, models=[model], runs=4, seed=3, threads=1, times=["60 s"])
    for one in (model, sinsim.Model(model)):
        b = sinsim.mc(sc, models=one, runs=4, seed=3, threads=1, times="60 s")
        assert b["labels"] == a["labels"]
        assert np.array_equal(a["errors"]["white"], b["errors"]["white"])
    with pytest.raises(sinsim.InputError, match="give a list of times"):
        sinsim.mc(sc, models=model, runs=4, times="1 min,2 min")


def test_mc_refuses_duplicate_labels(tmp_path):
    sc, model = scenario_file(tmp_path)
    with pytest.raises(sinsim.InputError, match="labelled"):
        sinsim.mc(sc, models=[sinsim.Model(model), sinsim.Model(model)], runs=8)


def test_a_dict_or_list_that_holds_itself_is_an_error_not_a_crash():
    # A dict holding itself (or 100 000 levels deep) recursed until the stack overflowed: the
    # interpreter died of a segfault. Now refused at 1000 levels, the depth a YAML file may have.
    seg = {"type": "static", "duration": "10 s"}
    seg["x"] = seg
    bad = dict(static_scenario(1), segments=[seg])
    with pytest.raises(sinsim.InputError, match="nested deeper than 1000 levels"):
        sinsim.Scenario(bad)
    loop = []
    loop.append(loop)
    with pytest.raises(sinsim.InputError, match="nested deeper"):
        sinsim.Model({"gyro": {"all": loop}})
    deep = cur = {}
    for _ in range(100000):
        cur["a"] = {}
        cur = cur["a"]
    with pytest.raises(sinsim.InputError, match="nested deeper"):
        sinsim.Scenario(dict(static_scenario(1), description=deep))


def test_model_edits_hold_to_the_model_files_limits():
    # with_param / scaled wrote 1e200 into a model: run returned NaN, and the file Model.write
    # made was refused when read back. Now refused as the reader refuses it.
    m = sinsim.Model(WHITE_GYRO)
    with pytest.raises(sinsim.InputError, match=r"gyro.all\[0\].density: .* beyond any physical value"):
        m.with_param("gyro", "all", 0, "density", 1e200)
    with pytest.raises(sinsim.InputError, match="beyond any physical value"):
        m.scaled("gyro", "all", 0, "density", 1e300)
    assert m.with_param("gyro", "all", 0, "density", 1e-4) is not None  # an ordinary edit as ever


def test_an_edited_model_file_says_it_is_edited_and_quotes_the_new_value(tmp_path, source_dir):
    # A refusal quoted the file's old value ('must be positive, got "0.05 deg/sqrt(h)"'), and a
    # run of an edited file's model reported the file itself.
    m = sinsim.Model(os.path.join(source_dir, "scenarios", "grade-tactical.yaml"))
    # ... at the effect's line of the file, which does not hold the new value: named as edited.
    with pytest.raises(sinsim.ConfigError,
                       match=r'grade-tactical\.yaml \(edited\): gyro\.all\[2\]\.density: must be positive, got "-1 rad/s\^\(1/2\)"'):
        m.with_param("gyro", "all", 2, "density", -1.0)
    with pytest.raises(sinsim.ConfigError, match=r'must be positive, got "-1\.45'):
        m.scaled("gyro", "all", 2, "density", -1)
    edited = m.scaled("gyro", "all", 2, "density", 100).scaled("gyro", "all", 2, "density", 0.5)
    r = sinsim.run(static_scenario(minutes=1), edited, output=str(tmp_path / "run"))
    assert r["summary"]["model"].endswith("grade-tactical.yaml (edited)")
    assert "model " + r["summary"]["model"] in r["summary"]["line"]


def test_a_bias_window_that_is_nan_or_negative_is_refused():
    # Read as 0 (no removal) before, silently.
    for bad in (float("nan"), -5.0):
        with pytest.raises(sinsim.InputError, match="bias window"):
            sinsim.run(static_scenario(1), model="none", bias_window=bad)


def test_an_aided_run_gives_its_outages_and_warnings(source_dir, tmp_path):
    # The default aided scenario: two outages, each maximum over every IMU epoch in its window
    # (the summary.json the same run writes holds the same), no warning. GNSS at 0.001 Hz in the
    # same 10 minutes uses no fix: warned as a Python warning and in the summary.
    path = os.path.join(source_dir, "scenarios/car-10min-aided.yaml")
    r = sinsim.run(path, output=str(tmp_path / "aided"))
    out = r["summary"]["outages"]
    assert [(o["start"], o["end"]) for o in out] == [(150.0, 180.0), (400.0, 460.0)]
    import json
    with open(tmp_path / "aided" / "summary.json") as f:
        written = json.load(f)["outages"]
    for o, w in zip(out, written):
        assert o["max_horizontal"] == pytest.approx(w["max_horizontal_m"], rel=1e-12)
        assert o["filter_sigma_horizontal"] == pytest.approx(w["filter_sigma_horizontal_m"], rel=1e-12)
        assert w["start_s"] <= o["at"] < w["end_s"]
    assert r["summary"]["warnings"] == []
    with open(path) as f:
        text = f.read()
    assert "\n  rate: 1 Hz" in text  # the GNSS rate (output_rate is another key)
    slow = tmp_path / "slow.yaml"
    slow.write_text(text.replace("\n  rate: 1 Hz", "\n  rate: 0.001 Hz").replace(
        "model: aided-model.yaml", "model: " + os.path.join(source_dir, "scenarios/aided-model.yaml")).replace(
        "errors: aided-model.yaml", "errors: " + os.path.join(source_dir, "scenarios/aided-model.yaml")))
    with pytest.warns(UserWarning, match="run: gnss: no fix is used"):
        r = sinsim.run(str(slow))
    assert any("no fix is used" in w for w in r["summary"]["warnings"])
    # mc along the same scenario warns too (it returned the batch in silence).
    with pytest.warns(UserWarning, match="mc: gnss: no fix is used"):
        b = sinsim.mc(str(slow), runs=2, threads=1)
    assert any("no fix is used" in w for w in b["warnings"])


def test_mc_refuses_an_empty_label(tmp_path):
    sc, model = scenario_file(tmp_path)
    m = sinsim.Model(model)
    m.label = ""
    with pytest.raises(sinsim.InputError, match="label is empty"):
        sinsim.mc(sc, models=[m], runs=2)


def test_a_negative_or_bool_count_or_seed_is_refused_by_name(tmp_path):
    # pybind11 refused seed=-1 as "incompatible function arguments", naming neither the argument
    # nor the value; True was read as 1.
    sc = static_scenario(1)
    calls = {
        "seed": lambda: sinsim.run(sc, model="none", seed=-1),
        "runs": lambda: sinsim.mc(sc, WHITE_GYRO, runs=-2, output=str(tmp_path / "mc")),
        "threads": lambda: sinsim.mc(sc, WHITE_GYRO, runs=2, threads=2**40, output=str(tmp_path / "mc")),
        "run": lambda: sinsim.synth(WHITE_GYRO, rate=100, duration="1 s", path=str(tmp_path / "r.csv"), run=True),
    }
    for name, call in calls.items():
        with pytest.raises(sinsim.InputError, match=f"^{name}: expected an integer"):
            call()
    assert not (tmp_path / "mc").exists() and not (tmp_path / "r.csv").exists()
    # The largest seed is a seed.
    rec = sinsim.synth(WHITE_GYRO, rate=100, duration="1 s", path=str(tmp_path / "r.csv"), seed=2**64 - 1)
    assert rec["gx"].shape == (100,)


def test_text_that_is_not_utf8_is_named_and_a_file_name_that_is_not_is_read(tmp_path, source_dir):
    # A str holding a lone surrogate (bytes decoded with surrogateescape) was a RuntimeError
    # "Unable to cast Python instance to C++ type" naming nothing, in a dict and as a path.
    with pytest.raises(sinsim.InputError, match=r"^<model dict>: gyro\.x\[0\]\.type: .* is not UTF-8 text"):
        sinsim.Model({"gyro": {"x": [{"type": "whi\udcffte", "density": "1 deg/sqrt(h)"}]}})
    with pytest.raises(sinsim.InputError, match=r"^<scenario dict>: name: .* is not UTF-8 text"):
        sinsim.run(dict(static_scenario(1), name="s\udcff"), model="none")
    # A file whose name is the byte 0xff (os.listdir gives '\udcff'), read by its name as listed.
    raw = os.path.join(os.fsencode(tmp_path), b"s\xff.yaml")
    with open(os.path.join(source_dir, "scenarios", "static.yaml"), "rb") as src, open(raw, "wb") as dst:
        dst.write(src.read())
    (listed,) = [f for f in os.listdir(tmp_path) if f.endswith(".yaml")]
    assert listed == "s\udcff.yaml"
    r = sinsim.run(os.path.join(str(tmp_path), listed), model="none")
    assert r["summary"]["final_horizontal"] < 1e-3  # at rest with a perfect IMU (closed form: 0)


def test_every_path_argument_and_result_takes_a_file_name_that_is_not_utf8(tmp_path, source_dir):
    # A folder named with the byte 0xff, as os.listdir lists it ('\udcff'). Before, the outputs,
    # load_record, synth, Model.write and mc's model files were cast to UTF-8 (TypeError), and a
    # result naming such a path (source, output, summary, labels) raised UnicodeDecodeError after
    # the work was done.
    os.mkdir(os.path.join(os.fsencode(tmp_path), b"d\xff"))
    (folder,) = os.listdir(tmp_path)
    assert folder == "d\udcff"
    d = os.path.join(str(tmp_path), folder)
    model = sinsim.Model(WHITE_GYRO)
    model.write(os.path.join(d, "m\udcfe.yaml"))
    rec = sinsim.synth(model, rate=100, duration="20 s", path=os.path.join(d, "r.csv"))
    assert rec["source"] == os.path.join(d, "r.csv")
    again = sinsim.load_record(os.path.join(d, "r.csv"))
    assert again["source"] == rec["source"] and np.array_equal(again["gx"], rec["gx"])
    sinsim.analyze(rec, json=os.path.join(d, "a.json"))
    scenario = os.path.join(source_dir, "scenarios", "static.yaml")
    r = sinsim.run(scenario, model=os.path.join(d, "m\udcfe.yaml"), output=os.path.join(d, "run"))
    assert r["output"] == os.path.join(d, "run")
    assert r["summary"]["model"] == os.path.join(d, "m\udcfe.yaml")
    mc = sinsim.mc(scenario, models=[os.path.join(d, "m\udcfe.yaml")], runs=2, times=["1 min"],
                   output=os.path.join(d, "mc"))
    assert mc["labels"] == ["m\udcfe"] and list(mc["final"]) == ["m\udcfe"]
    assert mc["output"] == os.path.join(d, "mc")
    # Every file landed under the name given, as bytes the file system holds.
    listed = set(os.listdir(os.path.join(os.fsencode(tmp_path), b"d\xff")))
    assert {b"m\xfe.yaml", b"r.csv", b"a.json", b"run", b"mc"} <= listed
    # A model read from such a file is labelled with the byte written out (a label is text).
    assert sinsim.Model(os.path.join(d, "m\udcfe.yaml")).label == "m\\xfe"
