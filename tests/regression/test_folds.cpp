// Folds (effect folds): the C-shaped blank of cases/lap.yaml pressed until
// its slot closes must fold, once, along the slot (2 < x < 8 mm, between the
// arms' faces at z 2.5 and 3.5 mm), found after the increment where the
// arms meet and not before; cases/upsetting.yaml must not fold (its barrel
// never meets itself). The VTK series marks the fold's nodes. Self-contact
// (the blank paired with itself) keeps the arms from passing through each
// other once they meet: the run goes on to its stroke.
#include "run_outputs.h"

#include "anvil/core/Timers.h"
#include "anvil/io/RunResults.h"
#include "anvil/scene/Scene.h"

#include <algorithm>
#include <cmath>

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

namespace {

/// How far (mm) the nodes of the upper arm's slot face (z = 3.5 mm at the
/// start, x > 2 mm) have passed below the lower arm's slot face (z = 2.5 mm),
/// at the nodes of `end` (the same mesh, `start` its initial nodes): the
/// largest depth of such a node under the lower face's facet it lies over.
double deepest_through(const anvil::mesh::TetMesh& start, const anvil::mesh::TetMesh& end) {
  auto on_slot_face = [&](int node, double z) {
    return std::abs(start.nodes[node].z() - z) < 1e-9 && start.nodes[node].x() > 2.0 + 1e-9;
  };
  double deepest = -1.0;
  for (int u = 0; u < end.node_count(); ++u) {
    if (!on_slot_face(u, 3.5)) continue;
    const anvil::mesh::Point& x = end.nodes[u];
    for (const anvil::mesh::Triangle& f : end.boundary_faces) {
      if (!std::all_of(f.begin(), f.end(), [&](int n) { return on_slot_face(n, 2.5); })) continue;
      // Barycentric coordinates of x's projection along z in the facet's projection.
      const Eigen::Vector2d a = end.nodes[f[0]].head<2>(), b = end.nodes[f[1]].head<2>(), c = end.nodes[f[2]].head<2>();
      Eigen::Matrix2d m;
      m << b - a, c - a;
      const Eigen::Vector2d l = m.colPivHouseholderQr().solve(x.head<2>() - a);
      if (l.minCoeff() < -1e-9 || l.sum() > 1.0 + 1e-9) continue;
      const double z = (1.0 - l.sum()) * end.nodes[f[0]].z() + l[0] * end.nodes[f[1]].z() + l[1] * end.nodes[f[2]].z();
      deepest = std::max(deepest, z - x.z());
    }
  }
  return deepest;
}

} // namespace

TEST_CASE("folds: a lap where a C-shaped blank's slot closes, none in an upsetting", "[regression]") {
  const RunOutputs lap = run_case(anvil::scene::read_case(source_path("cases/lap.yaml")), "anvil_folds_lap");
  const anvil::scene::RunState end = lap.final_state();
  REQUIRE(end.folds.size() == 1);
  const anvil::scene::FoldRecord& fold = end.folds.front();
  INFO("fold after increment " << fold.increment << " at " << fold.centre.transpose() << " mm, " << fold.area
                               << " mm2");
  CHECK(fold.centre.x() > 2.0);
  CHECK(fold.centre.x() < 8.0);
  CHECK(fold.centre.z() > 1.5); // the arms, pressed together, from about 2.5 mm
  CHECK(fold.centre.z() < 3.5);
  CHECK(fold.increment > 5); // the slot is 1 mm high: it takes most of the 1.2 mm stroke to close
  CHECK(fold.area > 1.0);
  const std::vector<anvil::io::SeriesEntry> series = anvil::io::read_series(lap.directory);
  const auto grid = anvil::io::read_grid(lap.directory + "/" + series.back().parts.front());
  vtkDataArray* marked = grid->GetPointData()->GetArray("fold");
  REQUIRE(marked != nullptr);
  double range[2];
  marked->GetRange(range);
  CHECK(range[1] == 1.0);

  // The arms pressed together, not through each other: no node of the upper
  // arm's face deeper under the lower arm's face than a hundredth of the
  // slot's height. The penalty's compliance lets a face sink by about 1e-4
  // mm here; without the self-contact pair the arms pass through each other
  // by 0.79 mm by the end of the stroke.
  anvil::Timers timers;
  const anvil::scene::Case input = anvil::scene::read_case(source_path("cases/lap.yaml"));
  const anvil::scene::Scene scene(input, timers);
  const double through = deepest_through(anvil::scene::initial_state(scene).mesh, end.mesh);
  INFO("deepest node of the upper arm under the lower arm's face: " << through << " mm");
  CHECK(through > -0.05); // the faces have met (they start 1 mm apart)
  CHECK(through < 0.01);  // 1 % of the slot's height

  const RunOutputs upsetting = run_case(
      anvil::scene::read_case(source_path("cases/upsetting.yaml"), {"output.folds=true"}), "anvil_folds_upsetting");
  CHECK(upsetting.final_state().folds.empty());
}
