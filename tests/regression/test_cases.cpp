// Runs every case of tests/regression/references.csv through the library
// (as `anvil run` does) and compares its signature with the reference.
#include "test_common.h"

#include "anvil/core/log.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Simulation.h"
#include "run_outputs.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace anvil;

namespace {

struct Reference {
  std::string case_name, surface;
  double fz;
  int newton_iterations;
};

std::vector<Reference> references() {
  std::ifstream in(source_path("tests/regression/references.csv"));
  std::vector<Reference> out;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::istringstream s(line);
    Reference r;
    std::string fz, it;
    std::getline(s, r.case_name, ',');
    std::getline(s, r.surface, ',');
    std::getline(s, fz, ',');
    std::getline(s, it, ',');
    r.fz = std::stod(fz);
    r.newton_iterations = std::stoi(it);
    out.push_back(r);
  }
  return out;
}

} // namespace

TEST_CASE("every case reproduces its reference signature", "[regression]") {
  const auto refs = references();
  REQUIRE(refs.size() >= 2);
  log::set_quiet(true);
  for (const Reference& r : refs) {
    INFO("case " << r.case_name);
    const RunOutputs out =
        run_case(scene::read_case(source_path("cases/" + r.case_name + ".yaml")), "anvil_regression_" + r.case_name);
    const auto rows = out.loads(r.surface);
    REQUIRE(!rows.empty());
    const double fz = rows.back().force.z();
    INFO("Fz " << fz << " N, reference " << r.fz << " N");
    CHECK(std::abs(fz - r.fz) <= 1e-6 * std::abs(r.fz));
    const int iterations = static_cast<int>(out.summary_number("newton_iterations"));
    CHECK(std::abs(iterations - r.newton_iterations) <= 3);
    CHECK(std::filesystem::exists(out.directory + "/anvil.pvd"));
  }
}
