// Everything the time loop carries from one increment to the next, and
// nothing else: what an HDF5 checkpoint stores, so that a resumed run
// continues exactly (bit for bit) as the uninterrupted one would, and one
// measure of the geometry the checkpoint does not need to store.
#pragma once
#include "anvil/fem/Assembler.h"
#include "anvil/mesh/TetMesh.h"
#include "anvil/solver/KeptSetUp.h"

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace anvil::scene {

/// Where a die is: press time runs at `speed_factor` × real time (< 1 when a
/// hydraulic press is held back by its load limit).
struct DieState {
  double press_time = 0.0; ///< s
  double speed_factor = 1.0;
  double stroke = 0.0;                                    ///< mm travelled
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero(); ///< mm, of the die frame
};

/// One file of the VTK series: a body's or a die's dataset at one time.
struct OutputFrame {
  double time;      ///< s
  int part;         ///< 0 the bodies, d + 1 die d
  std::string file; ///< relative to the run's folder
};

/// One line of loads.csv: the load on a die (or velocity plate) solved on the geometry after `increment` increments.
struct LoadRecord {
  int increment;
  double time;           ///< s
  int surface;           ///< index into the run's load surfaces (dies, then velocity plates)
  double stroke;         ///< mm
  Eigen::Vector3d force; ///< N, exerted by the body on the surface

  /// The press load (N): the force along the press axis z (docs/design.md §1), as
  /// the press's gauge reads it. A symmetry model's dies also carry lateral
  /// friction forces that the whole part would balance: they are in `force`
  /// only.
  double press_load() const { return std::abs(force.z()); }
  /// Die fill of a die that asks for it (effect die_fill) at the same
  /// geometry: mm² touching the part, and that area's share of the fill
  /// region; NaN otherwise (an empty cell in loads.csv).
  double contact_area = std::numeric_limits<double>::quiet_NaN();
  double fill = std::numeric_limits<double>::quiet_NaN();
};

/// Volume budget (mm³): where volume went, by cause.
struct VolumeBudget {
  double initial = 0.0;
  double solver = 0.0;            ///< change from x += Δt v (time-integration error plus compensation)
  double compensation = 0.0;      ///< volume the compensation dilatation asked the flow to restore
  double projection = 0.0;        ///< change from putting contact nodes back on the dies
  double remeshing = 0.0;         ///< change from remeshing (new mesh against old)
  double largest_increment = 0.0; ///< largest |relative change| in one increment
};

/// One remesh of one body: what it changed.
struct RemeshRecord {
  int increment; ///< after this increment
  int body;      ///< index into the case's bodies
  int nodes_before, nodes_after;
  double worst_quality_before, worst_quality_after;
  double volume_change;          ///< relative
  double strain_integral_change; ///< relative change of ∫ε̄ dV by the transfer
  double strain_max_change;      ///< relative change of max ε̄ by the transfer
  double seconds;                ///< wall time (remesh and transfer)
  /// N, press load (first load surface) of the next increment solved on the
  /// old mesh and on the new one, same geometry and Δt (remeshing.check_load;
  /// NaN when not checked or a solve failed).
  double load_old_mesh = std::numeric_limits<double>::quiet_NaN();
  double load_new_mesh = std::numeric_limits<double>::quiet_NaN();
  /// The jump the remesh puts in the load-stroke curve, relative; NaN when
  /// not measured.
  double load_jump() const { return load_new_mesh / load_old_mesh - 1.0; }
  /// Relative change of the body's material (its mesh less the part inside
  /// the dies) by the remesh, put-back and give-back included; NaN from a
  /// checkpoint written before it was kept.
  double material_change = std::numeric_limits<double>::quiet_NaN();
  /// mm, the deepest die vertex inside the body after a remesh that fitted
  /// its surface to the dies (what it could not fit); NaN when the remesh
  /// kept the surface, without dies, or from an older checkpoint.
  double die_depth_after = std::numeric_limits<double>::quiet_NaN();
  /// mm³, the body's overlap with the dies after a remesh that fitted its
  /// surface (what its put-back left); NaN when it kept the surface,
  /// without dies, or from an older checkpoint.
  double die_overlap_after = std::numeric_limits<double>::quiet_NaN();
  /// Share of the body's elements the remesh rebuilt: 1 for a whole
  /// remesh, less for a local one; NaN from an older checkpoint.
  double rebuilt_share = std::numeric_limits<double>::quiet_NaN();
};

/// One blow of an energy press (hammer, screw press), struck or under way.
struct BlowRecord {
  int die;                 ///< index into the case's dies
  int blow;                ///< 1 for the first
  int first_increment;     ///< the increment the blow starts with
  int last_increment = -1; ///< the last increment it has moved in so far
  double start_time;       ///< s
  double end_time = 0.0;   ///< s, at the end of its last increment so far
  double energy;           ///< mJ the blow brings to the part
  double work = 0.0;       ///< mJ done on the whole part so far, Σ F·v Δt
  double stroke = 0.0;     ///< mm
  double peak_load = 0.0;  ///< N, whole part
  double load = 0.0;       ///< N, whole part, resisting the ram in its last increment
  bool over = false;       ///< its energy spent
  double energy_left() const { return energy - work; }
};

/// A fold (effect folds): where a body's surface met itself.
struct FoldRecord {
  int increment; ///< first found after this increment
  int body;
  Eigen::Vector3d centre; ///< mm, where it was last found
  double area;            ///< mm², the largest it was found, both sides
};

/// Heat budget of a thermal run (mJ), summed over its heat steps
/// (summary.json "heat"). The bodies' balance is
///   stored = plastic + friction − to_dies − to_environment,
/// conduction inside and between bodies creating no heat.
struct HeatBudget {
  double plastic = 0.0;  ///< β × the plastic work
  double friction = 0.0; ///< friction heat generated, on both surfaces
  double to_dies = 0.0;  ///< into rigid dies (and bodies not solved for heat): conduction and their friction share
  double to_environment = 0.0; ///< convection and radiation to the air
  double stored = 0.0;         ///< change of the heat the bodies hold, Σ C ΔT over the steps
  double remeshing = 0.0;      ///< change of the stored heat by remeshing's transfer (apart from `stored`)
  double initial_heat = 0.0;   ///< Σ C T (above 0 °C) of the bodies at the start of the run
  /// stored − (plastic + friction − to_dies − to_environment): zero to the linear solver's precision.
  double imbalance() const { return stored - (plastic + friction - to_dies - to_environment); }
};

/// The remesh check after the increment that met the stop criterion, which
/// the loop does not make (its remesh would be wasted): that increment's Δt
/// (s), strain rate per element (1/s) and the die each node pressed on (−1:
/// none), as remesh::remesh_due and the remesh take them; a resumed run has
/// no contact solution of its own to find the last. A checkpoint written at
/// the stop carries it, and a run resumed past that stop makes the check
/// first, as the uninterrupted run made it after that increment.
struct RemeshCheck {
  double time_step = 0.0;
  std::vector<double> rate;
  std::vector<int> touching_die;
  bool empty() const { return rate.empty(); }
};

struct RunState {
  int increment = 0;
  double time = 0.0; ///< s
  mesh::TetMesh mesh;
  std::vector<mesh::MeshRange> bodies; ///< where each body sits in `mesh` (changes with remeshing)
  fem::BodyUnknowns unknowns;
  std::vector<double> equivalent_strain; ///< ε̄ per element
  /// D per element of each criterion of Case::damage (in its order); empty
  /// when the case asks for none. Zero in elastic bodies (no plastic flow).
  std::vector<std::vector<double>> damage;
  /// σ (MPa, Mandel, 6 per element) carried by the elements of elastic bodies
  /// solved in velocity form; empty when the scene has none.
  std::vector<double> elastic_stress;
  /// T (°C) per node in a thermal scene; empty otherwise.
  std::vector<double> temperature;
  /// (x, y, z) per node: where its material was at the start (mm), carried
  /// through remeshes (output.flow_lines); empty otherwise.
  std::vector<double> material_position;
  HeatBudget heat;
  double transfer_time = 0.0; ///< s of the transfer phase done (thermal.transfer_time), before increment 1
  std::vector<DieState> dies;
  std::vector<LoadRecord> loads;
  VolumeBudget volume;
  int newton_iterations = 0; ///< total over the run
  /// Per increment: Newton iterations and Krylov iterations (0 with a direct solver).
  std::vector<std::array<int, 2>> iterations;
  std::vector<RemeshRecord> remeshes;
  std::vector<FoldRecord> folds;
  std::vector<BlowRecord> blows; ///< of the energy presses, in the order struck
  /// Die wear (mm) at each vertex of each die's surface (effect die_wear);
  /// empty for a die without wear.
  std::vector<std::vector<double>> wear;
  /// Wear (mm) at each node of each meshed die (a body with wear), by its
  /// node in the body (elastic bodies keep their mesh); empty for the others.
  std::vector<std::vector<double>> body_wear;
  /// mm: the size a plane die is drawn to (without plane.half_size) and the
  /// spacing a worn die is sampled at, as the run's first scene drew them;
  /// a chain's later operations draw theirs alike, so that a die used again
  /// has the same vertices and wears on. 0: not drawn yet.
  double die_extent = 0.0, die_sampling = 0.0;
  std::vector<OutputFrame> outputs; ///< the VTK series written so far (io::VtkSeries)
  /// The linear solver's kept preconditioner, in a checkpoint written at a
  /// stop (solver::KeptSetUp); empty while the run goes on.
  solver::KeptSetUp kept_setup;
  /// In a checkpoint written at the stop criterion of a remeshing run; empty
  /// while the run goes on.
  RemeshCheck remesh_check_at_stop;
  /// mm³ per body of its mesh inside the dies (die::overlap_volume), measured
  /// whenever the mesh or the dies move; not stored: measured again on resume.
  std::vector<double> inside_dies;
};

} // namespace anvil::scene
