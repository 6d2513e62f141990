"""sinsim.synth / load_record / analyze / fit / diagnose and the Model object, against truth from
outside: a synthesized record of known white noise (its density and Allan deviation in closed
form) and the one model reader's round trip."""
import math

import numpy as np
import pytest

import sinsim
from conftest import static_scenario

DENSITY = 0.5 * math.pi / 180 / 60  # 0.5 deg/sqrt(h) in rad/s/sqrt(Hz) = rad/sqrt(s)
RATE = 100.0  # [Hz]
SECONDS = 2000.0
N = int(RATE * SECONDS)
TRUE_MODEL = {"gyro": {"x": [{"type": "white", "density": "0.5 deg/sqrt(h)"}]}}


@pytest.fixture(scope="module")
def record(tmp_path_factory):
    path = tmp_path_factory.mktemp("rec") / "white.csv"
    return sinsim.synth(TRUE_MODEL, rate=RATE, duration="2000 s", path=str(path), seed=5), path


def test_synth_returns_the_record_it_wrote(record):
    rec, path = record
    assert rec["gx"].shape == (N,) and rec["rate"] == pytest.approx(RATE)
    again = sinsim.load_record(str(path))
    assert np.array_equal(again["gx"], rec["gx"])
    # white noise of density N at rate f has a per-sample sd N sqrt(f); the sample sd of
    # 2e5 samples is within 5 x its relative sd 1/sqrt(2n) of it
    sd = np.std(rec["gx"])
    assert sd == pytest.approx(DENSITY * math.sqrt(RATE), rel=5 / math.sqrt(2 * N))


def white_density(model, sensor="gyro", axis="x"):
    for e in model.effects():
        if e["sensor"] == sensor and e["list"] in (axis, "all") and e["type"] == "white":
            return e["params"]["density"]
    raise AssertionError(f"no white effect in {model.effects()}")


def test_fit_recovers_the_white_density(record):
    rec, _ = record
    model = sinsim.fit(rec, axes=["gx"], kind="allan")
    # The Allan fit of 2e5 white samples: its tau0 point alone has a relative sd of about
    # 1/sqrt(2n) in variance; 5 x sqrt(2/n) on the density is a loose 5-sigma-class bound.
    assert white_density(model) == pytest.approx(DENSITY, rel=5 * math.sqrt(2 / N))


def test_fit_from_a_dict_of_arrays_equals_fit_from_the_file(record):
    rec, path = record
    from_file = sinsim.fit(str(path), axes=["gx"], kind="ar")
    arrays = {"rate": rec["rate"], "gx": np.asarray(rec["gx"])}  # the rate the loader read
    from_dict = sinsim.fit(arrays, axes=["gx"], kind="ar")
    assert from_file.effects() == from_dict.effects()


def test_analyze_allan_of_white_noise(record):
    rec, _ = record
    a = sinsim.analyze(rec)
    gx = a["gx"]["allan"]
    # white rate noise: ADEV(tau) = N / sqrt(tau) (IEEE Std 952-1997, C.1). Up to tau = 10 s the
    # estimate has >= 2e4/10 degrees of freedom, a relative sd < 3 %: 15 % is 5 sigma.
    short = gx["tau"] <= 10
    assert np.count_nonzero(short) >= 8
    assert np.allclose(gx["adev"][short], DENSITY / np.sqrt(gx["tau"][short]), rtol=0.15)
    assert a["gx"]["sd"] == pytest.approx(DENSITY * math.sqrt(RATE), rel=5 / math.sqrt(2 * N))
    assert a["gx"]["constant"] is False  # a live channel; a dead one: tests/hostile (CLI)


def test_model_write_read_round_trip_and_edits(record, tmp_path):
    rec, _ = record
    fitted = sinsim.fit(rec, axes=["gx"], kind="allan")
    p1, p2 = tmp_path / "m1.yaml", tmp_path / "m2.yaml"
    fitted.write(str(p1))
    m1 = sinsim.Model(str(p1))
    m1.write(str(p2))
    assert sinsim.Model(str(p2)) == m1  # read(write(read(text))) == read(text)
    edited = m1.with_param("gyro", "x", 0, "density", "1 deg/sqrt(h)")
    assert edited.get("gyro", "x", 0, "density") == pytest.approx(2 * DENSITY, rel=1e-12)
    assert m1.get("gyro", "x", 0, "density") != edited.get("gyro", "x", 0, "density")
    with pytest.raises(sinsim.InputError, match="speed"):
        m1.with_param("gyro", "x", 0, "speed", 1.0)
    with pytest.raises(sinsim.InputError, match="density"):
        m1.with_param("gyro", "x", 0, "density", "3 m")  # wrong dimension
    plus = m1.with_effect("accel", "y", {"type": "white", "density": "0.05 m/s/sqrt(h)"})
    assert "accel.y[0].white" in plus.effect_names()
    with pytest.raises(sinsim.ConfigError, match="densty"):
        m1.with_effect("accel", "y", {"type": "white", "densty": "0.05 m/s/sqrt(h)"})


def test_fitted_model_drives_a_run(record):
    rec, _ = record
    fitted = sinsim.fit(rec, axes=["gx"], kind="allan")
    r = sinsim.run(static_scenario(10), model=fitted, seed=2)
    assert r["summary"]["final_horizontal"] > 0
    none = sinsim.run(static_scenario(10), model="none", seed=2)
    assert r["summary"]["final_horizontal"] > 100 * none["summary"]["final_horizontal"]


def test_record_dict_errors_name_the_key():
    with pytest.raises(sinsim.InputError, match="gyro_x"):
        sinsim.fit({"rate": 100.0, "gyro_x": np.zeros(10)})
    with pytest.raises(sinsim.InputError, match="rate"):
        sinsim.analyze({"gx": np.random.default_rng(1).normal(size=1000)})


def test_diagnose_finds_nothing_missing_in_the_true_model(record):
    rec, _ = record
    d = sinsim.diagnose(rec, sinsim.Model(TRUE_MODEL), channels=["gx"], realisations=8, seed=3)
    # The record was drawn from this very model: no effect can be missing at the calibrated
    # reporting threshold (5.5, docs/diagnose.md).
    assert [f["effect"] for f in d["gx"]["findings"] if f["reported"]] == []
    assert d["gx"]["unexplained"] == []


def test_diagnose_says_what_stays_unexplained(record):
    # The same record with its noise tripled for the middle fifth: no stationary effect is that,
    # and the channel's unexplained sentences say the level changes (the CLI's line).
    rec, _ = record
    burst = dict(rate=rec["rate"], gx=np.array(rec["gx"]))
    burst["gx"][80000:120000] *= 3.0
    d = sinsim.diagnose(burst, sinsim.Model(TRUE_MODEL), channels=["gx"], realisations=8, seed=3)
    assert d["gx"]["fits"] is False
    assert any("the noise level changes over the record" in u for u in d["gx"]["unexplained"])


def test_diagnose_says_when_a_warmup_time_constant_is_a_bound(tmp_path):
    # White noise with a settling slower than half the 1000-s record (tau 600 s): the warm-up's
    # time constant stops at the top of its search (T/2 = 500 s) and the evidence says it is a
    # bound, like a ramp's curvature (a blind probe's ramps on real ADIS16405 windows came out as
    # warm-ups of tau 500 s without a word, bench/blind_probe). A fast settling (tau 50 s) is
    # estimated, and says nothing of the kind.
    model = tmp_path / "white.yaml"
    model.write_text("gyro:\n  x: [{type: white, sigma: 0.01 rad/s, rate: 100 Hz}]\n")
    t = np.arange(100_000) * 0.01
    noise = np.random.default_rng(2).standard_normal(t.size) * 0.01
    said = {}
    for tau in (600.0, 50.0):
        rec = {"rate": 100.0, "gx": noise + 0.05 * np.exp(-t / tau)}
        d = sinsim.diagnose(rec, sinsim.Model(str(model)), realisations=16, seed=1)["gx"]
        warm = [f for f in d["findings"] if f["reported"] and f["effect"] == "warmup"]
        assert warm, d["findings"]
        said[tau] = warm[0]["evidence"]
    assert "tau sits at the top of the range searched (500 s): a bound, not an estimate" in said[600.0]
    assert "a bound" not in said[50.0]


def test_diagnose_refuses_a_nan_next_threshold(record):
    rec, _ = record
    with pytest.raises(sinsim.InputError, match="--next-threshold"):
        sinsim.diagnose(rec, sinsim.Model(TRUE_MODEL), channels=["gx"], realisations=8,
                        next_threshold=float("nan"))


def test_fit_writes_a_line_as_a_sinusoid_or_leaves_it_in(tmp_path):
    # The fixture's white noise (0.5 deg/sqrt(h) = 0.0083 deg/s/sqrt(Hz): sd 0.083 deg/s per sample)
    # plus a line of 0.01 deg/s at 3.1 Hz. The fitted amplitude's sd is 0.083 sqrt(2 / N) deg/s,
    # 2.6 % of it (bound: 10 %); the frequency's ~1e-5 Hz (bound 1e-3).
    line = dict(TRUE_MODEL["gyro"]["x"][0])
    model = {"gyro": {"x": [line, {"type": "sinusoid", "amplitude": "0.01 deg/s", "frequency": "3.1 Hz"}]}}
    rec = sinsim.synth(model, rate=RATE, duration="2000 s", path=str(tmp_path / "line.csv"), seed=6)
    with pytest.warns(UserWarning, match="written as a sinusoid"):
        fitted = sinsim.fit(rec, axes=["gx"], kind="latent")
    lines = [e for e in fitted.effects() if e["type"] == "sinusoid"]
    assert len(lines) == 1
    assert lines[0]["params"]["frequency"] == pytest.approx(3.1, abs=1e-3)
    assert lines[0]["params"]["amplitude"] == pytest.approx(0.01 * math.pi / 180, rel=0.1)
    with pytest.warns(UserWarning, match="no fitted term is a line"):
        kept = sinsim.fit(rec, axes=["gx"], kind="latent", lines="warn")
    assert not [e for e in kept.effects() if e["type"] == "sinusoid"]
    with pytest.raises(sinsim.InputError, match="lines"):
        sinsim.fit(rec, axes=["gx"], lines="remove")


def test_fit_skips_a_settling_with_skip_auto(tmp_path):
    # The fixture's white noise plus a warm-up of 0.05 deg/s decaying with tau 60 s (0.6 sample sd
    # at t = 0): the fit warns of it; skip="auto" fits again from where it has settled.
    white = dict(TRUE_MODEL["gyro"]["x"][0])
    model = {"gyro": {"x": [white, {"type": "warmup", "amplitude": "0.05 deg/s", "tau": "60 s"}]}}
    rec = sinsim.synth(model, rate=RATE, duration="2000 s", path=str(tmp_path / "warm.csv"), seed=7)
    with pytest.warns(UserWarning, match="starts with a settling"):
        sinsim.fit(rec, axes=["gx"], kind="gm")
    with pytest.warns(UserWarning, match="--skip auto: fitted from"):
        sinsim.fit(rec, axes=["gx"], kind="gm", skip="auto")
    with pytest.raises(sinsim.InputError, match="skip"):
        sinsim.fit(rec, axes=["gx"], skip="soon")


def test_a_record_dict_is_checked_as_a_file_is():
    # The dict path skipped the file reader's checks: a 1e300 sample gave sd = inf, a rate of
    # 1e12 Hz ran, time stamps contradicting the rate and a max_lag of -1 or NaN were ignored.
    x = np.random.default_rng(1).standard_normal(2000) * 1e-3
    with pytest.raises(sinsim.InputError, match="beyond any sensor"):
        sinsim.analyze({"rate": 100.0, "gx": np.r_[x[:-1], 1e300]})
    with pytest.raises(sinsim.InputError, match="outside what an IMU record can be"):
        sinsim.analyze({"rate": 1e12, "gx": x})
    with pytest.raises(sinsim.InputError, match="disagrees with the time stamps"):
        sinsim.analyze({"rate": 100.0, "t": np.arange(2000) / 200.0, "gx": x})
    for lag in (-1.0, float("nan")):
        with pytest.raises(sinsim.InputError, match="max lag"):
            sinsim.analyze({"rate": 100.0, "gx": x}, max_lag=lag)
    # Time stamps alone give the rate, as in a file.
    assert "gx" in sinsim.analyze({"t": np.arange(2000) / 200.0, "gx": x})


def test_a_record_dict_takes_units_and_a_rate_with_its_unit():
    # gyro_unit / accel_unit were ignored for a dict (deg/s arrays read as rad/s, 57x, and an
    # unknown unit passed), and "rate": "100 Hz" raised a raw pybind RuntimeError.
    x = np.random.default_rng(2).standard_normal(4000) * 0.2  # deg/s
    si = sinsim.analyze({"rate": 100.0, "gx": x * math.pi / 180})["gx"]["sd"]
    deg = sinsim.analyze({"rate": "100 Hz", "gx": x}, gyro_unit="deg/s")["gx"]["sd"]
    assert deg == pytest.approx(si, rel=1e-12)
    g = sinsim.analyze({"rate": 100.0, "az": x / 9.80665 - 1.0}, accel_unit="g")["az"]["mean"]
    assert g == pytest.approx(np.mean(x) - 9.80665, rel=1e-12)
    assert sinsim.analyze({"gx": x}, rate="0.1 kHz")["gx"]["sd"] == pytest.approx(np.std(x), rel=1e-12)
    with pytest.raises(sinsim.InputError, match="gyro_unit"):
        sinsim.analyze({"rate": 100.0, "gx": x}, gyro_unit="blah")
    with pytest.raises(sinsim.InputError, match="gyro_unit: \"m/s\\^2\" has dimension"):
        sinsim.analyze({"rate": 100.0, "gx": x}, gyro_unit="m/s^2")
    with pytest.raises(sinsim.InputError, match="rate"):
        sinsim.analyze({"rate": "100 m", "gx": x})


def test_analyze_raises_the_warnings_the_cli_prints():
    # Python analyze raised none: a constant channel, and a deg/s gyro read as rad/s.
    x = np.random.default_rng(3).standard_normal(4000) * 0.2
    with pytest.warns(UserWarning) as caught:
        sinsim.analyze({"rate": 100.0, "gx": x, "gy": np.zeros(4000)})
    texts = [str(w.message) for w in caught]
    assert any(t.startswith("analyze: ") and "gy is constant" in t for t in texts)
    assert any("did you forget --gyro-unit deg/s?" in t for t in texts)
    # With the unit stated, the sd alone (3 deg/s of a noisy gyro) asks nothing.
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sinsim.analyze({"rate": 100.0, "gx": x * 15}, gyro_unit="deg/s")


def test_a_call_never_writes_over_a_file_it_read(tmp_path):
    # The CLI refused `analyze rec.csv --json rec.csv`; the module replaced the record with the JSON
    # (and synth a model file with the record). Between calls the session may rewrite its files.
    model = tmp_path / "m.yaml"
    sinsim.Model(TRUE_MODEL).write(str(model))
    rec = tmp_path / "r.csv"
    sinsim.synth(str(model), rate=RATE, duration="60 s", path=str(rec), seed=1)
    before = (rec.read_bytes(), model.read_bytes())
    with pytest.raises(sinsim.InputError, match="it is an input of this command"):
        sinsim.analyze(str(rec), json=str(rec))
    with pytest.raises(sinsim.InputError, match="it is an input of this command"):
        sinsim.analyze(str(rec), html=str(rec))
    with pytest.raises(sinsim.InputError, match="it is an input of this command"):
        sinsim.synth(str(model), rate=RATE, duration="60 s", path=str(model))
    assert (rec.read_bytes(), model.read_bytes()) == before
    sinsim.analyze(str(rec), json=str(tmp_path / "a.json"))
    sinsim.Model(str(model)).write(str(model))  # a later call rewrites what an earlier one read
    sinsim.synth(str(model), rate=RATE, duration="60 s", path=str(rec), seed=2)
    assert rec.read_bytes() != before[0]
    with pytest.raises(sinsim.InputError, match="max lag"):
        sinsim.analyze(str(rec), max_lag=1e300)


def test_ctrl_c_stops_a_long_call_and_leaves_no_file(tmp_path):
    # SIGINT reached Python only when the call had finished: a 1-h synth ran to its end (5 s),
    # wrote its file, then raised. Now the library's checkpoints stop it; nothing is written.
    import os
    import signal
    import threading
    import time

    out = tmp_path / "long.csv"
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    t0 = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        sinsim.synth(TRUE_MODEL, rate=2000, duration="2 h", path=str(out), seed=1)
    elapsed = time.monotonic() - t0
    timer.join()
    assert elapsed < 5.0  # uninterrupted: ~20 s
    assert not out.exists()
    assert not [p for p in tmp_path.iterdir() if ".tmp" in p.name]
    # the next call runs, and Python's own Ctrl-C handling is back
    assert sinsim.synth(TRUE_MODEL, rate=RATE, duration="10 s", path=str(out), seed=1)["gx"].shape == (1000,)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_record_dict_s_values_are_taken_as_given_or_refused():
    # rate=True read as 1 Hz; a complex array lost its imaginary part and a masked array its mask,
    # with only NumPy's warning.
    x = np.random.default_rng(2).standard_normal(2000) * 1e-3
    with pytest.raises(sinsim.InputError, match="got a bool"):
        sinsim.analyze({"rate": True, "gx": x})
    with pytest.raises(sinsim.InputError, match="complex values"):
        sinsim.analyze({"rate": 100.0, "gx": x + 0j})
    with pytest.raises(sinsim.InputError, match="masked values"):
        sinsim.analyze({"rate": 100.0, "gx": np.ma.masked_array(x, mask=x > 2e-3)})
    plain = sinsim.analyze({"rate": 100.0, "gx": x})["gx"]["sd"]
    assert sinsim.analyze({"rate": 100.0, "gx": np.ma.masked_array(x)})["gx"]["sd"] == plain


def test_a_message_holding_a_nul_byte_is_whole():
    # The message reached Python cut at the NUL: ConfigError('scen'), InputError('a').
    with pytest.raises(sinsim.ConfigError, match=r"scen\\x00arios/x.yaml: cannot open file"):
        sinsim.Model("scen\x00arios/x.yaml")
    with pytest.raises(sinsim.InputError, match=r"a\\x00b.csv: cannot open file"):
        sinsim.load_record("a\x00b.csv")
    with pytest.raises(sinsim.ConfigError, match=r'unknown effect type "white\\x00x" \(known: '):
        sinsim.Model({"gyro": {"all": [{"type": "white\x00x"}]}})


def test_analyze_refuses_bad_outputs_before_the_work(record, tmp_path):
    # As `sinsim analyze`: both outputs are checked before the statistics, so a refused HTML never
    # leaves the JSON written, and one file given as both would keep only the last written.
    rec, _ = record
    js = tmp_path / "a.json"
    with pytest.raises(sinsim.InputError, match="does not exist"):
        sinsim.analyze(rec, json=str(js), html=str(tmp_path / "no" / "a.html"))
    with pytest.raises(sinsim.InputError, match="it is also the output"):
        sinsim.analyze(rec, json=str(js), html=str(tmp_path / "." / "a.json"))
    assert not js.exists()
    sinsim.analyze(rec, json=str(js), html=str(tmp_path / "a.html"))
    assert js.exists() and (tmp_path / "a.html").exists()


@pytest.mark.parametrize("seed", [5, 11])
def test_auto_keeps_an_ar_branch_that_holds_the_short_tau_over_terms_that_do_not(seed):
    # A blind probe's accelerometer (bench/blind_probe/long60): AR(2) with poles 0.7 and 0.5 plus
    # white noise, 3 h at 100 Hz (1.08e6 samples). Its AR + slow branch from a scanned start was
    # within 2 % of the record below that start, yet auto wrote white + gm from an earlier start
    # that was 0.89x the record at 0.01 s (within the 25 % tolerance, far outside the band on 10^6
    # samples): the diagnosis of the record against its own fit said "does not fit" (chi2 116 /
    # 34; 146 / 34 by the CLI), and on the probe's other records of that sensor `quantization`.
    # The terms now give way where they are further off the record than a consistent AR branch at
    # any octave point, in standard errors of the record's Allan estimate (fit::worstAllanZ).
    # NumPy seeds 5 and 11 are the 2 in 8 (5-12) where the rule before chose them: chi2 116 and
    # 121 / 34, not fitting; the sixtieth session's ln-ratio form fixed 5 but not 11, whose AR
    # branch and terms were both 1.2x off at 328 s, where the record's estimate is loose.
    from scipy.signal import lfilter
    rng = np.random.default_rng(seed)
    n = 1_080_000
    x = lfilter([1.0], [1.0, -1.2, 0.35], rng.standard_normal(n) * 2e-4) + rng.standard_normal(n) * 5e-4
    rec = {"rate": 100.0, "ax": x}
    model = sinsim.fit(rec, axes=["ax"])
    d = sinsim.diagnose(rec, model, realisations=16)["ax"]
    assert d["fits"], d["chi2"]
    assert not [f["effect"] for f in d["findings"] if f["reported"]]
