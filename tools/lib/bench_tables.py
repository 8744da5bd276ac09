"""The solver benchmarks' tables, from the lines build/anvil_bench prints.

tools/bench_increment, tools/bench_mpi and tools/bench_increment --preconditioners
keep their output in a log and call this to write their table into docs/:
    bench_tables.py increment LOG [COMMAND]        docs/performance.md, block "blocks"
    bench_tables.py mpi LOG [COMMAND]              docs/parallel-runs.md, block "blocks"
    bench_tables.py preconditioners LOG [COMMAND]  docs/linear-solve.md, block "preconditioners"
    bench_tables.py growth LOG [COMMAND]           docs/linear-solve.md, block "growth"
COMMAND, the benchmark as it was run, heads the table.
A line of anvil_bench (tools/src/bench_increment.cpp), optionally after a
label and a colon: "PROBLEM nodes N unknowns U SOLVER newton K ... per solve:
assembly A s setup S s solve V s total T s krylov K ... pattern P s peak G GB".
"""
import os
import re
import sys
from collections import OrderedDict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import doc_figures  # noqa: E402

LINE = re.compile(r"(?:(?P<label>.+?):\s+)?(?P<problem>\w+)\s+nodes\s+(?P<nodes>\d+)\s+"
                  r"unknowns\s+(?P<unknowns>\d+)\s+(?P<solver>\w+)\s+newton.*?"
                  r"per solve: assembly\s+(?P<assembly>[\d.]+) s\s+setup\s+(?P<setup>[\d.]+) s"
                  r"\s+solve\s+(?P<solve>[\d.]+) s\s+total\s+(?P<total>[\d.]+) s\s+krylov\s+(?P<krylov>[\d.]+).*?"
                  r"pattern\s+(?P<pattern>[\d.]+) s\s+peak (?P<peak>[\d./]+) GB")
NAMES = {"newtonian": "Newtonian", "norton_hoff": "Norton-Hoff m = 0.1"}


def runs(log):
    with open(log) as f:
        return [m.groupdict() for m in map(LINE.search, f) if m]


def heading(command):
    return f"`{command}`:\n\n" if command else ""


def thousands(n):
    n = int(n)
    return f"{n / 1e6:.2f}M" if n >= 1e6 else f"{n / 1e3:.0f}k" if n >= 1e4 else str(n)


def span(values, digits=2):
    """"a" or "a-b" over the rounds."""
    low, high = f"{min(values):.{digits}f}", f"{max(values):.{digits}f}"
    return low if low == high else f"{low}-{high}"


def increment(log, command=""):
    lines, last = [], None
    for r in runs(log):
        iterative = r["solver"] in ("fgmres", "minres")
        block = (r["problem"], r["nodes"])
        lines.append([NAMES.get(r["problem"], r["problem"]) if block != last and r["problem"] != (last or ("",))[0]
                      else "", thousands(r["nodes"]) if block != last else "",
                      thousands(r["unknowns"]) if block != last else "", r["solver"],
                      f"{float(r['assembly']):.2f} s", f"{float(r['setup']):.2f} s", f"{float(r['solve']):.2f} s",
                      f"**{float(r['total']):.2f} s**" if r["solver"] == "fgmres" else f"{float(r['total']):.2f} s",
                      f"{float(r['krylov']):.0f}" if iterative else "–", f"{float(r['peak']):.2f} GB"])
        last = block
    doc_figures.write_block("performance.md", "tools/bench_increment", "blocks", heading(command) + doc_figures.table(
        ["block", "nodes", "unknowns", "solver", "assembly", "set-up", "solve", "per solve", "Krylov its",
         "peak memory"], lines))


def mpi(log, command=""):
    """Rounds of (1 process with every thread, 1 process 1 thread, 2 processes)
    per block; each speed-up against its own round's one-process runs."""
    blocks = OrderedDict()
    for r in runs(log):
        label = r["label"].strip()
        if label.startswith("1 thread beside"):
            continue
        blocks.setdefault((r["problem"], r["nodes"]), OrderedDict()).setdefault(label, []).append(r)
    lines = []
    for (problem, nodes), by_label in blocks.items():
        labels = list(by_label)
        one = by_label[labels[0]]
        single = by_label.get("1 process, 1 thread", [])
        two = by_label.get("2 processes", [])
        for i, label in enumerate(labels):
            rs = by_label[label]
            f = lambda key: span([float(r[key]) for r in rs])  # noqa: E731
            speed = "1" if i == 0 else ""
            if label == "2 processes" and rs:
                over_one = [float(a["total"]) / float(b["total"]) for a, b in zip(one, two)]
                over_single = [float(a["total"]) / float(b["total"]) for a, b in zip(single, two)]
                speed = f"**{' / '.join(f'{s:.2f}' for s in over_one)}x**"
                if over_single:
                    speed += f" ({' / '.join(f'{s:.2f}' for s in over_single)}x over 1 thread)"
            peaks = " / ".join(OrderedDict.fromkeys(r["peak"] for r in rs))
            lines.append([f"{NAMES.get(problem, problem)}, {thousands(nodes)}" if i == 0 else "", label,
                          f("assembly"), f("setup"), f("solve"), f("total"), speed, f("pattern"), f"{peaks} GB"])
    doc_figures.write_block("parallel-runs.md", "tools/bench_mpi", "blocks", heading(command) + doc_figures.table(
        ["block, nodes", "run", "assembly (s)", "set-up (s)", "solve (s)", "total (s)", "speed-up", "pattern (s)",
         "peak memory per process"], lines))


def preconditioners(log, command=""):
    blocks = OrderedDict()
    for r in runs(log):
        blocks.setdefault(r["label"].strip(), OrderedDict())[r["problem"]] = r
    problems = list(OrderedDict.fromkeys(p for b in blocks.values() for p in b))
    lines = []
    for label, by_problem in blocks.items():
        amg, schur = label.split(" + ")
        cells = []
        for p in problems:
            r = by_problem.get(p)
            cells.append(f"{float(r['krylov']):.1f} its, {float(r['solve']):.2f} s" if r else "failed")
        lines.append([amg, schur, *cells])
    nodes = thousands(next(iter(blocks.values()))[problems[0]]["nodes"])
    header = ["velocity AMG", "Schur",
              *(f"{NAMES.get(p, p)} ({nodes} nodes): Krylov its, solve per Newton iteration" for p in problems)]
    doc_figures.write_block("linear-solve.md", "tools/bench_increment --preconditioners", "preconditioners",
                            heading(command) + doc_figures.table(header, lines))


def growth(log, command=""):
    """Krylov iterations per solve of each variant (label) at each size, and
    their growth from the smallest size to the largest."""
    variants = OrderedDict()
    for r in runs(log):
        variants.setdefault(r["label"].strip(), OrderedDict())[int(r["nodes"])] = float(r["krylov"])
    sizes = sorted({n for v in variants.values() for n in v})
    lines = []
    for label, by_size in variants.items():
        cells = [f"{by_size[n]:.1f}" if n in by_size else "–" for n in sizes]
        measured = [n for n in sizes if n in by_size]
        rise = by_size[measured[-1]] / by_size[measured[0]] if len(measured) > 1 else None
        lines.append([label, *cells, f"**{rise:.2f}x** ({thousands(measured[0])} to {thousands(measured[-1])})"
                      if rise else "–"])
    header = ["Norton-Hoff m = 0.1 block", *(f"{thousands(n)} nodes" for n in sizes), "growth"]
    doc_figures.write_block("linear-solve.md", "tools/bench_increment --growth", "growth",
                            heading(command) + doc_figures.table(header, lines))


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4) or sys.argv[1] not in ("increment", "mpi", "preconditioners", "growth"):
        sys.exit(__doc__)
    globals()[sys.argv[1]](*sys.argv[2:])
