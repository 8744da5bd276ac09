// A body remeshed in a region (docs/remeshing.md): the poor elements and
// the layers around them, or the elements around a die corner with their part
// of the surface; the rest keeps its nodes, connectivity and fields.
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/remesh/fit_to_dies.h"
#include "anvil/remesh/remesh_body.h"
#include "anvil/remesh/remesh_due.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"
#include "anvil/thermal/HeatStep.h"

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace anvil::remesh {

/// A body's mesh and the fields a remesh carries.
struct BodyFields {
  mesh::TetMesh mesh;
  Eigen::VectorXd nodal;                   ///< 4 a node: v, p
  std::vector<double> strain;              ///< ε̄ a tet
  std::vector<std::vector<double>> damage; ///< D a tet, per damage criterion
  std::vector<double> temperature;         ///< a node; empty when isothermal
  std::vector<double> material;            ///< 3 a node; empty without flow lines
  std::vector<int> touching_die;           ///< a node: the die it presses on, or −1
};

/// A body remeshed around its poor elements, with its fields.
struct LocalRemesh {
  mesh::TetMesh mesh;
  Eigen::VectorXd nodal;                   ///< 4 a node: v, p
  std::vector<double> strain;              ///< ε̄ a tet
  std::vector<std::vector<double>> damage; ///< D a tet, per damage criterion
  Eigen::VectorXd temperature;             ///< a node; empty when isothermal
  Eigen::VectorXd material;                ///< 3 a node: where it started; empty without flow lines
  int rebuilt = 0;                         ///< tets of the old mesh rebuilt
  int flips = 0;                           ///< surface edges flipped (surface_mending.h), nodes unmoved
  int collapses = 0;                       ///< short surface edges collapsed, a node gone each
  int peeled = 0;                          ///< flat tets on a sharp edge of the kept surface taken off
  RegionSurface surface = RegionSurface::kept;
  double worst = 1.0; ///< worst quality of the rebuilt region
  /// Taken with `worst` below remeshing.quality: better than the body's
  /// worst before, and at least kQualityAgain of the trigger.
  bool short_of_trigger = false;
  /// With the surface rebuilt: the volume (mm³) of CGAL's mesh and after the
  /// put-back onto the dies, and what the put-back and keep_material did.
  double volume_remeshed = 0.0, volume_put_back = 0.0, given_back = 0.0;
  PutBack put_back;
  double strain_integral_change = 0.0, strain_max_change = 0.0; ///< relative, over the body
};

/// What remesh_locally rebuilds.
enum class Region {
  due,        ///< the poor elements or the die corners of the remesh due, and layers around them
  whole_body, ///< every element, the contact surface kept (a whole remesh that keeps the load)
};

/// A free boundary node this close to a die (× the element size) is about to
/// touch it: on the hub flange at 1 mm, the nodes the next increment brings
/// onto the dies lie within 0.05 mm of them.
constexpr double kAboutToTouch = 0.1;

/// A body's contact surface, which a remesh that rebuilds the surface keeps
/// (a flag per node of `part`, body `b` of the scene): the nodes that press
/// on a die (`touching_die`, per node: the die, or −1), and the boundary
/// nodes within kAboutToTouch element sizes of a die, which the next
/// increments bring onto it. Resampled, the edge of each contact zone moves
/// back by up to an element and the load falls with it (the hub flange at
/// 1 mm remeshed after one increment: 8 %, and 1.3 % with these nodes kept;
/// tools/remesh_study --periodic).
std::vector<char> contact_surface(const mesh::TetMesh& part, std::span<const int> touching_die,
                                  const scene::Scene& scene, int b, std::span<const scene::DieState> dies_now);

/// Body `b`'s mesh `part` rebuilt where its elements are poor (rebuild_region)
/// or around the die corners of `due`, the rest kept bit for bit with its
/// fields; the fields transferred in the rebuilt region only. Poor elements
/// held by the surface are first mended on it (surface_mending.h). The
/// region's surface is kept when that is enough (a flat element CGAL leaves
/// on a sharp edge of it taken off); it is rebuilt around a die corner,
/// or when the poor elements are held by the surface, and then its new
/// nodes are put onto the dies and the material `material` (mm³) kept on
/// its new free surface. Nothing, with `why_not` saying why, when the
/// region is most of the body or its result is still below the trigger.
/// With Region::whole_body, every element is rebuilt with the surface, the
/// contact surface (contact_surface) kept, the result checked alike.
std::optional<LocalRemesh> remesh_locally(const scene::Scene& scene, const scene::RunState& state, int b,
                                          const RemeshDue& due, BodyFields fields, double material, double time_step,
                                          Region choice, std::string& why_not);

/// after / before − 1 (after − before when before is 0).
double relative(double after, double before);

/// The nodal thermal mass of a body `part` of one thermal material.
thermal::NodalMass nodal_mass(const mesh::TetMesh& part, const thermal::ThermalMaterial& material);

/// The heat (mJ) a body `part` of one thermal material stores at the nodal temperatures `t`.
double stored_heat(const mesh::TetMesh& part, const double* t, const thermal::ThermalMaterial& material);

} // namespace anvil::remesh
