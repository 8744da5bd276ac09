// Upsetting between flat dies through the whole time loop:
// frictionless Norton-Hoff against the exact homogeneous solution, then the
// effect of friction (ordering, slab-method band, barrelling).
#include "test_common.h"

#include "anvil/core/log.h"
#include "anvil/material/homogeneous_compression.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/MaterialCard.h"
#include "anvil/scene/RunState.h"
#include "run_outputs.h"

#include <cmath>
#include <filesystem>
#include <numbers>

using namespace anvil;

namespace {

constexpr double kRadius = 10.0, kHeight = 15.0, kSpeed = 10.0; // cases/upsetting_frictionless.yaml

/// Runs the frictionless upsetting case with `friction` on both dies.
RunOutputs upset(const contact::FrictionLaw& friction, const std::string& tag) {
  scene::Case c = scene::read_case(source_path("cases/upsetting_frictionless.yaml"));
  for (scene::DieSpec& d : c.dies)
    d.friction = friction;
  c.write_vtk = false;
  return run_case(c, "anvil_upsetting_" + tag);
}

} // namespace

TEST_CASE("frictionless Norton-Hoff upsetting follows the exact homogeneous solution to 50 %", "[verification]") {
  log::set_quiet(true);
  const RunOutputs out = upset({}, "frictionless");
  const auto rows = out.loads("top");
  REQUIRE(rows.size() >= 20);
  const double volume = std::numbers::pi * kRadius * kRadius * kHeight / 4.0; // quarter model
  const scene::MaterialCard card = scene::read_material(source_path("materials/steel_c45_1100C.yaml"));
  auto exact_at = [&](double stroke) {
    return material::homogeneous_compression_load(*card.law, volume, kHeight - stroke, kHeight, kSpeed, 1100.0);
  };
  // Each row's load against the exact load at the row's own stroke, and the
  // load's change over the increment that follows (what a row one increment
  // late would be off by).
  double worst = 0.0;
  int lagging = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double load = rows[i].whole_part_load / 4.0, exact = exact_at(rows[i].stroke);
    worst = std::max(worst, std::abs(load - exact) / exact);
    // Closer to the exact load one increment before than to its own: a row
    // one increment late (the load of the geometry its increment started on).
    if (i > 0 && std::abs(load - exact_at(rows[i - 1].stroke)) <= std::abs(load - exact)) ++lagging;
  }
  INFO("worst load error " << worst << "; rows closer to the previous row's stroke than to their own: " << lagging);
  // 1 %: the bound. The flow is homogeneous, so the P1 field is exact
  // and what remains is the volume compensation and the Newton tolerance
  // (0.25 % measured), below the 0.8-2.7 % an increment changes the load by.
  CHECK(worst < 0.01);
  CHECK(lagging == 0);
  // The first row is the load at the start, the last the load at the final stroke.
  CHECK(rows.front().stroke == 0.0);
  CHECK(rows.back().stroke == Approx(7.5).epsilon(1e-9));

  const scene::RunState end = out.final_state();
  double radius = 0.0;
  for (const mesh::Point& p : end.mesh.nodes)
    radius = std::max(radius, std::hypot(p.x(), p.y()));
  const double exact_radius = kRadius * std::sqrt(kHeight / (kHeight - 7.5));
  INFO("final radius " << radius << " mm, exact " << exact_radius << " mm");
  CHECK(std::abs(radius - exact_radius) / exact_radius < 0.005);
  const double volume_change = out.summary_number("relative_change");
  INFO("volume change " << volume_change);
  CHECK(std::abs(volume_change) < 0.005);
}

TEST_CASE("friction raises the upsetting load within the slab band and barrels the billet", "[verification]") {
  log::set_quiet(true);
  using contact::FrictionKind;
  const RunOutputs frictionless = upset({}, "reference");
  const RunOutputs tresca = upset({FrictionKind::tresca, 0.3, 0.0, 0.0}, "tresca");
  const RunOutputs sticking = upset({FrictionKind::sticking, 0.0, 0.0, 0.0}, "sticking");
  const auto f0 = frictionless.loads("top"), ft = tresca.loads("top"), fs = sticking.loads("top");
  // Runs differ in increments (Δt follows the flow), so compare at equal stroke.
  auto load_at = [](const std::vector<LoadRow>& rows, double stroke) {
    for (std::size_t i = 1; i < rows.size(); ++i)
      if (rows[i].stroke >= stroke) {
        const double w = (stroke - rows[i - 1].stroke) / (rows[i].stroke - rows[i - 1].stroke);
        return (1.0 - w) * rows[i - 1].force.z() + w * rows[i].force.z();
      }
    FAIL("stroke " << stroke << " not reached");
    return 0.0;
  };
  for (double stroke = 0.5; stroke <= 7.5; stroke += 0.5) {
    const double load0 = load_at(f0, stroke), load_t = load_at(ft, stroke), load_s = load_at(fs, stroke);
    // Slab method (constant shear m̄ σ₀/√3 on both faces): mean pressure
    // σ₀ (1 + 2 m̄ R / (3√3 H)). Sticking is m̄ = 1, the top of the band.
    const double height = kHeight - stroke, radius = kRadius * std::sqrt(kHeight / height);
    const double slab_tresca = 1.0 + 2.0 * 0.3 * radius / (3.0 * std::sqrt(3.0) * height);
    const double slab_sticking = 1.0 + 2.0 * radius / (3.0 * std::sqrt(3.0) * height);
    INFO("stroke " << stroke << " mm: Tresca/frictionless " << load_t / load0 << " (slab " << slab_tresca
                   << "), sticking/frictionless " << load_s / load0 << " (slab " << slab_sticking << ")");
    CHECK(load_t > load0);
    CHECK(load_s > load_t);
    if (radius / height >= 1.0) CHECK(load_t / load0 < slab_sticking);
  }
  // Barrelling: with friction the lateral surface bulges at mid-height.
  const scene::RunState end = tresca.final_state();
  double top = 0.0, middle = 0.0, height = 0.0;
  for (const mesh::Point& p : end.mesh.nodes)
    height = std::max(height, p.z());
  for (const mesh::Point& p : end.mesh.nodes) {
    const double r = std::hypot(p.x(), p.y());
    if (p.z() > height - 1e-6) top = std::max(top, r);
    if (std::abs(p.z() - 0.5 * height) < 0.4) middle = std::max(middle, r);
  }
  INFO("radius at the die " << top << " mm, at mid-height " << middle << " mm");
  CHECK(middle > top + 0.1);
}
