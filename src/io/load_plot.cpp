#include "anvil/io/load_plot.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace anvil::io {

std::string write_load_plot(const std::string& directory, const std::string& title,
                            const std::vector<std::string>& surfaces, const std::vector<scene::LoadRecord>& loads) {
  if (loads.empty()) return "no load was recorded";
  std::map<int, double> press; // increment → press stroke
  for (const scene::LoadRecord& r : loads)
    press[r.increment] = std::max(press[r.increment], r.stroke);
  // One data block per surface (gnuplot's "index"), stroke and press load in kN.
  const std::string data = directory + "/loads.png.dat", png = directory + "/loads.png";
  {
    std::ofstream out(data);
    out.precision(10);
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
      for (const scene::LoadRecord& r : loads)
        if (r.surface == static_cast<int>(s)) out << press[r.increment] << " " << r.press_load() / 1e3 << "\n";
      out << "\n\n";
    }
    if (!out) return "cannot write " + data;
  }
  std::ostringstream script;
  script << "set terminal pngcairo size 900,600 noenhanced\nset output '" << png << ".tmp'\n"
         << "set title 'Press load against stroke: " << title << "'\nset xlabel 'press stroke (mm)'\n"
         << "set ylabel 'press load Fz (kN)'\nset grid\nset key top left\nplot ";
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    script << (s ? ", " : "") << "'" << data << "' index " << s << " using 1:2 with linespoints pointsize 0.5 title '"
           << surfaces[s] << "'";
  script << "\n";
  std::FILE* gnuplot = popen("gnuplot 2>/dev/null", "w");
  const bool sent = gnuplot && std::fputs(script.str().c_str(), gnuplot) >= 0;
  const int status = gnuplot ? pclose(gnuplot) : -1;
  std::filesystem::remove(data);
  if (!sent || status != 0) {
    std::filesystem::remove(png + ".tmp");
    return "gnuplot is not installed or failed (tools/setup installs gnuplot-nox)";
  }
  std::filesystem::rename(png + ".tmp", png);
  return "";
}

} // namespace anvil::io
