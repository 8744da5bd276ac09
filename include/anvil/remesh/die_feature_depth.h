// Remeshing trigger "a die feature penetrates the body surface". Contact is nodal: it keeps body nodes out of the die,
// not die corners out of the body. A die corner that has gone between body nodes is seen here, and a remesh puts nodes
// where the die shapes the body.
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <vector>

namespace anvil::remesh {

/// The deepest vertex of one die inside a body.
struct DieFeature {
  double depth = 0.0;                       ///< mm, distance to the body's surface; 0 when none is inside
  mesh::Point vertex = mesh::Point::Zero(); ///< mm, where that vertex is
};

/// A die vertex inside a body.
struct SunkVertex {
  int die = 0;
  DieFeature feature; ///< its depth and place
};

/// The vertices of the dies (each die's, in place) inside the body `body` of `mesh`,
/// shared out among the processes (processes::share_out).
std::vector<SunkVertex> sunk_die_vertices(const mesh::TetMesh& mesh, const mesh::MeshRange& body,
                                          const std::vector<std::vector<mesh::Point>>& die_vertices);

/// For each of `dies` dies, its deepest vertex among `sunk` (depth 0 when it has none).
std::vector<DieFeature> deepest_per_die(const std::vector<SunkVertex>& sunk, std::size_t dies);

/// For each die (its vertices, in place), its vertex deepest inside the
/// body `body` of `mesh`.
std::vector<DieFeature> die_feature_depths(const mesh::TetMesh& mesh, const mesh::MeshRange& body,
                                           const std::vector<std::vector<mesh::Point>>& die_vertices);

/// Each die's surface vertices where the die is now.
std::vector<std::vector<mesh::Point>> dies_in_place(const scene::Scene& scene, const scene::RunState& state);

} // namespace anvil::remesh
