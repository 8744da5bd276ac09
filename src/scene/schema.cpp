#include "anvil/scene/schema.h"

#include "anvil/contact/facet_quadrature.h"
#include "anvil/core/input_file.h"
#include "schema_keys.h"

#include <algorithm>

namespace anvil::scene {
namespace {

using namespace schema_keys;

/// "a regular file of at most 2 GiB": what an input file key takes (core/input_file).
std::string regular_file(std::uintmax_t max_bytes) {
  const bool gib = max_bytes >= (1ull << 30);
  return "a regular file of at most " + std::to_string(max_bytes >> (gib ? 30 : 20)) + (gib ? " GiB" : " MiB");
}

/// The keys of a `friction` map under `owner` ("dies[]", "contact_pairs[]").
std::vector<KeySpec> friction_keys(const std::string& owner, const std::string& between) {
  using T = KeyType;
  const std::string f = owner + ".friction";
  return {key(f, T::map, "friction between " + between + "; default frictionless"),
          with_default(choices(key(f + ".law", T::string, "friction law (docs/design.md §3)"),
                               {"frictionless", "sticking", "tresca", "coulomb", "norton"}),
                       "frictionless"),
          range(key(f + ".factor", T::number, "tresca: m̄ in τ = m̄ σ₀/√3; coulomb: optional Tresca cap", "-"), 0, 1),
          range(key(f + ".coefficient", T::number, "coulomb: μ; norton: α in τ = α K |Δv|^(q−1) Δv", "-"), 0, kInf),
          range(key(f + ".exponent", T::number, "norton: q", "-"), 0, 1, true)};
}

/// The heat transfer keys of a die or a contact pair under `owner`.
std::vector<KeySpec> heat_transfer_keys(const std::string& owner, const std::string& between) {
  using T = KeyType;
  return {range(key(owner + ".heat_transfer", T::numbers,
                    "thermal scenes: heat transfer coefficient h " + between +
                        "; one value, or one per heat_transfer_pressure",
                    "kW/(m2.K) = mW/(mm2.K)"),
                0, 10000),
          range(key(owner + ".heat_transfer_pressure", T::numbers,
                    "contact pressures of the heat_transfer table, increasing (h is held beyond its ends)", "MPa"),
                0, kInf)};
}

} // namespace

const std::vector<KeySpec>& case_schema() {
  using T = KeyType;
  static const std::vector<KeySpec> schema = [] {
    std::vector<KeySpec> keys = {
        required(range(key("anvil", T::integer, "case file format version"), 1, 1)),
        with_default(key("title", T::string, "one line shown in the log and summary"), ""),
        key("output", T::map, "what is written and where"),
        with_default(key("output.directory", T::string,
                         "output folder, relative to the working directory; default out/<case name>; -o overrides"),
                     ""),
        with_default(key("output.vtk", T::boolean, "write the .vtu/.pvd series"), "true"),
        with_default(key("output.picture", T::boolean,
                         "anvil run: final.png, the last increment drawn by anvil render (needs output.vtk)"),
                     "true"),
        with_default(
            key("output.picture_mirror", T::boolean,
                "final.png draws a quarter model (symmetry planes x = 0 and y = 0) whole: anvil render --mirror"),
            "false"),
        key("output.flow_lines", T::map,
            "flow lines (effect flow_lines): each node carries where its material started, through remeshes; "
            "the planes of material normal to `axis` at `count` heights are the flow lines "
            "(anvil render --flow-lines draws them on a cut; docs/reading-a-run.md §4)"),
        with_default(choices(key("output.flow_lines.axis", T::string, "the planes' normal"), {"x", "y", "z"}), "z"),
        with_default(range(key("output.flow_lines.count", T::integer,
                               "planes, evenly spaced through the bodies' extent along the axis at the start"),
                           1, 200),
                     "12"),
        with_default(key("output.folds", T::boolean,
                         "folds and laps (effect folds): a body's surface meeting itself, found after each "
                         "increment, logged, in summary.json and marked in the VTK series (docs/reading-a-run.md §5)"),
                     "false"),
        key("solver", T::map, "Newton and linear solver settings"),
        with_default(
            range(key("solver.tolerance", T::number, "Newton: relative tolerance on the force and div residuals"),
                  1e-14, 1e-2),
            "1e-6"),
        with_default(range(key("solver.increment_tolerance", T::number,
                               "Newton: relative tolerance on |dv|/|v| of the last step (a linear problem needs none "
                               "after a full step)"),
                           1e-14, 1),
                     "1e-4"),
        with_default(range(key("solver.max_iterations", T::integer,
                               "Newton iterations per increment and active set; a second budget at the same time step "
                               "when the residual still falls"),
                           1, 500),
                     "30"),
        with_default(
            choices(key("solver.linear_solver", T::string,
                        "fgmres: PETSc FGMRES with algebraic multigrid on the velocities and a Schur-complement "
                        "pressure preconditioner (large meshes); mumps: sparse direct (MUMPS); auto: mumps up to "
                        "5000 unknowns, fgmres above, mumps when fgmres stagnates; umfpack, cholmod_ldlt, "
                        "eigen_ldlt, minres: kept for comparison"),
                    {"auto", "fgmres", "mumps", "umfpack", "cholmod_ldlt", "eigen_ldlt", "minres"}),
            "auto"),
        with_default(
            range(key("solver.krylov_tolerance", T::number,
                      "fgmres: loosest relative tolerance of a Krylov solve; inexact Newton tightens it as the "
                      "residual falls (Eisenstat-Walker); at most 1e-3 while a contact active set follows the "
                      "iterates, 1e-5 for the predictor from rest"),
                  1e-12, 0.5),
            "1e-2"),
        with_default(range(key("solver.quadrature_degree", T::integer,
                               "degree of the quadrature over each element: 5 (14 points) integrates the bubble's "
                               "coupling with the linear velocity exactly; 6 (24 points) also the bubble-bubble "
                               "stiffness of a linear law (Newtonian, elastic), at more element work (measured: "
                               "docs/method.md, Element quadrature). No rule is exact for a power law"),
                           5, 6),
                     "5"),
        with_default(choices(key("solver.schur", T::string,
                                 "fgmres: pressure block of the preconditioner; bfbt: stabilised BFBT (follows the "
                                 "pressure of a layer squeezed between dies); mass: condensed-bubble block plus the "
                                 "viscosity-scaled pressure mass"),
                             {"bfbt", "mass"}),
                     "bfbt"),
        with_default(key("solver.reuse_preconditioner", T::boolean,
                         "fgmres: keep the multigrid set-up across Newton iterations and increments while the Krylov "
                         "iterations per decade stay within 1.5x of those right after it"),
                     "true"),
        with_default(
            key("solver.petsc_options", T::string,
                "PETSc options for experts, e.g. '-ksp_monitor -fieldsplit_0_pc_type gamg' (prefix direct_ for "
                "mumps); the same options on the anvil command line win"),
            ""),
        required(key("bodies", T::list, "deformable bodies, solved together (billets, deformable dies)")),
        required(key("bodies[].name", T::name, "name used by boundary conditions and in outputs")),
        required(key("bodies[].material", T::string,
                     "material card (YAML), path relative to the case file; " + regular_file(kMaxYamlBytes))),
        required(key("bodies[].mesh", T::map, "a mesh file or a generated shape")),
        key("bodies[].mesh.file", T::string,
            "Gmsh .msh (2.2, 4.1 ASCII) or Medit .mesh, relative to the case file; " + regular_file(kMaxMeshBytes)),
        choices(
            key("bodies[].mesh.generate", T::string,
                "generated shape instead of a file; quarter shapes (x, y >= 0) need symmetry planes x = 0 and y = 0: "
                "quarter_cylinder tags 1 x=0, 2 lateral, 3 y=0, 5 bottom, 6 top; quarter_ring tags 1 inner, "
                "2 outer, 3 y=0, 4 x=0, 5 bottom, 6 top"),
            {"box", "cylinder", "quarter_cylinder", "quarter_ring"}),
        with_default(key("bodies[].mesh.origin", T::vector3, "box: lowest corner", "mm"), "[0, 0, 0]"),
        key("bodies[].mesh.size", T::vector3, "box: edge lengths", "mm"),
        range(key("bodies[].mesh.radius", T::number, "cylinder, ring (axis z, base at z = 0): (outer) radius", "mm"), 0,
              kInf, true),
        range(key("bodies[].mesh.inner_radius", T::number, "quarter_ring: inner radius", "mm"), 0, kInf, true),
        range(key("bodies[].mesh.height", T::number, "cylinder: height", "mm"), 0, kInf, true),
        range(key("bodies[].mesh.element_size", T::number, "generated shapes: target edge length", "mm"), 0, kInf,
              true),
        key("boundary", T::list, "boundary conditions, applied in order (later ones win on shared nodes)"),
        required(key("boundary[].name", T::name, "name shown in loads.csv")),
        key("boundary[].body", T::string, "body it applies to; required when there are several"),
        required(
            choices(key("boundary[].type", T::string,
                        "velocity: given components; symmetry: zero normal velocity; sticking_plate: all "
                        "components = plate velocity; frictionless_plate: normal component only; traction; pressure"),
                    {"velocity", "symmetry", "sticking_plate", "frictionless_plate", "traction", "pressure"})),
        range(key("boundary[].tag", T::integer, "select the faces with this boundary tag"), 0, kInf),
        key("boundary[].plane", T::map, "select the boundary faces lying on a plane"),
        required(key("boundary[].plane.point", T::vector3, "a point of the plane", "mm")),
        required(key("boundary[].plane.normal", T::vector3, "plane normal (need not be unit)")),
        with_default(
            range(key("boundary[].plane.tolerance", T::number, "distance within which a node is on the plane", "mm"), 0,
                  kInf, true),
            "1e-6"),
        range(key("boundary[].velocity", T::vector3,
                  "velocity, plates: velocity; a component written ~ (null) is left free (velocity type only); "
                  "each within ±1e5 mm/s",
                  "mm/s"),
              -kFastest, kFastest),
        key("boundary[].traction", T::vector3, "traction: surface force density", "MPa"),
        key("boundary[].pressure", T::number, "pressure: positive pushes into the body", "MPa"),
        key("bodies[].wear", T::map,
            "meshed (elastic) dies: wear (effect die_wear) w = ∫ K p^a v^b / H^c dt at each boundary node (mm), "
            "H from 'hardness' or the body's own card's hardness table at the node's temperature"),
        required(range(key("bodies[].wear.coefficient", T::number, "K, as dies[].wear.coefficient"), 0, kInf, true)),
        with_default(range(key("bodies[].wear.pressure_exponent", T::number, "a"), 0, 10), "1"),
        with_default(range(key("bodies[].wear.velocity_exponent", T::number, "b"), 0, 10), "1"),
        with_default(range(key("bodies[].wear.hardness_exponent", T::number, "c"), 0, 10), "2"),
        range(key("bodies[].wear.hardness", T::number, "the die's hardness; default its card's table", "HRC"), 1, 80),
        range(key("bodies[].wear.temperature", T::number,
                  "the temperature the card's hardness is read at; default the node's (thermal scenes) or the body's",
                  "°C"),
              kAbsoluteZero, kHottest, true),
        range(key("bodies[].temperature", T::number,
                  "temperature of the body: held in an isothermal scene, initial in a thermal one; default the "
                  "material card's",
                  "°C"),
              kAbsoluteZero, kHottest, true),
        with_default(
            range(key("output.vtk_every", T::integer, "write the VTK series every N increments (and the last)"), 1,
                  kInf),
            "1"),
        with_default(range(key("output.checkpoint_every", T::integer,
                               "HDF5 checkpoint every N increments (and the last); 0 = never"),
                           0, kInf),
                     "10"),
        key("dies", T::list, "rigid dies: a surface, a press motion, friction with the body"),
        required(key("dies[].name", T::name, "name shown in loads.csv, the log and the VTK series")),
        key("dies[].stl", T::string,
            "die surface (STL, ASCII or binary), relative to the case file; normals out of the die; " +
                regular_file(kMaxStlBytes)),
        with_default(key("dies[].offset", T::vector3,
                         "STL dies: moves the surface from the file's coordinates to the "
                         "die's start position",
                         "mm"),
                     "[0, 0, 0]"),
        key("dies[].plane", T::map, "an analytic flat die instead of an STL surface"),
        required(key("dies[].plane.point", T::vector3, "a point of the die face", "mm")),
        required(key("dies[].plane.normal", T::vector3, "normal out of the die, towards the body (need not be unit)")),
        with_default(range(key("dies[].plane.half_size", T::number,
                               "display only: half side of the square drawn; 0 = automatic", "mm"),
                           0, kInf),
                     "0"),
        with_default(
            choices(key("dies[].motion", T::string,
                        "fixed; constant: velocity; table: speed or displacement against time along direction; "
                        "crank: mechanical press; hydraulic: velocity with a load limit; hammer and screw_press: "
                        "energy presses, the ram slowed by the work the part absorbs until each blow's energy is "
                        "spent"),
                    {"fixed", "constant", "table", "crank", "hydraulic", "hammer", "screw_press"}),
            "fixed"),
        range(key("dies[].velocity", T::vector3,
                  "constant, hydraulic: die velocity (each component within ±1e5 mm/s: 100 m/s, ten times a "
                  "hammer's blow)",
                  "mm/s"),
              -kFastest, kFastest),
        with_default(key("dies[].direction", T::vector3, "table, crank, hammer, screw_press: direction of travel"),
                     "[0, 0, -1]"),
        key("dies[].time", T::numbers, "table: times, increasing", "s"),
        key("dies[].speed", T::numbers, "table: speed at each time (give speed or displacement)", "mm/s"),
        key("dies[].displacement", T::numbers, "table: displacement at each time", "mm"),
        range(key("dies[].crank_radius", T::number, "crank: crank radius (half the stroke)", "mm"), 0, kInf, true),
        range(key("dies[].rod_length", T::number, "crank: connecting rod length", "mm"), 0, kInf, true),
        range(key("dies[].rpm", T::number, "crank: crank speed", "1/min"), 0, kInf, true),
        with_default(
            range(key("dies[].start_angle", T::number, "crank: crank angle at t = 0 from top dead centre", "deg"), 0,
                  360),
            "0"),
        range(key("dies[].load_limit", T::number,
                  "hydraulic, screw_press: press capacity, for the whole part; above it the press slows down as "
                  "(limit/load)^(1/m) (a screw press's slip clutch)",
                  "N"),
              0, kInf, true),
        range(key("dies[].blow_energy", T::number, "hammer: energy of one blow (before its efficiency)", "kJ"), 0, 1e5,
              true),
        range(key("dies[].ram_mass", T::number,
                  "hammer: mass of the ram and upper die; screw_press: of the ram (the flywheel adds its own)", "kg"),
              0, 1e6, true),
        with_default(range(key("dies[].efficiency", T::number,
                               "hammer, screw_press: share of the energy that reaches the part (blow efficiency)"),
                           0, 1, true),
                     "1"),
        with_default(range(key("dies[].blows", T::integer, "hammer, screw_press: blows struck"), 1, 1000), "1"),
        with_default(range(key("dies[].pause", T::number,
                               "hammer, screw_press: time between blows (heat alone: the part cools in air and on "
                               "the dies it touches)",
                               "s"),
                           0, 1e4),
                     "0"),
        range(key("dies[].flywheel_energy", T::number,
                  "screw_press: flywheel energy at impact (give it or flywheel_speed)", "kJ"),
              0, 1e5, true),
        range(key("dies[].flywheel_speed", T::number, "screw_press: flywheel speed at impact", "1/min"), 0, 1e5, true),
        range(key("dies[].inertia", T::number, "screw_press: flywheel moment of inertia", "kg m2"), 0, 1e7, true),
        range(key("dies[].screw_pitch", T::number, "screw_press: ram travel per turn of the screw", "mm"), 0, 1e4,
              true),
        key("dies[].wear", T::map,
            "die wear (effect die_wear): w = ∫ K p^a v^b / H^c dt at each vertex of the die (mm, with p in MPa, v the "
            "part's sliding speed in mm/s, H in HRC), in the VTK series and its largest value in summary.json"),
        required(range(key("dies[].wear.coefficient", T::number,
                           "K (tool steels: 1e-3 to 1e-2 with HRC hardness, for qualitative comparison)"),
                       0, kInf, true)),
        with_default(range(key("dies[].wear.pressure_exponent", T::number, "a"), 0, 10), "1"),
        with_default(range(key("dies[].wear.velocity_exponent", T::number, "b"), 0, 10), "1"),
        with_default(range(key("dies[].wear.hardness_exponent", T::number, "c"), 0, 10), "2"),
        range(key("dies[].wear.hardness", T::number, "the die's hardness (give it or 'material')", "HRC"), 1, 80),
        key("dies[].wear.material", T::string,
            "a die steel card whose hardness table (against temperature) gives H, relative to the case file"),
        range(key("dies[].wear.temperature", T::number,
                  "the temperature the card's hardness is read at; default the die's (thermal scenes), else 20", "°C"),
              kAbsoluteZero, kHottest, true),
        key("dies[].fill", T::map,
            "die fill (effect die_fill): the die's area touching the part and its share of a region, per increment "
            "in loads.csv and at the end in summary.json; the underfill field (distance from the part) on the die "
            "in the VTK series; 'fill: {}' measures the whole die with the default tolerance"),
        key("dies[].fill.region", T::map,
            "the cavity whose fill is asked, in the die's start position (the coordinates of the series' first "
            "frame): a box (min, max), a cylinder about the press axis (radius, axis), or both; default the whole "
            "die"),
        key("dies[].fill.region.min", T::vector3, "box: lowest corner", "mm"),
        key("dies[].fill.region.max", T::vector3, "box: highest corner", "mm"),
        range(key("dies[].fill.region.radius", T::number, "cylinder: radius about the axis", "mm"), 0, kInf, true),
        with_default(key("dies[].fill.region.axis", T::numbers, "cylinder: (x, y) of its axis, parallel to z", "mm"),
                     "[0, 0]"),
        range(key("dies[].fill.tolerance", T::number,
                  "a die point this close to the part is filled; default a tenth of the bodies' mean boundary edge "
                  "as built (it covers the chord of the part's facets on a curved die)",
                  "mm"),
              0, kInf, true),
        key("contact_pairs", T::list,
            "contact between two deformable bodies (node-to-facet, Fourment 2008), or of a body with itself "
            "(master and slave the same body: the sides of a fold or lap kept apart; symmetric, nodal)"),
        required(key("contact_pairs[].master", T::string, "master body (a name from bodies)")),
        required(
            key("contact_pairs[].slave", T::string, "slave body (a name from bodies; the master's: self-contact)")),
        with_default(choices(key("contact_pairs[].formulation", T::string,
                                 "master_slave: conditions at slave nodes (paper eq. 19); symmetric: at the nodes of "
                                 "both bodies (eq. 20); quasi_symmetric: both, with the master nodes' conditions "
                                 "added to the slave nodes' (eqs. 21-24)"),
                             {"master_slave", "symmetric", "quasi_symmetric"}),
                     "quasi_symmetric"),
        with_default(choices(key("contact_pairs[].integration", T::string,
                                 "nodal: the conditions at the boundary nodes (paper §4); facet: the contact term "
                                 "integrated over the boundary facets, λ interpolated on them (paper §3, eqs. 10-18)"),
                             {"nodal", "facet"}),
                     "nodal"),
        with_default(choices(key("contact_pairs[].facet_quadrature", T::string,
                                 "facet integration: intersection: 3 quadrature points on each part of a facet over "
                                 "one facet of the other body (their intersection); subdivision: the facet split in "
                                 "four where it projects onto several facets of the other body, 3 points on each part"),
                             {"intersection", "subdivision"}),
                     "intersection"),
        with_default(range(key("contact_pairs[].facet_subdivision", T::integer,
                               "subdivision quadrature: the most times a facet is split in four"),
                           0, contact::kMaxFacetSubdivision),
                     "4"),
        key("contact", T::map, "contact enforcement"),
        with_default(range(key("contact.penalty", T::number,
                               "penalty ρ = this × flow stress at the process rate (press speed / body size) / press "
                               "speed: contact nodes penetrate at about 1/this of the press speed"),
                           0, kInf, true),
                     "1000"),
        with_default(range(key("contact.regularisation", T::number,
                               "friction regularisation velocity relative to the fastest die speed"),
                           0, 1, true),
                     "1e-2"),
        key("time", T::map, "the time loop; without it the case is a single increment on the initial geometry"),
        range(key("time.stroke_increment", T::number,
                  "travel of the fastest die per increment (needed when something moves)", "mm"),
              0, kInf, true),
        range(key("time.heat_step", T::number,
                  "heat alone (nothing moves: cooling, dwell, transfer): Δt of each heat step; default a fiftieth of "
                  "the end time",
                  "s"),
              0, kInf, true),
        with_default(range(key("time.max_displacement", T::number,
                               "largest nodal displacement per increment, relative to the local element size"),
                           0, 1, true),
                     "0.2"),
        with_default(range(key("time.min_step_fraction", T::number,
                               "a node reaching a die shortens the increment, down to this fraction of the "
                               "nominal one and not by less"),
                           0, 1),
                     "0.1"),
        with_default(range(key("time.max_cuts", T::integer, "time-step halvings after a Newton failure"), 0, 30), "5"),
        with_default(range(key("time.max_increments", T::integer, "safety stop"), 1, kInf), "100000"),
        with_default(key("time.volume_compensation", T::boolean,
                         "incompressible bodies: each increment's flow restores the volume lost so far (explicit "
                         "update error, contact projection); false shows the raw loss"),
                     "true"),
        key("time.stop", T::map,
            "stop criteria: the first one reached ends the run (at least one, unless a hammer or screw press ends "
            "it after its blows)"),
        range(key("time.stop.stroke", T::number, "travel of the die `die`", "mm"), 0, kInf, true),
        key("time.stop.die", T::string, "die whose stroke is checked; default the first moving die"),
        range(key("time.stop.gap", T::number, "distance between the two dies along z", "mm"), 0, kInf, true),
        range(key("time.stop.load", T::number,
                  "largest press load (force along z) on any die or plate, of the whole part (a symmetry model's load "
                  "times its copies)",
                  "N"),
              0, kInf, true),
        range(key("time.stop.time", T::number, "end time", "s"), 0, kInf, true),
        key("damage", T::map,
            "ductile damage (effect damage): D = ∫ f(σ) dε̄ per element of the flowing bodies, carried through "
            "remeshes like ε̄, written to the VTK series (damage_<criterion>) and its largest value and where to "
            "summary.json (docs/method.md, \"Ductile damage\")"),
        with_default(key("damage.cockcroft_latham", T::boolean,
                         "normalized Cockcroft-Latham, f = max(σ1, 0)/σ̄ (Oh, Chen, Kobayashi 1979)"),
                     "false"),
        with_default(key("damage.oyane", T::boolean, "Oyane, f = 1 + σm/(a σ̄) (Oyane, Sato, Okimoto, Shima 1980)"),
                     "false"),
        range(key("damage.oyane_a", T::number,
                  "Oyane's material constant a (from two tests of the material at different triaxiality; "
                  "Oyane et al. 1980 §2); needed with damage.oyane",
                  "-"),
              0, kInf, true),
        with_default(key("damage.ayada", T::boolean, "Ayada, f = σm/σ̄ (Ayada, Higashino, Mori 1987)"), "false"),
        with_default(key("damage.brozzo", T::boolean, "Brozzo, f = 2σ1/(3(σ1 − σm)) (Brozzo, Deluca, Rendina 1972)"),
                     "false"),
        with_default(key("damage.progress", T::boolean, "the largest value of each criterion on the progress line"),
                     "false"),
        key("remeshing", T::map, "automatic remeshing of the flowing bodies (CGAL, fields transferred); absent: never"),
        with_default(range(key("remeshing.quality", T::number,
                               "remesh a body when its worst element's volume-edge ratio 6√2V/l_rms³ falls below this, "
                               "or would reach 0 in the next increment"),
                           0, 1),
                     "0.1"),
        with_default(range(key("remeshing.every", T::integer,
                               "also remesh every N increments (the whole body, its contact surface kept); 0 = off"),
                           0, kInf),
                     "0"),
        with_default(
            range(key("remeshing.die_penetration", T::number,
                      "also remesh when a die vertex lies this deep inside a body, relative to its element size"),
                  0, kInf, true),
            "0.25"),
        with_default(range(key("remeshing.die_overlap", T::number,
                               "also remesh the whole body when this share of its initial volume lies inside the "
                               "dies (die fillets sunk between contact nodes: a local remesh keeps that surface)",
                               "-"),
                           0, 1, true),
                     "0.01"),
        range(key("remeshing.element_size", T::number,
                  "target edge length, at most a third of the body's smallest extent; default each body's initial "
                  "mean boundary edge",
                  "mm"),
              0, kInf, true),
        with_default(range(key("remeshing.time_limit", T::number,
                               "time limit of one remesh: CGAL is stopped inside its pass after this. A whole "
                               "remesh with no try made by then is refused (the body keeps its mesh), a local one "
                               "falls back to the whole body, and the adaptive size field's finer levels stop (the "
                               "mesh is then coarser than smallest_size there)",
                               "s"),
                           0, kInf, true),
                     "120"),
        with_default(
            range(key("remeshing.max_nodes", T::integer,
                      "node budget of a remesh: sizes that would make more nodes are coarsened alike (the estimate "
                      "made before CGAL runs holds within about 12 %, docs/remeshing.md); 0 = "
                      "what this machine's memory can solve (about 20 kB a node)"),
                  0, kInf),
            "0"),
        with_default(range(key("remeshing.feature_angle", T::number,
                               "boundary edges where the surface turns more than this stay sharp", "deg"),
                           0, 180, true),
                     "40"),
        with_default(range(key("remeshing.iterations", T::integer, "CGAL remeshing passes"), 1, 20), "3"),
        with_default(
            choices(key("remeshing.size", T::string,
                        "size field: 'uniform' (element_size everywhere) or 'adaptive' (down to smallest_size: "
                        "3 elements across the gap between two dies, half a die fillet's radius, finer "
                        "where the strain rate is high; neighbours within 1.5x)"),
                    {"uniform", "adaptive"}),
            "uniform"),
        range(key("remeshing.smallest_size", T::number,
                  "adaptive size field: the smallest edge it asks for (a strain rate 4x the body's mean asks "
                  "for half the element size); "
                  "default half the element size; a remesh refuses a result that changes the body's volume by more "
                  "than 1 % or whose worst quality is below a third of remeshing.quality (the body keeps its mesh)",
                  "mm"),
              0, kInf, true),
        with_default(key("remeshing.local", T::boolean,
                         "a quality trigger rebuilds only the poor elements and two layers around them, the rest of "
                         "the body and its whole surface kept (the contact surface stays on the dies); when the "
                         "rebuilt elements stay below remeshing.quality (the surface holds them), the region is "
                         "rebuilt again with its part of the surface, its contact nodes held (not with "
                         "remeshing.split_sunk_edges); the whole body is "
                         "remeshed when that region is over half of it, when that too stays below, and for the "
                         "periodic and overlap triggers"),
                     "true"),
        key("remeshing.split_sunk_edges", T::boolean,
            "after each increment, split the boundary edges whose midpoint lies over a tenth of an "
            "element inside a die (a die fillet or edge sunk between contact nodes) and put their "
            "midpoints onto the die, nothing else moved: less of the body inside the dies and a "
            "smaller volume change, for more remeshes, and whole remeshes that then resample the "
            "refined surface with their load jumps (docs/remeshing.md); default: on with the adaptive "
            "size field, off with the uniform one"),
        key("remeshing.size_boxes", T::list,
            "adaptive size field: boxes where the edge is at most their size (graded by 1.5 around them); a box "
            "given with a die moves with it"),
        required(
            key("remeshing.size_boxes[].min", T::vector3, "lowest corner (with a die: where the die starts)", "mm")),
        required(key("remeshing.size_boxes[].max", T::vector3, "highest corner", "mm")),
        required(range(key("remeshing.size_boxes[].size", T::number,
                           "the largest edge inside; not below remeshing.smallest_size (whose default is lowered "
                           "to the smallest box's size)",
                           "mm"),
                       0, kInf, true)),
        key("remeshing.size_boxes[].die", T::string, "the die whose motion the box follows; default: fixed in space"),
        with_default(key("remeshing.check_load", T::boolean,
                         "also solve the increment after each remesh on the old mesh, and log and record the press "
                         "load's jump across the remesh at equal geometry (three more solves per remesh; the next "
                         "increment starts "
                         "from the last)"),
                     "false"),
    };
    const std::vector<KeySpec> thermal = {
        key("thermal", T::map,
            "heat: the temperature is solved in every body whose material card gives thermal properties, "
            "coupled to the flow each increment (staggered); absent: each body keeps its temperature"),
        with_default(range(key("thermal.taylor_quinney", T::number,
                               "β: share of the plastic work that becomes heat (Taylor & Quinney 1934 measured "
                               "about 0.9 in metals)"),
                           0, 1),
                     "0.9"),
        key("thermal.environment", T::map, "the air around the bodies"),
        with_default(range(key("thermal.environment.temperature", T::number, "air temperature", "°C"), kAbsoluteZero,
                           kHottest, true),
                     "20"),
        with_default(range(key("thermal.environment.convection", T::number,
                               "heat transfer coefficient to the air (free convection in gases: 2-25 W/(m2.K), "
                               "forced convection of liquids up to 20 kW/(m2.K), boiling up to 100 kW/(m2.K): "
                               "Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, Table 1.1)",
                               "kW/(m2.K) = mW/(mm2.K)"),
                           0, 100),
                     "0.01"),
        with_default(range(key("thermal.transfer_time", T::number,
                               "time before the press moves: the bodies cool in air, and on the dies where they touch "
                               "them",
                               "s"),
                           0, kInf),
                     "0"),
        with_default(range(key("thermal.transfer_steps", T::integer, "heat steps over the transfer time"), 1, 10000),
                     "10"),
        with_default(range(key("thermal.coupling_tolerance", T::number,
                               "0: staggered (the flow of an increment sees the temperatures at its start); > 0: "
                               "iterated (the flow is solved again with the temperatures its heat step gives, until "
                               "they change by less than this)",
                               "°C"),
                           0, kInf),
                     "0"),
        range(key("dies[].temperature", T::number, "thermal scenes: the die's temperature, held", "°C"), kAbsoluteZero,
              kHottest, true),
        with_default(range(key("dies[].friction_heat_to_body", T::number,
                               "thermal scenes: share of the friction heat that enters the body, the rest the die "
                               "(0.5: the two surfaces' effusivities are within 10 % for a steel billet on a steel "
                               "die)"),
                           0, 1),
                     "0.5"),
    };
    keys.insert(keys.end(), thermal.begin(), thermal.end());
    for (const auto& [owner, between] :
         {std::pair{"dies[]", "die-body; required (hot forging under pressure: 5-20 kW/(m2.K), much lower before "
                              "full contact)"},
          std::pair{"contact_pairs[]", "between the two bodies; default 1000 (perfect contact at forging time "
                                       "scales)"}}) {
      const std::vector<KeySpec> heat = heat_transfer_keys(owner, between);
      keys.insert(keys.end(), heat.begin(), heat.end());
    }
    for (const auto& [owner, between] :
         {std::pair{"dies[]", "die and body"}, std::pair{"contact_pairs[]", "the two bodies"}}) {
      const std::vector<KeySpec> friction = friction_keys(owner, between);
      keys.insert(keys.end(), friction.begin(), friction.end());
    }
    const std::vector<KeySpec> chain = operation_keys();
    keys.insert(keys.end(), chain.begin(), chain.end());
    return keys;
  }();
  return schema;
}

} // namespace anvil::scene
