#include "anvil/io/load_plot.h"

#include "anvil/core/subprocess.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace anvil::io {
namespace {

/// `text` as a single-quoted gnuplot string: a quote doubled, control
/// characters (a newline would end the command) as spaces.
std::string gnuplot_quoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text)
    if (c == '\'')
      quoted += "''";
    else
      quoted += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  return quoted + "'";
}

} // namespace

std::string write_load_plot(const std::string& directory, const std::string& title,
                            const std::vector<std::string>& surfaces, const std::vector<scene::LoadRecord>& loads,
                            int copies) {
  if (loads.empty()) return "no load was recorded";
  std::map<int, double> press; // increment → press stroke
  for (const scene::LoadRecord& r : loads)
    press[r.increment] = std::max(press[r.increment], r.stroke);
  // One data block per surface (gnuplot's "index"), stroke and press load in kN.
  // gnuplot runs in `directory` and reads and writes bare file names there: no
  // folder name enters its script.
  const std::string data_name = "loads.png.dat", png_name = "loads.png";
  const std::string data = directory + "/" + data_name, png = directory + "/" + png_name;
  {
    std::ofstream out(data);
    out.precision(10);
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
      for (const scene::LoadRecord& r : loads)
        if (r.surface == static_cast<int>(s)) out << press[r.increment] << " " << copies * r.press_load() / 1e3 << "\n";
      out << "\n\n";
    }
    if (!out) return "cannot write " + data;
  }
  std::ostringstream script;
  script << "set terminal pngcairo size 900,600 noenhanced\nset output '" << png_name << ".tmp'\n"
         << "set title " << gnuplot_quoted("Press load against stroke: " + title)
         << "\nset xlabel 'press stroke (mm)'\n"
         << "set ylabel "
         << gnuplot_quoted(copies > 1 ? "press load Fz of the whole part (kN): " + std::to_string(copies) +
                                            " x the symmetry model's"
                                      : "press load Fz (kN)")
         << "\nset grid\nset key top left\nplot ";
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    script << (s ? ", " : "") << "'" << data_name << "' index " << s
           << " using 1:2 with linespoints pointsize 0.5 title " << gnuplot_quoted(surfaces[s]);
  script << "\n";
  subprocess::Options options;
  options.directory = directory;
  options.input = script.str();
  const int status = subprocess::run({"gnuplot"}, options);
  std::filesystem::remove(data);
  if (status != 0) {
    std::filesystem::remove(png + ".tmp");
    return "gnuplot is not installed or failed (tools/setup installs gnuplot-nox)";
  }
  std::filesystem::rename(png + ".tmp", png);
  return "";
}

} // namespace anvil::io
