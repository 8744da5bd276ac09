// Structured tetrahedral meshes of simple shapes, for cases and tests.
#pragma once
#include "anvil/mesh/TetMesh.h"

namespace anvil::mesh {

/// Box [origin, origin+size] (mm) cut into cubes of about `element_size` mm
/// (at least one per side), each split into 6 tets (Kuhn; conforming).
/// Boundary tags: 1 x-min, 2 x-max, 3 y-min, 4 y-max, 5 z-min, 6 z-max.
TetMesh make_box(const Point& origin, const Point& size, double element_size);

/// Same with an explicit number of cells per direction.
TetMesh make_box(const Point& origin, const Point& size, const std::array<int, 3>& cells);

/// Cylinder of axis z, base centred at the origin, z in [0, height] (mm).
/// The disc is meshed in concentric rings of about `element_size` spacing
/// (ring k has 6k nodes), then extruded in layers; each prism is split into
/// 3 tets by the global-index rule, which keeps neighbouring prisms conforming.
/// Boundary tags: 1 bottom (z = 0), 2 top (z = height), 3 lateral.
TetMesh make_cylinder(double radius, double height, double element_size);

/// Quarter cylinder x, y ≥ 0 of axis z, z in [0, height]: a structured box
/// mapped onto the quarter disc (elliptical grid mapping), for models with
/// two symmetry planes. Tags: 1 plane x = 0, 2 lateral, 3 plane y = 0,
/// 5 bottom (z = 0), 6 top (z = height).
TetMesh make_quarter_cylinder(double radius, double height, double element_size);

/// Quarter ring x, y ≥ 0 between inner and outer radius, z in [0, height].
/// Tags: 1 inner surface, 2 outer surface, 3 plane y = 0, 4 plane x = 0,
/// 5 bottom, 6 top.
TetMesh make_quarter_ring(double outer_radius, double inner_radius, double height, double element_size);

/// Nodes the generators above make with these arguments, counted without
/// building the mesh (a double: a mistyped element size must not overflow
/// the count before it is refused).
double box_node_count(const Point& size, double element_size);
double cylinder_node_count(double radius, double height, double element_size);
double quarter_cylinder_node_count(double radius, double height, double element_size);
double quarter_ring_node_count(double outer_radius, double inner_radius, double height, double element_size);

} // namespace anvil::mesh
