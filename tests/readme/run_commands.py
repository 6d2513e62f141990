#!/usr/bin/env python3
"""Runs every fenced shell command of a Markdown guide as a user would, from a fresh checkout.

    run_commands.py DOC SOURCE_DIR BUILD_DIR SHARED_DIR

Each ```sh block of DOC (except the first block of README.md: the install and test commands this
very test runs under) is run with /bin/sh -e in a scratch copy of the repository layout: the
source tree's files are linked in, `build` points at BUILD_DIR and `../shared` at SHARED_DIR, so
the commands write their `out/` there and never into the source tree. A block fails when its exit
status is not 0 or a file it names with -o / --html / --json is missing afterwards. Prints one
line per block and the plain summary line "N passed, M failed".
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time


def blocks(text):
    """The bodies of the ```sh fences, in order, with the line each starts on."""
    out = []
    for m in re.finditer(r"^```sh\n(.*?)^```", text, flags=re.S | re.M):
        out.append((text.count("\n", 0, m.start()) + 1, m.group(1)))
    return out


def named_outputs(body):
    """Files a block says it writes (-o FILE, --html FILE, --json FILE) that are not folders."""
    files = []
    for m in re.finditer(r"(?:--html|--json)\s+(\S+)", body):
        files.append(m.group(1))
    return [f for f in files if "$" not in f]


def main():
    doc, source, build, shared = sys.argv[1:5]
    # --no-python: this build has no Python module (the sanitizer build): blocks that import it
    # are reported as skipped, not passed; the plain build runs them.
    no_python = "--no-python" in sys.argv[5:]
    text = open(doc, encoding="utf-8").read()
    todo = blocks(text)
    if os.path.basename(doc) == "README.md" and todo:
        todo = todo[1:]  # the two commands that install and run this test
    scratch = tempfile.mkdtemp(prefix="sinsim-doc-")
    repo = os.path.join(scratch, "repo")
    os.mkdir(repo)
    for name in os.listdir(source):
        if name in ("build", "out", ".git") or name.startswith("build"):
            continue
        os.symlink(os.path.join(source, name), os.path.join(repo, name))
    os.symlink(build, os.path.join(repo, "build"))
    os.symlink(shared, os.path.join(scratch, "shared"))
    passed = failed = skipped = 0
    try:
        for line, body in todo:
            if no_python and "build/python" in body:
                print(f"skip {os.path.basename(doc)}:{line} (needs the Python module, not in this build)")
                skipped += 1
                continue
            t0 = time.time()
            r = subprocess.run(["/bin/sh", "-ec", body], cwd=repo, capture_output=True, text=True)
            missing = [f for f in named_outputs(body) if not os.path.exists(os.path.join(repo, f))]
            ok = r.returncode == 0 and not missing
            took = time.time() - t0
            print(f"{'ok  ' if ok else 'FAIL'} {os.path.basename(doc)}:{line} ({took:.1f} s)")
            if not ok:
                failed += 1
                print(body)
                print(f"exit {r.returncode}; missing outputs: {missing}")
                print("stdout:", r.stdout[-3000:])
                print("stderr:", r.stderr[-3000:])
            else:
                passed += 1
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    print(f"{passed} passed, {failed} failed" + (f", {skipped} skipped" if skipped else ""))
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main())
