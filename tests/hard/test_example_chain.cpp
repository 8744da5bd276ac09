// The example chain (cases/hub_flange_chain.yaml) to its end: furnace,
// transfer, upsetting, the closed-die finisher, trim, cooling.
#include "run_outputs.h"

#include "anvil/core/log.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/run/chain.h"
#include "anvil/scene/Chain.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace anvil;

TEST_CASE("the hub-flange chain runs its five operations to the end", "[hard]") {
  log::set_quiet(true);
  const auto out = std::filesystem::temp_directory_path() / "anvil_hard_hub_flange_chain";
  std::filesystem::remove_all(out);
  const scene::Chain chain = scene::read_chain(source_path("cases/hub_flange_chain.yaml"), {"output.vtk=false"});
  const run::RunEnd end = run::run_chain(chain, {out.string()});
  CHECK(end.complete);
  CHECK(io::read_summary_number(out.string(), "operations_done") == 5);
  auto folder = [&](int k) { return RunOutputs{(out / run::operation_folder(chain, k)).string()}; };
  // The finisher closes its dies: the upper one's whole stroke.
  const std::vector<LoadRow> finish = folder(2).loads("upper");
  REQUIRE(!finish.empty());
  CHECK(finish.back().stroke == Approx(7.8).epsilon(1e-9));
  // The trim removes the flash beyond its line (a 48-gon inscribed in r 13
  // mm): what it keeps lies within r 13, and the removed and kept volumes,
  // less the change of the kept part by the nodes put onto the cut and by
  // the remesh along it (a mending of its surface), make up what the
  // finisher left, to rounding.
  const RunOutputs trim = folder(3);
  const scene::RunState finished = folder(2).final_state(), trimmed = trim.final_state();
  const double removed = trim.summary_number("removed_volume_model_mm3");
  const double reshaped = trim.summary_number("reshaped_volume_model_mm3");
  CHECK(removed > 0.0);
  const double remeshed = trim.summary_number("remeshed_volume_model_mm3");
  CHECK(mesh::volume(trimmed.mesh) + removed - reshaped - remeshed ==
        Approx(mesh::volume(finished.mesh)).epsilon(1e-9));
  // The rest of the part keeps its mesh: the cut leaves no piece below
  // remeshing.quality, or the local remesh rebuilds them along the cut.
  std::ifstream summary(trim.directory + "/summary.json");
  const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  CHECK((text.find("\"remesh\": \"none\"") != std::string::npos ||
         text.find("\"remesh\": \"along the cut\"") != std::string::npos));
  // Within the line: its corners, given to 0.1 µm, lie up to 17 nm beyond r 13.
  double outermost = 0.0;
  for (const Eigen::Vector2d& corner : chain.operations[3].trim.line)
    outermost = std::max(outermost, corner.norm());
  for (const mesh::Point& x : trimmed.mesh.nodes)
    CHECK(x.head<2>().norm() <= outermost + 1e-9);
  for (int e = 0; e < trimmed.mesh.tet_count(); ++e)
    CHECK(mesh::quality(trimmed.mesh, e) > 0.0);
  // In air the trimmed part only cools: its hottest node ends colder than
  // it started, its coldest no colder than the air.
  const scene::RunState cooled = folder(4).final_state();
  const auto [low, high] = std::minmax_element(cooled.temperature.begin(), cooled.temperature.end());
  CHECK(*high < *std::max_element(trimmed.temperature.begin(), trimmed.temperature.end()));
  CHECK(*low > 20.0);
}
