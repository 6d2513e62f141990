"""Ctrl-C and the progress line of every long command, driven through the real executable.

Each command is started in its own process group with work that takes far longer than the
test waits (tens of seconds to hours on this machine), then interrupted the way `timeout -s INT`
does it: one SIGINT to the process and the same one to its group, i.e. delivered twice within
microseconds. It must count once: a clear message naming the command, exit code 130, and no
output file — not even a temporary — left behind (mc: the finished chunks kept, their count right).
SIGTERM stops `run` the same way, with exit code 143.
"""
import os
import pathlib
import sys
import tempfile
import traceback
import re
import signal
import subprocess
import threading
import time

BIN = pathlib.Path(os.environ["SINSIM_BINARY_DIR"]) / "sinsim"
SRC = pathlib.Path(os.environ["SINSIM_SOURCE_DIR"])
RECORD = pathlib.Path(os.environ["SINSIM_SHARED_DIR"]) / "data" / "adis16405" / "run1.csv.gz"
# The ADIS16405 record's layout (README step 1): 100 Hz, deg/s and g, no time column.
LAYOUT = ["--rate", "100", "--gyro-unit", "deg/s", "--accel-unit", "g"]

# 10 h static at 200 Hz: 7.2 million navigation steps, far beyond the test's wait.
LONG_SCENARIO = """name: long-static
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 0 deg}
imu_rate: 200 Hz
output_rate: 1 Hz
errors: none
segments:
  - {type: static, duration: 10 h}
"""


def start(args, cwd):
    """sinsim ARGS in a new process group, stdout and stderr captured."""
    return subprocess.Popen([str(BIN)] + [str(a) for a in args], cwd=cwd, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)


def catches_sigint(pid):
    """Whether the process has installed a SIGINT handler (bit SIGINT - 1 of SigCgt)."""
    try:
        status = pathlib.Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return False
    m = re.search(r"^SigCgt:\s*([0-9a-f]+)$", status, flags=re.M)
    return bool(m) and bool(int(m.group(1), 16) >> (signal.SIGINT - 1) & 1)


def interrupt_like_timeout(proc, after_s):
    """`after_s` after the command catches SIGINT, SIGINT to the process and to its group (what
    `timeout -s INT` sends). Waiting for the handler (SigCgt in /proc) rather than for a fixed time
    keeps a loaded machine's slow start-up from turning the Ctrl-C into a plain kill."""
    deadline = time.time() + 30
    while time.time() < deadline and proc.poll() is None and not catches_sigint(proc.pid):
        time.sleep(0.005)
    time.sleep(after_s)
    assert proc.poll() is None, "the command ended before it could be interrupted"
    os.kill(proc.pid, signal.SIGINT)
    os.killpg(proc.pid, signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    return proc.returncode, out, err


def leftovers(folder):
    """Every file below folder (temporaries are hidden '.NAME.tmp.PID...' files)."""
    return sorted(str(p.relative_to(folder)) for p in pathlib.Path(folder).rglob("*") if p.is_file())


def commands(tmp):
    """(name, argv, outputs that must not appear) of every long command but mc."""
    scenario = tmp / "long.yaml"
    scenario.write_text(LONG_SCENARIO)
    model = SRC / "scenarios" / "adis16355-gm.yaml"
    out = tmp / "out"
    return [
        ("run", ["run", scenario, "-o", out / "run"], [out / "run"]),
        ("synth", ["synth", model, "--duration", "10 h", "--rate", "1000",
                   "-o", out / "synth.csv"], [out / "synth.csv"]),
        ("analyze", ["analyze", RECORD, *LAYOUT, "--json", out / "a.json", "--html", out / "a.html"],
         [out / "a.json", out / "a.html"]),
        ("fit", ["fit", RECORD, *LAYOUT, "-o", out / "fit.yaml"], [out / "fit.yaml"]),
        ("diagnose", ["diagnose", RECORD, *LAYOUT, "--model", model, "--add", "random_walk",
                      "-o", out / "improved.yaml", "--json", out / "d.json", "--html", out / "d.html"],
         [out / "improved.yaml", out / "d.json", out / "d.html"]),
    ]


def check_ctrl_c_stops_with_a_message_and_no_output(tmp_path, name):
    (tmp_path / "out").mkdir()
    _, argv, outputs = next(c for c in commands(tmp_path) if c[0] == name)
    proc = start(argv, tmp_path)
    # 0.2 s after the handler is in place (right after the command line is parsed): run and synth
    # take > 10 s here, but analyze, fit and diagnose read run 1 (10^6 rows of gzip text) for about
    # 0.5 s before they analyse it, and on an idle machine analyze and fit end within 1-2 s.
    code, out, err = interrupt_like_timeout(proc, 0.2)
    assert code == 130, err
    assert f"sinsim {name}: interrupted (Ctrl-C); no output was written" in err
    assert "twice" not in err  # the group's copy of the signal counted as the same Ctrl-C
    for o in outputs:
        assert not o.exists(), o
    assert leftovers(tmp_path / "out") == []


def test_ctrl_c_run(tmp_path):
    check_ctrl_c_stops_with_a_message_and_no_output(tmp_path, "run")


def test_ctrl_c_synth(tmp_path):
    check_ctrl_c_stops_with_a_message_and_no_output(tmp_path, "synth")


def test_ctrl_c_analyze(tmp_path):
    check_ctrl_c_stops_with_a_message_and_no_output(tmp_path, "analyze")


def test_ctrl_c_fit(tmp_path):
    check_ctrl_c_stops_with_a_message_and_no_output(tmp_path, "fit")


def test_ctrl_c_diagnose(tmp_path):
    check_ctrl_c_stops_with_a_message_and_no_output(tmp_path, "diagnose")


def test_sigterm_stops_run_the_same_way_with_143(tmp_path):
    """`kill`, `timeout` and batch systems send SIGTERM: the same clean stop as Ctrl-C (before,
    the default action killed the run and left its hidden temporaries in the new folder)."""
    (tmp_path / "out").mkdir()
    _, argv, outputs = next(c for c in commands(tmp_path) if c[0] == "run")
    proc = start(argv, tmp_path)
    deadline = time.time() + 30
    while time.time() < deadline and proc.poll() is None and not catches_sigint(proc.pid):
        time.sleep(0.005)
    time.sleep(0.3)
    assert proc.poll() is None, "the command ended before it could be stopped"
    os.kill(proc.pid, signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 143, err
    assert "sinsim run: interrupted (SIGTERM); no output was written" in err
    for o in outputs:
        assert not o.exists(), o
    assert leftovers(tmp_path / "out") == []


def test_mc_ctrl_c_keeps_whole_chunks_and_counts_them(tmp_path):
    scenario = tmp_path / "short.yaml"
    scenario.write_text(LONG_SCENARIO.replace("10 h", "60 s"))
    out = tmp_path / "mc"
    proc = start(["mc", scenario, "--runs", "4000", "--threads", "1", "--model",
                  SRC / "scenarios" / "adis16355-gm.yaml", "-o", out], tmp_path)
    deadline = time.time() + 60
    while not list(out.glob("runs/**/*.bin")) and time.time() < deadline:
        time.sleep(0.01)
    code, _, err = interrupt_like_timeout(proc, 0.3)
    assert code == 130, err
    assert "sinsim mc: interrupted (Ctrl-C)" in err and "--resume" in err
    m = re.search(r"(\d+) of 4000 runs saved", err)
    assert m, err
    chunks = list(out.glob("runs/**/*.bin"))
    assert chunks
    # Chunks hold 8 runs (sim/montecarlo.hpp kChunkRuns); 4000 is a multiple of 8.
    assert int(m.group(1)) == 8 * len(chunks)
    assert not (out / "stats.csv").exists()


def test_progress_line_on_a_terminal_only(tmp_path):
    model = SRC / "scenarios" / "adis16355-gm.yaml"
    argv = [str(BIN), "synth", str(model), "--duration", "10 h", "--rate", "1000",
            "-o", str(tmp_path / "x.csv")]
    # Without a terminal: no line.
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    _, _, err = interrupt_like_timeout(proc, 2.0)
    assert "synthesising" not in err
    # On a pseudo-terminal (stdout and stderr): the line with the stage, count, rate and time left.
    master, slave = os.openpty()
    proc = subprocess.Popen(argv, stdout=slave, stderr=slave, start_new_session=True)
    os.close(slave)
    chunks = []
    reader = threading.Thread(target=lambda: read_all(master, chunks))
    reader.start()
    code, _, _ = interrupt_like_timeout(proc, 2.5)
    reader.join(timeout=30)
    os.close(master)
    out = b"".join(chunks).decode("utf-8", "replace")
    assert code == 130
    assert re.search(r"sinsim synth: synthesising \d+/36000000 \(\d+ %\), \d+/s, \d+ s, ~\d+ s left",
                     out), out
    assert "e+" not in out  # no exponent in the rate
    assert "\r\x1b[Ksinsim synth: interrupted (Ctrl-C)" in out  # the line erased first


def read_all(fd, chunks):
    """Reads a pty master until the other side is closed (EIO on Linux)."""
    while True:
        try:
            data = os.read(fd, 4096)
        except OSError:
            return
        if not data:
            return
        chunks.append(data)


if __name__ == "__main__":
    # Runs without pytest too (ctest: `python3 test_interrupt.py`); pytest collects the same tests.
    failed = 0
    for name, fn in sorted(globals().items()):
        if not (name.startswith("test_") and callable(fn)):
            continue
        with tempfile.TemporaryDirectory(prefix="sinsim_cli_") as d:
            try:
                fn(pathlib.Path(d))
                print("PASS", name)
            except Exception:  # noqa: BLE001 - report every failure, then fail
                failed += 1
                print("FAIL", name)
                traceback.print_exc()
    sys.exit(1 if failed else 0)
