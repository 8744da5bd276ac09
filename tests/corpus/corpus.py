#!/usr/bin/env python3
"""Malformed inputs for anvil, and what it must answer to each.

Each entry builds a small folder (a case file, a material card, a mesh, an STL
die, a checkpoint, an output folder) and runs `anvil` on it once. The answer
checked for every entry:
  - the exit code (2 command-line misuse, 3 input error, 4 run stopped);
  - never a signal, never "internal error";
  - stderr is our one message and nothing before it (no HDF5, VTK, PETSc or
    CGAL noise);
  - the message names what the entry expects: the file (and line), the key,
    the value, what was expected;
  - an input error leaves no output folder behind.

  corpus.py --list                     the entries' names, one a line
  corpus.py --base                     the base case the entries damage (a
                                       valid case that runs in about a second)
  corpus.py --run ANVIL HELPER NAME    builds entry NAME in a scratch folder and
                                       runs ANVIL on it (HELPER: the checkpoint
                                       corrupter, tests/corpus/corrupt_checkpoint)
ctest runs one test per entry (label `corpus`); tests/CMakeLists.txt lists them.
"""
import filecmp
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MATERIAL = os.path.join(SOURCE, "materials", "steel_c45_1100C.yaml")

# A case that runs in about a second: a coarse quarter cylinder upset by
# 1 mm in two increments, with a checkpoint at each.
BASE = """anvil: 1
title: corpus base case
bodies:
  - name: billet
    material: {material}
    mesh: {{generate: quarter_cylinder, radius: 5, height: 7.5, element_size: 2.5}}
boundary:
  - {{name: symmetry_x, type: symmetry, tag: 1}}
  - {{name: symmetry_y, type: symmetry, tag: 3}}
dies:
  - name: top
    plane: {{point: [0, 0, 7.5], normal: [0, 0, -1]}}
    motion: constant
    velocity: [0, 0, -10]
    friction: {{law: tresca, factor: 0.3}}
  - name: bottom
    plane: {{point: [0, 0, 0], normal: [0, 0, 1]}}
    friction: {{law: tresca, factor: 0.3}}
time:
  stroke_increment: 0.5
  stop: {{stroke: 1}}
output:
  checkpoint_every: 1
"""

CARD = """format: 1
name: corpus card
law: norton_hoff
consistency: 36.67
sensitivity: 0.1685
regularisation_rate: 1.0e-4
sources:
  consistency: "corpus"
  sensitivity: "corpus"
  regularisation_rate: "corpus"
"""

TET_MSH = """$MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
4
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
$EndNodes
$Elements
1
1 4 2 1 1 1 2 3 4
$EndElements
"""

TET_MEDIT = """MeshVersionFormatted 2
Dimension 3
Vertices
4
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
Tetrahedra
1
1 2 3 4 1
End
"""

# A square plate 40 x 40 mm at z = 0, normal +z (a lower die), two facets.
PLATE_STL = """solid plate
facet normal 0 0 1
 outer loop
  vertex -20 -20 0
  vertex 20 -20 0
  vertex 20 20 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -20 -20 0
  vertex 20 20 0
  vertex -20 20 0
 endloop
endfacet
endsolid plate
"""


class Entry:
    def __init__(self, name, files, args, code, words, before=None, harmless_ok=False):
        self.name = name
        self.files = files    # relative path -> text (str) or bytes
        self.args = args      # anvil's arguments; {dir} is the entry's folder
        self.code = code      # expected exit code
        self.words = words    # each must appear in the message
        self.before = before  # optional: prepare(folder, anvil, helper) run first
        # Damage that may hit unused bytes: exit 0 passes too, when the run's
        # loads.csv is that of an undamaged resume ({dir}/clean, made by `before`).
        self.harmless_ok = harmless_ok
        self.output_ok = False  # an input error found once the run has begun may leave its folder


ENTRIES = []


def add(name, files, args, code, words, before=None, harmless_ok=False):
    assert not any(e.name == name for e in ENTRIES), name
    ENTRIES.append(Entry(name, files, args, code, words, before, harmless_ok))


def base(**replace):
    """The base case with text replacements (old -> new) applied."""
    text = BASE.format(material=MATERIAL)
    for old, new in replace.items():
        old = old.replace("__", " ")
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


def swap(old, new, text=None):
    text = BASE.format(material=MATERIAL) if text is None else text
    assert old in text, old
    return text.replace(old, new, 1)


def run_case(text, *extra, name="case.yaml", files=None):
    f = {name: text}
    f.update(files or {})
    return f, ["run", "{dir}/" + name, "-o", "{dir}/out"] + list(extra)


def case_error(name, text, words, *extra, files=None):
    f, a = run_case(text, *extra, files=files)
    add(name, f, a, 3, words)


# --- YAML syntax and structure ------------------------------------------------
case_error("yaml-unclosed-bracket", base() + "extra: [1, 2\n", ["case.yaml:", "YAML syntax error"])
case_error("yaml-tab-indent", swap("  stroke_increment: 0.5", "\tstroke_increment: 0.5"), ["case.yaml:", "YAML"])
case_error("yaml-bad-indent", swap("  stop: {stroke: 1}", "    stop: {stroke: 1}"), ["case.yaml:", "YAML"])
case_error("yaml-not-a-map", "- just\n- a list\n", ["case.yaml", "map"])
case_error("yaml-empty-file", "", ["case.yaml", "map"])
case_error("yaml-scalar-file", "hello\n", ["case.yaml", "map"])
case_error("yaml-duplicate-top-key", base() + "title: twice\n", ["case.yaml:", "'title'", "twice"])
case_error("yaml-duplicate-nested-key", swap("  stroke_increment: 0.5", "  stroke_increment: 0.5\n  stroke_increment: 0.2"),
           ["case.yaml:", "time.stroke_increment", "twice"])
case_error("yaml-duplicate-flow-key", swap("{law: tresca, factor: 0.3}", "{law: tresca, factor: 0.3, factor: 0.5}"),
           ["case.yaml:", "dies[0].friction.factor", "twice"])
case_error("yaml-duplicate-in-mesh", swap("element_size: 2.5}", "element_size: 2.5, radius: 6}"),
           ["case.yaml:", "bodies[0].mesh.radius", "twice"])
case_error("yaml-binary-garbage", "\x00\x01\x02anvil: 1\n", ["case.yaml"])
add("case-missing-file", {}, ["run", "{dir}/nowhere.yaml", "-o", "{dir}/out"], 3, ["nowhere.yaml", "cannot open"])
add("case-is-a-folder", {"folder/x": "x"}, ["run", "{dir}/folder", "-o", "{dir}/out"], 3, ["folder"])

# --- unknown and missing keys -------------------------------------------------
case_error("unknown-top-key", base() + "solverr: {}\n", ["case.yaml:", "unknown key 'solverr'", "known keys here"])
case_error("unknown-body-key", swap("    material:", "    materiel: x\n    material:"),
           ["unknown key 'bodies[0].materiel'"])
case_error("unknown-mesh-key", swap("element_size: 2.5}", "element_size: 2.5, hieght: 3}"),
           ["unknown key 'bodies[0].mesh.hieght'"])
case_error("unknown-die-key", swap("    motion: constant", "    motoin: constant\n    motion: constant"),
           ["unknown key 'dies[0].motoin'"])
case_error("unknown-time-key", swap("  stroke_increment: 0.5", "  stroke_incr: 0.5\n  stroke_increment: 0.5"),
           ["unknown key 'time.stroke_incr'"])
case_error("unknown-stop-key", swap("stop: {stroke: 1}", "stop: {strok: 1}"), ["unknown key 'time.stop.strok'"])
case_error("unknown-friction-key", swap("{law: tresca, factor: 0.3}", "{law: tresca, factor: 0.3, mu: 1}"),
           ["unknown key 'dies[0].friction.mu'"])
case_error("unknown-output-key", swap("  checkpoint_every: 1", "  checkpoint_evry: 1"),
           ["unknown key 'output.checkpoint_evry'"])
case_error("missing-anvil-key", swap("anvil: 1\n", ""), ["missing key 'anvil'"])
case_error("missing-bodies", swap("bodies:", "bodiez:"), ["unknown key 'bodiez'"])
case_error("missing-body-name", swap("  - name: billet\n    material:", "  - material:"), ["bodies[0]", "name"])
case_error("missing-material", swap("    material: " + MATERIAL + "\n", ""), ["bodies[0]", "material"])
case_error("missing-mesh", swap("    mesh: {generate: quarter_cylinder, radius: 5, height: 7.5, element_size: 2.5}\n", ""),
           ["bodies[0]", "mesh"])
case_error("missing-die-velocity", swap("    velocity: [0, 0, -10]\n", ""), ["dies[0]", "velocity", "constant"])
case_error("missing-tresca-factor", swap("{law: tresca, factor: 0.3}", "{law: tresca}"), ["factor", "tresca"])
case_error("missing-stroke-increment", swap("  stroke_increment: 0.5\n", ""), ["stroke_increment"])
case_error("empty-bodies-list", swap("bodies:\n  - name: billet", "bodies: []\nx:\n  - name: billet"), ["bodies"])

# --- wrong types ----------------------------------------------------------------
case_error("type-number-as-text", swap("stroke_increment: 0.5", "stroke_increment: half"),
           ["case.yaml:", "time.stroke_increment", "'half'", "expected"])
case_error("type-list-for-map", swap("stop: {stroke: 1}", "stop: [1]"), ["time.stop", "map"])
case_error("type-map-for-list", swap("  - {name: symmetry_x, type: symmetry, tag: 1}\n  - {name: symmetry_y, type: symmetry, tag: 3}",
                                      "  x: {name: symmetry_x, type: symmetry, tag: 1}\n  y: {name: symmetry_y, type: symmetry, tag: 3}"),
           ["key 'boundary'", "list"])
case_error("type-vector-two", swap("velocity: [0, 0, -10]", "velocity: [0, -10]"), ["dies[0].velocity", "[x, y, z]"])
case_error("type-vector-text", swap("velocity: [0, 0, -10]", "velocity: [0, 0, down]"), ["dies[0].velocity"])
case_error("type-boolean", swap("  checkpoint_every: 1", "  checkpoint_every: 1\n  vtk: maybe"), ["output.vtk"])
case_error("type-integer-fraction", swap("checkpoint_every: 1", "checkpoint_every: 1.5"), ["output.checkpoint_every", "integer"])
case_error("type-choice", swap("law: tresca", "law: glue"), ["dies[0].friction.law", "one of"])
case_error("type-generate-choice", swap("generate: quarter_cylinder", "generate: sphere"), ["bodies[0].mesh.generate"])
case_error("type-motion-choice", swap("motion: constant", "motion: teleport"), ["dies[0].motion"])
case_error("type-title-map", swap("title: corpus base case", "title: {a: 1}"), ["title"])
case_error("fill-region-inverted",
           swap("    friction: {law: tresca, factor: 0.3}\n  - name: bottom",
                "    friction: {law: tresca, factor: 0.3}\n    fill: {region: {min: [0, 0, 5], max: [9, 9, 1]}}\n"
                "  - name: bottom"),
           ["dies[0].fill.region", "'min' must be below 'max'"])
case_error("self-contact-formulation",
           base() + "contact_pairs:\n  - {master: billet, slave: billet, formulation: master_slave}\n",
           ["case.yaml:", "contact_pairs[0].formulation", "itself", "symmetric and nodal"])
case_error("self-contact-quadrature",
           base() + "contact_pairs:\n  - {master: billet, slave: billet, facet_quadrature: subdivision}\n",
           ["case.yaml:", "contact_pairs[0].facet_quadrature", "leave out"])
case_error("damage-no-criterion", base() + "damage: {progress: true}\n",
           ["case.yaml:", "damage", "no criterion asked for"])
case_error("damage-oyane-without-a", base() + "damage: {oyane: true}\n",
           ["case.yaml:", "oyane_a", "Oyane's criterion needs the material's constant a"])
case_error("damage-oyane-a-negative", base() + "damage: {oyane: true, oyane_a: -0.5}\n",
           ["case.yaml:", "damage.oyane_a", "'-0.5'"])
case_error("damage-unknown-criterion", base() + "damage: {rice_tracey: true}\n",
           ["case.yaml:", "unknown key 'damage.rice_tracey'"])
case_error("damage-criterion-not-boolean", base() + "damage: {ayada: 3}\n", ["case.yaml:", "damage.ayada"])
case_error("hammer-without-ram-mass",
           swap("motion: constant\n    velocity: [0, 0, -10]", "motion: hammer\n    blow_energy: 1"),
           ["case.yaml:", "ram_mass", "motion 'hammer' needs it"])
case_error("hammer-with-velocity",
           swap("motion: constant\n    velocity: [0, 0, -10]",
                "motion: hammer\n    blow_energy: 1\n    ram_mass: 100\n    velocity: [0, 0, -10]"),
           ["case.yaml:", "velocity", "motion 'hammer'"])
case_error("hammer-efficiency-above-one",
           swap("motion: constant\n    velocity: [0, 0, -10]",
                "motion: hammer\n    blow_energy: 1\n    ram_mass: 100\n    efficiency: 1.5"),
           ["case.yaml:", "dies[0].efficiency", "'1.5'"])
case_error("hammer-zero-blows",
           swap("motion: constant\n    velocity: [0, 0, -10]",
                "motion: hammer\n    blow_energy: 1\n    ram_mass: 100\n    blows: 0"),
           ["case.yaml:", "dies[0].blows", "'0'"])
case_error("screw-press-energy-and-speed",
           swap("motion: constant\n    velocity: [0, 0, -10]",
                "motion: screw_press\n    flywheel_energy: 1\n    flywheel_speed: 100\n    inertia: 10\n"
                "    screw_pitch: 100"),
           ["case.yaml:", "exactly one of 'flywheel_energy' (kJ) or 'flywheel_speed' (rpm)"])
case_error("screw-press-without-pitch",
           swap("motion: constant\n    velocity: [0, 0, -10]",
                "motion: screw_press\n    flywheel_energy: 1\n    inertia: 10"),
           ["case.yaml:", "screw_pitch", "motion 'screw_press' needs it"])
case_error("no-stop-without-energy-press", swap("  stop: {stroke: 1}\n", ""),
           ["case.yaml:", "time.stop", "a hammer or screw press stops after its blows"])
case_error("wear-without-coefficient",
           swap("  - name: bottom\n", "    wear: {hardness: 50}\n  - name: bottom\n"),
           ["case.yaml:", "dies[0].wear.coefficient", "missing"])
case_error("wear-without-hardness",
           swap("  - name: bottom\n", "    wear: {coefficient: 1.0e-3}\n  - name: bottom\n"),
           ["case.yaml:", "dies[0].wear", "give the die's hardness"])
case_error("wear-hardness-and-card",
           swap("  - name: bottom\n", "    wear: {coefficient: 1.0e-3, hardness: 50, material: card.yaml}\n"
                "  - name: bottom\n"),
           ["case.yaml:", "dies[0].wear", "give the die's hardness"])
case_error("wear-card-missing",
           swap("  - name: bottom\n", "    wear: {coefficient: 1.0e-3, material: no_such_card.yaml}\n"
                "  - name: bottom\n"),
           ["case.yaml:", "dies[0].wear.material", "no_such_card.yaml"])
case_error("wear-card-without-hardness",
           swap("  - name: bottom\n", "    wear: {coefficient: 1.0e-3, material: " + MATERIAL + "}\n"
                "  - name: bottom\n"),
           ["case.yaml:", "dies[].wear.material", "has no hardness table"])
case_error("wear-hardness-out-of-range",
           swap("  - name: bottom\n", "    wear: {coefficient: 1.0e-3, hardness: 300}\n  - name: bottom\n"),
           ["case.yaml:", "dies[0].wear.hardness", "'300'"])
case_error("nothing-moves-isothermal",
           swap("motion: constant\n    velocity: [0, 0, -10]", "motion: fixed",
                swap("  stop: {stroke: 1}", "  stop: {time: 1}")),
           ["case.yaml", "nothing moves", "needs a motion, or a 'thermal' section"])
case_error("wear-on-a-flowing-body",
           swap("    mesh: {generate", "    wear: {coefficient: 1.0e-3, hardness: 50}\n    mesh: {generate"),
           ["case.yaml:", "bodies[0].wear", "only a meshed (elastic) die wears"])
case_error("quadrature-degree-out-of-range", base() + "solver: {quadrature_degree: 7}\n",
           ["case.yaml:", "solver.quadrature_degree", "7"])
case_error("fill-region-without-max",
           swap("    friction: {law: tresca, factor: 0.3}\n  - name: bottom",
                "    friction: {law: tresca, factor: 0.3}\n    fill: {region: {min: [0, 0, 0]}}\n  - name: bottom"),
           ["dies[0].fill.region", "both 'min' and 'max'"])
case_error("fill-region-axis-without-radius",
           swap("    friction: {law: tresca, factor: 0.3}\n  - name: bottom",
                "    friction: {law: tresca, factor: 0.3}\n    fill: {region: {axis: [1, 2]}}\n  - name: bottom"),
           ["dies[0].fill.region", "'radius'"])
case_error("fill-tolerance-negative",
           swap("    friction: {law: tresca, factor: 0.3}\n  - name: bottom",
                "    friction: {law: tresca, factor: 0.3}\n    fill: {tolerance: -0.1}\n  - name: bottom"),
           ["dies[0].fill.tolerance", "'-0.1'"])

# --- numbers out of range -----------------------------------------------------
for key, old, new, words in [
    ("negative-element-size", "element_size: 2.5", "element_size: -1", ["element_size", "'-1'", "> 0"]),
    ("zero-element-size", "element_size: 2.5", "element_size: 0", ["element_size", "'0'"]),
    ("negative-radius", "radius: 5", "radius: -5", ["radius"]),
    ("zero-height", "height: 7.5", "height: 0", ["height"]),
    ("friction-factor-above-one", "factor: 0.3", "factor: 1.5", ["friction.factor", "'1.5'"]),
    ("friction-factor-negative", "factor: 0.3", "factor: -0.1", ["friction.factor"]),
    ("negative-stroke-increment", "stroke_increment: 0.5", "stroke_increment: -0.5", ["stroke_increment"]),
    ("zero-stroke-increment", "stroke_increment: 0.5", "stroke_increment: 0", ["stroke_increment"]),
    ("negative-stop-stroke", "stop: {stroke: 1}", "stop: {stroke: -1}", ["time.stop.stroke"]),
    ("anvil-version-7", "anvil: 1", "anvil: 7", ["'7'", "equal to 1"]),
    ("negative-checkpoint-every", "checkpoint_every: 1", "checkpoint_every: -1", ["checkpoint_every"]),
]:
    case_error("range-" + key, swap(old, new), words)

# --- NaN, infinities, overflow ------------------------------------------------
for key, old, new, what in [
    ("nan-element-size", "element_size: 2.5", "element_size: .nan", "element_size"),
    ("inf-element-size", "element_size: 2.5", "element_size: .inf", "element_size"),
    ("nan-velocity", "velocity: [0, 0, -10]", "velocity: [0, 0, .nan]", "dies[0].velocity"),
    ("inf-velocity", "velocity: [0, 0, -10]", "velocity: [0, 0, -.inf]", "dies[0].velocity"),
    ("overflow-stroke", "stop: {stroke: 1}", "stop: {stroke: 1e400}", "time.stop.stroke"),
    ("nan-plane-point", "point: [0, 0, 0]", "point: [0, NaN, 0]", "dies[1].plane.point"),
    ("inf-friction", "factor: 0.3", "factor: inf", "dies[0].friction.factor"),
    ("nan-text-stroke-increment", "stroke_increment: 0.5", "stroke_increment: nan", "time.stroke_increment"),
]:
    case_error(key, swap(old, new), [what])

# --- integers past 32 bits ----------------------------------------------------
for key, old, new, what in [
    ("tag-1e12", "tag: 1}", "tag: 1e12}", "boundary[0].tag"),
    ("tag-2147483648", "tag: 1}", "tag: 2147483648}", "boundary[0].tag"),
    ("tag-negative-huge", "tag: 1}", "tag: -3000000000}", "boundary[0].tag"),
    ("checkpoint-every-1e12", "checkpoint_every: 1", "checkpoint_every: 1e12", "output.checkpoint_every"),
    ("anvil-version-huge", "anvil: 1", "anvil: 4294967297", "anvil"),
    ("max-increments-1e10", "  stroke_increment: 0.5", "  stroke_increment: 0.5\n  max_increments: 1e10",
     "time.max_increments"),
    ("max-increments-negative", "  stroke_increment: 0.5", "  stroke_increment: 0.5\n  max_increments: -1",
     "time.max_increments"),
    ("max-cuts-huge", "  stroke_increment: 0.5", "  stroke_increment: 0.5\n  max_cuts: 9e15", "time.max_cuts"),
]:
    case_error("integer-" + key, swap(old, new), [what])

# --- names that become file names or CSV fields ------------------------------------
for key, name, what in [
    ("slash", "bil/let", "bodies[0].name"),
    ("comma", "bil,let", "bodies[0].name"),
    ("space", "bil let", "bodies[0].name"),
    ("empty", "''", "bodies[0].name"),
    ("dotdot", "..", "bodies[0].name"),
    ("newline", '"bil\\nlet"', "bodies[0].name"),
]:
    case_error("name-body-" + key, swap("  - name: billet", "  - name: " + name), [what])
for key, name in [("comma", "to,p"), ("slash", "t/op"), ("quote", '"to\\"p"'), ("plus", "top+1")]:
    case_error("name-die-" + key, swap("  - name: top", "  - name: " + name), ["dies[0].name"])
case_error("name-die-twice", swap("  - name: bottom", "  - name: top"), ["dies[1].name", "twice"])

# --- references to other files and entities -------------------------------------
case_error("material-file-missing", swap(MATERIAL, "/nonexistent/card.yaml"), ["card.yaml"])
case_error("mesh-file-missing", swap("mesh: {generate: quarter_cylinder, radius: 5, height: 7.5, element_size: 2.5}",
                                     "mesh: {file: nowhere.msh}"), ["nowhere.msh"])
case_error("mesh-file-unknown-format", swap("mesh: {generate: quarter_cylinder, radius: 5, height: 7.5, element_size: 2.5}",
                                            "mesh: {file: body.obj}"), ["body.obj", "format"],
           files={"body.obj": "v 0 0 0\n"})
case_error("stl-file-missing", swap("    plane: {point: [0, 0, 0], normal: [0, 0, 1]}", "    stl: nowhere.stl"),
           ["nowhere.stl", "not found"])
case_error("boundary-unknown-body", swap("{name: symmetry_x, type: symmetry, tag: 1}",
                                         "{name: symmetry_x, body: ingot, type: symmetry, tag: 1}"),
           ["no body is named 'ingot'"])
case_error("boundary-tag-selects-nothing", swap("tag: 3}", "tag: 77}"), ["symmetry_y", "77"])
case_error("die-plane-zero-normal", swap("normal: [0, 0, 1]}", "normal: [0, 0, 0]}"), ["dies[1].plane.normal", "zero"])
case_error("die-stl-and-plane", swap("    plane: {point: [0, 0, 0], normal: [0, 0, 1]}",
                                     "    plane: {point: [0, 0, 0], normal: [0, 0, 1]}\n    stl: plate.stl"),
           ["dies[1]", "exactly one"], files={"plate.stl": PLATE_STL})
case_error("stop-die-unknown", swap("stop: {stroke: 1}", "stop: {stroke: 1, die: middle}"), ["middle"])

# --- motions a stop criterion can never reach -------------------------------------
case_error("stop-gap-dies-moving-apart",
           swap("stop: {stroke: 1}", "stop: {gap: 3}", swap("velocity: [0, 0, -10]", "velocity: [0, 0, 10]")),
           ["time.stop.gap", "apart"])
case_error("stop-gap-sideways-die",
           swap("stop: {stroke: 1}", "stop: {gap: 3}", swap("velocity: [0, 0, -10]", "velocity: [10, 0, 0]")),
           ["time.stop.gap", "never"])
case_error("stop-stroke-increment-tiny", swap("stroke_increment: 0.5", "stroke_increment: 1e-12"),
           ["stroke_increment", "increments", "max_increments"])
case_error("stop-end-time-too-far", swap("stop: {stroke: 1}", "stop: {time: 1e9}"),
           ["stroke_increment", "increments", "end time"])
case_error("stop-stroke-fixed-die", swap("stop: {stroke: 1}", "stop: {stroke: 1, die: bottom}"),
           ["time.stop.stroke", "does not move"])
case_error("stop-load-die-moving-away",
           swap("stop: {stroke: 1}", "stop: {load: 1e9}", swap("velocity: [0, 0, -10]", "velocity: [0, 0, 10]")),
           ["time.stop.load", "away"])
case_error("stop-time-with-nothing-moving", swap("velocity: [0, 0, -10]", "velocity: [0, 0, 0]"), ["nothing moves"])

# --- sizes that do not fit ----------------------------------------------------
case_error("mesh-too-fine", swap("element_size: 2.5", "element_size: 1e-6"), ["element_size", "nodes", "memory"])
case_error("mesh-too-fine-box", swap("mesh: {generate: quarter_cylinder, radius: 5, height: 7.5, element_size: 2.5}",
                                     "mesh: {generate: box, size: [1000, 1000, 1000], element_size: 0.01}"),
           ["element_size", "nodes"])

# --- material cards -------------------------------------------------------------
def card_error(name, card, words):
    case_error("card-" + name, swap(MATERIAL, "card.yaml"), words, files={"card.yaml": card})


def card_swap(old, new):
    assert old in CARD, old
    return CARD.replace(old, new, 1)


card_error("missing-source", card_swap('  sensitivity: "corpus"\n', ""), ["card.yaml", "sensitivity", "source"])
card_error("unknown-law", card_swap("law: norton_hoff", "law: magic"), ["card.yaml:", "law"])
card_error("negative-consistency", card_swap("consistency: 36.67", "consistency: -1"), ["card.yaml:", "consistency"])
card_error("sensitivity-above-one", card_swap("sensitivity: 0.1685", "sensitivity: 1.5"), ["card.yaml:", "sensitivity"])
card_error("nan-consistency", card_swap("consistency: 36.67", "consistency: .nan"), ["card.yaml:", "consistency"])
card_error("unknown-key", CARD + "colour: red\n", ["card.yaml:", "colour"])
card_error("duplicate-key", CARD + "consistency: 40\n", ["card.yaml:", "consistency", "twice"])
card_error("not-a-map", "- 1\n- 2\n", ["card.yaml", "map"])
card_error("syntax", CARD + "x: [\n", ["card.yaml:", "YAML"])
card_error("missing-consistency", card_swap("consistency: 36.67\n", ""), ["card.yaml", "consistency"])
card_error("format-2", card_swap("format: 1", "format: 2"), ["card.yaml:", "format"])
card_error("empty", "", ["card.yaml"])

# --- mesh files -------------------------------------------------------------------
def mesh_error(name, text, words, ext="msh"):
    mesh_key = "mesh: {generate: quarter_cylinder, radius: 5, height: 7.5, element_size: 2.5}"
    case_error("mesh-" + name, swap(mesh_key, "mesh: {file: body." + ext + "}"), words, files={"body." + ext: text})


def tet_swap(old, new, text=TET_MSH):
    assert old in text, old
    return text.replace(old, new, 1)


mesh_error("gmsh-not-gmsh", "hello\n", ["body.msh:1", "MeshFormat"])
mesh_error("gmsh-binary", tet_swap("2.2 0 8", "2.2 1 8"), ["body.msh:2", "binary"])
mesh_error("gmsh-version-3", tet_swap("2.2 0 8", "3.0 0 8"), ["body.msh:2", "format 3.0"])
mesh_error("gmsh-truncated", TET_MSH[: TET_MSH.index("$Elements")], ["body.msh"])
mesh_error("gmsh-truncated-nodes", TET_MSH[: TET_MSH.index("3 0 1 0")], ["body.msh", "end of file"])
mesh_error("gmsh-nan-coordinate", tet_swap("2 1 0 0", "2 nan 0 0"), ["body.msh:7"])
mesh_error("gmsh-inf-coordinate", tet_swap("2 1 0 0", "2 inf 0 0"), ["body.msh:7"])
mesh_error("gmsh-overflow-coordinate", tet_swap("2 1 0 0", "2 1e400 0 0"), ["body.msh:7"])
mesh_error("gmsh-undefined-node", tet_swap("1 2 3 4\n$EndElements", "1 2 3 9\n$EndElements"), ["body.msh", "node 9"])
mesh_error("gmsh-duplicate-node", tet_swap("3 0 1 0", "2 0 1 0"), ["body.msh:8", "twice"])
mesh_error("gmsh-inverted-tet", tet_swap("1 2 3 4\n$EndElements", "2 1 3 4\n$EndElements"), ["body.msh", "tetrahedron 1", "inverted"])
mesh_error("gmsh-flat-tet", tet_swap("4 0 0 1", "4 1 1 0"), ["body.msh", "tetrahedron 1", "degenerate"])
mesh_error("gmsh-repeated-vertex", tet_swap("1 2 3 4\n$EndElements", "1 2 3 3\n$EndElements"), ["body.msh", "tetrahedron 1", "repeats"])
mesh_error("gmsh-no-tets", tet_swap("1\n1 4 2 1 1 1 2 3 4", "0\n"), ["body.msh", "no"])
mesh_error("gmsh-unsupported-element", tet_swap("1 4 2 1 1 1 2 3 4", "1 11 2 1 1 1 2 3 4 1 2 3 4 1 2 3"),
           ["body.msh:13", "element type 11"])
mesh_error("gmsh-huge-node-count", tet_swap("$Nodes\n4", "$Nodes\n1000000000000"), ["body.msh"])
mesh_error("gmsh-negative-node-count", tet_swap("$Nodes\n4", "$Nodes\n-4"), ["body.msh:5", "count"])
mesh_error("gmsh-unused-node", tet_swap("$Nodes\n4", "$Nodes\n5").replace("4 0 0 1\n", "4 0 0 1\n5 3 3 3\n"),
           ["body.msh", "node 5"])
mesh_error("gmsh4-huge-block", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 1000000000000000\n",
           ["body.msh:6", "count"])
mesh_error("gmsh4-negative-block", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 -4\n",
           ["body.msh:6", "count"])
mesh_error("medit-dimension-2", TET_MEDIT.replace("Dimension 3", "Dimension 2"), ["body.mesh:2", "3D"], "mesh")
mesh_error("medit-unknown-keyword", TET_MEDIT.replace("Tetrahedra", "Hexahedra"), ["body.mesh", "Medit keyword"], "mesh")
mesh_error("medit-nan", TET_MEDIT.replace("1 0 0 0\n0 1", "nan 0 0 0\n0 1"), ["body.mesh:6"], "mesh")
mesh_error("medit-bad-index", TET_MEDIT.replace("1 2 3 4 1", "1 2 3 40 1"), ["body.mesh", "node 40"], "mesh")
mesh_error("medit-huge-count", TET_MEDIT.replace("Vertices\n4", "Vertices\n99999999999999"), ["body.mesh"], "mesh")

# --- STL dies -----------------------------------------------------------------------
def stl_case(stl_name):
    return swap("    plane: {point: [0, 0, 0], normal: [0, 0, 1]}", "    stl: " + stl_name)


def stl_error(name, content, words):
    case_error("stl-" + name, stl_case("die.stl"), words, files={"die.stl": content})


def binary_stl(triangles, count=None):
    import struct
    data = b"binary corpus stl".ljust(80, b" ")
    data += struct.pack("<I", len(triangles) if count is None else count)
    for t in triangles:
        data += struct.pack("<3f", 0.0, 0.0, 1.0)
        for v in t:
            data += struct.pack("<3f", *v)
        data += b"\0\0"
    return data


PLATE = [((-20, -20, 0), (20, -20, 0), (20, 20, 0)), ((-20, -20, 0), (20, 20, 0), (-20, 20, 0))]
INF = float("inf")
NAN = float("nan")
stl_error("empty", "", ["die.stl"])
stl_error("garbage", "not an stl at all\n", ["die.stl"])
stl_error("binary-inf-vertex", binary_stl([((-20, -20, 0), (INF, -20, 0), (20, 20, 0)), PLATE[1]]), ["die.stl", "finite"])
stl_error("binary-nan-vertex", binary_stl([((-20, -20, 0), (NAN, -20, 0), (20, 20, 0)), PLATE[1]]), ["die.stl", "finite"])
stl_error("ascii-nan-vertex", PLATE_STL.replace("vertex 20 -20 0", "vertex nan -20 0"), ["die.stl"])
stl_error("ascii-inf-vertex", PLATE_STL.replace("vertex 20 -20 0", "vertex inf -20 0"), ["die.stl"])
stl_error("binary-truncated", binary_stl(PLATE)[:-30], ["die.stl"])
stl_error("binary-count-too-large", binary_stl(PLATE, count=1000000), ["die.stl"])
stl_error("all-degenerate", binary_stl([((0, 0, 0), (1, 0, 0), (2, 0, 0))]), ["die.stl", "degenerate"])
stl_error("reversed-normals-open", PLATE_STL.replace("vertex 20 -20 0\n  vertex 20 20 0", "vertex 20 20 0\n  vertex 20 -20 0")
          .replace("vertex 20 20 0\n  vertex -20 20 0", "vertex -20 20 0\n  vertex 20 20 0"),
          ["die 'bottom'", "inside", "normals"])
case_error("stl-offset-die-inside-billet", stl_case("die.stl") .replace("    stl: die.stl", "    stl: die.stl\n    offset: [0, 0, 3]"),
           ["die 'bottom'", "inside", "3"], files={"die.stl": PLATE_STL})
case_error("plane-die-inside-billet", swap("point: [0, 0, 0], normal: [0, 0, 1]", "point: [0, 0, 3], normal: [0, 0, 1]"),
           ["die 'bottom'", "inside", "3"])

# --- --set overrides ------------------------------------------------------------------
for name, override, words in [
    ("no-equals", "time.stroke_increment", ["--set 'time.stroke_increment'", "key.path=value"]),
    ("unknown-key", "time.strok=1", ["--set 'time.strok=1'", "no key"]),
    ("bad-value", "time.stroke_increment=fast", ["--set 'time.stroke_increment=fast'", "expected"]),
    ("nan-value", "time.stroke_increment=.nan", ["--set 'time.stroke_increment=.nan'"]),
    ("huge-integer", "output.checkpoint_every=1e12", ["--set 'output.checkpoint_every=1e12'"]),
    ("index-out-of-range", "dies[5].friction.factor=0.1", ["--set", "2 elements"]),
    ("bad-index", "dies[x].friction.factor=0.1", ["--set", "not a list index"]),
    ("not-a-list", "time[0].stroke_increment=1", ["--set", "no key 'time[].stroke_increment'"]),
    ("empty-key", ".=1", ["--set", "empty key"]),
    ("range", "dies[].friction.factor=2", ["--set 'dies[].friction.factor=2'", "expected"]),
    ("yaml-syntax", "title=[", ["--set 'title=['", "YAML"]),
    ("name-with-slash", "bodies[0].name=a/b", ["--set 'bodies[0].name=a/b'"]),
]:
    f, a = run_case(base(), "--set", override)
    add("set-" + name, f, a, 3, words)

# --- output folders ---------------------------------------------------------------
add("output-is-a-file", {"case.yaml": base(), "out": "a file, not a folder\n"},
    ["run", "{dir}/case.yaml", "-o", "{dir}/out"], 3, ["out", "not a folder"])
add("output-under-a-file", {"case.yaml": base(), "file": "x\n"},
    ["run", "{dir}/case.yaml", "-o", "{dir}/file/out"], 3, ["file/out"])
add("output-in-proc", {"case.yaml": base()}, ["run", "{dir}/case.yaml", "-o", "/proc/anvil_out"], 3, ["/proc/anvil_out"])

# --- command line -------------------------------------------------------------------
add("cli-no-command", {}, [], 2, ["no command"])
add("cli-unknown-command", {}, ["fly"], 2, ["unknown command 'fly'"])
add("cli-no-case", {}, ["run"], 2, ["needs a case file"])
add("cli-two-cases", {"a.yaml": base(), "b.yaml": base()}, ["run", "{dir}/a.yaml", "{dir}/b.yaml"], 2, ["more than one"])
add("cli-unknown-option", {"case.yaml": base()}, ["run", "{dir}/case.yaml", "--frobnicate"], 2, ["unknown option"])
add("cli-resume-no-dir", {"case.yaml": base()}, ["run", "{dir}/case.yaml", "--resume"], 2, ["--resume needs"])
add("cli-set-no-value", {"case.yaml": base()}, ["run", "{dir}/case.yaml", "--set"], 2, ["--set needs"])
add("cli-o-no-dir", {"case.yaml": base()}, ["run", "{dir}/case.yaml", "-o"], 2, ["needs a directory"])
add("cli-petsc-option-unknown-to-case", {"case.yaml": base()},
    ["run", "{dir}/case.yaml", "-o", "{dir}/out", "--set", "solver.petsc_options=ksp_type"], 3, ["solver.petsc_options"])

# --- checkpoints -----------------------------------------------------------------------
def with_checkpoint(mode=None, offset=None):
    """Runs the base case for one increment into {dir}/out, then corrupts its
    checkpoint as `mode` says (the helper) or at byte `offset` (64 bytes)."""
    def prepare(folder, anvil, helper):
        out = os.path.join(folder, "out")
        case = os.path.join(folder, "case.yaml")
        subprocess.run([anvil, "run", case, "-o", out, "--set", "time.max_increments=1"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120)
        path = os.path.join(out, "checkpoint.h5")
        if not os.path.exists(path):
            raise RuntimeError("the base case wrote no checkpoint")
        if mode:
            subprocess.run([helper, path, mode], check=True, timeout=60)
        if offset is not None:
            clean = os.path.join(folder, "clean")
            shutil.copytree(out, clean)
            subprocess.run([anvil, "run", case, "--resume", clean], stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL, timeout=120)
            with open(path, "r+b") as f:
                size = os.path.getsize(path)
                f.seek(int(offset * (size - 64)))
                f.write(bytes((i * 37 + 11) % 256 for i in range(64)))
    return prepare


def resume_error(name, words, mode=None, offset=None, case=None, extra=(), files=None, after=None):
    """--resume of the base case's checkpoint, corrupted by `mode` or at `offset`,
    or with the case (`extra` overrides) or a file changed by `after(folder)`."""
    prepare = with_checkpoint(mode, offset)
    if after:
        def prepare_then_change(folder, anvil, helper, first=prepare):
            first(folder, anvil, helper)
            after(folder)
        prepare = prepare_then_change
    entry_files = {"case.yaml": case or base()}
    entry_files.update(files or {})
    add("checkpoint-" + name, entry_files, ["run", "{dir}/case.yaml", "--resume", "{dir}/out"] + list(extra), 3,
        words, before=prepare, harmless_ok=offset is not None)


resume_error("none", ["checkpoint.h5", "no checkpoint"], mode="remove")
resume_error("not-hdf5", ["checkpoint.h5", "HDF5"], mode="text")
resume_error("truncated", ["checkpoint.h5"], mode="truncate")
resume_error("tet-index", ["checkpoint.h5", "tets", "node"], mode="tet_index")
resume_error("tet-negative-index", ["checkpoint.h5", "tets", "node"], mode="tet_negative")
resume_error("face-index", ["checkpoint.h5", "boundary_faces"], mode="face_index")
resume_error("load-surface", ["checkpoint.h5", "loads", "surface"], mode="load_surface")
resume_error("nan-node", ["checkpoint.h5", "nodes", "finite"], mode="nan_node")
resume_error("inf-velocity", ["checkpoint.h5", "nodal", "finite"], mode="inf_nodal")
resume_error("negative-increment", ["checkpoint.h5", "increment"], mode="negative_increment")
resume_error("missing-dataset", ["checkpoint.h5", "tets"], mode="drop_tets")
resume_error("format-9", ["checkpoint.h5", "format 9"], mode="format_9")
resume_error("body-ranges", ["checkpoint.h5", "body"], mode="body_ranges")
resume_error("die-count", ["checkpoint", "dies"], mode="extra_die")
resume_error("output-part", ["checkpoint.h5", "outputs"], mode="output_part")
# 64 bytes overwritten across the file: a clear error where they hit data or
# metadata (checksums), the same results where they hit unused bytes.
for k in range(20):
    resume_error("overwritten-64-bytes-%02d" % k, ["checkpoint.h5"], offset=(k + 0.5) / 20)
resume_error("changed-friction", ["changed", "dies[0].friction.factor", "0.3", "0.1"],
             extra=["--set", "dies[].friction.factor=0.1"])
resume_error("changed-mesh-size", ["changed", "bodies[0].mesh.element_size"],
             extra=["--set", "bodies[0].mesh.element_size=2"])


resume_error("is-a-fifo", ["checkpoint.h5", "FIFO"], mode="remove",
             after=lambda folder: os.mkfifo(os.path.join(folder, "out", "checkpoint.h5")))
resume_error("is-a-folder", ["checkpoint.h5", "folder"], mode="remove",
             after=lambda folder: os.mkdir(os.path.join(folder, "out", "checkpoint.h5")))


def stiffer_card(folder):
    with open(os.path.join(folder, "card.yaml"), "w") as f:
        f.write(card_swap("consistency: 36.67", "consistency: 40"))


resume_error("changed-material-card", ["changed", "card.yaml", "consistency", "36.67", "40"],
             case=swap(MATERIAL, "card.yaml"), files={"card.yaml": CARD}, after=stiffer_card)

# --- special and oversized input files ---------------------------------------------------
# A FIFO would block the first read for ever, a device never ends, a folder is
# no file, a file past the stated size would take the machine's memory: each is
# refused with exit 3 and the key, before anything is read.
MESH_KEY = "mesh: {generate: quarter_cylinder, radius: 5, height: 7.5, element_size: 2.5}"
STL_KEY = "    plane: {point: [0, 0, 0], normal: [0, 0, 1]}"


def make_special(kind, name):
    """A `before` hook that makes {dir}/name a FIFO, a folder, a symbolic link
    to a FIFO, or a sparse file of `kind` bytes."""
    def prepare(folder, anvil, helper):
        path = os.path.join(folder, name)
        if kind == "fifo":
            os.mkfifo(path)
        elif kind == "folder":
            os.mkdir(path)
        elif kind == "link-to-fifo":
            os.mkfifo(path + ".fifo")
            os.symlink(path + ".fifo", path)
        else:
            with open(path, "wb") as f:
                f.truncate(kind)  # sparse: no disk taken
    return prepare


def special_case(name, text, file_name, kind, words, args=None):
    add(name, {"case.yaml": text}, args or ["run", "{dir}/case.yaml", "-o", "{dir}/out"], 3, words,
        before=make_special(kind, file_name))


special_case("special-case-fifo", base(), "fifo.yaml", "fifo", ["fifo.yaml", "FIFO"],
             ["run", "{dir}/fifo.yaml", "-o", "{dir}/out"])
special_case("special-case-too-large", base(), "big.yaml", 2 << 20, ["big.yaml", "MB"],
             ["run", "{dir}/big.yaml", "-o", "{dir}/out"])
special_case("special-case-link-to-fifo", base(), "link.yaml", "link-to-fifo", ["link.yaml", "FIFO"],
             ["run", "{dir}/link.yaml", "-o", "{dir}/out"])
add("special-case-dev-zero", {}, ["run", "/dev/zero", "-o", "{dir}/out"], 3, ["/dev/zero", "character device"])
add("special-case-dev-urandom", {}, ["run", "/dev/urandom", "-o", "{dir}/out"], 3, ["/dev/urandom", "device"])
for key, kind, what in [("fifo", "fifo", "FIFO"), ("folder", "folder", "folder"),
                        ("link-to-fifo", "link-to-fifo", "FIFO"), ("too-large", "large", "MB")]:
    special_case("special-card-" + key, swap(MATERIAL, "card.yaml"), "card.yaml",
                 2 << 20 if kind == "large" else kind, ["case.yaml:", "bodies[0].material", "card.yaml", what])
    special_case("special-mesh-" + key, swap(MESH_KEY, "mesh: {file: body.msh}"), "body.msh",
                 3 << 30 if kind == "large" else kind, ["case.yaml:", "bodies[0].mesh.file", "body.msh", what])
    special_case("special-stl-" + key, swap(STL_KEY, "    stl: die.stl"), "die.stl",
                 2 << 30 if kind == "large" else kind, ["case.yaml:", "dies[1].stl", "die.stl", what])
for device in ["/dev/zero", "/dev/urandom", "/dev/null"]:
    case_error("special-stl-" + device[5:], swap(STL_KEY, "    stl: " + device), ["dies[1].stl", device, "device"])
    case_error("special-mesh-" + device[5:], swap(MESH_KEY, "mesh: {file: %s}" % device),
               ["bodies[0].mesh.file", device, "device"])
case_error("special-card-dev-zero", swap(MATERIAL, "/dev/zero"), ["bodies[0].material", "/dev/zero", "device"])



def huge_count_mesh(name, header, file_name, words):
    """A mesh whose node count is past this machine's memory, in a sparse file
    large enough for the count to pass the file-size check."""
    def prepare(folder, anvil, helper):
        with open(os.path.join(folder, file_name), "wb") as f:
            f.write(header.encode())
            f.truncate(1 << 30)
    add(name, {"case.yaml": swap(MESH_KEY, "mesh: {file: %s}" % file_name)},
        ["run", "{dir}/case.yaml", "-o", "{dir}/out"], 3, words, before=prepare)


huge_count_mesh("special-gmsh-nodes-past-memory", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n900000000\n",
                "body.msh", ["body.msh:5", "900000000 nodes", "memory"])
huge_count_mesh("special-medit-nodes-past-memory", "MeshVersionFormatted 2\nDimension 3\nVertices\n900000000\n",
                "body.mesh", ["body.mesh:4", "900000000 nodes", "memory"])
special_case("special-output-is-fifo", base(), "out", "fifo", ["out", "not a folder"])

# --- physical ranges of the thermal keys --------------------------------------------------
THERMAL = swap("    friction: {law: tresca, factor: 0.3}\n  - name: bottom",
               "    friction: {law: tresca, factor: 0.3}\n    temperature: 250\n    heat_transfer: 10\n  - name: bottom",
               swap("    friction: {law: tresca, factor: 0.3}\ntime:",
                    "    friction: {law: tresca, factor: 0.3}\n    temperature: 250\n    heat_transfer: 10\n"
                    "thermal:\n  environment: {temperature: 20, convection: 0.01}\ntime:"))


def thermal_error(name, old, new, words, *extra):
    case_error("thermal-" + name, swap(old, new, THERMAL), words, *extra)


DIE_0 = "    temperature: 250\n    heat_transfer: 10\n  - name: bottom"
BODY = "    material: " + MATERIAL
thermal_error("die-below-absolute-zero", DIE_0, DIE_0.replace("250", "-500"),
              ["dies[0].temperature", "'-500'", "-273.15"])
case_error("thermal-heat-alone-with-load-stop",
           swap("motion: constant\n    velocity: [0, 0, -10]", "motion: fixed",
                swap("  stop: {stroke: 1}", "  stop: {time: 1, load: 1000}", THERMAL)),
           ["case.yaml:", "time.stop", "nothing moves (heat alone)", "an end time"])
thermal_error("air-below-absolute-zero", "temperature: 20, convection", "temperature: -300, convection",
              ["thermal.environment.temperature", "'-300'"])
thermal_error("air-at-1e6", "temperature: 20, convection", "temperature: 1e6, convection",
              ["thermal.environment.temperature", "3500"])
thermal_error("body-at-1e6", BODY, "    temperature: 1e6\n" + BODY, ["bodies[0].temperature", "'1e6'", "3500"])
thermal_error("body-at-absolute-zero", BODY, "    temperature: -273.15\n" + BODY,
              ["bodies[0].temperature", "> -273.15"])
thermal_error("convection-huge", "convection: 0.01", "convection: 1e6", ["thermal.environment.convection", "'1e6'"])
thermal_error("convection-negative", "convection: 0.01", "convection: -1", ["thermal.environment.convection"])
thermal_error("heat-transfer-huge", DIE_0, DIE_0.replace("heat_transfer: 10", "heat_transfer: 1e9"),
              ["dies[0].heat_transfer", "'1e9'"])
thermal_error("taylor-quinney-above-one", "thermal:\n", "thermal:\n  taylor_quinney: 1.5\n",
              ["thermal.taylor_quinney", "'1.5'"])
case_error("set-body-below-absolute-zero", THERMAL, ["--set 'bodies[0].temperature=-300'", "-273.15"],
           "--set", "bodies[0].temperature=-300")
THERMAL_CARD = CARD.replace("sources:", "conductivity: 30\nspecific_heat: 460\ndensity: 7800\nsources:") + \
    '  conductivity: "corpus"\n  specific_heat: "corpus"\n  density: "corpus"\n'
for name, old, new, words in [
    ("density-1e-300", "density: 7800", "density: 1e-300", ["card.yaml:", "density", "'1e-300'", ">= 100"]),
    ("density-1e6", "density: 7800", "density: 1e6", ["card.yaml:", "density", "30000"]),
    ("conductivity-1e9", "conductivity: 30", "conductivity: 1e9", ["card.yaml:", "conductivity", "'1e9'"]),
    ("conductivity-zero", "conductivity: 30", "conductivity: 0", ["card.yaml:", "conductivity"]),
    ("specific-heat-tiny", "specific_heat: 460", "specific_heat: 0.001", ["card.yaml:", "specific_heat"]),
    ("table-below-absolute-zero", "conductivity: 30\nspecific_heat: 460",
     "conductivity: [30, 31]\nspecific_heat: 460\nthermal_temperatures: [-400, 20]",
     ["card.yaml:", "thermal_temperatures", "'-400'"]),
    ("emissivity-above-one", "density: 7800", "density: 7800\nemissivity: 1.5", ["card.yaml:", "emissivity"]),
    ("temperature-5000", "law: norton_hoff", "law: norton_hoff\ntemperature: 5000", ["card.yaml:", "temperature"]),
]:
    card = THERMAL_CARD.replace(old, new, 1)
    for key in ["emissivity", "temperature", "thermal_temperatures"]:
        if "\n" + key + ":" in "\n" + new and '  %s: "corpus"' % key not in card:
            card += '  %s: "corpus"\n' % key
    assert card != THERMAL_CARD, name
    case_error("thermal-card-" + name, swap(MATERIAL, "card.yaml", THERMAL), words, files={"card.yaml": card})

# --- velocities beyond any press ------------------------------------------------------------
case_error("velocity-1e300", swap("velocity: [0, 0, -10]", "velocity: [0, 0, -1e300]"),
           ["dies[0].velocity", "100000"])
case_error("velocity-1e6", swap("velocity: [0, 0, -10]", "velocity: [1e6, 0, -10]"), ["dies[0].velocity", "each"])
case_error("boundary-velocity-huge", swap("{name: symmetry_y, type: symmetry, tag: 3}",
                                          "{name: symmetry_y, type: velocity, velocity: [~, 1e9, ~], tag: 3}"),
           ["boundary[1].velocity"])

# --- remeshing that would destroy a body ------------------------------------------------------
REMESHING = base() + "remeshing: {quality: 0.1}\n"
case_error("remesh-size-larger-than-body", swap("quality: 0.1}", "quality: 0.1, element_size: 20}", REMESHING),
           ["remeshing.element_size", "20 mm", "a third", "billet"])
case_error("remesh-size-half-the-body", swap("quality: 0.1}", "quality: 0.1, element_size: 2.5}", REMESHING),
           ["remeshing.element_size", "2.5 mm", "three elements"])
case_error("remesh-max-nodes-negative", swap("quality: 0.1}", "quality: 0.1, max_nodes: -1}", REMESHING),
           ["remeshing.max_nodes"])
case_error("remesh-time-limit-zero", swap("quality: 0.1}", "quality: 0.1, time_limit: 0}", REMESHING),
           ["remeshing.time_limit", "> 0"])
case_error("remesh-smallest-size-negative", swap("quality: 0.1}", "quality: 0.1, smallest_size: -0.05}", REMESHING),
           ["remeshing.smallest_size"])
case_error("set-remesh-size-larger-than-body", REMESHING, ["remeshing.element_size", "a third"],
           "--set", "remeshing.element_size=50")
BOX = "{min: [0, 0, 0], max: [2, 2, 2], size: 0.5}"
case_error("remesh-size-box-uniform", swap("quality: 0.1}", "quality: 0.1, size_boxes: [" + BOX + "]}", REMESHING),
           ["remeshing.size_boxes[0]", "size: adaptive"])
case_error("remesh-size-box-unknown-die",
           swap("quality: 0.1}", "quality: 0.1, size: adaptive, size_boxes: [" + BOX[:-1] + ", die: press}]}",
                REMESHING), ["remeshing.size_boxes[0].die", "no die is named 'press'"])
case_error("remesh-size-box-inverted",
           swap("quality: 0.1}", "quality: 0.1, size: adaptive, size_boxes: [" + BOX.replace("[2, 2, 2]", "[2, -2, 2]")
                + "]}", REMESHING), ["remeshing.size_boxes[0]", "'min' must be below 'max'"])
case_error("remesh-size-box-below-smallest",
           swap("quality: 0.1}", "quality: 0.1, size: adaptive, smallest_size: 0.8, size_boxes: [" + BOX + "]}",
                REMESHING), ["remeshing.size_boxes[0].size", "0.5 mm", "smallest_size (0.8 mm)"])
case_error("remesh-size-box-no-size",
           swap("quality: 0.1}", "quality: 0.1, size: adaptive, size_boxes: [" + BOX.replace(", size: 0.5", "") + "]}",
                REMESHING), ["remeshing.size_boxes[0]", "size"])

# --- stops the geometry cannot reach ------------------------------------------------------------
case_error("stop-stroke-past-the-other-die", swap("stop: {stroke: 1}", "stop: {stroke: 8}"),
           ["time.stop.stroke", "8 mm is never reached", "meets die 'bottom'", "7.5"])
case_error("stop-stroke-at-the-other-die", swap("stop: {stroke: 1}", "stop: {stroke: 7.5}"),
           ["time.stop.stroke", "never reached"])
case_error("set-stop-stroke-past-the-other-die", base(), ["time.stop.stroke", "never reached"],
           "--set", "time.stop.stroke=20")

# --- PETSc options the solver reads at its first solve ---------------------------------------------
for name, option in [("rtol-text", ["-ksp_rtol", "abc"]), ("ksp-type", ["-ksp_type", "nonsense"])]:
    f, a = run_case(base(), "--set", "solver.linear_solver=fgmres", *option)
    add("petsc-option-" + name, f, a, 3, ["PETSc option", "not valid"])
    ENTRIES[-1].output_ok = True  # read once the output folder exists

# --- a run that reaches max_increments before its stop ---------------------------------
f, a = run_case(base(), "--set", "time.max_increments=1")
add("stop-max-increments", f, a, 4, ["max_increments", "1", "final stroke"])


f, a = run_case(swap("    motion: constant\n    velocity: [0, 0, -10]",
                     "    motion: table\n    direction: [0, 0, -1]\n    time: [0, 0.05]\n    displacement: [0, 0.5]"))
add("stop-table-motion-ends-short", f, a, 4, ["die 'top'", "rest", "final stroke 1 mm"])

# ---------------------------------------------------------------------------------------
NOISE_OK = re.compile(r"^(anvil: |\(run 'anvil --help')")


def run_entry(anvil, helper, name):
    entry = next((e for e in ENTRIES if e.name == name), None)
    if entry is None:
        print("no corpus entry named " + name)
        return 1
    folder = tempfile.mkdtemp(prefix="anvil_corpus_")
    try:
        for rel, content in entry.files.items():
            path = os.path.join(folder, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "wb" if isinstance(content, bytes) else "w") as f:
                f.write(content)
        if entry.before:
            entry.before(folder, anvil, helper)
        out_existed = os.path.exists(os.path.join(folder, "out"))
        args = [a.replace("{dir}", folder) for a in entry.args]
        try:
            done = subprocess.run([anvil] + args, capture_output=True, text=True, errors="replace", timeout=120,
                                  env=dict(os.environ, OMPI_MCA_btl="self"))
        except subprocess.TimeoutExpired:
            print("FAIL: no answer within 120 s (a run that does not stop?)")
            return 1
        message = done.stderr.strip()
        lines = message.splitlines()
        problems = []
        if entry.harmless_ok and done.returncode == 0:
            same = filecmp.cmp(os.path.join(folder, "out", "loads.csv"), os.path.join(folder, "clean", "loads.csv"),
                               False)
            print("anvil " + " ".join(args))
            print("exit 0: the damage hit unused bytes; loads.csv %s an undamaged resume's" %
                  ("equals" if same else "DIFFERS FROM"))
            if same:
                print("ok")
                return 0
            print("FAIL: a silent wrong answer")
            return 1
        if done.returncode < 0:
            problems.append("killed by signal %s" % signal.Signals(-done.returncode).name)
        elif done.returncode != entry.code:
            problems.append("exit code %d, expected %d" % (done.returncode, entry.code))
        if "internal error" in message:
            problems.append("an internal error")
        # Our message: lines "anvil: ...", its continuation lines indented by two
        # spaces (a list of changes), the usage hint. Anything else is noise.
        if not lines or not lines[0].startswith("anvil: "):
            problems.append("stderr does not start with our message")
        if any(line and not NOISE_OK.match(line) and not line.startswith("  ") for line in lines):
            problems.append("other output than our message on stderr")
        if len([line for line in lines if line.startswith("anvil: ")]) > 1:
            problems.append("more than one message")
        for word in entry.words:
            if word.replace("{dir}", folder) not in message:
                problems.append("the message lacks '%s'" % word)
        if entry.code == 3 and not out_existed and not entry.output_ok and os.path.exists(os.path.join(folder, "out")):
            problems.append("an input error left an output folder behind")
        print("anvil " + " ".join(args))
        print("exit %d; stderr:\n%s" % (done.returncode, message))
        if problems:
            print("FAIL: " + "; ".join(problems))
            return 1
        print("ok")
        return 0
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def main():
    if len(sys.argv) == 2 and sys.argv[1] == "--base":
        print(base(), end="")
        return 0
    if len(sys.argv) == 2 and sys.argv[1] == "--list":
        for e in ENTRIES:
            print(e.name)
        return 0
    if len(sys.argv) == 5 and sys.argv[1] == "--run":
        return run_entry(sys.argv[2], sys.argv[3], sys.argv[4])
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main())
