// Mesh readers. Each returns a validated TetMesh (see validate()) with the
// boundary triangles' tags kept: Gmsh physical tag (else the entity tag),
// Medit triangle reference.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <string>

namespace anvil::mesh {

/// Gmsh ASCII, formats 2.2 and 4.1. Element types other than 4-node tets
/// and 3-node triangles (points, lines) are skipped.
TetMesh read_gmsh(const std::string& path);

/// Medit ASCII .mesh (Vertices, Triangles, Tetrahedra sections).
TetMesh read_medit(const std::string& path);

/// Dispatch on the extension: .msh -> Gmsh, .mesh -> Medit.
TetMesh read_mesh(const std::string& path);

} // namespace anvil::mesh
