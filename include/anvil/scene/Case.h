// A case file (scene) as read and checked, before anything is built.
#pragma once
#include "anvil/contact/BodyContact.h"
#include "anvil/contact/Friction.h"
#include "anvil/contact/die_fill.h"
#include "anvil/contact/die_wear.h"
#include "anvil/material/Material.h"
#include "anvil/material/damage.h"
#include "anvil/scene/BoundaryCondition.h"
#include "anvil/solver/IncrementSolver.h"
#include "anvil/thermal/ThermalMaterial.h"

#include <Eigen/Geometry>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace anvil::scene {

struct MeshSpec {
  std::string file;     ///< absolute or relative to the working directory, resolved from the case's folder
  std::string generate; ///< "box", "cylinder", "quarter_cylinder", "quarter_ring" or empty
  mesh::Point origin = mesh::Point::Zero(), size = mesh::Point::Zero();
  double radius = 0.0, inner_radius = 0.0, height = 0.0, element_size = 0.0; ///< mm
  std::string source;                                                        ///< "file:line" of the mesh key
};

/// Wear (effects die_wear) of a rigid die or a meshed (elastic) die: the
/// Archard law and where its hardness comes from.
struct WearSpec {
  bool enabled = false;
  contact::WearLaw law; ///< its hardness when given (`card` empty)
  /// Material card whose hardness table gives H; empty: law.hardness given.
  /// A meshed die reads its own card's table unless given a hardness.
  std::string card;
  double temperature = std::numeric_limits<double>::quiet_NaN(); ///< °C the card is read at; NaN: the die's
};

struct BodySpec {
  std::string name;
  std::string material_file;
  MeshSpec mesh;
  std::optional<double> temperature; ///< °C, isothermal or initial; default: the material card's
  WearSpec wear;                     ///< elastic bodies (meshed dies)
  std::string source;
};

/// Heat exchange through a contact (die-billet, body-body): the heat transfer
/// coefficient, constant or a table against the contact pressure.
struct ContactHeatSpec {
  thermal::PropertyTable coefficient; ///< h (kW/(m²·K) = mW/(mm²·K)) against σn (MPa)
  bool given = false;
};

/// A rigid die: surface, press motion and friction with the body.
struct DieSpec {
  std::string name;
  std::string stl_file; ///< STL surface (die frame = file coordinates), or empty for a plane
  Eigen::Vector3d stl_offset = Eigen::Vector3d::Zero(); ///< mm, moves the STL surface to its start position
  mesh::Point plane_point = mesh::Point::Zero();
  Eigen::Vector3d plane_normal = Eigen::Vector3d::UnitZ(); ///< out of the die, towards the body
  double plane_half_size = 0.0;                            ///< mm, display only; 0 = twice the body size
  std::string motion = "fixed";                       ///< fixed, constant, table, crank, hydraulic, hammer, screw_press
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); ///< constant, hydraulic (mm/s)
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ(); ///< table, crank
  std::vector<double> table_time, table_values;          ///< table: s and mm/s (speed) or mm (displacement)
  bool table_is_speed = true;
  double crank_radius = 0.0, rod_length = 0.0, rpm = 0.0, start_angle = 0.0; ///< mm, mm, 1/min, deg
  double load_limit = std::numeric_limits<double>::infinity();               ///< N, hydraulic, screw_press
  // Energy presses (hammer, screw_press): die::EnergyPress.
  double blow_energy = 0.0;    ///< kJ: a hammer's blow, a screw press's flywheel (0: from flywheel_speed)
  double efficiency = 1.0;     ///< share of the energy that reaches the part
  double ram_mass = 0.0;       ///< kg
  double flywheel_speed = 0.0; ///< rpm, screw press
  double inertia = 0.0;        ///< kg·m², screw press flywheel
  double screw_pitch = 0.0;    ///< mm per turn, screw press
  int blows = 1;
  double pause = 0.0; ///< s between blows
  contact::FrictionLaw friction;
  // Thermal scenes only.
  double temperature = 20.0;          ///< °C, held (a die is a heat sink)
  ContactHeatSpec heat;               ///< to the bodies it touches
  double friction_heat_to_body = 0.5; ///< share of the friction heat into the body
  WearSpec wear;                      ///< die wear (effect die_wear): contact/die_wear.h
  // Die fill (effect die_fill), when `fill`.
  bool fill = false;
  contact::FillRegion fill_region; ///< die at its start position; unbounded: the whole die
  double fill_tolerance = 0.0;     ///< mm; 0: a tenth of the bodies' mean boundary edge as built
  std::string source;
};

/// Contact between two deformable bodies (docs/design.md §3, Fourment 2008).
struct ContactPairSpec {
  int master = 0, slave = 1; ///< body indices
  contact::PairMethod method;
  contact::FrictionLaw friction;
  ContactHeatSpec heat; ///< thermal scenes: between the two bodies (perfect contact when absent)
  std::string source;
};

/// Heat (thermal scenes, docs/design.md §2): absent from a case, every body keeps its temperature.
struct ThermalSpec {
  bool enabled = false;
  double taylor_quinney = 0.9;           ///< β: share of the plastic work that becomes heat
  double environment_temperature = 20.0; ///< °C, of the air around the bodies
  double convection = 0.01;              ///< h to the air, mW/(mm²·K) = kW/(m²·K)
  double transfer_time = 0.0;      ///< s before the press moves (the billet cools in air and on the dies it touches)
  int transfer_steps = 10;         ///< heat steps over the transfer time
  double coupling_tolerance = 0.0; ///< °C; 0: staggered, > 0: iterated (scene/Increment.h solve_coupled)
  std::string source;
};

/// The time loop (docs/design.md §4). Absent from a case: one increment, no update.
struct TimeSpec {
  bool enabled = false;
  double stroke_increment = 0.0; ///< mm of travel of the fastest die per increment (0: not given)
  double heat_step = 0.0;        ///< s, heat alone (nothing moves); 0: a fiftieth of end_time
  double max_displacement = 0.2; ///< largest nodal displacement per increment / local element size
  double min_step_fraction =
      0.1;          ///< contact events shorten Δt down to this fraction of the nominal one, and not by less
  int max_cuts = 5; ///< Δt halvings after a Newton failure
  int max_increments = 100000;
  bool max_increments_given = false; ///< set in the case: a run cut short on purpose (it then ends with exit 4)
  std::string source;                ///< "file:line" of the time section
  bool volume_compensation = true;   ///< incompressible bodies: restore lost volume each increment
  // Stop criteria; the first one reached ends the run.
  double final_stroke = std::numeric_limits<double>::infinity(); ///< mm, of `stroke_die`
  int stroke_die = 0;
  double final_gap = 0.0; ///< mm between the two dies along the press axis (z); 0 = none
  double max_load = std::numeric_limits<double>::infinity(); ///< N, on any die
  double end_time = std::numeric_limits<double>::infinity(); ///< s
  /// °C, heat alone: the bodies' hottest node cooled to it
  double stop_temperature = -std::numeric_limits<double>::infinity();
};

/// A box of the adaptive size field (remeshing.size_boxes): edges of at
/// most `size` inside it, graded by 1.5 around it.
struct SizeBox {
  Eigen::AlignedBox3d box; ///< mm; with a die, where it is when the die is at its start
  double size = 0.0;       ///< mm
  int die = -1;            ///< the die whose motion it follows; −1: fixed in space
};

/// Automatic remeshing. Flowing bodies only: an elastic die strains
/// too little to need it and keeps its mesh.
struct RemeshSpec {
  bool enabled = false;
  double quality = 0.1;            ///< trigger: worst volume-edge ratio below this (or ≤ 0 predicted next increment)
  int every = 0;                   ///< trigger: every N increments (0 = off)
  double die_penetration = 0.25;   ///< trigger: a die vertex this deep inside the body, × element size
  double die_overlap = 0.01;       ///< trigger: this share of the body's initial volume inside the dies
  double element_size = 0.0;       ///< mm, target edge length; 0 = the body's initial mean boundary edge
  double feature_angle = 40.0;     ///< degrees
  int iterations = 3;              ///< CGAL passes
  bool adaptive = false;           ///< size field: finer near the dies and where ε̄̇ is high (else uniform)
  double smallest_size = 0.0;      ///< mm, adaptive: edge length at a die surface; 0 = half the element size
  int max_nodes = 0;               ///< node budget of one body's remesh; 0 = what the machine's memory allows
  double time_limit = 120.0;       ///< s, work limit of one body's remesh (checked between CGAL passes)
  bool check_load = false;         ///< solve the increment after a remesh on the old mesh too: the load jump it makes
  bool local = true;               ///< a quality trigger rebuilds the poor elements' region only (remesh_region)
  bool split_sunk_edges = false;   ///< split surface edges over a die fillet or edge sunk between contact nodes
  std::vector<SizeBox> size_boxes; ///< adaptive: where the user asks for finer elements

  /// The worst element quality a remesh may leave, and a contact node's move
  /// back onto its die after an increment: a third of the trigger. (Not
  /// RemeshSettings::quality_floor, which is the trigger itself.)
  double worst_allowed_quality() const { return quality / 3.0; }
};

struct ContactSpec {
  double penalty = 1e3;         ///< ρ relative to σ₀ / v_ref (mean flow stress / press speed)
  double regularisation = 1e-2; ///< friction w₀ relative to the fastest die speed
};

struct Case {
  std::string path;                   ///< the case file
  std::vector<std::string> overrides; ///< command-line "key.path=value" changes applied to the file
  std::vector<std::string> settings;  ///< every key as "key = value", overrides applied (the resume fingerprint)
  std::string title;
  std::string output_directory; ///< empty = out/<case name>
  bool write_vtk = true;
  bool write_picture = true;   ///< anvil run: final.png of the last increment (anvil render)
  bool picture_mirror = false; ///< final.png: a quarter model drawn whole (anvil render --mirror)
  solver::NewtonSettings newton;
  solver::LinearSolverSettings linear_solver;
  int quadrature_degree = 5; ///< solver.quadrature_degree: of the rule over each element (fem::tet_quadrature)
  std::string petsc_options; ///< solver.petsc_options, for ScopedPetscOptions
  std::vector<BodySpec> bodies;
  std::vector<BoundaryCondition> boundary;
  std::vector<int> boundary_body; ///< body index of each boundary condition
  std::vector<DieSpec> dies;
  std::vector<ContactPairSpec> contact_pairs;
  ContactSpec contact;
  TimeSpec time;
  RemeshSpec remeshing;
  ThermalSpec thermal;
  int vtk_every = 1;         ///< write the VTK series every N increments (and the last)
  int checkpoint_every = 10; ///< HDF5 checkpoint every N increments (and the last); 0 = never
  int flow_line_axis = -1;   ///< output.flow_lines: 0, 1, 2 for planes normal to x, y, z; −1: none
  int flow_line_count = 12;  ///< planes of material
  bool detect_folds = false; ///< output.folds
  /// damage: the ductile damage criteria integrated per element (effect
  /// damage), in the order of material::damage_criterion_names(); empty: none.
  std::vector<material::DamageModel> damage;
  bool damage_on_progress = false; ///< damage.progress: the largest value of each on the progress line
};

/// Reads and checks a case file, with command-line `overrides` applied first:
/// "key.path=value", where "dies[]" means every die and "dies[1]" the second,
/// e.g. "dies[].friction.factor=0.1" or "bodies[0].mesh.element_size=1.5".
/// Throws InputError naming file, line and key (or the override).
Case read_case(const std::string& path, const std::vector<std::string>& overrides = {});

} // namespace anvil::scene
