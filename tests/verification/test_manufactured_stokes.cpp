// Manufactured smooth Stokes flow on the unit cube (η = 1):
//   u = (sin πy cos πz, sin πz cos πx, sin πx cos πy)   (div u = 0),
//   p = cos πx cos πy cos πz                              (mean 0),
//   f = −η Δu + ∇p = 2π² η u + ∇p.
// Velocity prescribed on the whole boundary, pressure pinned at one node and
// compared up to its mean. Observed rates over 5 meshes against the MINI
// element's theory: velocity H1 O(h), pressure L2 O(h), velocity L2 O(h²).
#include "test_common.h"

#include "anvil/fem/mini_element.h"
#include "anvil/fem/tet_quadrature.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/solver/IncrementSolver.h"

#include <cmath>
#include <numbers>

using namespace anvil;

namespace {

constexpr double pi = std::numbers::pi;

Eigen::Vector3d exact_velocity(const mesh::Point& x) {
  return {std::sin(pi * x.y()) * std::cos(pi * x.z()), std::sin(pi * x.z()) * std::cos(pi * x.x()),
          std::sin(pi * x.x()) * std::cos(pi * x.y())};
}

Eigen::Matrix3d exact_gradient(const mesh::Point& x) { // G(i, j) = ∂u_i/∂x_j
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  g(0, 1) = pi * std::cos(pi * x.y()) * std::cos(pi * x.z());
  g(0, 2) = -pi * std::sin(pi * x.y()) * std::sin(pi * x.z());
  g(1, 2) = pi * std::cos(pi * x.z()) * std::cos(pi * x.x());
  g(1, 0) = -pi * std::sin(pi * x.z()) * std::sin(pi * x.x());
  g(2, 0) = pi * std::cos(pi * x.x()) * std::cos(pi * x.y());
  g(2, 1) = -pi * std::sin(pi * x.x()) * std::sin(pi * x.y());
  return g;
}

double exact_pressure(const mesh::Point& x) {
  return std::cos(pi * x.x()) * std::cos(pi * x.y()) * std::cos(pi * x.z());
}

Eigen::Vector3d body_force(const mesh::Point& x) {
  const Eigen::Vector3d grad_p(-pi * std::sin(pi * x.x()) * std::cos(pi * x.y()) * std::cos(pi * x.z()),
                               -pi * std::cos(pi * x.x()) * std::sin(pi * x.y()) * std::cos(pi * x.z()),
                               -pi * std::cos(pi * x.x()) * std::cos(pi * x.y()) * std::sin(pi * x.z()));
  return 2.0 * pi * pi * exact_velocity(x) + grad_p;
}

struct Errors {
  double h, velocity_l2, velocity_h1, pressure_l2;
};

Errors solve_on(int cells) {
  const mesh::TetMesh mesh = mesh::make_box(mesh::Point::Zero(), mesh::Point(1, 1, 1), {cells, cells, cells});
  const int n = mesh.node_count();
  std::vector<char> prescribed(4 * static_cast<std::size_t>(n), 0);
  fem::BodyUnknowns u;
  u.nodal = Eigen::VectorXd::Zero(4 * n);
  u.bubble = Eigen::VectorXd::Zero(3 * mesh.tet_count());
  for (const auto& face : mesh.boundary_faces)
    for (int v : face)
      for (int c = 0; c < 3; ++c) {
        prescribed[4 * v + c] = 1;
        u.nodal[4 * v + c] = exact_velocity(mesh.nodes[v])[c];
      }
  prescribed[3] = 1; // enclosed flow: pressure defined up to a constant
  u.nodal[3] = exact_pressure(mesh.nodes[0]);

  Timers timers;
  solver::IncrementSolver solver(mesh, prescribed, {solver::LinearSolverKind::umfpack}, timers);
  const material::NortonHoff newtonian(1.0, 1.0, 0.0);
  solver::NewtonSettings settings;
  settings.verbose = false;
  settings.tolerance = 1e-10;
  const auto report = solver.solve(mesh, newtonian, {}, Eigen::VectorXd::Zero(4 * n), body_force, settings, u);
  REQUIRE(report.converged);

  // Pressure mean offset (the pin fixes one node, the comparison is up to a constant).
  double volume = 0.0, mean_difference = 0.0;
  for (int e = 0; e < mesh.tet_count(); ++e) {
    const auto& t = mesh.tets[e];
    const double v = mesh::signed_volume(mesh, e);
    for (const auto& q : fem::tet_quadrature()) {
      mesh::Point x = mesh::Point::Zero();
      double p = 0.0;
      for (int a = 0; a < 4; ++a) {
        x += q.barycentric[a] * mesh.nodes[t[a]];
        p += q.barycentric[a] * u.nodal[4 * t[a] + 3];
      }
      mean_difference += q.weight * v * (p - exact_pressure(x));
    }
    volume += v;
  }
  mean_difference /= volume;

  Errors err{1.0 / cells, 0, 0, 0};
  for (int e = 0; e < mesh.tet_count(); ++e) {
    const auto& t = mesh.tets[e];
    const auto g = mesh::p1_gradients(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]);
    const Eigen::Vector3d bubble = u.bubble.segment<3>(3 * e);
    for (const auto& q : fem::tet_quadrature()) {
      const auto& l = q.barycentric;
      mesh::Point x = mesh::Point::Zero();
      Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
      Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
      double p = 0.0;
      for (int a = 0; a < 4; ++a) {
        x += l[a] * mesh.nodes[t[a]];
        const Eigen::Vector3d va = u.nodal.segment<3>(4 * t[a]);
        velocity += l[a] * va;
        gradient += va * g.grad.row(a);
        p += l[a] * u.nodal[4 * t[a] + 3];
      }
      const double b = 256.0 * l[0] * l[1] * l[2] * l[3];
      const Eigen::RowVector3d grad_b = fem::bubble_gradient(l, g.grad).transpose();
      velocity += b * bubble;
      gradient += bubble * grad_b;
      const double w = q.weight * g.volume;
      err.velocity_l2 += w * (velocity - exact_velocity(x)).squaredNorm();
      err.velocity_h1 += w * (gradient - exact_gradient(x)).squaredNorm();
      err.pressure_l2 += w * std::pow(p - mean_difference - exact_pressure(x), 2);
    }
  }
  err.velocity_l2 = std::sqrt(err.velocity_l2);
  err.velocity_h1 = std::sqrt(err.velocity_h1);
  err.pressure_l2 = std::sqrt(err.pressure_l2);
  return err;
}

} // namespace

TEST_CASE("manufactured Stokes flow converges at the MINI element's rates", "[verification]") {
  std::vector<Errors> runs;
  for (int cells : {4, 6, 8, 12, 16})
    runs.push_back(solve_on(cells));
  auto rate = [&](double Errors::*field, std::size_t k) {
    return std::log(runs[k - 1].*field / runs[k].*field) / std::log(runs[k - 1].h / runs[k].h);
  };
  for (std::size_t k = 0; k < runs.size(); ++k) {
    std::printf("MMS h %.4f  velocity L2 %.4e  H1 %.4e  pressure L2 %.4e", runs[k].h, runs[k].velocity_l2,
                runs[k].velocity_h1, runs[k].pressure_l2);
    if (k > 0)
      std::printf("  rates %.2f %.2f %.2f", rate(&Errors::velocity_l2, k), rate(&Errors::velocity_h1, k),
                  rate(&Errors::pressure_l2, k));
    std::printf("\n");
  }
  const std::size_t last = runs.size() - 1;
  // Theory (Arnold, Brezzi, Fortin 1984): |u−u_h|_1 + |p−p_h|_0 = O(h), |u−u_h|_0 = O(h²).
  // Margins: asymptotic rates on the two finest pairs, 0.15 below theory for
  // the pre-asymptotic range (pressure is often super-convergent, ~1.5, on
  // structured meshes; only the lower bound is asserted).
  for (std::size_t k = last - 1; k <= last; ++k) {
    CHECK(rate(&Errors::velocity_l2, k) >= 1.85);
    CHECK(rate(&Errors::velocity_h1, k) >= 0.85);
    CHECK(rate(&Errors::pressure_l2, k) >= 0.85);
  }
}
