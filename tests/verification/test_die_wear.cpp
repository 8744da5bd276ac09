// Die wear (effect die_wear) on a run whose answer is known: a stiff block
// pressed on a flat die by a uniform pressure p and pushed along it at a
// speed v, frictionless. Under the block the contact pressure is p and the
// sliding speed v, so a die vertex covered by the block for the whole run
// wears w = K p^a v^b / H^c × T exactly; a vertex the block never reaches
// does not wear.
#include "run_outputs.h"

#include "anvil/core/Timers.h"
#include "anvil/scene/Scene.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPressure = 10.0, kSpeed = 10.0, kTime = 0.5;   // MPa, mm/s, s
constexpr double kCoefficient = 1e-3, kHardness = 50.0;          // K, HRC (a = b = 1, c = 2)
constexpr double kLength = 20.0, kWidth = 10.0, kElement = 1.25; // mm

/// The block's entry of `bodies` (its card written beside the case files):
/// a Newtonian block 1e4 times stiffer than the reference fluid, which under
/// 10 MPa creeps at 3e-4 1/s, so it slides as a rigid block.
std::string block_body() {
  std::ofstream(std::filesystem::temp_directory_path() / "anvil_stiff_block.yaml")
      << "format: 1\nname: stiff Newtonian block\nlaw: newtonian\nviscosity: 1.0e4\n"
         "sources:\n  viscosity: \"test value: 10 MPa hardly squeezes the block\"\n";
  return "  - name: block\n"
         "    material: anvil_stiff_block.yaml\n"
         "    mesh: {generate: box, size: [20, 10, 5], element_size: " +
         std::to_string(kElement) + "}\n";
}

std::string sliding_block_case() {
  const std::string path = (std::filesystem::temp_directory_path() / "anvil_die_wear_case.yaml").string();
  std::ofstream(path) << "anvil: 1\n"
                         "title: a block sliding on a worn plate\n"
                         "bodies:\n"
                      << block_body()
                      << "boundary:\n"
                         "  - {name: push, type: pressure, tag: 6, pressure: "
                      << kPressure << "}\n"
                      << "  - {name: pusher, type: velocity, tag: 1, velocity: [" << kSpeed << ", ~, ~]}\n"
                      << "  - {name: wall, type: symmetry, tag: 3}\n"
                         "dies:\n"
                         "  - name: plate\n"
                         "    plane: {point: [0, 0, 0], normal: [0, 0, 1], half_size: 30}\n"
                         "    friction: {law: frictionless}\n"
                         "    wear: {coefficient: "
                      << kCoefficient << ", hardness: " << kHardness << "}\n"
                      << "time:\n  stroke_increment: 0.25\n  stop: {time: " << kTime << "}\n";
  return path;
}

/// The worn points of a run against the exact answer: those under the block
/// from start to end (an element's width in from its sides) against
/// K p v / H² × T, and those it never reached (more than an element beyond
/// where it swept), which must not wear.
struct WearCheck {
  double exact = kCoefficient * kPressure * kSpeed / (kHardness * kHardness) * kTime;
  double worst = 0.0, largest = 0.0, outside = 0.0; ///< relative error; mm; mm
  int covered = 0;

  void add(const anvil::mesh::Point& x, double w) {
    const double travel = kSpeed * kTime;
    largest = std::max(largest, w);
    if (x.x() > travel + kElement && x.x() < kLength - kElement && x.y() > kElement && x.y() < kWidth - kElement) {
      worst = std::max(worst, std::abs(w / exact - 1.0));
      ++covered;
    }
    if (x.x() < -kElement || x.x() > kLength + travel + kElement || x.y() < -kElement || x.y() > kWidth + kElement)
      outside = std::max(outside, w);
  }
  std::string text() const {
    return "exact " + std::to_string(exact) + " mm; " + std::to_string(covered) +
           " covered throughout, largest relative error " + std::to_string(worst) + "; largest wear " +
           std::to_string(largest) + " mm, off the swept band " + std::to_string(outside) + " mm";
  }
};

} // namespace

TEST_CASE("a block sliding on a plate wears it by the Archard law exactly", "[verification]") {
  const RunOutputs out = run_case(anvil::scene::read_case(sliding_block_case()), "anvil_die_wear");
  const anvil::scene::RunState end = out.final_state();
  REQUIRE(end.wear.size() == 1);
  // The plate's vertices as the scene samples a worn die.
  anvil::Timers timers;
  const anvil::scene::Scene scene(anvil::scene::read_case(sliding_block_case()), timers);
  const std::vector<anvil::mesh::Point>& vertices = scene.dies[0].shown().vertices;
  REQUIRE(end.wear[0].size() == vertices.size());
  WearCheck check;
  for (std::size_t v = 0; v < vertices.size(); ++v)
    check.add(vertices[v], end.wear[0][v]);
  INFO(check.text());
  REQUIRE(check.covered > 20);
  // The contact pressure is p to the penalty's and the creep's share of it
  // (measured: the covered vertices within 0.3 %), the sliding speed v to the creep's
  // 1e-4: 1 % holds both with room.
  CHECK(check.worst < 0.01);
  CHECK(check.largest < 1.01 * check.exact);
  CHECK(check.outside == 0.0);
  CHECK(out.summary_number("max_mm") == Approx(check.largest).epsilon(1e-9));
}

TEST_CASE("a block sliding on a meshed elastic plate wears its nodes by the Archard law", "[verification]") {
  // The same block on an elastic plate (a meshed die, quasi-symmetric
  // contact pair, frictionless) clamped at its base: under the block the
  // pair carries p, the block slides at v, so a plate node covered
  // throughout wears K p v / H² × T. The plate is a thousand times stiffer
  // than steel: on a plate as compliant as the block, the block would press
  // as a flat punch on an elastic layer, its pressure rising towards its
  // edges (measured on steel: 6 % low one element in from the sides).
  const auto folder = std::filesystem::temp_directory_path();
  std::ofstream(folder / "anvil_stiff_plate.yaml")
      << "format: 1\nname: a plate a thousand times stiffer than steel\nlaw: linear_elastic\n"
         "young_modulus: 2.1e8\npoisson_ratio: 0.3\n"
         "sources:\n  young_modulus: \"test value\"\n  poisson_ratio: \"test value\"\n";
  const std::string path = (folder / "anvil_body_wear_case.yaml").string();
  std::ofstream(path) << "anvil: 1\n"
                         "title: a block sliding on a worn elastic plate\n"
                         "bodies:\n"
                      << block_body()
                      << "  - name: plate\n"
                         "    material: anvil_stiff_plate.yaml\n"
                         "    mesh: {generate: box, origin: [-5, -5, -4], size: [40, 20, 4], element_size: "
                      << kElement << "}\n"
                      << "    wear: {coefficient: " << kCoefficient << ", hardness: " << kHardness << "}\n"
                      << "boundary:\n"
                         "  - {name: push, body: block, type: pressure, tag: 6, pressure: "
                      << kPressure << "}\n"
                      << "  - {name: pusher, body: block, type: velocity, tag: 1, velocity: [" << kSpeed << ", ~, ~]}\n"
                      << "  - {name: wall, body: block, type: symmetry, tag: 3}\n"
                         "  - {name: clamp, body: plate, type: velocity, tag: 5, velocity: [0, 0, 0]}\n"
                         "contact_pairs:\n"
                         "  - {master: plate, slave: block, friction: {law: frictionless}}\n"
                         "time:\n  stroke_increment: 0.25\n  stop: {time: "
                      << kTime << "}\n";
  const RunOutputs out = run_case(anvil::scene::read_case(path), "anvil_body_wear");
  const anvil::scene::RunState end = out.final_state();
  REQUIRE(end.body_wear.size() == 2);
  REQUIRE(end.body_wear[0].empty());
  const anvil::mesh::MeshRange& plate = end.bodies[1];
  REQUIRE(end.body_wear[1].size() == static_cast<std::size_t>(plate.node_count));
  WearCheck check; // the plate's top face (its nodes below it never touch)
  for (int i = 0; i < plate.node_count; ++i)
    if (const anvil::mesh::Point& x = end.mesh.nodes[plate.first_node + i]; x.z() > -0.1)
      check.add(x, end.body_wear[1][i]);
  INFO(check.text());
  REQUIRE(check.covered > 20);
  CHECK(check.worst < 0.01); // measured: 0.09 %
  CHECK(check.outside == 0.0);
  // Below the top face nothing touches: nothing wears.
  for (int i = 0; i < plate.node_count; ++i)
    if (end.mesh.nodes[plate.first_node + i].z() < -0.1) CHECK(end.body_wear[1][i] == 0.0);
}
