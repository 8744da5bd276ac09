// How many nodes a remesh makes (not a test; prints its tables): CGAL's
// isotropic remeshing (remesh_body, uniform) of generated bodies at several
// edge lengths h, against their volume V and surface area A; the fit of
// nodes = a V/h³ + b A/h². Then the same bodies under graded size fields
// (remesh_body's levels), against that estimate at the sizes asked and the
// borders between the levels; the fit of the borders' k and r₀
// (mesh/node_budget.h). The estimate is what remesh/expected_nodes.h makes
// before CGAL runs (the node budget, the progress line).
#include "anvil/core/log.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/node_budget.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/expected_nodes.h"
#include "anvil/remesh/remesh_body.h"
#include "anvil/remesh/size_field.h"
#include "anvil/remesh/size_levels.h"

#include <algorithm>
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

/// A body under a size field growing by ½ mm per mm (the adaptive field's
/// gradation) from `smallest` at a plane or a point (a die's flash land,
/// a die corner) up to the coarse `edge_length`.
struct Graded {
  std::string body, field;
  std::function<mesh::TetMesh(double)> make;
  double edge_length, smallest;
  std::function<double(const mesh::Point&)> distance; ///< mm, to the plane or point
};

} // namespace

int main() {
  log::set_quiet(true); // the tables go to stdout, into docs/remeshing.md
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

  auto box = [](mesh::Point high) { return [high](double h) { return mesh::make_box({0, 0, 0}, high, h); }; };
  auto to_plane = [](int axis, double at) {
    return [axis, at](const mesh::Point& x) { return std::abs(x[axis] - at); };
  };
  auto to_point = [](mesh::Point p) { return [p](const mesh::Point& x) { return (x - p).norm(); }; };
  const std::vector<Graded> graded{
      {"cube 20 mm", "plane z = 10", box({20, 20, 20}), 2.0, 0.7, to_plane(2, 10.0)},
      {"cube 20 mm", "corner (0, 0, 20)", box({20, 20, 20}), 2.0, 0.6, to_point({0, 0, 20})},
      {"cylinder r 10, 20 mm", "plane z = 5", [](double h) { return mesh::make_cylinder(10, 20, h); }, 1.4, 0.5,
       to_plane(2, 5.0)},
      {"cylinder r 10, 20 mm", "rim point (10, 0, 20)", [](double h) { return mesh::make_cylinder(10, 20, h); }, 1.4,
       0.45, to_point({10, 0, 20})},
      {"plate 40 x 40 x 4 mm", "plane x = 20", box({40, 40, 4}), 1.4, 0.55, to_plane(0, 20.0)},
      {"quarter cylinder r 10, 15 mm", "plane z = 7.5", [](double h) { return mesh::make_quarter_cylinder(10, 15, h); },
       1.0, 0.4, to_plane(2, 7.5)},
      {"quarter ring 20/10, 5 mm", "point (0, 15, 5)", [](double h) { return mesh::make_quarter_ring(20, 10, 5, h); },
       1.0, 0.35, to_point({0, 15, 5})},
  };
  // Per body: the estimate at the sizes asked, the borders, the nodes made.
  std::vector<double> asked, made;
  std::vector<std::vector<remesh::LevelBorder>> borders;
  for (const Graded& g : graded) {
    const mesh::TetMesh body = g.make(g.edge_length);
    remesh::RemeshSettings settings;
    settings.edge_length = g.edge_length;
    settings.smallest_edge_length = g.smallest;
    settings.quality_floor = 0.1; // remeshing.quality's default: flat tets below a third of it are mended
    settings.size = [&g](const mesh::Point& x) {
      return std::min(g.edge_length, g.smallest + (remesh::kGradation - 1.0) * g.distance(x));
    };
    const mesh::TetMesh out = remesh::remesh_body(body, settings);
    asked.push_back(remesh::expected_nodes(body, settings.size, g.edge_length, g.edge_length).at(1.0));
    borders.push_back(remesh::level_borders(body, settings.size, g.edge_length, g.smallest));
    made.push_back(out.node_count());
    std::fprintf(stderr, "%s, graded from %s: %d nodes\n", g.body.c_str(), g.field.c_str(), out.node_count());
  }
  auto with_borders = [&](std::size_t row, double k, double r0) {
    double nodes = asked[row];
    for (const remesh::LevelBorder& l : borders[row])
      nodes += mesh::level_border_nodes(l.area, l.coarser, l.length / l.coarser, k, r0);
    return nodes;
  };
  auto worst_graded = [&](double k, double r0) {
    double worst = 0.0;
    for (std::size_t row = 0; row < made.size(); ++row)
      worst = std::max(worst, std::abs(with_borders(row, k, r0) / made[row] - 1.0));
    return worst;
  };
  double k = 0.0, r0 = 0.0;
  best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 50; ++j)
      if (const double miss = worst_graded(0.02 * i, 0.76 + 0.005 * j); miss < best)
        best = miss, k = 0.02 * i, r0 = 0.76 + 0.005 * j;
  std::printf("\nUnder size fields growing by 0.5 mm per mm from the smallest size at a plane or a point, "
              "the estimate at the sizes asked (a and b as in mesh/node_budget.h: %.2f and %.2f) and with the "
              "borders between the levels:\n\n",
              mesh::kRemeshedNodesPerVolume, mesh::kRemeshedNodesPerArea);
  std::printf("| body | graded from | h -> smallest (mm) | levels the estimate sees (mm) | nodes | at the sizes asked "
              "| with the borders |\n"
              "|---|---|---|---|---|---|---|\n");
  for (std::size_t row = 0; row < made.size(); ++row) {
    std::string levels;
    for (const remesh::LevelBorder& l : borders[row])
      levels += (levels.empty() ? "" : ", ") + std::to_string(l.length).substr(0, 5);
    const double estimate = with_borders(row, k, r0);
    std::printf("| %s | %s | %.2f -> %.2f | %s | %.0f | %.0f (%+.0f %%) | %.0f (%+.0f %%) |\n",
                graded[row].body.c_str(), graded[row].field.c_str(), graded[row].edge_length, graded[row].smallest,
                levels.c_str(), made[row], asked[row], 100.0 * (asked[row] / made[row] - 1.0), estimate,
                100.0 * (estimate / made[row] - 1.0));
  }
  std::printf("\nFit: a level's border adds %.2f g(r) A/L² nodes, g falling from 1 at r = 0.75 to 0 at r = %.3f; "
              "the worst row off by %.0f %%.\n",
              k, r0, 100.0 * best);
}
