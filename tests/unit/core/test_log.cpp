// log::Holding: the lines a thread logs while it holds them are written only
// by write_held, in their order, so that tasks run side by side (a remesh's
// tries) log as if run one after the other.
#include "test_common.h"

#include "anvil/core/log.h"

#include <filesystem>
#include <string>
#include <thread>
#include <vector>

using namespace anvil;

TEST_CASE("log::Holding keeps a thread's lines until write_held, each thread its own", "[unit][log]") {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "anvil_unit_log_holding.log";
  log::set_quiet(true);
  log::open_file(path.string());
  std::vector<log::HeldLine> first, second;
  log::info("before");
  std::thread other([&] {
    const log::Holding holding(second);
    log::info("second %d", 1);
    log::detail("second %d", 2);
  });
  {
    const log::Holding holding(first);
    log::info("first %d", 1);
  }
  other.join();
  log::info("after");
  log::close_file();
  CHECK(file_text(path) == "before\nafter\n");
  REQUIRE(first.size() == 1);
  CHECK(first[0].text == "first 1");
  REQUIRE(second.size() == 2);
  CHECK(second[0].text == "second 1");
  CHECK(second[0].terminal);
  CHECK(second[1].text == "second 2");
  CHECK_FALSE(second[1].terminal); // a detail line, not verbose

  log::open_file(path.string(), true);
  log::write_held(first);
  log::write_held(second);
  log::close_file();
  CHECK(file_text(path) == "before\nafter\nfirst 1\nsecond 1\nsecond 2\n");
  std::filesystem::remove(path);
}
