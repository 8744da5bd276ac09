// The CGAL side of SurfaceSearch: an AABB tree of triangles whose primitive
// id is the position in the list, so the hit names the facet.
#include "anvil/contact/SurfaceSearch.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <boost/iterator/function_output_iterator.hpp>

namespace anvil::contact {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle3 = Kernel::Triangle_3;
using Iterator = std::vector<Triangle3>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 to_cgal(const mesh::Point& p) {
  return {p.x(), p.y(), p.z()};
}
} // namespace

struct SurfaceSearch::Tree {
  std::vector<Triangle3> triangles;
  contact::Tree tree;
};

SurfaceSearch::SurfaceSearch(const std::vector<mesh::Point>& nodes, const std::vector<mesh::Triangle>& faces)
    : tree_(std::make_unique<Tree>()) {
  tree_->triangles.reserve(faces.size());
  for (const mesh::Triangle& f : faces)
    tree_->triangles.emplace_back(to_cgal(nodes[f[0]]), to_cgal(nodes[f[1]]), to_cgal(nodes[f[2]]));
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
}

SurfaceSearch::~SurfaceSearch() = default;
SurfaceSearch::SurfaceSearch(SurfaceSearch&&) noexcept = default;
SurfaceSearch& SurfaceSearch::operator=(SurfaceSearch&&) noexcept = default;

SurfaceSearch::Closest SurfaceSearch::closest(const mesh::Point& x) const {
  const auto [point, triangle] = tree_->tree.closest_point_and_primitive(to_cgal(x));
  return {static_cast<int>(triangle - tree_->triangles.cbegin()), mesh::Point(point.x(), point.y(), point.z())};
}

void SurfaceSearch::overlapping(const Eigen::AlignedBox3d& box, std::vector<int>& found) const {
  found.clear();
  const CGAL::Bbox_3 query(box.min().x(), box.min().y(), box.min().z(), box.max().x(), box.max().y(), box.max().z());
  const Iterator first = tree_->triangles.cbegin();
  tree_->tree.all_intersected_primitives(query, boost::make_function_output_iterator([&](const Iterator& triangle) {
                                           found.push_back(static_cast<int>(triangle - first));
                                         }));
}

} // namespace anvil::contact
