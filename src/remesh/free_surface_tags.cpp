#include "anvil/remesh/free_surface_tags.h"

#include "anvil/mesh/flat_tags.h"

#include <algorithm>

namespace anvil::remesh {

int free_surface_tags(mesh::TetMesh& body, std::span<const scene::BoundaryCondition> conditions) {
  const auto planes = mesh::flat_tags(body);
  int changed = 0;
  for (int& tag : body.boundary_tags) {
    const bool selected = std::any_of(conditions.begin(), conditions.end(),
                                      [&](const scene::BoundaryCondition& c) { return c.faces.tag == tag; });
    if (tag != 0 && !selected && !planes.contains(tag)) {
      tag = 0;
      ++changed;
    }
  }
  return changed;
}

} // namespace anvil::remesh
