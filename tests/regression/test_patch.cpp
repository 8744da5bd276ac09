// The contact patch test of Fourment 2008 §5.2 (issue 4a), on tetrahedral
// blocks meshed independently: matching meshes transmit the uniform stress
// exactly with every formulation, and the quasi-symmetric formulation
// transmits it better than master/slave on non-matching meshes. The full
// table (four load cases, six mesh pairs, three formulations) is printed by
// tools/patch_test; the README gives it.
//
// What this test does not assert, because it is not true of this nodal
// implementation (measured, see the README): that the QS error is at most
// half the M/S error in every non-matching case. On the 7/4 (master finer)
// pair QS has 0.51 of the M/S error; with the slave 3.75 times finer (4/15)
// under a pressure, and with the master finer under an imposed velocity, QS
// is worse than M/S.
#include "test_common.h"

#include "anvil/core/log.h"
#include "patch_test_cases.h"

#include <filesystem>

namespace {

patch_test::Errors run(const patch_test::LoadCase& load, const patch_test::MeshPair& meshes, const char* formulation) {
  anvil::log::set_quiet(true);
  const auto out = std::filesystem::temp_directory_path() / "anvil_patch_test";
  return patch_test::run(load, meshes, formulation, ANVIL_SOURCE_DIR, out.string());
}

} // namespace

TEST_CASE("matching meshes transmit the patch-test stress exactly, with master/slave and quasi-symmetric alike",
          "[regression]") {
  const patch_test::MeshPair matching = patch_test::mesh_pairs().front();
  REQUIRE(matching.master_cells == matching.slave_cells);
  for (const patch_test::LoadCase& load : patch_test::load_cases()) {
    INFO(load.name);
    const patch_test::Errors ms = run(load, matching, "master_slave");
    const patch_test::Errors qs = run(load, matching, "quasi_symmetric");
    // Exact up to the penalty compliance: σn/ρ is 1e-5 of the imposed motion
    // with the cases' penalty factor 1e5, a uniform error of that size.
    CHECK(ms.interface_max < 1e-4);
    CHECK(ms.interior_max < 1e-4);
    // On matching meshes each master node sits on a slave node, and eq. 24
    // reduces to eq. 19: the two runs agree to round-off.
    CHECK(qs.interface_max == Approx(ms.interface_max).margin(1e-9));
    CHECK(qs.interface_rms == Approx(ms.interface_rms).margin(1e-9));
    CHECK(qs.interior_max == Approx(ms.interior_max).margin(1e-9));
  }
}

TEST_CASE("quasi-symmetric contact transmits the patch-test stress better than master/slave on non-matching meshes",
          "[regression]") {
  for (const char* pair_name : {"similar 4/5", "slave finer 4/7", "master finer 7/4"}) {
    const auto& pairs = patch_test::mesh_pairs();
    const auto meshes = *std::find_if(pairs.begin(), pairs.end(), [&](const auto& p) { return p.name == std::string(pair_name); });
    for (const patch_test::LoadCase& load : patch_test::load_cases()) {
      if (load.exact_stress < 1.0 && meshes.master_cells > meshes.slave_cells) continue; // see the header comment
      INFO(load.name << ", " << meshes.name);
      const patch_test::Errors ms = run(load, meshes, "master_slave");
      const patch_test::Errors qs = run(load, meshes, "quasi_symmetric");
      // Non-matching meshes make node-to-facet contact lose the uniform
      // stress: M/S errors are several percent at least (measured 3.9-67 % RMS).
      CHECK(ms.interface_rms > 0.02);
      CHECK(qs.interface_rms < ms.interface_rms);
      CHECK(qs.interface_max < ms.interface_max);
      CHECK(qs.interior_max < ms.interior_max);
    }
  }
}
