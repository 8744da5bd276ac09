"""One case run by build/anvil for a study tool, and what it wrote.

run_case(tool, case, out, settings, anvil, resume) runs cases/<case>.yaml with
`anvil` (build/anvil unless given) into `out` with the --set `settings` (no
picture), quietly (with resume, on from the checkpoint in `out`, the settings
allowed to change), and returns its summary.json with
"stopped": the last line the run said when it stopped early (empty when it
reached its stop), so a tool can report the run rather than drop it.
"""
import json
import os
import subprocess

import doc_figures

ROOT = doc_figures.ROOT
ANVIL = os.path.join(ROOT, "build", "anvil")  # this checkout's build


def run_case(tool, case, out, settings=(), anvil=ANVIL, resume=False):
    where = ["--resume", out, "--allow-changes"] if resume else ["-o", out]
    command = [anvil, "run", os.path.join(ROOT, "cases", case + ".yaml"), *where, "--set", "output.picture=false"]
    for s in settings:
        command += ["--set", s]
    print(f"{tool}: {case} ...", flush=True)
    run = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    summary["stopped"] = run.stderr.strip().splitlines()[-1] if run.returncode else ""
    return summary
