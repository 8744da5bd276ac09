"""The agreement table of docs/parallel-runs.md, from tools/mpi_agreement's runs.

    mpi_tables.py [--block NAME [--command TEXT]] DIR CASE ...
        DIR/<case>/np1, np2, np3 (loads.csv, summary.json); TEXT, the
        command that made the runs, heads the block

Per case and process count: the largest difference of a force component
from the one-process run over its peak load (and of the press load Fz), up to
the first remesh; past it, at equal time (tests/mpi/compare_loads.py), the
largest and the mean. Into block NAME of docs/parallel-runs.md (default:
agreement, the table of every case).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import doc_figures  # noqa: E402

sys.path.insert(0, os.path.join(doc_figures.ROOT, "tests", "mpi"))
import compare_loads  # noqa: E402


def cell(reference_path, other_path):
    everything, other_everything = compare_loads.rows(reference_path), compare_loads.rows(other_path)
    remesh = compare_loads.first_remesh(reference_path)
    reference = everything if remesh is None else compare_loads.up_to(everything, remesh - 1)
    other = other_everything if remesh is None else compare_loads.up_to(other_everything, remesh - 1)
    worst, _, same = compare_loads.largest_difference(reference, other)
    press = compare_loads.largest_difference(reference, other, ("model_Fz_N",))[0]
    text = f"{worst:.1e} (Fz {press:.1e})" + ("" if same else ", other rows")
    if remesh is not None:
        after = compare_loads.at_equal_time(everything, other_everything, remesh - 1)["model_Fz_N"]
        text += f"; after remesh 1: Fz {max(after, default=0.0):.1e}"
        if after:
            text += f" (mean {sum(after) / len(after):.1e})"
    return text


def main(directory, cases, block="agreement", command=""):
    lines = []
    for case in cases:
        runs = [os.path.join(directory, case, f"np{n}", "loads.csv") for n in (1, 2, 3)]
        if not all(os.path.exists(r) for r in runs):
            lines.append([case, "failed", "failed"])
            continue
        lines.append([case, cell(runs[0], runs[1]), cell(runs[0], runs[2])])
    table = doc_figures.table(["case", "2 processes", "3 processes"], lines)
    doc_figures.write_block("parallel-runs.md", "tools/mpi_agreement", block,
                            f"`{command}`:\n\n{table}" if command else table)


if __name__ == "__main__":
    arguments = sys.argv[1:]
    block, command = "agreement", ""
    if arguments[:1] == ["--block"] and len(arguments) > 1:
        block, arguments = arguments[1], arguments[2:]
    if arguments[:1] == ["--command"] and len(arguments) > 1:
        command, arguments = arguments[1], arguments[2:]
    if len(arguments) < 2:
        sys.exit(__doc__)
    main(arguments[0], arguments[1:], block, command)
