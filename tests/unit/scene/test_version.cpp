// One version number everywhere: CMake's project version is what
// `anvil --version` and summary.json print (ANVIL_VERSION), and the README's
// title names it.
#include "test_common.h"

#include <fstream>
#include <string>

TEST_CASE("The README names the version the build prints", "[unit][scene]") {
  std::ifstream readme(source_path("README.md"));
  std::string title;
  std::getline(readme, title);
  CHECK(title == std::string("# Anvil ") + ANVIL_VERSION);
}
