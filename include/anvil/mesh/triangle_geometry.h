// Points and triangles: the nearest point of a triangle to a point, for the
// measures that look at a body's surface from outside (die fill, folds).
#pragma once
#include "anvil/mesh/TetMesh.h"

namespace anvil::mesh {

/// The point of triangle abc nearest to p (Ericson, Real-Time Collision
/// Detection, 2005, §5.1.5: by the Voronoi regions of its corners and edges).
Point nearest_on_triangle(const Point& p, const Point& a, const Point& b, const Point& c);

} // namespace anvil::mesh
