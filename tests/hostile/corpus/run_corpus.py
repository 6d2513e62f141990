#!/usr/bin/env python3
"""Runs sinsim on every case of a hostile corpus (make_corpus.py) and classifies what happened.

    run_corpus.py SINSIM CORPUS [-j N] [--timeout 15] [--memory-mb 1536] [--report FILE]
    run_corpus.py SINSIM DIR --make --fast     # write the fast slice into DIR and run it (ctest)

Each command runs in a fresh scratch folder, under a wall-clock timeout and an address-space
limit (setrlimit RLIMIT_AS, as `ulimit -v`). Classes, worst first (a run gets the first that
applies):

  hang            still running at the timeout (killed)
  over-memory     std::bad_alloc / out of memory, or a peak RSS above the limit
  crash           killed by a signal (segfault, abort, ...)
  internal-error  "internal error" on stderr (an exception other than sinsim's own)
  accepted-nonsense  exit 0 on an input that must be refused
  nonsense-output exit 0 but NaN / inf / null in an output file, or a written model that does
                  not load back (`sinsim synth MODEL` refuses it)
  unnamed-error   exit != 0 but the message does not name the input file (or option)
  leftover        an output file, folder or temporary (*.tmp*) left behind after an error
                  (or a temporary after success)
  flood           more than 64 KB on stderr
  refused         a clear error (not a finding)
  ok              exit 0, outputs clean (not a finding)

Exit status 1 if any run is a finding. Prints counts per class and every finding.
"""
import argparse
import concurrent.futures
import json
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

FINDINGS = ["hang", "over-memory", "crash", "internal-error", "accepted-nonsense",
            "nonsense-output", "unnamed-error", "leftover", "flood"]
CLASSES = FINDINGS + ["refused", "ok"]
NONSENSE = re.compile(rb"(?i)(?<![A-Za-z_])(nan|-?inf|infinity|null)(?![A-Za-z_])")
# Documented markers that are not nonsense: diagnose's JSON writes "ljung_box": null for a channel
# without the test. (The aided filter.csv used to write nis = nan without a GNSS fix: now empty.)
ALLOWED = [re.compile(rb'"ljung_box": null')]


def limited(memory_bytes):
    def pre():
        os.setsid()
        if memory_bytes:  # 0: no limit (a sanitizer build reserves terabytes of address space)
            resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    return pre


def execute(argv, cwd, timeout, memory_bytes):
    """(status, stderr bytes, peak RSS in bytes, timed out, seconds)."""
    with open(os.path.join(cwd, ".stdout"), "wb") as out, \
            open(os.path.join(cwd, ".stderr"), "wb") as err:
        t0 = time.monotonic()
        proc = subprocess.Popen(argv, cwd=cwd, stdout=out, stderr=err, stdin=subprocess.DEVNULL,
                                preexec_fn=limited(memory_bytes))
        timed_out = False
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() - t0 > timeout:
                timed_out = True
                os.killpg(proc.pid, signal.SIGKILL)
                pid, status, usage = os.wait4(proc.pid, 0)
                break
            time.sleep(0.01)
        proc.returncode = 0  # reaped here, keep Popen from waiting again
    with open(os.path.join(cwd, ".stderr"), "rb") as f:
        stderr = f.read()
    return status, stderr, usage.ru_maxrss * 1024, timed_out, time.monotonic() - t0


def output_files(scratch):
    for dirpath, _, files in os.walk(scratch):
        for f in files:
            if not f.startswith("."):
                yield os.path.join(dirpath, f)


def model_loads_back(sinsim, model, scratch, timeout, memory_bytes):
    """None if `sinsim synth` takes the model, else its message."""
    text = open(model, "rb").read().decode("utf-8", "replace")
    rates = [float(x) for x in re.findall(r"rate: ([0-9.eE+-]+) Hz", text)] or [100.0]
    rate = max(1.0, min(1000.0, max(rates)))
    check = os.path.join(scratch, ".loadback")
    os.makedirs(check, exist_ok=True)
    status, stderr, _, timed_out, _ = execute(
        [sinsim, "synth", model, "--rate", f"{rate:g}", "--duration", "2", "-o", "x.csv"],
        check, timeout, memory_bytes)
    if timed_out or not os.WIFEXITED(status) or os.WEXITSTATUS(status) != 0:
        return stderr.decode("utf-8", "replace").strip()[:300] or "synth timed out"
    return None


def classify(case, argv, outputs, scratch, sinsim, opts):
    status, stderr, rss, timed_out, seconds = execute(argv, scratch, opts.timeout,
                                                      opts.memory_mb << 20)
    text = stderr.decode("utf-8", "replace")
    r = {"case": case["name"], "kind": case["kind"], "command": argv[1], "seconds": seconds,
         "rss_mb": rss >> 20, "stderr": text[:400]}
    code = os.WEXITSTATUS(status) if os.WIFEXITED(status) else None
    names = case["names"] if case["names"] is not None else (
        [case["input"]] if case["kind"] in ("scenario", "model", "record") else [])

    def done(cls, detail=""):
        r["class"], r["detail"] = cls, detail
        return r

    if timed_out:
        return done("hang", f"killed after {opts.timeout} s")
    if ("bad_alloc" in text or "out of memory" in text.lower() or
            (opts.memory_mb and rss > (opts.memory_mb << 20))):
        return done("over-memory", f"peak RSS {rss >> 20} MB")
    if os.WIFSIGNALED(status):
        return done("crash", f"signal {os.WTERMSIG(status)}")
    if "internal error" in text:
        return done("internal-error")
    temporaries = [f for f in output_files(scratch) if ".tmp" in os.path.basename(f)]
    if code == 0:
        if case["expect"] == "reject":
            return done("accepted-nonsense", "exit 0 on an input that must be refused")
        for f in output_files(scratch):
            if ".loadback" in f:
                continue
            with open(f, "rb") as fh:
                data = fh.read(64 << 20)
            for allowed in ALLOWED:
                data = allowed.sub(b"", data)
            m = NONSENSE.search(data)
            if m:
                return done("nonsense-output", f"{os.path.relpath(f, scratch)}: "
                                               f"'{m.group(0).decode()}'")
            if f.endswith(".yaml"):
                why = model_loads_back(sinsim, f, scratch, opts.timeout, opts.memory_mb << 20)
                if why:
                    return done("nonsense-output", f"{os.path.basename(f)} does not load back: "
                                                   f"{why}")
        if temporaries:
            return done("leftover", ", ".join(os.path.relpath(t, scratch) for t in temporaries))
        if len(stderr) > 65536:
            return done("flood", f"{len(stderr)} bytes on stderr")
        return done("ok")
    if case["expect"] == "accept":
        r["detail"] = "refused a valid input"
    # The message names the input file, or the option the bad value came from.
    names = names + [a for a in argv if a.startswith("--") and len(a) > 2]
    if names and not any(n and (n in text or os.path.basename(n) in text) for n in names):
        return done("unnamed-error", "message names none of: " + ", ".join(
            os.path.basename(n) for n in names))
    left = [o for o in outputs if os.path.lexists(o)] + temporaries
    if left:
        return done("leftover", ", ".join(os.path.relpath(o, scratch) for o in left))
    if len(stderr) > 65536:
        return done("flood", f"{len(stderr)} bytes on stderr")
    return done("refused", r.get("detail", ""))


def run_case(case, index, bases, corpus, sinsim, opts, work):
    results = []
    source = os.path.join(corpus, case["kind"], case["name"])
    case = dict(case, input=source)
    for k, template in enumerate(case["commands"]):
        scratch = os.path.join(work, f"{index:04d}-{k}")
        os.makedirs(scratch)
        out = os.path.join(scratch, "out")
        subst = dict(bases, IN=source, OUT=out, TMP=scratch)
        argv = [sinsim] + [re.sub(r"\{(\w+)\}", lambda m: subst.get(m.group(1), m.group(0)), a)
                           for a in template]
        outputs = [out + ext for ext in ("", ".csv", ".json", ".yaml", ".html")]
        r = classify(case, argv, outputs, scratch, sinsim, opts)
        r["argv"] = " ".join(a if len(a) < 80 else a[:77] + "..." for a in argv[1:])
        results.append(r)
        shutil.rmtree(scratch, ignore_errors=True)
    return results


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("sinsim")
    ap.add_argument("corpus")
    ap.add_argument("-j", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=15)
    ap.add_argument("--memory-mb", type=int, default=1536)
    ap.add_argument("--only", help="regular expression on case names")
    ap.add_argument("--make", action="store_true",
                    help="write the corpus into CORPUS first (make_corpus.py)")
    ap.add_argument("--fast", action="store_true", help="with --make: only the fast slice")
    ap.add_argument("--report", help="write every result as JSON here")
    opts = ap.parse_args()
    sinsim = os.path.abspath(opts.sinsim)
    if opts.make:
        shutil.rmtree(opts.corpus, ignore_errors=True)
        subprocess.run([sys.executable, os.path.join(os.path.dirname(__file__), "make_corpus.py")]
                       + (["--fast"] if opts.fast else []) + [opts.corpus], check=True)
    manifest = json.load(open(os.path.join(opts.corpus, "manifest.json")))
    cases = [c for c in manifest["cases"] if not opts.only or re.search(opts.only, c["name"])]
    work = tempfile.mkdtemp(prefix="sinsim-corpus-")
    t0 = time.monotonic()
    results = []
    with concurrent.futures.ThreadPoolExecutor(opts.j) as pool:
        futures = [pool.submit(run_case, c, i, manifest["bases"], os.path.abspath(opts.corpus),
                               sinsim, opts, work) for i, c in enumerate(cases)]
        for f in futures:
            results += f.result()
    shutil.rmtree(work, ignore_errors=True)
    counts = {cls: sum(1 for r in results if r["class"] == cls) for cls in CLASSES}
    findings = [r for r in results if r["class"] in FINDINGS]
    for r in findings:
        print(f"{r['class']:17s} {r['kind']}/{r['case']}: sinsim {r['argv']}\n"
              f"{'':17s} {r['detail']} | {r['stderr'].strip()[:300]!r}")
    print(f"{len(cases)} cases, {len(results)} runs in {time.monotonic() - t0:.0f} s: " +
          ", ".join(f"{k} {v}" for k, v in counts.items()))
    slow = sorted(results, key=lambda r: -r["seconds"])[:5]
    print("slowest: " + ", ".join(f"{r['case']} ({r['command']}) {r['seconds']:.1f} s"
                                  for r in slow))
    print(f"largest peak RSS: {max((r['rss_mb'] for r in results), default=0)} MB")
    if opts.report:
        with open(opts.report, "w") as f:
            json.dump({"counts": counts, "results": results}, f, indent=1)
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
