#!/usr/bin/env python3
"""Runs on several processes against one (ctest label `mpi`).

  mpi_runs.py CHECK ANVIL DISK_BUDGET_LIBRARY SOURCE_DIR

CHECK is one of:
  upsetting   cases/upsetting.yaml to 2 mm on 2 processes: loads.csv as on 1
  landing     cases/hot_upsetting.yaml to 1.5 mm on 2 processes (its top
              die lands on the chilled end face: the same contact set as
              on 1 process); loads.csv as on 1
  pair        cases/two_cubes.yaml (two deformable bodies, one contact pair)
              on 2 and 3 processes: loads.csv as on 1
  patch       cases/patch_test_cubes.yaml on 2 processes: loads.csv and the
              interface table (interface.csv) as on 1
  resume      stopped after 6 increments on 2 processes, resumed to 2 mm on
              1 and on 3: loads.csv as the uninterrupted run on 1
  repeat      cases/upsetting_75.yaml to 7.5 mm twice on 2 processes (its
              direct solves, its first remesh at 6.9 mm and four increments
              on the new mesh): the same loads.csv and last VTK file, bit
              for bit
  input       an input error on 2 processes: said once, both exit 3
  disk        the disk fills up on rank 0 (its writes fail): one message,
              exit 4, every process stopped, no hang
  alone       one process fails alone (it cannot read its case): it says so,
              the other is stopped, no hang
  default     `anvil run` without mpirun starts itself on every core this
              test may use (ANVIL_PROCESSES unset) and says so in its log;
              --np 1 keeps one process; both give the same loads.csv; a
              Ctrl-C (SIGINT to anvil) on --np 2 checkpoints, exits 130
              and the run resumes to the uninterrupted one's loads

Agreement: the Newton tolerance of the cases is 1e-6 of the relative
residual; each run's loads carry that error, accumulated over the geometry
updates of up to 20 increments, so two runs may differ by up to ten times
it: 1e-5 of the peak load."""
import filecmp
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_loads  # noqa: E402

AGREEMENT = 1e-5
TIMEOUT = 600  # s: a hang fails the test instead of the CI job


def mpirun(arguments):
    """mpirun --oversubscribe ARGUMENTS (as root, as CI runs it)."""
    environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return subprocess.run(["mpirun", "--oversubscribe"] + arguments, capture_output=True, text=True, errors="replace",
                          env=environment, timeout=TIMEOUT)


class Checks:
    def __init__(self, anvil, library, source, work):
        self.anvil, self.library, self.source, self.work = anvil, library, source, work
        self.failures = []

    def case(self, name):
        return os.path.join(self.source, "cases", name)

    def run(self, processes, case, out, *extra, code=0):
        result = mpirun(["-n", str(processes), self.anvil, "run", case, "-o", os.path.join(self.work, out)] + list(extra))
        self.expect(result.returncode == code, f"{out}: exit {result.returncode}\n{result.stderr[-2000:]}")
        return result

    def expect(self, condition, message):
        if not condition:
            self.failures.append(message)
        return condition

    def agree(self, reference, other, table="loads.csv"):
        path = lambda run: os.path.join(self.work, run, table)  # noqa: E731
        if table == "loads.csv":
            worst, same = compare_loads.compare(compare_loads.rows(path(reference)), compare_loads.rows(path(other)))
        else:
            worst, same = compare_tables(path(reference), path(other))
        print(f"{other} against {reference}: {table} differs by {worst:.2e}" + ("" if same else ", rows differ"))
        self.expect(same, f"{other}: {table} has other rows than {reference}")
        self.expect(worst <= AGREEMENT, f"{other}: {table} differs from {reference} by {worst:.2e} > {AGREEMENT}")

    def same_as_one(self, case, counts, *extra):
        """CASE on 1 process and on each of COUNTS: loads.csv as on 1."""
        for n in (1,) + counts:
            self.run(n, self.case(case), f"np{n}", *extra)
        for n in counts:
            self.agree("np1", f"np{n}")

    def upsetting(self):
        self.same_as_one("upsetting.yaml", (2,), "--set", "time.stop.stroke=2")

    def landing(self):
        self.same_as_one("hot_upsetting.yaml", (2,), "--set", "time.stop.stroke=1.5")

    def pair(self):
        self.same_as_one("two_cubes.yaml", (2, 3))

    def patch(self):
        self.same_as_one("patch_test_cubes.yaml", (2,))
        self.agree("np1", "np2", "interface.csv")

    def resume(self):
        case = self.case("upsetting.yaml")
        self.run(1, case, "whole", "--set", "time.stop.stroke=2")
        for n in (1, 3):  # stopped after increment 6 of about 14
            self.run(2, case, f"to_np{n}", "--set", "time.stop.stroke=2", "--set", "time.max_increments=6",
                     code=4)  # stopped before its stop criterion
            self.run(n, case, f"to_np{n}", "--set", "time.stop.stroke=2", "--resume", os.path.join(self.work, f"to_np{n}"))
            self.agree("whole", f"to_np{n}")

    def repeat(self):
        case = self.case("upsetting_75.yaml")
        for out in ("first", "second"):
            self.run(2, case, out, "--set", "time.stop.stroke=7.5", "--set", "output.vtk_every=50")
        for name in ("loads.csv", "anvil_billet_000050.vtu"):
            files = [os.path.join(self.work, out, name) for out in ("first", "second")]
            if self.expect(all(os.path.exists(f) for f in files), f"{name} missing"):
                same = filecmp.cmp(files[0], files[1], shallow=False)
                print(f"{name}: {'the same bytes' if same else 'different'} in the two runs")
                self.expect(same, f"{name} differs between two runs of the same input on 2 processes")

    def input(self):
        bad = os.path.join(self.work, "bad.yaml")
        with open(self.case("two_cubes.yaml")) as f:
            text = f.read()
        with open(bad, "w") as f:
            f.write(text.replace("contact_pairs:", "contact_pairs:\n  - {master: nowhere, slave: lower}\n", 1))
        result = mpirun(["-n", "2", self.anvil, "run", bad, "-o", os.path.join(self.work, "bad")])
        print(result.stderr.strip())
        self.expect(result.returncode == 3, f"exit {result.returncode}, expected 3")
        self.expect(result.stderr.count("input error") == 1, "the input error is not said exactly once")

    def disk(self):
        # Rank 0 with a disk that is full after 20 kB: its first VTK file fails.
        out = os.path.join(self.work, "full")
        result = mpirun(["-n", "1", "-x", f"LD_PRELOAD={self.library}", "-x", "ANVIL_TEST_DISK_BYTES=20000", self.anvil,
                         "run", self.case("upsetting.yaml"), "-o", out, ":",
                         "-n", "1", self.anvil, "run", self.case("upsetting.yaml"), "-o", out])
        print(result.stderr.strip())
        self.expect(result.returncode == 4, f"exit {result.returncode}, expected 4")
        self.expect(result.stderr.count("anvil: run stopped") == 1, "the failure is not said exactly once")
        self.expect("No space left" in result.stderr or "full" in result.stderr, "the message does not say the disk is full")

    def alone(self):
        out = os.path.join(self.work, "alone")
        result = mpirun(["-n", "1", self.anvil, "run", self.case("upsetting.yaml"), "-o", out, ":",
                         "-n", "1", self.anvil, "run", os.path.join(self.work, "missing.yaml"), "-o", out])
        print(result.stderr.strip()[-3000:])
        self.expect(result.returncode != 0, "exit 0 although a process failed")
        self.expect("missing.yaml" in result.stderr, "the failing process does not say why")
        self.expect("failed alone" in result.stderr, "the failing process does not say it stops the others")


    def default(self):
        case = self.case("upsetting.yaml")
        environment = {k: v for k, v in os.environ.items() if k != "ANVIL_PROCESSES"}
        environment.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        cores = len(os.sched_getaffinity(0))

        def anvil(out, *extra, code=0):
            result = subprocess.run([self.anvil, "run", case, "-o", os.path.join(self.work, out),
                                     "--set", "time.stop.stroke=2"] + list(extra),
                                    capture_output=True, text=True, errors="replace", env=environment, timeout=TIMEOUT)
            self.expect(result.returncode == code, f"{out}: exit {result.returncode}, expected {code}\n{result.stderr[-2000:]}")
            return result

        def processes(out):
            with open(os.path.join(self.work, out, "anvil.log")) as f:
                found = re.search(r"(\d+) process(es)? x (\d+) thread", f.read())
            return int(found.group(1)) if found else None

        anvil("cores")
        anvil("one", "--np", "1")
        print(f"default: {processes('cores')} processes on {cores} cores; --np 1: {processes('one')}")
        self.expect(processes("cores") == cores, f"the default run used {processes('cores')} processes, not {cores}")
        self.expect(processes("one") == 1, "--np 1 did not keep one process")
        self.agree("one", "cores")
        # Ctrl-C reaches anvil alone (mpirun runs in its own session): it is
        # passed on, the processes checkpoint the last accepted increment.
        out = os.path.join(self.work, "stopped")
        run = subprocess.Popen([self.anvil, "run", case, "-o", out, "--set", "time.stop.stroke=2", "--np", "2"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=environment)
        for line in run.stdout:
            if line.startswith("inc    3"):
                run.send_signal(signal.SIGINT)
                break
        _, errors = run.communicate(timeout=TIMEOUT)
        print(errors.strip()[-600:])
        self.expect(run.returncode == 130, f"Ctrl-C on --np 2: exit {run.returncode}, expected 130")
        self.expect("resume with" in errors, "Ctrl-C on --np 2: no resume command")
        anvil("stopped", "--np", "2", "--resume", out)
        self.agree("one", "stopped")


def compare_tables(reference, other):
    """Largest difference of two CSV tables of numbers, relative to the largest magnitude in each column."""
    def read(path):
        with open(path) as f:
            lines = [line.rstrip("\n").split(",") for line in f if line.strip()]
        return lines[0], lines[1:]
    head_a, rows_a = read(reference)
    head_b, rows_b = read(other)
    if head_a != head_b or len(rows_a) != len(rows_b):
        return float("inf"), False
    worst = 0.0
    for column in range(len(head_a)):
        try:
            a = [float(r[column]) for r in rows_a]
            b = [float(r[column]) for r in rows_b]
        except ValueError:
            if any(x[column] != y[column] for x, y in zip(rows_a, rows_b)):
                return float("inf"), False
            continue
        scale = max((abs(x) for x in a), default=0.0) or 1.0
        worst = max([worst] + [abs(x - y) / scale for x, y in zip(a, b)])
    return worst, True


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    check, anvil, library, source = sys.argv[1:]
    work = tempfile.mkdtemp(prefix=f"anvil_mpi_{check}_")
    try:
        checks = Checks(anvil, library, source, work)
        getattr(checks, check)()
        for failure in checks.failures:
            print("FAILED:", failure)
        return 1 if checks.failures else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
