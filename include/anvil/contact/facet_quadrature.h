// Quadrature of facet (integrated) contact, paper §3. On a facet the
// integrand M_k h is a polynomial only between the edges of the other
// body's facets that its points project onto; across such an edge it has a
// kink. Two quadratures, each with the 3-point rule of degree 2 (Strang &
// Fix 1973: barycentric (2/3, 1/6, 1/6) and permutations, weights 1/3) on
// the parts of a facet:
// - intersection (the default): the parts are the facet's overlaps with the
//   other body's facets, each projected along that facet's normal and
//   clipped to it (the segments a mortar method integrates over), fanned
//   into triangles. Each part lies over one facet, so the rule is exact for
//   M_k N_j between flat facets.
// - subdivision: the paper's own way, with no intersection surface: the
//   facet is split adaptively (midpoint subdivision into 4 congruent
//   triangles) until each part projects onto a single facet of the other
//   body, or a level limit is reached; the error is confined to strips
//   along the other body's edges that halve with each level.
#pragma once
#include <Eigen/Core>
#include <array>

namespace anvil::contact {

inline constexpr int kMaxFacetSubdivision = 6;

/// A triangle inside a facet, by the barycentric coordinates of its corners in the facet.
using SubTriangle = std::array<Eigen::Vector3d, 3>;

struct FacetQuadraturePoint {
  Eigen::Vector3d barycentric; ///< in the facet
  double weight;               ///< fraction of the facet area
};

/// The facet itself.
SubTriangle whole_facet();

/// The four children of `t` by midpoint subdivision, each a quarter of it.
std::array<SubTriangle, 4> split(const SubTriangle& t);

/// The 3-point rule on `t`, which covers `area_fraction` of the facet.
std::array<FacetQuadraturePoint, 3> degree_two_rule(const SubTriangle& t, double area_fraction);

/// The part of facet `own` whose projection along the normal of facet
/// `other` falls inside `other`, as at most 4 triangles in own's barycentric
/// coordinates with the fraction of own's area each covers.
struct FacetOverlap {
  int count = 0; ///< none when the facets do not overlap or own is edge-on to other
  std::array<SubTriangle, 4> parts;
  std::array<double, 4> area_fraction;
};
FacetOverlap overlap(const std::array<Eigen::Vector3d, 3>& own, const std::array<Eigen::Vector3d, 3>& other);

} // namespace anvil::contact
