// The adaptive size field of a remesh (remeshing.adaptive): small elements
// where a die's shape is imprinted on the body and where it flows fast.
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/remesh/field_transfer.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <functional>
#include <span>

namespace anvil::remesh {

/// The edge length wanted at a point (mm) for a remesh at `scale` times the
/// body's size: near a die, the distance to it (contact is nodal: what the
/// die's shape puts on the body is resolved by the nodes there); where the
/// body flows fast, coarse·√(mean ε̄̇ / ε̄̇), so a rate 4 times the body's
/// volume-weighted mean gets half the edge; between scale × `smallest` and
/// scale × `coarse`. `old` is the body's mesh before the remesh, `in_old`
/// locates points in it, `rate` is ε̄̇ per element of `old` in the increment
/// just solved, the dies are at `dies_now`; `old`, `in_old` and `rate` must
/// outlive the returned function.
std::function<double(const mesh::Point&, double scale)>
adaptive_size(const mesh::TetMesh& old, const PointLocator& in_old, std::span<const double> rate,
              const scene::Scene& scene, std::span<const scene::DieState> dies_now, double coarse, double smallest);

} // namespace anvil::remesh
