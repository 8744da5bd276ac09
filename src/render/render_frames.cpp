#include "render_frames.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace anvil::render {
namespace {

std::shared_ptr<const RunLoads> read_run_loads(const std::string& directory) {
  auto loads = std::make_shared<RunLoads>();
  if (!std::filesystem::exists(directory + "/loads.csv")) return loads;
  const std::vector<std::string> surfaces = io::read_load_surfaces(directory);
  if (surfaces.empty()) return loads;
  loads->surface = surfaces.front();
  loads->rows = io::read_loads(directory, loads->surface);
  return loads;
}

} // namespace

std::vector<Shot> spread_frames(const std::string& directory, int count) {
  const std::vector<io::SeriesEntry> series = io::read_series(directory);
  const std::shared_ptr<const RunLoads> loads = read_run_loads(directory);
  count = std::min<int>(count, int(series.size()));
  std::vector<Shot> shots;
  for (int k = 0; k < count; ++k)
    shots.push_back({series[count == 1 ? series.size() - 1 : k * (series.size() - 1) / (count - 1)], loads});
  return shots;
}

std::vector<Shot> operation_ends(const std::string& directory) {
  std::vector<std::filesystem::path> folders;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
        std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '-' &&
        std::filesystem::exists(entry.path() / "anvil.pvd"))
      folders.push_back(entry.path());
  }
  if (folders.empty())
    throw std::runtime_error(directory + " holds no operation (NN-name folders): not a chain's folder");
  std::sort(folders.begin(), folders.end());
  std::vector<Shot> shots;
  for (const std::filesystem::path& folder : folders) {
    io::SeriesEntry last = io::read_series(folder.string()).back();
    for (std::string& part : last.parts)
      part = (folder.filename() / part).string();
    shots.push_back({last, read_run_loads(folder.string())});
  }
  return shots;
}

} // namespace anvil::render
