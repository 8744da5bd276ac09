#include "anvil/remesh/field_transfer.h"

#include "anvil/mesh/tet_geometry.h"

#include <Eigen/Dense>
#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <memory>

namespace anvil::remesh {
namespace {

/// Barycentric coordinates of x in tet `e`, clamped to the tet (negative ones
/// set to zero and the rest rescaled): exact inside, the nearest sensible
/// weights just outside.
std::array<double, 4> barycentric(const mesh::TetMesh& m, int e, const mesh::Point& x) {
  const mesh::Tet& t = m.tets[e];
  Eigen::Matrix3d jacobian;
  for (int k = 0; k < 3; ++k) jacobian.col(k) = m.nodes[t[k + 1]] - m.nodes[t[0]];
  const Eigen::Vector3d local = jacobian.partialPivLu().solve(x - m.nodes[t[0]]);
  std::array<double, 4> w{1.0 - local.sum(), local[0], local[1], local[2]};
  double sum = 0.0;
  for (double& v : w) sum += (v = std::max(v, 0.0));
  for (double& v : w) v /= sum;
  return w;
}

} // namespace

struct PointLocator::Vtk {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkStaticCellLocator> locator;
  vtkNew<vtkGenericCell> cell; ///< scratch for the queries
};

PointLocator::PointLocator(const mesh::TetMesh& old_mesh) : mesh_(old_mesh), vtk_(std::make_unique<Vtk>()) {
  vtkNew<vtkPoints> vertices;
  vertices->SetNumberOfPoints(old_mesh.node_count());
  for (int i = 0; i < old_mesh.node_count(); ++i) vertices->SetPoint(i, old_mesh.nodes[i].data());
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

Location PointLocator::locate(const mesh::Point& p) const {
  double x[3] = {p.x(), p.y(), p.z()}, pcoords[3], weights[4], closest[3], distance2;
  int sub = 0;
  vtkIdType tet = vtk_->locator->FindCell(x, 0.0, vtk_->cell.GetPointer(), pcoords, weights);
  const bool inside = tet >= 0;
  if (!inside) vtk_->locator->FindClosestPoint(x, closest, vtk_->cell.GetPointer(), tet, sub, distance2);
  return {static_cast<int>(tet), barycentric(mesh_, static_cast<int>(tet), p), inside};
}

std::vector<Location> PointLocator::locate(const std::vector<mesh::Point>& points) const {
  std::vector<Location> out;
  out.reserve(points.size());
  for (const mesh::Point& p : points) out.push_back(locate(p));
  return out;
}

std::vector<mesh::Point> centroids(const mesh::TetMesh& m) {
  std::vector<mesh::Point> out;
  out.reserve(m.tets.size());
  for (int e = 0; e < m.tet_count(); ++e) out.push_back(mesh::centroid(m, e));
  return out;
}

Eigen::VectorXd interpolate_nodal(const mesh::TetMesh& old_mesh, const Eigen::VectorXd& values, int stride,
                                  const std::vector<Location>& at) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(stride * static_cast<Eigen::Index>(at.size()));
  for (std::size_t i = 0; i < at.size(); ++i)
    for (int a = 0; a < 4; ++a)
      out.segment(stride * i, stride) += at[i].weights[a] * values.segment(stride * old_mesh.tets[at[i].tet][a], stride);
  return out;
}

std::vector<double> transfer_element(const mesh::TetMesh& old_mesh, const std::vector<double>& values,
                                     const PointLocator& in_old, const mesh::TetMesh& new_mesh) {
  const std::vector<mesh::Point> old_centres = centroids(old_mesh);
  // Elements around each node, and the range of the field there.
  const std::vector<std::vector<int>> around = mesh::tets_around_nodes(old_mesh);
  std::vector<double> low(old_mesh.nodes.size()), high(old_mesh.nodes.size());
  for (std::size_t v = 0; v < around.size(); ++v) {
    low[v] = high[v] = values[around[v].front()];
    for (int e : around[v]) low[v] = std::min(low[v], values[e]), high[v] = std::max(high[v], values[e]);
  }
  // The gradient of each old element and its limiter factor.
  std::vector<Eigen::Vector3d> gradient(old_mesh.tets.size());
  std::vector<double> limit(old_mesh.tets.size(), 1.0);
  std::vector<int> patch;
  for (int e = 0; e < old_mesh.tet_count(); ++e) {
    const mesh::Point& c = old_centres[e];
    // Least squares over the elements sharing a node with e: min Σ_n (f_n − f_e − g·(c_n − c_e))².
    patch.clear();
    for (int v : old_mesh.tets[e]) patch.insert(patch.end(), around[v].begin(), around[v].end());
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
      if (rise > 0.0) limit[e] = std::min(limit[e], (high[v] - values[e]) / rise);
      else if (rise < 0.0) limit[e] = std::min(limit[e], (low[v] - values[e]) / rise);
    }
  }
  const std::vector<mesh::Point> centres = centroids(new_mesh);
  const std::vector<Location> centres_at = in_old.locate(centres);
  std::vector<double> out;
  out.reserve(centres.size());
  std::vector<char> holds_new_centroid(old_mesh.tets.size(), 0);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const int e = centres_at[i].tet;
    out.push_back(values[e] + limit[e] * gradient[e].dot(centres[i] - old_centres[e]));
    holds_new_centroid[e] = 1;
  }
  // Peaks no new centroid fell in go to the new element around them.
  std::unique_ptr<PointLocator> in_new;
  for (int e = 0; e < old_mesh.tet_count(); ++e) {
    if (holds_new_centroid[e]) continue;
    bool peak = true, flat = true;
    for (int v : old_mesh.tets[e]) peak = peak && values[e] >= high[v], flat = flat && low[v] == high[v];
    if (!peak || flat) continue;
    if (!in_new) in_new = std::make_unique<PointLocator>(new_mesh);
    double& value = out[in_new->locate(old_centres[e]).tet];
    value = std::max(value, values[e]);
  }
  return out;
}

double integral(const mesh::TetMesh& m, const std::vector<double>& values) {
  double sum = 0.0;
  for (int e = 0; e < m.tet_count(); ++e) sum += values[e] * mesh::signed_volume(m, e);
  return sum;
}

} // namespace anvil::remesh
