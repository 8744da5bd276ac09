// Boundary tags that are planes: a symmetry plane, an end face not yet
// deformed. The remesher keeps such a tag's nodes on its plane, and only
// while every face of the tag lies in it.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <map>
#include <utility>

namespace anvil::mesh {

/// Tags whose faces all lie in one plane (normals and offsets within 1e-9):
/// the plane's unit normal n and offset n·x.
std::map<int, std::pair<Point, double>> flat_tags(const TetMesh& mesh);

/// Whether all of `face`'s nodes lie in `plane` (normal, offset) to flat_tags' tolerance.
bool in_plane(const TetMesh& mesh, const Triangle& face, const std::pair<Point, double>& plane);

} // namespace anvil::mesh
