// The README and docs/ name only what is there: every case file, tool,
// die, material card, figure and page they name exists, and every case they
// name is a valid case (read as `anvil run` reads it; running them is the
// regression tier's job).
#include "test_common.h"

#include "anvil/scene/Chain.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>

TEST_CASE("README and docs/ name only files that exist, and the cases they name are valid", "[unit][scene]") {
  const std::filesystem::path root = source_path("");
  std::vector<std::filesystem::path> pages{root / "README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  REQUIRE(pages.size() >= 2);
  // Paths into the repository's folders, as the pages write them (from the
  // root in the README, from docs/ with ../ in the pages beside it).
  const std::regex named(R"((?:\.\./)?((?:cases|tools|dies|materials|docs)/[A-Za-z0-9_./-]*[A-Za-z0-9_]))");
  const std::regex linked(R"(\]\(([a-z-]+\.md)\))"); // a page of docs/ linked from another
  std::set<std::string> cases;
  int named_count = 0;
  for (const auto& page : pages) {
    const std::string text = file_text(page);
    for (std::sregex_iterator m(text.begin(), text.end(), named), end; m != end; ++m) {
      const std::string path = (*m)[1];
      if (path.find("out/") != std::string::npos) continue; // a run's output, made by the run
      // A one-letter name is a placeholder in an example (cases/x.yaml in an error message).
      if (std::filesystem::path(path).stem().string().size() == 1) continue;
      INFO(page.filename().string() << " names " << path);
      CHECK(std::filesystem::exists(root / path));
      ++named_count;
      if (path.starts_with("cases/") && path.ends_with(".yaml")) cases.insert(path);
    }
    if (page.parent_path().filename() == "docs")
      for (std::sregex_iterator m(text.begin(), text.end(), linked), end; m != end; ++m) {
        INFO(page.filename().string() << " links " << (*m)[1]);
        CHECK(std::filesystem::exists(page.parent_path() / std::string((*m)[1])));
      }
  }
  CHECK(named_count > 20);
  REQUIRE(cases.size() >= 5);
  for (const std::string& c : cases) {
    INFO("case " << c);
    CHECK_NOTHROW(anvil::scene::read_chain((root / c).string())); // a case is a chain of one
  }
}

TEST_CASE("docs/ tables of measured figures are written by their tools", "[unit][scene]") {
  // A table row outside a `<!-- figures: TOOL (NAME) -->` ... `<!-- end
  // figures -->` block that holds a measured quantity (a number with a unit
  // of time, memory, force or a percentage) was typed by hand; the tool that
  // measures it must write it (tools/lib/doc_figures.py).
  const std::regex measured(R"(\d(?:\.\d+)?(?:e[-+]?\d+)? ?(?:%|s|ms|GB|MB|kN|N)(?:\s|\||$|,|\)))");
  int blocks = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_path("docs"))) {
    if (entry.path().extension() != ".md") continue;
    std::ifstream in(entry.path());
    bool inside = false;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      if (line.starts_with("<!-- figures: ")) inside = true, ++blocks;
      if (line.starts_with("<!-- end figures -->")) inside = false;
      if (inside || !line.starts_with("|")) continue;
      INFO(entry.path().filename().string() << ":" << number << ": " << line);
      CHECK_FALSE(std::regex_search(line, measured));
    }
    CHECK_FALSE(inside); // every block closed
  }
  CHECK(blocks >= 20);
}
