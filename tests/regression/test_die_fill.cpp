// Die fill (effect die_fill) in a run: a quarter cylinder upset without
// friction between flat dies, the upper die asking for its fill. The fill
// is measured, not solved for: the loads are those of the run without it.
// A frictionless upsetting keeps the billet a prism, so the area of its top
// face is V / h exactly; the die touches that face and a band around its rim
// as wide as the tolerance, up to the sampling's error (the rim's length
// times a sample triangle's diameter). A resumed run writes the same fill.
// anvil render draws the dies in the underfill's colours.
#include "run_outputs.h"

#include "anvil/core/subprocess.h"
#include "anvil/mesh/TetMesh.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

anvil::scene::Case upsetting(bool fill, int checkpoint_every = 10) {
  const std::string path = (std::filesystem::temp_directory_path() / "anvil_die_fill_case.yaml").string();
  std::ofstream(path) << "anvil: 1\n"
                         "title: die fill of a frictionless upsetting\n"
                         "bodies:\n"
                         "  - name: billet\n"
                         "    material: "
                      << source_path("materials/steel_c45_1100C.yaml")
                      << "\n"
                         "    mesh: {generate: quarter_cylinder, radius: 5, height: 7.5, element_size: 0.75}\n"
                         "boundary:\n"
                         "  - {name: symmetry_x, type: symmetry, tag: 1}\n"
                         "  - {name: symmetry_y, type: symmetry, tag: 3}\n"
                         "dies:\n"
                         "  - name: top\n"
                         "    plane: {point: [0, 0, 7.5], normal: [0, 0, -1], half_size: 8}\n"
                         "    motion: constant\n"
                         "    velocity: [0, 0, -10]\n"
                      << (fill ? "    fill: {tolerance: 0.01}\n" : "")
                      << "  - name: bottom\n"
                         "    plane: {point: [0, 0, 0], normal: [0, 0, 1]}\n"
                         "time:\n"
                         "  stroke_increment: 0.5\n"
                         "  stop: {stroke: 2}\n"
                         "output: {checkpoint_every: "
                      << checkpoint_every << "}\n";
  return anvil::scene::read_case(path);
}

} // namespace

TEST_CASE("die fill: measured each increment, the loads unchanged, the top face's area, kept on resume",
          "[regression]") {
  const anvil::scene::Case with = upsetting(true), without = upsetting(false);
  const RunOutputs filled = run_case(with, "anvil_die_fill"), plain = run_case(without, "anvil_die_fill_plain");
  const std::vector<LoadRow> top = filled.loads("top"), bottom = filled.loads("bottom");
  const std::vector<LoadRow> top_plain = plain.loads("top");
  REQUIRE(top.size() == top_plain.size());
  for (std::size_t i = 0; i < top.size(); ++i) {
    CHECK(top[i].force == top_plain[i].force); // bit for bit: nothing solved differs
    CHECK(std::isfinite(top[i].contact_area));
    CHECK(top[i].fill >= 0.0);
    CHECK(top[i].fill <= 1.0);
    CHECK(std::isnan(bottom[i].contact_area)); // it did not ask
    CHECK(std::isnan(top_plain[i].contact_area));
  }
  // The last row: the final geometry, h = 7.5 − 2 mm.
  const anvil::scene::RunState end = filled.final_state();
  const double volume = anvil::mesh::volume(end.mesh), height = 5.5;
  const double face = volume / height, radius = std::sqrt(4.0 * face / std::acos(-1.0));
  const double rim = std::acos(-1.0) * radius / 2.0; // the quarter's arc; the straight edges lie on the planes
  const double spacing = 0.5 * 0.75;                 // half the mesh's mean boundary edge, about
  const double diameter = 2.0 * spacing;             // a sample triangle's, at most (twice its edge: generous)
  CHECK(std::abs(top.back().contact_area - (face + rim * 0.01)) <= rim * diameter);
  CHECK(filled.summary_number("contact_area_model_mm2") == Approx(top.back().contact_area).epsilon(1e-9));

  // The picture: the top die in the underfill's colours (saturated pixels);
  // the run without fill has no such field.
  const std::string png = filled.directory + "/underfill.png";
  REQUIRE(anvil::subprocess::run({ANVIL_EXECUTABLE, "render", filled.directory, "--field", "underfill", "--range", "0",
                                  "2", "--out", png}) == 0);
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(png.c_str());
  reader->Update();
  int size[3];
  reader->GetOutput()->GetDimensions(size);
  int saturated = 0;
  for (int y = 0; y < size[1]; ++y)
    for (int x = 0; x < size[0]; ++x) {
      const auto* p = static_cast<unsigned char*>(reader->GetOutput()->GetScalarPointer(x, y, 0));
      saturated += std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) > 100;
    }
  CHECK(saturated > 0.02 * size[0] * size[1]);
  CHECK(anvil::subprocess::run({ANVIL_EXECUTABLE, "render", plain.directory, "--field", "underfill", "--out",
                                plain.directory + "/underfill.png"}) == 1);

  // Stopped after 4 increments (a run cut short keeps its steps) and
  // resumed from its checkpoint: the same rows, fill included.
  const anvil::scene::Case chunked = upsetting(true, 2);
  const RunOutputs whole = run_case(chunked, "anvil_die_fill_chunked");
  const auto dir = std::filesystem::temp_directory_path() / "anvil_die_fill_resumed";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    anvil::scene::Case first = chunked;
    first.time.max_increments = 4;
    first.time.max_increments_given = true;
    anvil::run::run(first, {dir.string()});
  }
  anvil::run::run(chunked, {dir.string(), true});
  const std::vector<LoadRow> resumed = anvil::io::read_loads(dir.string(), "top"), straight = whole.loads("top");
  REQUIRE(resumed.size() == straight.size());
  for (std::size_t i = 0; i < resumed.size(); ++i) {
    CHECK(resumed[i].contact_area == straight[i].contact_area);
    CHECK(resumed[i].fill == straight[i].fill);
  }
}
