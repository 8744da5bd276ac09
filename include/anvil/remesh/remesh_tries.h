// The tries of a whole remesh (Remesher.cpp), the best acceptable one kept.
// A result whose worst element is below the trigger would be due again at
// once: CGAL can keep elements whose four nodes lie on patch borders. It is
// remade with edges 5 % and then 10 % shorter, which changes where CGAL
// splits, and last with a feature angle twice as wide (at most
// kWidestFeatureAngle: a die edge presses a crease into the surface that
// the feature angle keeps as a patch border, with the element it crushed,
// the connecting rod's 0.002) and with the billet's faces one free surface
// (free_surface_tags.h: a border between two of them that the dies drew
// smooth is kept too, and a die presses its nodes together, the connecting
// rod at 1.0 mm).
#pragma once

#include <algorithm>
#include <array>

namespace anvil::remesh {

/// The widest feature angle the last try takes (deg).
constexpr double kWidestFeatureAngle = 80.0;

/// One try at a body's new mesh.
struct RemeshTry {
  double scale;         ///< its edge length, times the body's
  double feature_angle; ///< deg (remesh_body)
  bool free_surface;    ///< the faces no condition names are one free surface (free_surface_tags.h)
};

/// The tries, in the order they are taken up, for remeshing.feature_angle `feature_angle` (deg).
inline std::array<RemeshTry, 4> remesh_tries(double feature_angle) {
  return {{{1.0, feature_angle, false},
           {0.95, feature_angle, false},
           {0.9, feature_angle, false},
           {1.0, std::max(feature_angle, std::min(2.0 * feature_angle, kWidestFeatureAngle)), true}}};
}

} // namespace anvil::remesh
