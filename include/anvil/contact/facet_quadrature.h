// Quadrature of facet (integrated) contact, paper §3. On a facet the
// integrand M_k h is a polynomial only between the edges of the other
// body's facets that its points project onto; across such an edge it has a
// kink, so a higher-degree rule gains little there. The facet is therefore
// split adaptively (midpoint subdivision into 4 congruent triangles) until
// each sub-triangle projects onto a single facet of the other body, or a
// level limit is reached, and the 3-point rule of degree 2 (Strang & Fix
// 1973: barycentric (2/3, 1/6, 1/6) and permutations, weights 1/3) is
// applied on each sub-triangle: exact for M_k N_j on a sub-triangle over
// one facet, with the error confined to strips along the other body's edges
// that halve with each level. The paper avoids building the intersection
// (mortar) surface; this approaches it where it matters only.
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

} // namespace anvil::contact
