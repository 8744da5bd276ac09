// The folders depend one way (docs/design.md §6): each includes only the
// folders before it in this order, so a reader can follow one increment from
// the command line down to the element without a loop back.
#include "test_common.h"

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

TEST_CASE("The source folders include one way: cli and render, run, remesh, io, scene, contact, solver, thermal, die, "
          "fem, mesh, material, core",
          "[unit][core]") {
  const std::vector<std::string> order{"core",    "material", "mesh", "fem",    "die", "thermal", "solver",
                                       "contact", "scene",    "io",   "remesh", "run", "cli",     "render"};
  const auto rank = [&](const std::string& folder) {
    return static_cast<int>(std::find(order.begin(), order.end(), folder) - order.begin());
  };
  const std::regex include(R"(#include "anvil/(\w+)/)");
  int files = 0;
  for (const std::string& top : {std::string("src"), std::string("include/anvil")}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(source_path(top))) {
      const std::string extension = entry.path().extension().string();
      if (extension != ".cpp" && extension != ".h") continue;
      const std::string folder =
          std::filesystem::relative(entry.path(), source_path(top)).begin()->string(); // its first component
      INFO(entry.path().string() << " (folder " << folder << ")");
      REQUIRE(rank(folder) < static_cast<int>(order.size())); // a new folder takes its place in the order
      const std::string source = file_text(entry.path());
      for (std::sregex_iterator m(source.begin(), source.end(), include), end; m != end; ++m) {
        const std::string used = (*m)[1];
        INFO("includes anvil/" << used << "/");
        CHECK(rank(used) <= rank(folder));
      }
      ++files;
    }
  }
  CHECK(files > 100);
}
