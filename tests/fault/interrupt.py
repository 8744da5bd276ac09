#!/usr/bin/env python3
"""Ctrl-C during a run (ctest label `fault`).

A run interrupted part-way must finish or abandon its increment, checkpoint the
last accepted one, say where it is and the command that resumes it, and exit
130 (SIGINT); resumed with that command, it ends exactly as the uninterrupted
run (loads.csv identical). Checked on one process (SIGINT), on two processes
under mpirun (SIGUSR1, as anvil run passes Ctrl-C on: mpirun forwards it to
every process), and for a second Ctrl-C, which stops the run at once. Each
with the direct solver and with FGMRES, whose preconditioner set-up is kept
from one increment to the next: the checkpoint carries it
(solver/KeptSetUp.h), and without it the resumed run solved on a new set-up
and parted from the uninterrupted one. Also part-way through an increment
of a closed die that set up anew the preconditioner the increment before
had kept: the checkpoint carries the kept one.

  interrupt.py ANVIL
"""
import filecmp
import os
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "corpus"))
import corpus  # noqa: E402  the corpus's base case, finer and longer: a few seconds a run

CASE = corpus.swap("stop: {stroke: 1}", "stop: {stroke: 3}",
                   corpus.swap("element_size: 2.5", "element_size: 1.0",
                               corpus.swap("stroke_increment: 0.5", "stroke_increment: 0.1",
                                           corpus.swap("  checkpoint_every: 1", "  checkpoint_every: 1000\n"
                                                       "  picture: false"))))
CASES = {"direct solver": CASE, "fgmres": CASE + "solver: {linear_solver: fgmres}\n",
         # FGMRES stopped after 5 iterations: MUMPS takes over for the mesh, and the checkpoint says so
         "fgmres taken over by MUMPS": CASE + "solver: {linear_solver: fgmres, petsc_options: '-ksp_max_it 5'}\n"}
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# The hub flange's first 1.5 mm (15 increments, FGMRES): its closed die
# sets a kept preconditioner up anew part-way through most increments.
with open(os.path.join(ROOT, "cases", "closed_die_flash.yaml")) as f:
    CLOSED_DIE = (f.read().replace("../dies/", ROOT + "/dies/").replace("../materials/", ROOT + "/materials/")
                  .replace("stop: {stroke: 10.7}", "stop: {stroke: 1.5}")
                  .replace("\noutput:\n", "\noutput:\n  vtk: false\n  picture: false\n  checkpoint_every: 1000\n"))
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_btl="self,vader")


def interrupted_run(command, sig, after, twice=False, part_way=False):
    """Starts `command`, sends `sig` once its progress lines (flushed to
    standard output line by line) show `after` accepted increments, and when
    `twice` again as soon as it says it was interrupted, while it writes its
    outputs; returns (exit code, stderr, seconds from the first signal to the end).
    With `part_way` (the command runs --verbose), the signal waits further for
    an increment whose first Newton iteration solved on the preconditioner the
    increment before kept and a later one on a new set-up: the increment the
    signal abandons has replaced the set-up the checkpoint must carry."""
    run = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=MPI_ENV,
                           start_new_session=True)
    accepted, sent, first_newton, kept_from_before = 0, None, True, False
    for line in run.stdout:
        accepted += line.startswith("inc ")
        if line.startswith("inc "):
            first_newton = True
        elif line.lstrip().startswith("newton ") and "fgmres iterations" in line:
            new_set_up = "on a new set-up" in line
            if first_newton:
                kept_from_before, first_newton = not new_set_up, False
            elif new_set_up and kept_from_before and part_way and sent is None and accepted >= after:
                sent = time.time()
                run.send_signal(sig)
                continue
        if sent is None and accepted >= after and not part_way:
            sent = time.time()
            run.send_signal(sig)
        elif twice and line.startswith("interrupted by"):
            run.send_signal(sig)
            twice = False
    _, err = run.communicate(timeout=300)
    if sent is None:
        raise SystemExit("FAIL: the run ended before increment %d%s" %
                         (after, ", or no later increment replaced its kept preconditioner part-way" if part_way else ""))
    return run.returncode, err, time.time() - sent


def check_interrupt_and_resume(anvil, work, case, prefix, sig, code, part_way=False):
    whole, stopped = os.path.join(work, "whole"), os.path.join(work, "stopped")
    for folder in (whole, stopped):
        shutil.rmtree(folder, ignore_errors=True)
    done = subprocess.run(prefix + [anvil, "run", case, "-o", whole], capture_output=True, text=True, env=MPI_ENV)
    if done.returncode != 0:
        return ["the uninterrupted run failed: " + done.stderr]
    verbose = ["--verbose"] if part_way else []
    rc, err, _ = interrupted_run(prefix + [anvil, "run", case, "-o", stopped] + verbose, sig, 3, part_way=part_way)
    print("interrupted after 3 increments%s: exit %d\n%s" %
          (" and part-way through a later one that set its preconditioner up anew" if part_way else "", rc, err))
    problems = []
    if rc != code:
        problems.append("exit %d, expected %d" % (rc, code))
    lines = err.strip().splitlines()
    if not lines or not lines[0].startswith("anvil: interrupted by") or "checkpoint.h5" not in lines[0]:
        problems.append("the first line does not say the run was interrupted and where its checkpoint is")
    resume = [line.strip() for line in lines if line.strip().startswith(anvil + " run ")]
    if not resume:
        return problems + ["no resume command"]
    words = shlex.split(resume[0])
    if words[-2:] != ["--resume", stopped]:
        problems.append("the resume command does not name the run's folder: " + resume[0])
    done = subprocess.run(prefix + [anvil] + words[1:], capture_output=True, text=True, env=MPI_ENV)
    if done.returncode != 0:
        return problems + ["the resume command failed: " + done.stderr]
    if not filecmp.cmp(os.path.join(whole, "loads.csv"), os.path.join(stopped, "loads.csv"), False):
        problems.append("resumed, loads.csv differs from the uninterrupted run's")
    return problems


def check_second_interrupt(anvil, work):
    stopped = os.path.join(work, "twice")
    rc, err, seconds = interrupted_run([anvil, "run", os.path.join(work, "case.yaml"), "-o", stopped], signal.SIGINT,
                                       3, twice=True)
    print("a second Ctrl-C while the outputs are written: exit %d after %.2f s\n%s" % (rc, seconds, err))
    problems = []
    if rc != 130 or err.strip() != "anvil: stopped at once (second interrupt); the last checkpoint is kept":
        problems.append("the second Ctrl-C did not stop the run at once")
    if seconds > 5:
        problems.append("the run took %.1f s to stop" % seconds)
    return problems


def main():
    anvil = sys.argv[1]
    work = tempfile.mkdtemp(prefix="anvil_interrupt_")
    try:
        problems = []
        for solver, text in CASES.items():
            case = os.path.join(work, solver.replace(" ", "_") + ".yaml")
            with open(case, "w") as f:
                f.write(text)
            problems += ["1 process, %s: %s" % (solver, p)
                         for p in check_interrupt_and_resume(anvil, work, case, [], signal.SIGINT, 130)]

            if shutil.which("mpirun"):
                mpirun = ["mpirun", "-q", "-n", "2", "--oversubscribe"]
                problems += ["2 processes, %s: %s" % (solver, p)
                             for p in check_interrupt_and_resume(anvil, work, case, mpirun, signal.SIGUSR1, 128 + 10)]
        if not shutil.which("mpirun"):
            print("mpirun is not installed: the 2-process checks are skipped")
        case = os.path.join(work, "closed_die.yaml")
        with open(case, "w") as f:
            f.write(CLOSED_DIE)
        problems += ["1 process, closed die, part-way through an increment: " + p
                     for p in check_interrupt_and_resume(anvil, work, case, [], signal.SIGINT, 130, True)]
        with open(os.path.join(work, "case.yaml"), "w") as f:
            f.write(CASE)
        problems += ["second Ctrl-C: " + p for p in check_second_interrupt(anvil, work)]
        if problems:
            print("FAIL: " + "; ".join(problems))
            return 1
        print("ok")
        return 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
