// Chains of operations (run/chain.h, docs/chains.md): two upsettings in a
// row are one upsetting, a trim removes the volume of its cut, and a chain
// stopped in its third operation resumes there as the uninterrupted one.
#include "run_outputs.h"

#include "anvil/core/log.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/run/chain.h"
#include "anvil/scene/Chain.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <regex>

using namespace anvil;

namespace {

/// A quarter C45 cylinder (r 5, h 8 mm) between Tresca dies; every step a
/// full stroke increment (no contact-event or displacement cuts), so that
/// the chain and the single run solve on the same geometries.
std::string billet(const std::string& extra) {
  return "anvil: 1\n"
         "bodies:\n"
         "  - name: billet\n"
         "    material: " +
         source_path("materials/steel_c45_1100C.yaml") +
         "\n"
         "    mesh: {generate: quarter_cylinder, radius: 5, height: 8, element_size: 1.0}\n"
         "boundary:\n"
         "  - {name: symmetry_x, type: symmetry, tag: 1}\n"
         "  - {name: symmetry_y, type: symmetry, tag: 3}\n"
         "time: {stroke_increment: 0.25, min_step_fraction: 0.5, max_displacement: 1}\n"
         "output: {picture: false}\n" +
         extra;
}

/// Dies with the top one starting at z = `top` mm, moving down at 10 mm/s;
/// `bottom` adds keys to the bottom die.
std::string dies(double top, const std::string& bottom = "") {
  return "  - {name: top, plane: {point: [0, 0, " + std::to_string(top) +
         "], normal: [0, 0, -1]}, motion: constant, velocity: [0, 0, -10], friction: {law: tresca, factor: 0.3}}\n"
         "  - {name: bottom, plane: {point: [0, 0, 0], normal: [0, 0, 1]}, friction: {law: tresca, factor: 0.3}" +
         bottom + "}\n";
}

std::string write_case(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / (name + ".yaml")).string();
  std::ofstream(path) << text;
  return path;
}

/// Runs the chain of `path` into <tmp>/`name` (emptied first).
std::string run_chain(const std::string& path, const std::string& name, const std::vector<std::string>& settings = {},
                      bool resume = false) {
  const auto out = std::filesystem::temp_directory_path() / name;
  if (!resume) std::filesystem::remove_all(out);
  run::RunOptions options{out.string(), resume, resume};
  run::run_chain(scene::read_chain(path, settings), options);
  return out.string();
}

/// A chain of upsettings, each `stroke` mm, the n-th die starting where
/// the one before stopped; `bottom` adds keys to the bottom die.
std::string upsettings(int count, double stroke, const std::string& bottom = "") {
  std::string text = "operations:\n";
  for (int k = 0; k < count; ++k)
    text += "  - name: upset" + std::to_string(k + 1) + "\n    dies:\n" +
            std::regex_replace(dies(8.0 - k * stroke, bottom), std::regex("  - "), "      - ") +
            "    time: {stop: {stroke: " + std::to_string(stroke) + "}}\n";
  return text;
}

} // namespace

TEST_CASE("an operation's own sections stand over the top level's for it alone", "[verification]") {
  // The first operation remeshes and allows 60 Newton iterations; the
  // second says neither, so it takes the top level's (no remeshing, the
  // default budget), whatever the one before asked.
  const std::string text = billet("dies:\n" + dies(8.0) +
                                  "operations:\n"
                                  "  - {name: first, remeshing: {quality: 0.2}, solver: {max_iterations: 60}, "
                                  "time: {stop: {stroke: 1}}}\n"
                                  "  - {name: second, time: {stop: {stroke: 1}}}\n");
  const scene::Chain chain = scene::read_chain(write_case("anvil_chain_sections", text));
  REQUIRE(chain.operations.size() == 2);
  CHECK(chain.operations[0].input.remeshing.enabled);
  CHECK(chain.operations[0].input.newton.max_iterations == 60);
  CHECK_FALSE(chain.operations[1].input.remeshing.enabled);
  const scene::Case plain =
      scene::read_case(write_case("anvil_chain_plain", billet("dies:\n" + dies(8.0))), {"time.stop.stroke=1"});
  CHECK(chain.operations[1].input.newton.max_iterations == plain.newton.max_iterations);
}

TEST_CASE("a chain of two upsettings gives the loads of one upsetting of the same total stroke", "[verification]") {
  log::set_quiet(true);
  const std::string chain = write_case("anvil_chain_two", billet(upsettings(2, 2.0)));
  const std::string single = write_case("anvil_chain_one", billet("dies:\n" + dies(8.0)));
  const std::string out = run_chain(chain, "anvil_chain_two");
  const RunOutputs one = run_case(scene::read_case(single, {"time.stop.stroke=4"}), "anvil_chain_one");
  const std::vector<LoadRow> whole = one.loads("top");
  std::vector<LoadRow> chained = RunOutputs{out + "/01-upset1"}.loads("top");
  const std::vector<LoadRow> second = RunOutputs{out + "/02-upset2"}.loads("top");
  for (LoadRow row : second) {
    row.stroke += 2.0;
    chained.push_back(row);
  }
  // The second operation starts from the first's last flow (its Newton
  // guess and the rates its friction stress is read at): the loads agree to
  // what Newton leaves, |dv|/|v| <= 1e-4 at quadratic convergence (measured
  // 3.2e-6 at most).
  int compared = 0;
  for (const LoadRow& row : chained)
    for (const LoadRow& ref : whole)
      if (std::abs(ref.stroke - row.stroke) < 1e-9 && row.stroke > 1e-9) {
        INFO("stroke " << row.stroke << " mm: " << row.whole_part_load << " N against " << ref.whole_part_load);
        CHECK(std::abs(row.whole_part_load / ref.whole_part_load - 1.0) < 1e-5);
        ++compared;
      }
  CHECK(compared >= 15);
  CHECK(io::read_summary_number(out, "operations_done") == 2);
  CHECK(io::read_summary_number(out, "time_s") == Approx(0.4).epsilon(1e-12));
}

TEST_CASE("a die's wear accumulates over the operations of a chain as over one stroke", "[verification]") {
  // The bottom die of two upsettings of 2 mm in a row (the same die by
  // name in both) wears as in one upsetting of 4 mm: it is drawn with the
  // same vertices in both operations and its wear is carried from the first
  // into the second. To what Newton leaves of the sliding velocities it
  // integrates: |dv|/|v| <= 1e-4 (measured 7e-6 of the largest wear).
  log::set_quiet(true);
  const std::string wear = ", wear: {coefficient: 1.0e-3, hardness: 50}";
  const std::string chain = write_case("anvil_chain_wear_two", billet(upsettings(2, 2.0, wear)));
  const std::string single = write_case("anvil_chain_wear_one", billet("dies:\n" + dies(8.0, wear)));
  const std::string out = run_chain(chain, "anvil_chain_wear_two");
  const scene::RunState one =
      run_case(scene::read_case(single, {"time.stop.stroke=4"}), "anvil_chain_wear_one").final_state();
  const scene::RunState two = RunOutputs{out + "/02-upset2"}.final_state();
  REQUIRE(one.wear.size() == 2);
  REQUIRE(two.wear.size() == 2);
  const std::vector<double>&a = two.wear[1], &b = one.wear[1];
  REQUIRE(a.size() == b.size());
  const double largest = *std::max_element(b.begin(), b.end());
  REQUIRE(largest > 0.0);
  double worst = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
    worst = std::max(worst, std::abs(a[v] - b[v]));
  INFO("largest wear " << largest << " mm, largest difference " << worst << " mm");
  CHECK(worst < 1e-4 * largest);
  // The first operation alone wore less: the second added to it.
  const scene::RunState first = RunOutputs{out + "/01-upset1"}.final_state();
  CHECK(*std::max_element(first.wear[1].begin(), first.wear[1].end()) < 0.9 * largest);
}

/// The trim of a 10 x 10 x 4 mm block (x, y in [0, 10]) by `cut` (the
/// trim's YAML; `extra`, more keys of the operation), run as a chain of
/// that one operation; its folder.
std::string trimmed_block(const std::string& name, const std::string& cut, const std::string& extra = "") {
  log::set_quiet(true);
  const std::string path = write_case(name, "anvil: 1\n"
                                            "bodies:\n"
                                            "  - name: block\n"
                                            "    material: " +
                                                source_path("materials/steel_c45_1100C.yaml") +
                                                "\n"
                                                "    mesh: {generate: box, size: [10, 10, 4], element_size: 1.0}\n"
                                                "output: {picture: false}\n"
                                                "operations:\n"
                                                "  - name: cut\n"
                                                "    type: trim\n"
                                                "    trim: " +
                                                cut + "\n" + extra);
  return run_chain(path, name) + "/01-cut";
}

/// A closed STL box [lo, hi] with outward normals.
std::string stl_box(const std::string& name, const mesh::Point& lo, const mesh::Point& hi) {
  const std::string path = (std::filesystem::temp_directory_path() / (name + ".stl")).string();
  std::ofstream stl(path);
  stl << "solid box\n";
  auto corner = [&](int k) {
    return mesh::Point(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  };
  // Each side as two triangles, counter-clockwise seen from outside.
  const int sides[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : sides)
    for (const auto& tri : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
      const mesh::Point a = corner(tri[0]), b = corner(tri[1]), c = corner(tri[2]);
      const mesh::Point n = (b - a).cross(c - a).normalized();
      stl << "facet normal " << n.transpose() << "\n outer loop\n";
      for (const mesh::Point& x : {a, b, c})
        stl << "  vertex " << x.transpose() << "\n";
      stl << " endloop\nendfacet\n";
    }
  stl << "endsolid box\n";
  return path;
}

/// Checks the kept part of a trimmed block: its volume, no node where
/// `outside` says, no inverted element.
void check_trim(const std::string& folder, double kept, const std::function<bool(const mesh::Point&)>& outside) {
  const RunOutputs trim{folder};
  CHECK(trim.summary_number("removed_volume_model_mm3") == Approx(400.0 - kept).epsilon(1e-9));
  CHECK(trim.summary_number("volume_mm3") == Approx(kept).epsilon(1e-9));
  const scene::RunState state = trim.final_state();
  for (const mesh::Point& x : state.mesh.nodes)
    CHECK_FALSE(outside(x));
  for (int e = 0; e < state.mesh.tet_count(); ++e)
    CHECK(mesh::quality(state.mesh, e) > 0.0);
}

TEST_CASE("a trim removes the volume of its cut", "[verification]") {
  // The elements the cut crosses are split along it, so the part kept is
  // exactly the block's side of a plane cut, whatever the mesh (to 1e-9,
  // rounding of the summed element volumes).
  SECTION("a line along the mesh: the plane x = 7.3 (292 mm3 kept)") {
    check_trim(trimmed_block("anvil_chain_trim", "{line: [-1, -1, 7.3, -1, 7.3, 11, -1, 11]}"), 292.0,
               [](const mesh::Point& x) { return x.x() > 7.3 + 1e-12; });
  }
  SECTION("a line across the mesh: the plane x + y = 12 (a corner of 8 x 8 / 2 x 4 = 128 mm3 removed)") {
    check_trim(trimmed_block("anvil_chain_trim_oblique", "{line: [-1, -1, 13, -1, -1, 13]}"), 272.0,
               [](const mesh::Point& x) { return x.x() + x.y() > 12.0 + 1e-9; });
  }
  SECTION("pieces below remeshing.quality rebuilt along the cut, the rest kept") {
    // The plane 14.3 x + 14 y = 171.9 cuts off the corner (10, 10) with legs
    // 10 - 28.9/14 and 10 - 31.9/14.3 mm; remeshing.quality 0.3 leaves
    // pieces of the cut below it, which the local remesh rebuilds (it keeps
    // the region's boundary, hence the volume).
    const double removed = 4.0 * 0.5 * (10.0 - 28.9 / 14.0) * (10.0 - 31.9 / 14.3);
    const std::string folder = trimmed_block("anvil_chain_trim_local", "{line: [-1, -1, 13, -1, -1, 13.3]}",
                                             "    remeshing: {quality: 0.3}\n");
    check_trim(folder, 400.0 - removed,
               [](const mesh::Point& x) { return 14.3 * x.x() + 14.0 * x.y() > 171.9 + 1e-9; });
    std::ifstream summary(folder + "/summary.json");
    const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
    CHECK(text.find("\"remesh\": \"along the cut\"") != std::string::npos);
  }
  SECTION("a closed STL: the box x <= 7.3 (292 mm3 kept)") {
    const std::string stl = stl_box("anvil_chain_trim_box", {-1, -1, -1}, {7.3, 11, 5});
    check_trim(trimmed_block("anvil_chain_trim_stl", "{stl: " + stl + "}"), 292.0,
               [](const mesh::Point& x) { return x.x() > 7.3 + 1e-12; });
  }
}

TEST_CASE("a chain stopped in its third operation resumes there and ends as the uninterrupted one", "[verification]") {
  log::set_quiet(true);
  const std::string path = write_case("anvil_chain_three", billet(upsettings(3, 1.0)));
  const std::string whole = run_chain(path, "anvil_chain_three_whole");
  const std::string part = run_chain(path, "anvil_chain_three_part", {"operations[2].time.max_increments=2"});
  CHECK(io::read_summary_number(part, "operations_done") == 2);
  run_chain(path, "anvil_chain_three_part", {}, true);
  CHECK(io::read_summary_number(part, "operations_done") == 3);
  const scene::RunState a = RunOutputs{whole + "/03-upset3"}.final_state();
  const scene::RunState b = RunOutputs{part + "/03-upset3"}.final_state();
  REQUIRE(a.mesh.node_count() == b.mesh.node_count());
  REQUIRE(a.increment == b.increment);
  for (int n = 0; n < a.mesh.node_count(); ++n)
    REQUIRE(a.mesh.nodes[n] == b.mesh.nodes[n]); // bit for bit
  CHECK(a.equivalent_strain == b.equivalent_strain);
  CHECK(io::read_summary_number(whole, "time_s") == io::read_summary_number(part, "time_s"));
}
