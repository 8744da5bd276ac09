#include "anvil/remesh/field_transfer.h"

#include "anvil/mesh/tet_geometry.h"
#include "anvil/mesh/tet_overlap.h"
#include "anvil/remesh/overlap_candidates.h"

#include <Eigen/Dense>
#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace anvil::remesh {
namespace {

/// Barycentric coordinates of x in tet `e` (negative outside).
std::array<double, 4> barycentric(const mesh::TetMesh& m, int e, const mesh::Point& x) {
  const mesh::Tet& t = m.tets[e];
  Eigen::Matrix3d jacobian;
  for (int k = 0; k < 3; ++k)
    jacobian.col(k) = m.nodes[t[k + 1]] - m.nodes[t[0]];
  const Eigen::Vector3d local = jacobian.partialPivLu().solve(x - m.nodes[t[0]]);
  return {1.0 - local.sum(), local[0], local[1], local[2]};
}

/// `w` clamped to the tet (negative weights set to zero and the rest
/// rescaled): unchanged inside, the nearest sensible weights just outside.
std::array<double, 4> clamped(std::array<double, 4> w) {
  double sum = 0.0;
  for (double& v : w)
    sum += (v = std::max(v, 0.0));
  for (double& v : w)
    v /= sum;
  return w;
}

/// Weights of a point this far outside a tet (relative) still count as inside.
constexpr double kOnFace = 1e-12;

} // namespace

struct PointLocator::Vtk {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkStaticCellLocator> locator;
  vtkNew<vtkGenericCell> cell; ///< scratch for the queries
  vtkNew<vtkIdList> found;     ///< scratch for the box queries
  std::vector<int> candidates; ///< scratch for locate
};

PointLocator::PointLocator(const mesh::TetMesh& old_mesh) : mesh_(old_mesh), vtk_(std::make_unique<Vtk>()) {
  vtkNew<vtkPoints> vertices;
  vertices->SetNumberOfPoints(old_mesh.node_count());
  for (int i = 0; i < old_mesh.node_count(); ++i)
    vertices->SetPoint(i, old_mesh.nodes[i].data());
  vtkNew<vtkCellArray> cells;
  for (const mesh::Tet& t : old_mesh.tets) {
    const vtkIdType ids[4] = {t[0], t[1], t[2], t[3]};
    cells->InsertNextCell(4, ids);
  }
  vtk_->grid->SetPoints(vertices);
  vtk_->grid->SetCells(VTK_TETRA, cells);
  vtk_->locator->SetDataSet(vtk_->grid);
  vtk_->locator->BuildLocator();
}

PointLocator::~PointLocator() = default;

std::optional<Location> PointLocator::containing(const mesh::Point& p) const {
  // VTK's static locator lists a bin's cells in an order that changes with
  // its threads (its SMP sort), so which of the tets sharing a face FindCell
  // returns, or which of two equally close ones FindClosestPoint does, is not
  // reproducible. The tets are chosen here by one rule: the most inside one,
  // else (locate) the nearest, ties to the lowest index.
  std::vector<int>& candidates = vtk_->candidates;
  tets_in_box(p, p, candidates);
  int best = -1;
  double most_inside = -std::numeric_limits<double>::infinity();
  std::array<double, 4> linear{}; // the best tet's barycentric coordinates
  for (const int e : candidates) {
    const std::array<double, 4> w = barycentric(mesh_, e, p);
    const double lowest = *std::min_element(w.begin(), w.end());
    if (lowest > most_inside || (lowest == most_inside && e < best)) most_inside = lowest, best = e, linear = w;
  }
  if (best >= 0 && most_inside >= -kOnFace) return Location{best, clamped(linear), true, linear};
  return std::nullopt;
}

Location PointLocator::locate(const mesh::Point& p) const {
  if (const std::optional<Location> in = containing(p)) return *in;
  // Outside the mesh (a boundary node a hair off the old surface): the tets
  // within VTK's closest distance, and among them the nearest by the clamped
  // weights' point.
  std::vector<int>& candidates = vtk_->candidates;
  std::array<double, 4> linear{};
  double x[3] = {p.x(), p.y(), p.z()}, closest[3], distance2 = 0.0;
  vtkIdType tet = -1;
  int sub = 0;
  vtk_->locator->FindClosestPoint(x, closest, vtk_->cell.GetPointer(), tet, sub, distance2);
  const double reach = std::sqrt(distance2) * (1.0 + 1e-9) + 1e-12;
  tets_in_box(p - mesh::Point::Constant(reach), p + mesh::Point::Constant(reach), candidates);
  int best = -1;
  double nearest = std::numeric_limits<double>::infinity();
  std::array<double, 4> weights{};
  for (const int e : candidates) {
    const std::array<double, 4> unclamped = barycentric(mesh_, e, p), w = clamped(unclamped);
    mesh::Point at = mesh::Point::Zero();
    for (int a = 0; a < 4; ++a)
      at += w[a] * mesh_.nodes[mesh_.tets[e][a]];
    const double d = (at - p).squaredNorm();
    if (d < nearest || (d == nearest && e < best)) nearest = d, best = e, weights = w, linear = unclamped;
  }
  if (best < 0) best = static_cast<int>(tet), linear = barycentric(mesh_, best, p), weights = clamped(linear);
  return {best, weights, false, linear};
}

std::vector<Location> PointLocator::locate(const std::vector<mesh::Point>& points) const {
  std::vector<Location> out;
  out.reserve(points.size());
  for (const mesh::Point& p : points)
    out.push_back(locate(p));
  return out;
}

void PointLocator::tets_in_box(const mesh::Point& low, const mesh::Point& high, std::vector<int>& tets) const {
  double box[6] = {low.x(), high.x(), low.y(), high.y(), low.z(), high.z()};
  vtk_->locator->FindCellsWithinBounds(box, vtk_->found);
  tets.resize(vtk_->found->GetNumberOfIds());
  for (vtkIdType k = 0; k < vtk_->found->GetNumberOfIds(); ++k)
    tets[k] = static_cast<int>(vtk_->found->GetId(k));
  std::sort(tets.begin(), tets.end()); // VTK's order is not reproducible (see locate)
}

std::vector<mesh::Point> centroids(const mesh::TetMesh& m) {
  std::vector<mesh::Point> out;
  out.reserve(m.tets.size());
  for (int e = 0; e < m.tet_count(); ++e)
    out.push_back(mesh::centroid(m, e));
  return out;
}

Eigen::VectorXd interpolate_nodal(const mesh::TetMesh& old_mesh, const Eigen::VectorXd& values, int stride,
                                  const std::vector<Location>& at, bool extend) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(stride * static_cast<Eigen::Index>(at.size()));
  for (std::size_t i = 0; i < at.size(); ++i)
    for (int a = 0; a < 4; ++a)
      out.segment(stride * i, stride) +=
          (extend ? at[i].linear[a] : at[i].weights[a]) * values.segment(stride * old_mesh.tets[at[i].tet][a], stride);
  return out;
}

namespace {

/// The lowest and highest value of an element field over the elements around each node.
struct NodeRange {
  std::vector<double> low, high;
};

NodeRange range_around_nodes(const std::vector<std::vector<int>>& around, const std::vector<double>& values) {
  NodeRange r{std::vector<double>(around.size()), std::vector<double>(around.size())};
  for (std::size_t v = 0; v < around.size(); ++v) {
    r.low[v] = r.high[v] = values[around[v].front()];
    for (int e : around[v])
      r.low[v] = std::min(r.low[v], values[e]), r.high[v] = std::max(r.high[v], values[e]);
  }
  return r;
}

} // namespace

std::vector<double> remap_element(const mesh::TetMesh& old_mesh, const std::vector<double>& values,
                                  const PointLocator& in_old, const mesh::TetMesh& new_mesh) {
  const std::vector<mesh::Point> old_centres = centroids(old_mesh);
  const std::vector<std::vector<int>> around = mesh::tets_around_nodes(old_mesh);
  const NodeRange range = range_around_nodes(around, values);
  // The gradient of each old element and its limiter factor.
  std::vector<Eigen::Vector3d> gradient(old_mesh.tets.size());
  std::vector<double> limit(old_mesh.tets.size(), 1.0);
  std::vector<int> patch;
  for (int e = 0; e < old_mesh.tet_count(); ++e) {
    const mesh::Point& c = old_centres[e];
    // Least squares over the elements sharing a node with e: min Σ_n (f_n − f_e − g·(c_n − c_e))².
    patch.clear();
    for (int v : old_mesh.tets[e])
      patch.insert(patch.end(), around[v].begin(), around[v].end());
    std::sort(patch.begin(), patch.end());
    patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (int n : patch) {
      const Eigen::Vector3d d = old_centres[n] - c;
      normal += d * d.transpose();
      rhs += (values[n] - values[e]) * d;
    }
    Eigen::Vector3d& g = gradient[e];
    g.setZero();
    const Eigen::LDLT<Eigen::Matrix3d> fit(normal);
    if (fit.info() == Eigen::Success && fit.vectorD().minCoeff() > 1e-9 * normal.trace()) g = fit.solve(rhs);
    // Vertex-based limiter (Barth-Jespersen as in Kuzmin 2010): the value the
    // gradient gives at each vertex stays within the range of the elements around it.
    for (int v : old_mesh.tets[e]) {
      const double rise = g.dot(old_mesh.nodes[v] - c);
      if (rise > 0.0)
        limit[e] = std::min(limit[e], (range.high[v] - values[e]) / rise);
      else if (rise < 0.0)
        limit[e] = std::min(limit[e], (range.low[v] - values[e]) / rise);
    }
  }
  auto reconstruction = [&](int e, const mesh::Point& x) {
    return values[e] + limit[e] * gradient[e].dot(x - old_centres[e]);
  };
  // Each new element takes the mean of the reconstruction over it: over the
  // old elements it overlaps, the reconstruction's integral on the common
  // part (a linear function's: its value at the part's centroid times the
  // part's volume), summed and divided by the volume covered.
  std::vector<double> out(new_mesh.tets.size());
  const OverlapCandidates candidates = overlap_candidates(new_mesh, old_mesh);
  mesh::TetCorners corners, old_corners;
  for (int n = 0; n < new_mesh.tet_count(); ++n) {
    for (int k = 0; k < 4; ++k)
      corners[k] = new_mesh.nodes[new_mesh.tets[n][k]];
    double covered = 0.0, sum = 0.0;
    for (int c = candidates.first[n]; c < candidates.first[n + 1]; ++c) {
      const int e = candidates.tets[c];
      for (int k = 0; k < 4; ++k)
        old_corners[k] = old_mesh.nodes[old_mesh.tets[e][k]];
      const mesh::Overlap common = mesh::tet_overlap(corners, old_corners);
      if (common.volume <= 0.0) continue;
      covered += common.volume;
      sum += common.volume * reconstruction(e, common.centroid);
    }
    if (covered > 0.0) {
      out[n] = sum / covered;
    } else { // wholly off the old mesh (not met in practice): the closest old element's reconstruction
      const mesh::Point centre = mesh::centroid(new_mesh, n);
      out[n] = reconstruction(in_old.locate(centre).tet, centre);
    }
  }
  return out;
}

void keep_peaks(const mesh::TetMesh& old_mesh, const std::vector<double>& values, const mesh::TetMesh& new_mesh,
                std::vector<double>& new_values) {
  const NodeRange range = range_around_nodes(mesh::tets_around_nodes(old_mesh), values);
  std::unique_ptr<PointLocator> in_new; // built at the first peak
  for (int e = 0; e < old_mesh.tet_count(); ++e) {
    bool peak = true, flat = true;
    for (int v : old_mesh.tets[e])
      peak = peak && values[e] >= range.high[v], flat = flat && range.low[v] == range.high[v];
    if (!peak || flat) continue;
    if (!in_new) in_new = std::make_unique<PointLocator>(new_mesh);
    double& value = new_values[in_new->locate(mesh::centroid(old_mesh, e)).tet];
    value = std::max(value, values[e]);
  }
}

std::vector<double> transfer_element(const mesh::TetMesh& old_mesh, const std::vector<double>& values,
                                     const PointLocator& in_old, const mesh::TetMesh& new_mesh) {
  std::vector<double> out = remap_element(old_mesh, values, in_old, new_mesh);
  keep_peaks(old_mesh, values, new_mesh, out);
  return out;
}

double integral(const mesh::TetMesh& m, const std::vector<double>& values) {
  double sum = 0.0;
  for (int e = 0; e < m.tet_count(); ++e)
    sum += values[e] * mesh::signed_volume(m, e);
  return sum;
}

} // namespace anvil::remesh
