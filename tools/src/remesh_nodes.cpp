// How many nodes a remesh makes (not a test; prints its table): CGAL's
// isotropic remeshing (remesh_body, uniform) of generated bodies at several
// edge lengths h, against their volume V and surface area A; the fit of
// nodes = a V/h³ + b A/h², the estimate remesh/Remesher.cpp makes before CGAL
// runs (the node budget, the progress line).
#include "anvil/mesh/generators.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/remesh_body.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace anvil;

namespace {

struct Shape {
  std::string name;
  std::function<mesh::TetMesh(double)> make; ///< the body, meshed at about this size
};

} // namespace

int main() {
  const std::vector<Shape> shapes{
      {"cube 20 mm",
       [](double h) {
         return mesh::make_box({0, 0, 0}, {20, 20, 20}, h);
       }},
      {"plate 40 x 40 x 4 mm",
       [](double h) {
         return mesh::make_box({0, 0, 0}, {40, 40, 4}, h);
       }},
      {"plate 40 x 40 x 2 mm",
       [](double h) {
         return mesh::make_box({0, 0, 0}, {40, 40, 2}, h);
       }},
      {"cylinder r 10, 20 mm", [](double h) { return mesh::make_cylinder(10, 20, h); }},
      {"quarter ring 20/10, 5 mm", [](double h) { return mesh::make_quarter_ring(20, 10, 5, h); }},
      {"quarter cylinder r 10, 15 mm", [](double h) { return mesh::make_quarter_cylinder(10, 15, h); }},
  };
  const std::vector<double> lengths{2.0, 1.4, 1.0};
  std::vector<std::array<double, 3>> rows; // V/h³, A/h², nodes
  std::vector<std::string> names;
  std::vector<double> hs;
  for (const Shape& shape : shapes)
    for (double h : lengths) {
      const mesh::TetMesh body = shape.make(h);
      remesh::RemeshSettings settings;
      settings.edge_length = h;
      const mesh::TetMesh out = remesh::remesh_body(body, settings);
      rows.push_back(
          {mesh::volume(out) / std::pow(h, 3), mesh::boundary_area(out) / std::pow(h, 2), double(out.node_count())});
      names.push_back(shape.name);
      hs.push_back(h);
      std::fprintf(stderr, "%s at %.2f mm: %d nodes\n", shape.name.c_str(), h, out.node_count());
    }
  // The constants that make the worst row's relative error smallest (a
  // grid search: a budget is judged by its worst miss, not its mean).
  auto worst_miss = [&](double a, double b) {
    double worst = 0.0;
    for (const auto& [volume_term, area_term, nodes] : rows)
      worst = std::max(worst, std::abs((a * volume_term + b * area_term) / nodes - 1.0));
    return worst;
  };
  double a = 0.0, b = 0.0, best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 300; ++i)
    for (int j = 0; j <= 300; ++j)
      if (const double miss = worst_miss(0.01 * i, 0.01 * j); miss < best) best = miss, a = 0.01 * i, b = 0.01 * j;
  std::printf(
      "| body | h (mm) | V/h³ | A/h² | nodes | bulk only, 1.5 V/h³ | the fit |\n|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& [volume_term, area_term, nodes] = rows[k];
    const double estimate = a * volume_term + b * area_term;
    std::printf("| %s | %.2f | %.0f | %.0f | %.0f | %.0f (%+.0f %%) | %.0f (%+.0f %%) |\n", names[k].c_str(), hs[k],
                volume_term, area_term, nodes, 1.5 * volume_term, 100.0 * (1.5 * volume_term / nodes - 1.0), estimate,
                100.0 * (estimate / nodes - 1.0));
  }
  std::printf("\nFit: nodes = %.2f V/h³ + %.2f A/h², the worst row off by %.0f %%.\n", a, b, 100.0 * best);
}
