// Flow lines (effect flow_lines) through remeshes: a block compressed
// between frictionless plates (velocity conditions, no contact penalty) flows
// homogeneously, exactly on P1 elements: the material that started at
// (X, Y, Z) is at (a X, a Y, Z h/h0) (the lower plate at z = 0; a close to
// √(h0/h), what the explicit update and the volume compensation make of
// it), so the planes of material stay planes at exactly scaled heights.
// Remeshed every 3 increments, the new nodes take the material positions by
// linear interpolation (extended linearly to a new surface node off the old
// surface), exact for this linear map: every node's carried start must fit
// it to round-off (1e-9 of the height). anvil render --flow-lines draws
// them.
#include "run_outputs.h"

#include "anvil/core/subprocess.h"

#include <cmath>

TEST_CASE("flow lines: the planes of material of a homogeneous compression, through remeshes", "[regression]") {
  const std::string path = homogeneous_compression_case(
      "anvil_flow_lines_case", 1.5, 0.4, "remeshing: {every: 3}\noutput: {flow_lines: {axis: z, count: 6}}\n");
  const RunOutputs out = run_case(anvil::scene::read_case(path), "anvil_flow_lines");
  const anvil::scene::RunState end = out.final_state();
  REQUIRE(end.material_position.size() == 3 * end.mesh.nodes.size());
  REQUIRE(!end.remeshes.empty());
  const double h0 = 10.0, h = h0 - 10.0 * end.time;
  // The lateral factor, by least squares over the nodes: Σ X x / Σ x².
  double xx = 0.0, xX = 0.0;
  for (int i = 0; i < end.mesh.node_count(); ++i)
    for (int k = 0; k < 2; ++k)
      xx += end.mesh.nodes[i][k] * end.mesh.nodes[i][k], xX += end.mesh.nodes[i][k] * end.material_position[3 * i + k];
  const double lateral = xX / xx;
  double worst = 0.0;
  for (int i = 0; i < end.mesh.node_count(); ++i) {
    const anvil::mesh::Point& x = end.mesh.nodes[i];
    const double* started = &end.material_position[3 * i];
    worst = std::max({worst, std::abs(started[0] - lateral * x.x()), std::abs(started[1] - lateral * x.y()),
                      std::abs(started[2] - x.z() * h0 / h)});
  }
  INFO(end.remeshes.size() << " remeshes, t = " << end.time << " s; a = " << 1.0 / lateral
                           << " (√(h0/h) = " << std::sqrt(h0 / h) << "); worst departure " << worst << " mm");
  CHECK(worst <= 1e-9 * h0);
  const std::vector<std::string> command = {ANVIL_EXECUTABLE, "render", out.directory,
                                            "--flow-lines",   "--out",  out.directory + "/flow_lines.png"};
  CHECK(anvil::subprocess::run(command) == 0);
  CHECK(std::filesystem::exists(out.directory + "/flow_lines.png"));
}
