// What a frame of the VTK series shows: the increment it is written for, on
// the mesh that increment was solved on. A remesh after the increment
// renumbers the nodes and transfers the fields; the contact candidates name
// nodes of the old mesh. A frame written after the remesh gave the contact
// fields of other nodes, with velocities transferred onto them: on the
// connecting rod's increment 101 a hundredth of the nodes in contact showed
// contact pressures of 18-82 GPa where the solution had none above 0.5 GPa.
#include "run_outputs.h"

#include "anvil/io/RunResults.h"

#include <algorithm>
#include <cmath>

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

TEST_CASE("a frame written at an increment followed by a remesh shows that increment's mesh and contact",
          "[regression]") {
  // cases/upsetting_75.yaml on a coarse mesh to 8.4 mm (a whole remesh and
  // local ones), a frame at every increment.
  const RunOutputs run = run_case(anvil::scene::read_case(source_path("cases/upsetting_75.yaml"),
                                                          {"bodies[0].mesh.element_size=2", "remeshing.element_size=2",
                                                           "remeshing.check_load=false", "time.stop.stroke=8.4",
                                                           "output.vtk_every=1", "output.picture=false"}),
                                  "anvil_frames_at_remeshes");
  const anvil::scene::RunState end = run.final_state();
  REQUIRE(!end.remeshes.empty());
  const std::vector<anvil::io::SeriesEntry> series = anvil::io::read_series(run.directory);
  auto first_remesh_after = [&](int increment) {
    return std::find_if(end.remeshes.begin(), end.remeshes.end(),
                        [&](const anvil::scene::RemeshRecord& r) { return r.increment == increment; });
  };
  int checked = 0;
  for (const anvil::io::SeriesEntry& frame : series) {
    const auto first = first_remesh_after(frame.increment);
    if (first == end.remeshes.end()) continue;
    INFO("frame of increment " << frame.increment);
    const auto grid = anvil::io::read_grid(run.directory + "/" + frame.parts.front());
    // The mesh the increment was solved on: the first remesh after it started from it.
    CHECK(grid->GetNumberOfPoints() == first->nodes_before);
    // The contact pressure at a node a die presses on is the normal stress
    // there, of the order of the pressure field: on this run at most 0.65 of
    // the largest pressure. The bound of twice that pressure leaves room for
    // a nodal penalty value on other meshes; frames written after the remesh
    // read no contact at all here (0 MPa) and tens of times the largest
    // pressure on the connecting rod.
    vtkDataArray* contact = grid->GetPointData()->GetArray("contact_pressure");
    vtkDataArray* pressure = grid->GetPointData()->GetArray("pressure");
    REQUIRE(contact != nullptr);
    REQUIRE(pressure != nullptr);
    double contact_range[2], pressure_range[2];
    contact->GetRange(contact_range);
    pressure->GetRange(pressure_range);
    const double largest_pressure = std::max(std::abs(pressure_range[0]), std::abs(pressure_range[1]));
    INFO("contact pressure up to " << contact_range[1] << " MPa, pressure up to " << largest_pressure << " MPa");
    CHECK(contact_range[1] > 0.0);
    CHECK(contact_range[1] < 2.0 * largest_pressure);
    ++checked;
  }
  CHECK(checked == static_cast<int>(std::count_if(series.begin(), series.end(), [&](const anvil::io::SeriesEntry& f) {
          return first_remesh_after(f.increment) != end.remeshes.end();
        })));
  CHECK(checked > 0);
}
