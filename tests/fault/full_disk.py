#!/usr/bin/env python3
"""A disk that fills up during a run (ctest label `fault`).

Runs a small time-stepping case with ever larger disk budgets (the preloaded
disk_budget library fails every write past the budget with ENOSPC, as a full
disk does) and checks, for every budget that stops the run:
  - exit code 4, never a signal, and one message on stderr that names the
    file and says the disk is full;
  - no torn file under a final name: every .vtu and the .pvd end with their
    closing tag, loads.csv holds whole rows, summary.json (when written) is
    whole, no *.tmp file is left;
  - the last checkpoint is intact: resumed with the disk free again, the run
    ends exactly as a run that never met a full disk (loads.csv identical).

  full_disk.py ANVIL DISK_BUDGET_LIBRARY
"""
import filecmp
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "corpus"))
import corpus  # noqa: E402  the corpus's base case, on a finer mesh and a longer stroke

CASE = corpus.swap("stop: {stroke: 1}", "stop: {stroke: 2}",
                   corpus.swap("element_size: 2.5", "element_size: 1.5",
                               corpus.swap("stroke_increment: 0.5", "stroke_increment: 0.4")))


def run(anvil, args, budget=None, library=None):
    env = dict(os.environ)
    if budget is not None:
        env["LD_PRELOAD"] = library
        env["ANVIL_TEST_DISK_BYTES"] = str(budget)
    return subprocess.run([anvil] + args, capture_output=True, text=True, errors="replace", env=env, timeout=600)


def torn_files(out):
    """The files of `out` that are not whole."""
    torn = []
    for name in sorted(os.listdir(out)):
        path = os.path.join(out, name)
        with open(path, "rb") as f:
            data = f.read()
        if name.endswith(".tmp"):
            torn.append(name + " (a temporary file left behind)")
        elif name.endswith(".vtu") or name.endswith(".pvd"):
            if not data.rstrip().endswith(b"</VTKFile>"):
                torn.append(name)
        elif name == "loads.csv":
            lines = data.decode(errors="replace").split("\n")
            if lines[-1] != "" or any(len(line.split(",")) != 10 for line in lines[:-1]):  # io::kLoadsColumns
                torn.append(name)
        elif name == "summary.json":
            if not data.rstrip().endswith(b"}"):
                torn.append(name)
    return torn


def main():
    anvil, library = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="anvil_full_disk_")
    failures = []
    try:
        case = os.path.join(work, "case.yaml")
        with open(case, "w") as f:
            f.write(CASE)
        reference = os.path.join(work, "reference")
        done = run(anvil, ["run", case, "-o", reference])
        if done.returncode != 0:
            print(done.stderr)
            print("FAIL: the case does not run on a free disk")
            return 1
        stopped = 0
        budget = 2000
        while True:
            out = os.path.join(work, "out_%d" % budget)
            done = run(anvil, ["run", case, "-o", out], budget, library)
            message = done.stderr.strip()
            if done.returncode == 0:
                print("budget %8d bytes: the run completes" % budget)
                break
            stopped += 1
            problems = []
            if done.returncode != 4:
                problems.append("exit %d, expected 4" % done.returncode)
            lines = [line for line in message.splitlines() if line]
            if len(lines) != 1 or not lines[0].startswith("anvil: run stopped: "):
                problems.append("stderr is not one message: %r" % message)
            elif "no space left" not in message.lower() or out not in message:
                problems.append("the message does not name the file and the full disk: %r" % message)
            torn = torn_files(out)
            if torn:
                problems.append("torn files: " + ", ".join(torn))
            resumed = "no checkpoint yet"
            if os.path.exists(os.path.join(out, "checkpoint.h5")):
                again = run(anvil, ["run", case, "--resume", out])
                if again.returncode != 0:
                    problems.append("resume failed: exit %d: %s" % (again.returncode, again.stderr.strip()))
                elif not filecmp.cmp(os.path.join(out, "loads.csv"), os.path.join(reference, "loads.csv"), False):
                    problems.append("the resumed run's loads.csv differs from the uninterrupted run's")
                else:
                    resumed = "resumed to the same loads.csv"
            print("budget %8d bytes: exit %d, %s; %s" % (budget, done.returncode, lines[0] if lines else "",
                                                          resumed))
            if problems:
                failures.append("budget %d: %s" % (budget, "; ".join(problems)))
                print("  FAIL: " + "; ".join(problems))
            budget = int(budget * 1.25)
        if stopped < 10:
            failures.append("only %d budgets stopped the run: the test did not reach every writer" % stopped)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        return 1
    print("ok: %d full-disk stops, each clean" % stopped)
    return 0


if __name__ == "__main__":
    sys.exit(main())
