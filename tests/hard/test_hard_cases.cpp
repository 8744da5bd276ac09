// Hard cases that must finish (issue 3 §8): near rigid-plastic upsetting
// (m = 0.02), a die that separates from the billet and comes back.
#include "run_outputs.h"

#include "anvil/core/log.h"

#include <filesystem>
#include <fstream>

using namespace anvil;

namespace {

/// The frictionless upsetting case with a Tresca die pair and the given law.
scene::Case upsetting_case() {
  scene::Case c = scene::read_case(source_path("cases/upsetting_frictionless.yaml"));
  for (scene::DieSpec& d : c.dies) d.friction = {contact::FrictionKind::tresca, 0.3, 0.0, 0.0};
  c.write_vtk = false;
  return c;
}

} // namespace

TEST_CASE("near rigid-plastic upsetting (m = 0.02) with Tresca friction runs to 50 %", "[hard]") {
  log::set_quiet(true);
  scene::Case c = upsetting_case();
  const auto card = std::filesystem::temp_directory_path() / "anvil_m002.yaml";
  std::ofstream(card) << "format: 1\nname: near rigid-plastic test material\nlaw: norton_hoff\nconsistency: 100\n"
                         "sensitivity: 0.02\nregularisation_rate: 1.0e-4\nsources:\n"
                         "  consistency: \"test value\"\n  sensitivity: \"test value: the hard limit m -> 0\"\n"
                         "  regularisation_rate: \"numerical\"\n";
  c.bodies.front().material_file = card.string();
  const RunOutputs out = run_case(c, "anvil_hard_m002");
  const auto rows = out.loads("top");
  REQUIRE(!rows.empty());
  CHECK(rows.back().stroke == Approx(7.5).epsilon(1e-9));
  for (const LoadRow& r : rows) CHECK(std::isfinite(r.force.z()));
  CHECK(std::abs(out.summary_number("relative_change")) < 0.005);
}

TEST_CASE("a die that lifts off the billet and comes back re-contacts it", "[hard]") {
  log::set_quiet(true);
  scene::Case c = upsetting_case();
  // Top die: down 2 mm, up 1 mm (the billet is left free), down again to 4 mm.
  scene::DieSpec& top = c.dies.front();
  top.motion = "table";
  top.direction = -Eigen::Vector3d::UnitZ();
  top.table_time = {0.0, 0.2, 0.3, 0.6};
  top.table_values = {0.0, 2.0, 1.0, 4.0};
  top.table_is_speed = false;
  c.time.final_stroke = 8.0; // travel: 2 down + 1 up + 3 down
  const RunOutputs out = run_case(c, "anvil_hard_recontact");
  const auto rows = out.loads("top");
  REQUIRE(!rows.empty());
  bool lifted = false, back = false;
  for (const LoadRow& r : rows) {
    if (r.time > 0.21 && r.time < 0.29) lifted = lifted || std::abs(r.force.z()) < 1e-6;
    if (r.time > 0.45) back = back || r.force.z() > 1000.0;
  }
  CHECK(lifted); // no load while the die is away
  CHECK(back);   // full load once it is back
  CHECK(rows.back().stroke == Approx(8.0).epsilon(1e-6));
}
