// The scene a case describes, built once at the start of a run (and again,
// identically, on --resume): the bodies with their laws and conditions, the
// dies, the load surfaces of loads.csv, the effects and the process scales.
// The time loop reads it and never changes it.
#pragma once
#include "anvil/contact/die_fill.h"
#include "anvil/core/Timers.h"
#include "anvil/material/Material.h"
#include "anvil/mesh/TetMesh.h"
#include "anvil/scene/BoundaryCondition.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Die.h"
#include "anvil/scene/RunState.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace anvil::scene {

/// A deformable body of the scene.
struct Body {
  std::string name;
  std::string material_file;
  std::unique_ptr<material::Material> law;
  /// An elastic body solved with flowing ones or over time: its unknown is
  /// a velocity, each increment applies its law in velocity form over that
  /// increment's Δt (material::IncrementalElastic), and it carries its
  /// stress from one increment to the next (RunState::elastic_stress).
  bool velocity_form = false;
  material::PointState state; ///< the body's temperature: held, or initial in a thermal scene
  /// Thermal properties of a thermal scene's body that is solved for heat;
  /// empty otherwise (the body keeps its temperature).
  std::optional<thermal::ThermalMaterial> thermal;
  std::vector<BoundaryCondition> conditions; ///< the case's conditions on this body
  /// What they impose on the mesh as the case builds it (faces chosen on the
  /// initial geometry: a plane condition on a moving face is found there once).
  ImposedConditions initial_imposed;
  double initial_volume = 0.0; ///< mm³, of the mesh as built
  double remesh_size = 0.0;    ///< mm, target edge of a remesh: the case's, else the mean boundary edge as built
  /// A meshed die's wear (effect die_wear); its hardness the law's, else
  /// `hardness` (its card's table) at `wear_temperature`, or NaN: at each
  /// node's temperature (thermal scenes) or the body's.
  std::optional<contact::WearLaw> wear;
  std::optional<thermal::PropertyTable> hardness;
  double wear_temperature = std::numeric_limits<double>::quiet_NaN();
};

/// A load surface of loads.csv: a die, or a velocity condition (a plate).
struct LoadSurface {
  std::string name;
  int die = -1;       ///< index into Scene::dies, or −1
  int condition = -1; ///< index into Scene::conditions, or −1
};

struct Scene {
  /// Builds the scene of `c`. Throws InputError (a material card, a mesh, an
  /// STL die, a boundary condition that selects nothing, nothing moving).
  /// An operation of a chain after the first gives `part`: the bodies as
  /// the operation before left them (placed), whose meshes replace the
  /// ones the case builds (scene/Chain.h).
  Scene(const Case& c, Timers& timers, const RunState* part = nullptr);

  const Case& input; ///< the checked case file, as read
  std::vector<Body> bodies;
  std::vector<BoundaryCondition> conditions; ///< every body's, in body order
  std::vector<Die> dies;
  std::vector<LoadSurface> surfaces;           ///< the dies, then the velocity conditions
  std::vector<std::string> effects;            ///< resolve_effects
  std::vector<std::string> fingerprint;        ///< case_fingerprint: what a resumed run compares
  mesh::TetMesh initial_mesh;                  ///< the bodies as built: one mesh of disjoint parts
  std::vector<mesh::MeshRange> initial_ranges; ///< each body in initial_mesh
  /// Every body elastic and no time loop: the unknown is the displacement
  /// (mm); otherwise it is the velocity (mm/s) and elastic bodies carry σ.
  bool solve_displacement = false;
  bool carries_stress = false; ///< some body is elastic in velocity form
  /// Every body elastic: an increment's loads hold at its end (σ_{n+1} =
  /// σ_n + Δt C:ε̇), not on the geometry it starts from as a flow's do.
  bool all_elastic = false;
  bool compensate_volume = false; ///< the volume_compensation effect
  /// Some body's conditions leave it a rotation (fewer than two symmetry
  /// planes of different normals, no face whose velocity is prescribed):
  /// only contact holds it.
  bool free_rotations = false;
  bool thermal = false; ///< the heat effect: some body is solved for heat
  /// Nothing moves (no moving die, no prescribed velocity) in a thermal
  /// scene: the time loop solves heat alone (cooling, dwell, transfer).
  bool heat_only = false;
  double body_size = 0.0;        ///< mm, diagonal of the initial bounding box
  double reference_length = 0.0; ///< mm, mean boundary edge of the initial mesh
  /// mm: the dies' drawing (RunState::die_extent, die_sampling): the body's
  /// size and mean boundary edge, or what the carried part's dies were drawn with.
  double die_extent = 0.0, die_sampling = 0.0;
  double reference_velocity = 0.0; ///< mm/s, fastest die or imposed velocity at t = 0
  int upper_die = 0;               ///< with a final gap: the die above
  double die_gap0 = 0.0;           ///< mm, gap between the two dies at zero displacement
  /// The whole part is this many copies of the model: 2 for each axis (x, y)
  /// normal to one of its symmetry planes, which contain the press axis z. A
  /// plane normal to z halves the part's height, not the press load.
  int symmetry_copies = 1;
  /// output.flow_lines: the coordinates along its axis of the planes of
  /// material drawn as flow lines, evenly through the bodies' extent at the
  /// start; empty without flow lines.
  std::vector<double> flow_line_levels;
  /// The model's side of its symmetry planes (unbounded along an axis
  /// without one): the whole part is its mirror images.
  Eigen::AlignedBox3d model_side{Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity()),
                                 Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity())};

  bool has_contact() const { return !dies.empty() || !input.contact_pairs.empty(); }
  /// ε̇ of the process (1/s): v_ref over the scene size.
  double reference_rate() const { return reference_velocity / body_size; }
  /// Distance between the two dies along z (mm), for the gap stop criterion.
  double die_gap(std::span<const DieState> dies_now) const;
  /// The press load of the whole part (N) for `record`'s model load.
  double whole_part_load(const LoadRecord& record) const { return symmetry_copies * record.press_load(); }
  /// "quarter model (symmetry planes normal to x and y)", "half model (...)", "whole part".
  std::string model_text() const;
};

/// mm: a point of die `die` this close to the part is filled (dies[].fill.tolerance).
double fill_tolerance(const Scene& scene, int die);

/// The fill of each die at the geometry `mesh`, the dies at `dies_now`
/// (docs/reading-a-run.md §3); empty for a die that does not ask for it.
std::vector<std::optional<contact::DieFill>> die_fills(const Scene& scene, const mesh::TetMesh& mesh,
                                                       std::span<const DieState> dies_now, bool with_underfill);

/// The state of a run that starts: the bodies as built, at rest, t = 0. An
/// operation of a chain starts from `part` (the scene's own): its bodies
/// keep their mesh and every field they carry (ε̄, damage, σ of elastic
/// bodies, T, the material's start positions, a meshed die's wear, their
/// last flow); the dies, the clock and the records start anew.
RunState initial_state(const Scene& scene, const RunState* part = nullptr);

/// Throws InputError when the state of the checkpoint at `path` does not
/// belong to the scene (its dies, bodies, load surfaces, outputs).
void check_resumable(const Scene& scene, const RunState& state, const std::string& path);

/// mm³ of body `body`, as `range` of `mesh` holds it, inside the dies at `dies_now`.
double inside_dies(const Scene& scene, const mesh::TetMesh& mesh, const mesh::MeshRange& range, int body,
                   std::span<const DieState> dies_now);
/// The same for every body of `state` (RunState::inside_dies).
std::vector<double> inside_dies(const Scene& scene, const RunState& state);

} // namespace anvil::scene
