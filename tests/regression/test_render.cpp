// Quick-look pictures (anvil render): a hot upsetting run rendered headless
// gives a PNG of the expected size, not one flat colour, with the part in
// the colours of its field and the dies in grey; an animated GIF and a
// contact sheet of three frames. The run's folder has a hostile name (quotes,
// a semicolon, spaces, $(), a newline): the external programs get it as one
// argument, never through a shell, and nothing but the pictures appears.
#include "run_outputs.h"

#include "anvil/core/log.h"
#include "anvil/core/subprocess.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <cstdlib>
#include <fstream>
#include <set>

TEST_CASE("anvil render draws a run's final state: the part in its field's colours, the dies in grey", "[regression]") {
  anvil::log::set_quiet(true);
  const RunOutputs out = run_case(
      anvil::scene::read_case(source_path("cases/hot_upsetting.yaml"),
                              {"bodies[0].mesh.element_size=2", "time.stop.stroke=2", "thermal.transfer_time=0.5"}),
      "anvil_render_test x';touch INJECTED;' $(touch INJECTED) \"q\"\nline");
  const std::vector<std::string> command = {ANVIL_EXECUTABLE, "render", out.directory, "--field", "temperature"};
  REQUIRE(anvil::subprocess::run(command) == 0);
  const std::string png = out.directory + "/render/temperature_000014.png";
  REQUIRE(std::filesystem::exists(png));
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(png.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int size[3];
  image->GetDimensions(size);
  CHECK(size[0] == 1000);
  CHECK(size[1] == 750);
  std::set<int> colours;
  int grey = 0, saturated = 0;
  for (int y = 0; y < size[1]; ++y)
    for (int x = 0; x < size[0]; ++x) {
      const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
      const int high = std::max({p[0], p[1], p[2]}), low = std::min({p[0], p[1], p[2]});
      if (high - low < 12 && high < 235 && high > 60) ++grey; // a die over the white background
      if (high - low > 100) ++saturated;                      // the part in its colour map
    }
  INFO(colours.size() << " colours, " << grey << " grey pixels, " << saturated << " saturated");
  CHECK(colours.size() > 100);
  CHECK(grey > 0.02 * size[0] * size[1]);
  CHECK(saturated > 0.05 * size[0] * size[1]);

  // Three frames: an animated GIF of them and a contact sheet, two half-size
  // frames to a row (two rows: 1000 × 750).
  std::vector<std::string> frames = command;
  frames.insert(frames.end(), {"--frames", "3", "--sheet"});
  REQUIRE(anvil::subprocess::run(frames) == 0);
  std::ifstream gif(out.directory + "/render/temperature.gif", std::ios::binary);
  std::string header(6, '\0');
  gif.read(header.data(), 6);
  CHECK(header == "GIF89a");
  CHECK(std::filesystem::file_size(out.directory + "/render/temperature.gif") > 10000);
  vtkNew<vtkPNGReader> sheet;
  sheet->SetFileName((out.directory + "/render/temperature_sheet.png").c_str());
  sheet->Update();
  sheet->GetOutput()->GetDimensions(size);
  CHECK(size[0] == 1000);
  CHECK(size[1] == 750);
  // With ffmpeg installed (tools/setup does not), an MP4 too: an ISO media
  // file ("ftyp" box at byte 4) of some size; no partial file left behind.
  const bool ffmpeg = anvil::subprocess::on_path("ffmpeg");
  if (ffmpeg) {
    std::ifstream mp4(out.directory + "/render/temperature.mp4", std::ios::binary);
    std::string box(8, '\0');
    mp4.read(box.data(), 8);
    CHECK(box.substr(4) == "ftyp");
    CHECK(std::filesystem::file_size(out.directory + "/render/temperature.mp4") > 10000);
  }
  CHECK_FALSE(std::filesystem::exists(out.directory + "/render/temperature.mp4.part"));
  CHECK_FALSE(std::filesystem::exists(out.directory + "/render/temperature.gif.part"));

  // Nothing but the pictures: no file a shell would have made, no leftovers.
  std::set<std::string> made, expected = {"temperature_000001.png", "temperature_000007.png", "temperature_000014.png",
                                          "temperature_sheet.png", "temperature.gif"};
  if (ffmpeg) expected.insert("temperature.mp4");
  for (const auto& entry : std::filesystem::directory_iterator(out.directory + "/render"))
    made.insert(entry.path().filename().string());
  CHECK(made == expected);
  for (const std::filesystem::path& folder :
       {std::filesystem::current_path(), std::filesystem::temp_directory_path(), std::filesystem::path(out.directory)})
    CHECK_FALSE(std::filesystem::exists(folder / "INJECTED"));
}
