// Folds (effect folds): the C-shaped blank of cases/lap.yaml pressed until
// its slot closes must fold, once, along the slot (2 < x < 8 mm, between the
// arms' faces at z 2.5 and 3.5 mm), found after the increment where the
// arms meet and not before; cases/upsetting.yaml must not fold (its barrel
// never meets itself). The VTK series marks the fold's nodes.
#include "run_outputs.h"

#include "anvil/io/RunResults.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

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

  const RunOutputs upsetting = run_case(
      anvil::scene::read_case(source_path("cases/upsetting.yaml"), {"output.folds=true"}), "anvil_folds_upsetting");
  CHECK(upsetting.final_state().folds.empty());
}
