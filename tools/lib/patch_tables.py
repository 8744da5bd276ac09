"""The contact tables of docs/verification.md (and the facet-contact Krylov
table of docs/linear-solve.md), from what tools/patch_test measured.

tools/patch_test (tools/src/patch_test.cpp) writes one CSV row a run; this
pivots those rows into the tables the page shows and writes them with
doc_figures, so a rerun of the tool rewrites the page:
    patch_tables.py cubes|paper|quadrature|curved DIR
    patch_tables.py swap DIR ANVIL   runs cases/two_cubes.yaml itself
    patch_tables.py krylov DIR ANVIL runs cases/patch_test_cubes.yaml itself
"""
import csv
import json
import os
import subprocess
import sys
from collections import OrderedDict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import doc_figures  # noqa: E402

PAGE = "verification.md"
TOOL = "tools/patch_test"
SHORT = {"master_slave": "M/S", "quasi_symmetric": "QS", "symmetric": "symmetric"}


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def percent(fraction):
    """A relative error in %, "0" below 1e-8 % (exact to round-off)."""
    p = 100 * float(fraction)
    return "0" if abs(p) < 1e-8 else f"{p:.0f}" if abs(p) >= 1000 else f"{p:.3g}"


def cubes(directory):
    runs = rows(os.path.join(directory, "patch_test_cubes.csv"))
    by = {(r["case"], r["lower_cells"] + "/" + r["upper_cells"], r["master"], r["formulation"], r["integration"]): r
          for r in runs}
    pairs = list(OrderedDict.fromkeys((r["lower_cells"] + "/" + r["upper_cells"], r["master"]) for r in runs))

    def stress(r):  # interface pressure / worst σzz of both cubes
        szz = max(float(r["lower_szz_max"]), float(r["upper_szz_max"]))
        return f"{percent(r['pressure_max'])} / {percent(szz)} %"

    load = "elastic 0.3, pressure"
    lines = []
    for pair, master in pairs:
        get = lambda f, i: by[(load, pair, master, f, i)]  # noqa: E731
        lines.append([pair, master, stress(get("master_slave", "nodal")), stress(get("quasi_symmetric", "nodal")),
                      stress(get("symmetric", "nodal")), stress(get("quasi_symmetric", "facet")),
                      f"{float(get('quasi_symmetric', 'nodal')['master_penetration_ratio']):.3g} / "
                      f"{float(get('quasi_symmetric', 'facet')['master_penetration_ratio']):.3g}"])
    doc_figures.write_block(PAGE, TOOL, "cubes", doc_figures.table(
        ["n_l/n_u", "master", "M/S nodal", "QS nodal", "symmetric nodal", "QS facet",
         "master depth / penalty, QS nodal / facet"], lines))

    # Worst over every case, mesh pair and master; the swap: the support force
    # with the other body as master, displacement cases (the force is the answer).
    worst = {}
    for r in runs:
        w = worst.setdefault((r["formulation"], r["integration"]), [0.0, 0.0, 0.0, 0.0])
        w[0] = max(w[0], float(r["pressure_max"]))
        w[1] = max(w[1], float(r["lower_szz_max"]), float(r["upper_szz_max"]))
        w[2] = max(w[2], float(r["master_penetration_ratio"]))
        if "displacement" in r["case"] or "velocity" in r["case"]:
            other = by[(r["case"], r["lower_cells"] + "/" + r["upper_cells"],
                        "upper" if r["master"] == "lower" else "lower", r["formulation"], r["integration"])]
            f, g = float(r["support_force_N"]), float(other["support_force_N"])
            w[3] = max(w[3], abs(f - g) / max(abs(f), abs(g)))
    lines = []
    for formulation in SHORT:
        n, f = worst[(formulation, "nodal")], worst[(formulation, "facet")]
        lines.append([formulation.replace("_", " ").replace("master slave", "master/slave").replace(
            "quasi symmetric", "quasi-symmetric"),
            f"{percent(n[0])} / {percent(n[1])} %, {n[2]:.4g}", f"{percent(f[0])} / {percent(f[1])} %, {f[2]:.4g}",
            f"{percent(n[3])} % / {percent(f[3])} %"])
    cases = len(OrderedDict.fromkeys(r["case"] for r in runs))
    doc_figures.write_block(PAGE, TOOL, "cubes worst", f"{len(runs)} runs, {cases} load cases:\n\n" + doc_figures.table(
        ["formulation", "nodal: pressure / σzz max, depth / penalty", "facet: pressure / σzz max, depth / penalty",
         "swap force change, displacement cases, nodal / facet"], lines))


def paper(directory):
    runs = rows(os.path.join(directory, "patch_test.csv"))
    by = {(r["meshes"], r["formulation"]): r for r in runs if r["case"].startswith("1 ")}
    meshes = list(OrderedDict.fromkeys(r["meshes"] for r in runs))
    lines = []
    for m in meshes:
        ms, qs, sym = by[(m, "master_slave")], by[(m, "quasi_symmetric")], by[(m, "symmetric")]
        f = lambda x: f"{100 * float(x):.2f} %"  # noqa: E731
        lines.append([m, f(ms["interface_max"]), f(ms["interface_rms"]), f(qs["interface_max"]),
                      f(qs["interface_rms"]), f(sym["interface_rms"]),
                      f"{100 * float(ms['interior_max']):.2f} / {100 * float(qs['interior_max']):.2f} %"])
    doc_figures.write_block(PAGE, TOOL + " --paper", "case 1", doc_figures.table(
        ["meshes (master/slave cells a side)", "M/S max", "M/S RMS", "QS max", "QS RMS", "symmetric RMS",
         "interior max M/S / QS"], lines))


def quadrature(directory):
    runs = rows(os.path.join(directory, "facet_quadrature.csv"))
    groups = OrderedDict()
    for r in runs:
        label = "intersection" if r["quadrature"] == "intersection" else r["levels"]
        groups.setdefault((r["meshes"], r["master"], SHORT[r["formulation"]]), OrderedDict())[label] = r
    columns = list(next(iter(groups.values())).keys())
    lines = [[*key, *(f"{percent(g[c]['pressure_max'])} %, {float(g[c]['contact_time_s']):.3f} s" for c in columns)]
             for key, g in groups.items()]
    header = ["n_l/n_u", "master", "formulation"] + [
        c if c == "intersection" else f"subdivision {c} levels" if c == "0" else c for c in columns]
    doc_figures.write_block(PAGE, TOOL + " --quadrature", "quadrature", doc_figures.table(header, lines))


def curved(directory):
    lines = []
    for r in rows(os.path.join(directory, "hertz_cylinder.csv")):
        lines.append([f"{float(r['block_size']):g} mm", r["master"], SHORT[r["formulation"]], r["integration"],
                      f"{float(r['support_force_N']):.4g} N",
                      f"{float(r['peak_cylinder']):.3f} / {float(r['peak_block']):.3f}",
                      f"{100 * float(r['profile_max']):.1f} / {100 * float(r['profile_rms']):.1f} %",
                      f"{float(r['master_depth_um']):.2g} µm"])
    doc_figures.write_block(PAGE, TOOL + " --curved", "hertz", doc_figures.table(
        ["block facets", "master", "formulation", "integration", "load", "peak / p0, cylinder / block",
         "profile error max / RMS", "deepest master node"], lines))


def swap(directory, anvil):
    """cases/two_cubes.yaml with either cube as master: the top plate's load and
    the area-weighted mean vertical velocity of each side of the interface."""
    root = doc_figures.ROOT

    def run(lower, upper, formulation, lower_master):
        out = os.path.join(directory, "swap")
        subprocess.run([anvil, "run", os.path.join(root, "cases/two_cubes.yaml"), "-o", out, "--set",
                        "output.picture=false", "--set", f"bodies[0].mesh.element_size={10 / lower:.10g}", "--set",
                        f"bodies[1].mesh.element_size={10 / upper:.10g}", "--set",
                        f"contact_pairs[0].formulation={formulation}", "--set",
                        f"contact_pairs[0].master={'lower' if lower_master else 'upper'}", "--set",
                        f"contact_pairs[0].slave={'upper' if lower_master else 'lower'}"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        load = abs(float([r for r in rows(os.path.join(out, "loads.csv")) if r["surface"] == "top"][-1]["model_Fz_N"]))
        vz, interface = {}, rows(os.path.join(out, "interface.csv"))
        for body in ("lower", "upper"):
            side = [r for r in interface if r["body"] == body]
            vz[body] = sum(float(r["area_mm2"]) * float(r["vz"]) for r in side) / sum(
                float(r["area_mm2"]) for r in side)
        return load, vz

    def change(a, b):
        return abs(a - b) / max(abs(a), abs(b))

    lines = []
    for lower, upper in ((4, 4), (4, 9), (16, 2)):
        for formulation in ("quasi_symmetric", "master_slave"):
            (fl, vl), (fu, vu) = (run(lower, upper, formulation, m) for m in (True, False))
            vz = " / ".join(f"{100 * change(vl[b], vu[b]):.2g} %" for b in ("lower", "upper"))
            lines.append([f"{lower}/{upper}", SHORT[formulation], f"{fl:.5g} N", f"{fu:.5g} N",
                          f"{100 * change(fl, fu):.2g} %", vz])
    doc_figures.write_block(PAGE, TOOL + " --swap", "swap", doc_figures.table(
        ["meshes (lower/upper cells)", "formulation", "load, lower master", "load, upper master", "change",
         "interface vz change lower / upper"], lines))


def krylov(directory, anvil):
    """Krylov iterations of the unit-cube patch test (1 MPa) with facet against
    nodal contact on non-matching meshes, whose facet contact rows couple a
    node with many nodes of the other body, for the velocity AMGs an expert
    can pick (ML aggregating on the matrix or on the nodes' geometry,
    smoothing with point-block Jacobi or SOR; its defaults with facet
    contact are the geometry and SOR); then, where the velocity block is
    regular (the displacement-driven test, its interface sticking), ML
    against an exact velocity solve. One process, so that the counts do not
    depend on the cores."""
    root = doc_figures.ROOT
    sor, jacobi = ["-fieldsplit_0_mg_levels_pc_type", "sor"], ["-fieldsplit_0_mg_levels_pc_type", "pbjacobi"]
    matrix, geometric = ["-fieldsplit_0_pc_ml_Aux", "false"], ["-fieldsplit_0_pc_ml_Aux", "true"]
    facet_defaults_for_both = ("ML, geometric aggregation, SOR", geometric + sor)
    amgs = OrderedDict([("ML (default: with facet contact, geometric aggregation and SOR)", []),
                        facet_defaults_for_both,
                        ("ML, matrix aggregation, SOR", matrix + sor),
                        ("ML, matrix aggregation, point-block Jacobi", matrix + jacobi),
                        ("ML, geometric aggregation, point-block Jacobi", geometric + jacobi),
                        ("GAMG", ["-fieldsplit_0_pc_type", "gamg"]),
                        ("BoomerAMG", ["-fieldsplit_0_pc_type", "hypre"])])

    def iterations(lower, upper, formulation, integration, options, case):
        out = os.path.join(directory, "krylov")
        subprocess.run([anvil, "run", os.path.join(root, case), "-o", out, "--np", "1",
                        "--set", "output.picture=false", "--set", "solver.linear_solver=fgmres", "--set",
                        f"bodies[0].mesh.element_size={1 / lower:.10g}", "--set",
                        f"bodies[1].mesh.element_size={1 / upper:.10g}", "--set",
                        f"contact_pairs[0].formulation={formulation}", "--set",
                        f"contact_pairs[0].integration={integration}"] + options,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f)["krylov_iterations"]

    pairs = ((2, 16), (4, 16), (2, 8), (16, 2))  # cells an edge, lower/upper

    def table(variants, case, extra=(), pairs=pairs):
        """nodal / facet iterations of `case` per mesh pair (cells an edge,
        lower/upper) and formulation, a column per variant (name -> anvil
        options, after `extra`)."""
        lines = []
        for lower, upper in pairs:
            for formulation in ("master_slave", "quasi_symmetric"):
                line = [f"{lower}/{upper}", SHORT[formulation]]
                for options in variants.values():
                    nodal, facet = (iterations(lower, upper, formulation, i, list(extra) + options, case)
                                    for i in ("nodal", "facet"))
                    line.append(f"{nodal} / {facet} ({facet / nodal:.2f}x)")
                lines.append(line)
                print(" | ".join(line), flush=True)
        return doc_figures.table(["meshes (lower/upper cells)", "formulation"] +
                                 [f"{name}: nodal / facet" for name in variants], lines)

    doc_figures.write_block("linear-solve.md", TOOL + " --krylov", "facet krylov",
                            table(amgs, "cases/patch_test_cubes.yaml",  # 8/32: too large for the exact solve below
                                  pairs=pairs + ((8, 32),)))
    # The same pairs where the velocity block is regular: the upper cube's
    # top driven by a velocity and the interface sticking hold the uniform
    # contraction of one cube against the dilatation of the other that the
    # pressure-loaded, frictionless test leaves to the pressure alone. An
    # exact velocity solve (LU) then shows what the rest of the
    # preconditioner makes of the contact rows.
    held = OrderedDict([("ML (default)", []), facet_defaults_for_both,
                        ("velocity block exact (LU)", ["-fieldsplit_0_pc_type", "lu"])])
    doc_figures.write_block("linear-solve.md", TOOL + " --krylov", "facet krylov held",
                            table(held, "cases/patch_test_cubes_displacement.yaml",
                                  ["--set", "contact_pairs[0].friction.law=sticking"]))


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("cubes", "paper", "quadrature", "curved", "swap", "krylov"):
        sys.exit(__doc__)
    if sys.argv[1] in ("swap", "krylov"):
        globals()[sys.argv[1]](sys.argv[2], sys.argv[3])
    else:
        globals()[sys.argv[1]](sys.argv[2])
