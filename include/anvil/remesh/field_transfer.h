// Fields from an old mesh to a new one after a remesh.
// Vertex handles do not survive CGAL's splits and collapses, so the transfer
// is geometric (docs/libraries.md §2): each new node is located in the old mesh, each
// new element intersected with the old elements it overlaps.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace anvil::remesh {

/// Where a point lies in the old mesh: a tet and its barycentric weights
/// (≥ 0, sum 1). A point outside (a boundary node a hair off the old surface)
/// gets the closest tet, its weights clamped to the tet.
struct Location {
  int tet;
  std::array<double, 4> weights;
  bool inside; ///< the point is in the tet (not the closest tet to a point outside the mesh)
  /// The barycentric coordinates themselves, negative ones too: `weights`
  /// inside, the tet's linear field extended outside.
  std::array<double, 4> linear;
};

/// Finds points in an old mesh: a VTK static cell locator built once.
class PointLocator {
public:
  explicit PointLocator(const mesh::TetMesh& old_mesh); ///< keeps a reference: `old_mesh` must outlive it
  ~PointLocator();
  PointLocator(const PointLocator&) = delete;
  PointLocator& operator=(const PointLocator&) = delete;

  Location locate(const mesh::Point& point) const;
  /// The tet `point` lies in (on a shared face the most inside one, ties to
  /// the lowest index), or nullopt outside the mesh: locate without its
  /// search for the closest tet, for points that are mostly outside.
  std::optional<Location> containing(const mesh::Point& point) const;
  std::vector<Location> locate(const std::vector<mesh::Point>& points) const;
  /// The tets whose bounding boxes meet the box [low, high] (some may not meet it), into `tets`.
  void tets_in_box(const mesh::Point& low, const mesh::Point& high, std::vector<int>& tets) const;

private:
  struct Vtk;
  const mesh::TetMesh& mesh_;
  std::unique_ptr<Vtk> vtk_;
};

/// Centroids of the tets of `m`.
std::vector<mesh::Point> centroids(const mesh::TetMesh& m);

/// Nodal field with `stride` values per node (e.g. 4: velocity and pressure),
/// interpolated linearly at `at`; outside the old mesh the nearest tet's
/// values bounded (clamped weights), or with `extend` its linear field
/// extended (for a smooth map, such as where the material started).
Eigen::VectorXd interpolate_nodal(const mesh::TetMesh& old_mesh, const Eigen::VectorXd& values, int stride,
                                  const std::vector<Location>& at, bool extend = false);

/// Element field (one value per tet, e.g. ε̄) onto the elements of
/// `new_mesh` by a conservative remap (Dukowicz and Kodis 1987; Farrell et
/// al. 2009): in each old element a linear reconstruction, its gradient
/// fitted by least squares to the neighbours' values and limited
/// (Barth-Jespersen) so that it never leaves the range of the element and its
/// neighbours; each new element takes the mean of the reconstruction over it,
/// integrated exactly over its intersections with the old elements. The
/// reconstruction keeps each old element's mean, so ∫ f dV is conserved up to
/// where the two meshes' boundaries differ; exact for a linear field where the
/// limiter is off; never overshoots.
std::vector<double> remap_element(const mesh::TetMesh& old_mesh, const std::vector<double>& values,
                                  const PointLocator& in_old, const mesh::TetMesh& new_mesh);

/// A peak (an old element at or above every element sharing a node with it,
/// the field not flat there) raises the new element that holds its centroid
/// to its value. ε̄ peaks (a fold, a die corner) are what hardening and damage
/// read; averaged over larger new elements at every remesh they would wear
/// away. The cost is conservation: each peak's excess over the remapped mean
/// times the new element's volume (logged with each remesh).
void keep_peaks(const mesh::TetMesh& old_mesh, const std::vector<double>& values, const mesh::TetMesh& new_mesh,
                std::vector<double>& new_values);

/// Anvil's transfer of element fields: remap_element, then keep_peaks.
std::vector<double> transfer_element(const mesh::TetMesh& old_mesh, const std::vector<double>& values,
                                     const PointLocator& in_old, const mesh::TetMesh& new_mesh);

/// ∫ f dV over `m` of a one-value-per-tet field (mm³ × unit of f).
double integral(const mesh::TetMesh& m, const std::vector<double>& values);

} // namespace anvil::remesh
