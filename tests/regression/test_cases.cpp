// Every case of cases/ against its regression signature
// (tests/regression/signatures/CASE.csv, written by tools/update_signatures):
// its first increments, run through the library as `anvil run` does.
#include "test_common.h"

#include "anvil/core/log.h"
#include "anvil/io/Checkpoint.h"
#include "anvil/material/mandel.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/RunState.h"
#include "run_outputs.h"
#include "signature.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace anvil;

namespace {

/// Largest |value| of column `of` over the rows of `sig`.
template <typename F> double peak(const signature::Signature& sig, F of) {
  double m = 0.0;
  for (const signature::Row& r : sig.rows)
    m = std::max(m, std::abs(of(r)));
  return m;
}

/// Every other case of cases/ in name order, from the `half`-th (0 or 1), against its signature.
void check_signatures(int half) {
  // Tolerances, each against the largest value of its column in the
  // reference run. The Newton tolerance (1e-6 on the force residual, relative
  // to the load) bounds loads to about 1e-6; 1e-4 leaves room for round-off
  // of another BLAS or thread count and for an active set that tips by one
  // node, and still catches any change of the discrete problem (a changed
  // penalty or friction law moves loads by 1e-3 or more). Stroke and volume
  // follow Δt and v: 1e-6. ε̄: 1e-4. Newton iterations: a band of ±3 (never
  // checked exactly).
  log::set_quiet(true);
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(source_path("cases")))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  REQUIRE(names.size() >= 10);
  for (std::size_t k = static_cast<std::size_t>(half); k < names.size(); k += 2) {
    const std::string& name = names[k];
    INFO("case " << name << " (reference: tests/regression/signatures/" << name << ".csv; tools/update_signatures)");
    const signature::Signature ref = signature::read_csv(source_path("tests/regression/signatures/" + name + ".csv"));
    const signature::Signature got = signature::of_run(
        signature::run(source_path("cases/" + name + ".yaml"),
                       (std::filesystem::temp_directory_path() / ("anvil_signature_" + name)).string()));
    REQUIRE(got.surfaces == ref.surfaces);
    REQUIRE(got.rows.size() == ref.rows.size());
    const double stroke = peak(ref, [](const auto& r) { return r.stroke; });
    const double volume = peak(ref, [](const auto& r) { return r.volume; });
    const double strain = peak(ref, [](const auto& r) { return r.max_strain; });
    for (std::size_t i = 0; i < ref.rows.size(); ++i) {
      const signature::Row &a = got.rows[i], &b = ref.rows[i];
      INFO("written increment " << b.increment);
      CHECK(a.increment == b.increment);
      CHECK(std::abs(a.stroke - b.stroke) <= 1e-6 * stroke);
      CHECK(std::abs(a.volume - b.volume) <= 1e-6 * volume);
      CHECK(std::abs(a.max_strain - b.max_strain) <= 1e-4 * strain);
      CHECK(std::abs(a.newton - b.newton) <= 3);
      for (std::size_t s = 0; s < ref.surfaces.size(); ++s) {
        const double load = peak(ref, [s](const auto& r) { return r.loads[s]; });
        INFO("surface " << ref.surfaces[s] << ": " << a.loads[s] << " N, reference " << b.loads[s] << " N");
        CHECK(std::abs(a.loads[s] - b.loads[s]) <= 1e-4 * load);
      }
    }
  }
}

} // namespace

// Two halves of the cases, two tests: ctest runs them side by side.
TEST_CASE("every case reproduces its regression signature at each written increment (first half)", "[regression]") {
  check_signatures(0);
}

TEST_CASE("every case reproduces its regression signature at each written increment (second half)", "[regression]") {
  check_signatures(1);
}

TEST_CASE("a billet forged between elastic dies: the press load rises and the dies carry stress", "[regression]") {
  // cases/forging_elastic_dies.yaml to its end (3 mm of press travel).
  anvil::log::set_quiet(true);
  const anvil::scene::Case c = anvil::scene::read_case(source_path("cases/forging_elastic_dies.yaml"));
  const RunOutputs out = run_case(c, "anvil_forging_elastic_dies");
  const auto press = out.loads("press");
  REQUIRE(press.size() >= 2);
  CHECK(press.back().stroke == Approx(3.0).epsilon(1e-9));
  for (std::size_t k = 1; k < press.size(); ++k)
    CHECK(press[k].force.z() > press[k - 1].force.z());
  // Die stress: the press load spread over the die's section is a lower
  // bound of its largest von Mises stress; the billet's flow stress at the
  // start (C45 at 1100 °C, < 200 MPa) cannot be exceeded by the dies' mean.
  const std::vector<double> von_mises = anvil::io::read_last_cell_field(out.directory, "von_mises_stress", 1);
  const std::vector<double> body = anvil::io::read_last_cell_field(out.directory, "body_id", 1);
  REQUIRE(von_mises.size() == body.size());
  double die_max = 0.0;
  for (std::size_t e = 0; e < body.size(); ++e) {
    REQUIRE(std::isfinite(von_mises[e]));
    if (body[e] > 0.5) die_max = std::max(die_max, von_mises[e]);
  }
  const double mean_press_stress = press.back().force.z() / (16.0 * 16.0); // MPa over the quarter die's back face
  INFO("press load " << press.back().force.z() << " N, die von Mises max " << die_max << " MPa");
  CHECK(die_max > mean_press_stress);
  CHECK(std::abs(out.summary_number("relative_change")) < 0.005);
  // The stress written for a die is the stress it carries into the next
  // increment (the checkpoint's σ_n+1), not that stress plus the last
  // increment's Δt C:ε̇ once more. Both are the same doubles: 1e-12 of the
  // largest is round-off of the Mandel-to-tensor conversion only.
  const anvil::scene::RunState last = anvil::io::read_checkpoint(out.directory + "/checkpoint.h5");
  const std::vector<double> stress = anvil::io::read_last_cell_field(out.directory, "stress", 6);
  REQUIRE(last.elastic_stress.size() == stress.size());
  double largest = 0.0, difference = 0.0;
  for (std::size_t e = 0; e < body.size(); ++e) {
    if (body[e] < 0.5) continue;
    const anvil::material::Vec6 carried =
        anvil::material::to_components(Eigen::Map<const anvil::material::Vec6>(&last.elastic_stress[6 * e]));
    for (int k = 0; k < 6; ++k) {
      largest = std::max(largest, std::abs(carried[k]));
      difference = std::max(difference, std::abs(carried[k] - stress[6 * e + k]));
    }
  }
  INFO("die stress: largest component " << largest << " MPa, written against carried " << difference << " MPa");
  CHECK(largest > 0.0);
  CHECK(difference <= 1e-12 * largest);
}
