// Bad case files: one clear error naming file, line, key, value and what was
// expected; and nothing written.
#include "test_common.h"

#include "anvil/core/error.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/MaterialCard.h"

#include <filesystem>
#include <fstream>

using namespace anvil;

namespace {

const std::string kValid = R"(anvil: 1
bodies:
  - name: block
    material: MATERIAL
    mesh: {generate: box, size: [2, 2, 1], element_size: 0.5}
boundary:
  - {name: bottom, type: sticking_plate, tag: 5, velocity: [0, 0, 0]}
  - {name: top, type: sticking_plate, tag: 6, velocity: [0, 0, -1]}
)";

/// The case files' folder, inside the test program's own (tests/main.cpp).
std::filesystem::path scratch() {
  return std::filesystem::temp_directory_path() / "anvil_case_tests";
}

std::string write_case(const std::string& name, std::string text) {
  const auto dir = scratch();
  std::filesystem::create_directories(dir);
  const std::string material = source_path("materials/newtonian_reference.yaml");
  if (auto at = text.find("MATERIAL"); at != std::string::npos) text.replace(at, 8, material);
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& name, const std::string& text) {
  try {
    scene::read_case(write_case(name, text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

} // namespace

TEST_CASE("a valid case reads", "[unit]") {
  const scene::Case c = scene::read_case(write_case("valid.yaml", kValid));
  CHECK(c.bodies.size() == 1);
  CHECK(c.boundary.size() == 2);
  CHECK(c.newton.tolerance == 1e-6); // schema default
}

TEST_CASE("case-file errors name file, line, key and expectation", "[unit]") {
  using Catch::Contains;
  CHECK_THAT(error_of("unknown.yaml", kValid + "solverr: {}\n"),
             Contains("unknown.yaml:9") && Contains("unknown key 'solverr'") && Contains("known keys here"));
  CHECK_THAT(error_of("range.yaml", replaced(kValid, "element_size: 0.5", "element_size: -1")),
             Contains("range.yaml:5") && Contains("bodies[0].mesh.element_size") && Contains("'-1'") &&
                 Contains("> 0") && Contains("(mm)"));
  CHECK_THAT(error_of("missing.yaml", replaced(kValid, "anvil: 1\n", "")), Contains("missing key 'anvil'"));
  CHECK_THAT(error_of("version.yaml", replaced(kValid, "anvil: 1", "anvil: 7")),
             Contains("version.yaml:1") && Contains("'7'") && Contains("equal to 1"));
  CHECK_THAT(error_of("choice.yaml", replaced(kValid, "type: sticking_plate, tag: 5", "type: glue, tag: 5")),
             Contains("choice.yaml:7") && Contains("boundary[0].type") && Contains("one of"));
  CHECK_THAT(error_of("body.yaml", replaced(kValid, "{name: bottom,", "{name: bottom, body: billet,")),
             Contains("no body is named 'billet'"));
  CHECK_THAT(error_of("syntax.yaml", kValid + "boundary: [\n"),
             Contains("syntax.yaml:") && Contains("YAML syntax error"));
}

TEST_CASE("an input error leaves no output behind", "[unit]") {
  const auto out = scratch() / "no_output";
  std::filesystem::remove_all(out);
  // The face selection is checked only once the mesh exists: still before any file is written.
  const scene::Case c = scene::read_case(write_case("tag.yaml", replaced(kValid, "tag: 6", "tag: 42")));
  CHECK_THROWS_WITH(run::run(c, {out.string()}),
                    Catch::Contains("selects no boundary face") && Catch::Contains("tag 42"));
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("material cards must cite a source for every number", "[unit]") {
  const std::string card = write_case("card.yaml", "format: 1\nname: x\nlaw: newtonian\nviscosity: 2\nsources: {}\n");
  CHECK_THROWS_WITH(scene::read_material(card),
                    Catch::Contains("card.yaml:4") && Catch::Contains("viscosity") && Catch::Contains("sources"));
  for (const auto& entry : std::filesystem::directory_iterator(source_path("materials"))) {
    INFO(entry.path());
    CHECK_NOTHROW(scene::read_material(entry.path().string()));
  }
}

TEST_CASE("command-line overrides change one key, every list element or one element", "[unit]") {
  const std::string path = write_case("overrides.yaml", kValid);
  const scene::Case c = scene::read_case(path, {"bodies[0].mesh.element_size=0.25", "boundary[].velocity=[0, 0, -2]",
                                                "boundary[0].velocity=[0, 0, 0]", "solver.tolerance=1e-6"});
  CHECK(c.bodies[0].mesh.element_size == 0.25);
  CHECK(*c.boundary[0].velocity[2] == 0.0);
  CHECK(*c.boundary[1].velocity[2] == -2.0);
  CHECK(c.newton.tolerance == 1e-6); // a map absent from the file is created
  CHECK(c.overrides.size() == 4);

  using Catch::Contains;
  auto error_with = [&](const std::string& change) {
    try {
      scene::read_case(path, {change});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(error_with("bodies[0].mesh.element_size=-1"),
             Contains("--set 'bodies[0].mesh.element_size=-1'") && Contains("> 0"));
  CHECK_THAT(error_with("bodies[].mesh.elementsize=1"), Contains("no key 'bodies[].mesh.elementsize'"));
  CHECK_THAT(error_with("boundary[5].velocity=[0, 0, 1]"), Contains("has 2 elements"));
  CHECK_THAT(error_with("time.stroke_increment"), Contains("expected key.path=value"));
  CHECK_THAT(error_with("title.x=1"), Contains("no key 'title.x'"));
}

TEST_CASE("the adaptive size field splits sunk edges unless the case says otherwise", "[unit]") {
  const std::string path = source_path("cases/closed_die_flash.yaml");
  CHECK_FALSE(scene::read_case(path).remeshing.split_sunk_edges);
  CHECK(scene::read_case(path, {"remeshing.size=adaptive"}).remeshing.split_sunk_edges);
  CHECK_FALSE(scene::read_case(path, {"remeshing.size=adaptive", "remeshing.split_sunk_edges=false"})
                  .remeshing.split_sunk_edges);
  CHECK(scene::read_case(path, {"remeshing.split_sunk_edges=true"}).remeshing.split_sunk_edges);
}
