// A new body mesh made to sit on the dies as the old one did: its boundary
// nodes put onto the dies, and the material that costs given back on its
// free surface. Both keep the next increment from having to correct the
// remesh at once (a jump of the active set, of the volume, of the load).
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <array>
#include <span>
#include <vector>

namespace anvil::remesh {

/// What put_onto_dies did.
struct PutBack {
  int nodes = 0;             ///< boundary nodes put onto a die from inside it
  double deepest = 0.0;      ///< the deepest of them was (mm)
  int closed = 0;            ///< boundary nodes put onto a die across a gap, where the old surface touched it
  double widest = 0.0;       ///< the widest such gap (mm)
  int carried = 0;           ///< of `nodes`, those whose move carried the interior under them along
  int left = 0;              ///< boundary nodes left inside a die: moving them would spoil an element
  double deepest_left = 0.0; ///< the deepest of them (mm)
};

/// Puts boundary nodes of `fresh`, the new mesh of body `body`, onto the dies
/// at `dies_now`: those inside a die (by less than `element_size`, mm), and
/// those within a quarter element of a die where the old mesh `old` touched
/// it (`touching_die`, per node of `old`: the die it presses on, or −1).
/// Nodes on a symmetry plane of the body stay on it. A node whose move alone
/// would leave an element around it worse than `quality_floor` (or than it
/// was) is moved, under an adaptive size field, with the free interior under
/// it (QualityGuard::move_carrying), in full or in part; what is still
/// inside (PutBack::left) the next increment's contact pushes out, no faster
/// than ContactIncrement::recovery_speed,
/// and the update after it projects the node where it can. With `movable`
/// (a flag per node of `fresh`) only the flagged nodes move (a local remesh's new ones).
PutBack put_onto_dies(mesh::TetMesh& fresh, const mesh::TetMesh& old, std::span<const int> touching_die,
                      const scene::Scene& scene, int body, std::span<const scene::DieState> dies_now,
                      double element_size, double quality_floor, std::span<const char> movable = {});

/// A boundary edge over a die fillet or edge: its nodes (numbered from the
/// body's first node) and the point of the die its midpoint goes onto.
struct SunkEdge {
  std::array<int, 2> nodes;
  mesh::Point on_die;
};

/// The boundary edges of the body `range` of `mesh` longer than `shortest` (mm) whose midpoint lies
/// deeper than `depth` (mm) inside a die at `dies_now`, below the face:
/// where a die fillet or edge has sunk between the contact nodes that
/// nodal contact keeps out of the die. Deeper than `deepest` is the far side
/// of an open die surface; a die wall more than 60° from facing the face is
/// not below it (a face on a symmetry plane).
std::vector<SunkEdge> edges_over_die_features(const mesh::TetMesh& mesh, const mesh::MeshRange& range,
                                              const scene::Scene& scene, std::span<const scene::DieState> dies_now,
                                              double depth, double shortest, double deepest);

/// Gives `fresh`, the new mesh of body `body`, the material `material` (mm³:
/// its volume less its overlap with the dies at `dies_now`) by moving its
/// free surface (boundary nodes off the symmetry planes and more than a
/// tenth of `element_size` off the dies) along its normal. Returns the
/// distance moved (mm; 0 when the scene has no dies). With `movable`, only
/// the flagged nodes of that free surface move.
double keep_material(mesh::TetMesh& fresh, const scene::Scene& scene, int body,
                     std::span<const scene::DieState> dies_now, double material, double element_size,
                     std::span<const char> movable = {});

} // namespace anvil::remesh
