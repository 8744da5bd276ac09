// Die surfaces from STL files (ASCII or binary), read, repaired and checked
// with CGAL (docs/libraries.md §2), searched with a CGAL AABB tree. CGAL stays
// behind this function: it is compiled in its own library.
#pragma once
#include "anvil/die/DieSurface.h"

#include <memory>
#include <string>

namespace anvil::die {

/// Reads `path` and moves it by `offset` (mm: the die's start position when
/// the file holds it at another); `source` ("case.yaml:12") names the
/// referring line in errors. Closed surfaces are oriented outwards; open ones keep their facet order
/// (normals must point out of the die). Degenerate facets are reported in the
/// log and dropped; a surface that is not a consistent triangle mesh is an
/// InputError.
std::unique_ptr<DieSurface> read_stl_surface(const std::string& path, const std::string& source,
                                             const Eigen::Vector3d& offset = Eigen::Vector3d::Zero());

} // namespace anvil::die
