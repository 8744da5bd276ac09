// Runs every case of tests/regression/references.csv through the library
// (as `anvil run` does) and compares its signature with the reference.
#include "test_common.h"

#include "anvil/core/log.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/Simulation.h"

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

double load_on(const std::string& loads_csv, const std::string& surface) {
  std::ifstream in(loads_csv);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cols;
    std::istringstream s(line);
    for (std::string c; std::getline(s, c, ',');) cols.push_back(c);
    if (cols.size() == 6 && cols[2] == surface) return std::stod(cols[5]);
  }
  FAIL("no surface " << surface << " in " << loads_csv);
  return 0.0;
}

int newton_iterations(const std::string& summary_json) {
  std::ifstream in(summary_json);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("\"newton_iterations\": ");
  REQUIRE(at != std::string::npos);
  return std::stoi(text.substr(at + 21));
}

} // namespace

TEST_CASE("every case reproduces its reference signature", "[regression]") {
  const auto refs = references();
  REQUIRE(refs.size() >= 2);
  log::set_quiet(true);
  for (const Reference& r : refs) {
    INFO("case " << r.case_name);
    const auto out = std::filesystem::temp_directory_path() / ("anvil_regression_" + r.case_name);
    std::filesystem::remove_all(out);
    scene::run(scene::read_case(source_path("cases/" + r.case_name + ".yaml")), {out.string()});
    const double fz = load_on((out / "loads.csv").string(), r.surface);
    INFO("Fz " << fz << " N, reference " << r.fz << " N");
    CHECK(std::abs(fz - r.fz) <= 1e-6 * std::abs(r.fz));
    const int iterations = newton_iterations((out / "summary.json").string());
    CHECK(std::abs(iterations - r.newton_iterations) <= 3);
    CHECK(std::filesystem::exists(out / "anvil.pvd"));
  }
}
