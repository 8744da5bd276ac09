// External programs get their arguments as a vector, never through a shell:
// an argument full of shell syntax reaches the program as it is, and runs
// nothing.
#include "test_common.h"

#include "anvil/core/subprocess.h"

#include <filesystem>

TEST_CASE("A program gets a hostile argument as one argument and no shell runs it", "[unit][core]") {
  const auto folder = std::filesystem::temp_directory_path() / "anvil_subprocess_test";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::string hostile = "x';touch INJECTED;' $(touch INJECTED) `touch INJECTED` \"q\"\nline";
  anvil::subprocess::Options options;
  options.directory = folder.string();
  // cp copies its standard input (/dev/stdin) to a file named by the argument.
  options.input = "fed through standard input\n";
  REQUIRE(anvil::subprocess::run({"cp", "/dev/stdin", hostile}, options) == 0);
  CHECK(file_text(folder / hostile) == options.input);
  CHECK_FALSE(std::filesystem::exists(folder / "INJECTED"));
  CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()) == 1);
  std::filesystem::remove_all(folder);
}

TEST_CASE("A program's exit status comes back, and one that cannot start gives -1", "[unit][core]") {
  CHECK(anvil::subprocess::run({"true"}) == 0);
  CHECK(anvil::subprocess::run({"false"}) == 1);
  CHECK(anvil::subprocess::run({"anvil-no-such-program"}) == -1);
  CHECK(anvil::subprocess::on_path("sh"));
  CHECK_FALSE(anvil::subprocess::on_path("anvil-no-such-program"));
}
