#include "anvil/scene/fingerprint.h"

#include "anvil/core/error.h"

#include "checked_yaml.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

namespace anvil::scene {
namespace {

/// Keys a resumed run may change without a word: they stop, show or solve
/// the same problem differently, not another problem.
bool free_to_change(const std::string& key) {
  if (key.rfind("output.flow_lines", 0) == 0) return false; // the checkpoint carries them or not
  for (const char* prefix :
       {"title", "output.", "damage.progress", "time.stop.", "time.max_increments", "solver.linear_solver",
        "solver.schur", "solver.krylov_tolerance", "solver.reuse_preconditioner", "solver.petsc_options"})
    if (key.rfind(prefix, 0) == 0) return true;
  // A die's fill is measured, not solved for.
  const auto fill = key.find("].fill");
  return key.rfind("dies[", 0) == 0 && fill != std::string::npos && key.find('.') == fill + 1;
}

/// FNV-1a hash of a file's bytes, as 16 hex digits.
std::string contents_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the file");
  std::uint64_t h = 1469598103934665603ull;
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it)
    h = (h ^ static_cast<unsigned char>(*it)) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

/// Splits "key = value".
std::pair<std::string, std::string> key_value(const std::string& line) {
  const auto at = line.find(" = ");
  return at == std::string::npos ? std::pair{line, std::string()} : std::pair{line.substr(0, at), line.substr(at + 3)};
}

} // namespace

std::vector<std::string> case_fingerprint(const Case& c) {
  std::vector<std::string> lines;
  for (const std::string& line : c.settings)
    if (!free_to_change(key_value(line).first)) lines.push_back(line);
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const std::string body = "bodies[" + std::to_string(b) + "]";
    const std::string card = std::filesystem::path(c.bodies[b].material_file).filename().string();
    std::vector<std::string> card_lines;
    try {
      card_lines = flatten(YAML::LoadFile(c.bodies[b].material_file));
    } catch (const YAML::Exception& e) {
      throw InputError(c.bodies[b].material_file + ": cannot read the material card again: " + e.msg);
    }
    for (const std::string& line : card_lines)
      if (line.rfind("sources.", 0) != 0) lines.push_back(body + ".material (" + card + "): " + line);
    if (!c.bodies[b].mesh.file.empty())
      lines.push_back(body + ".mesh.file contents = " + contents_hash(c.bodies[b].mesh.file));
  }
  for (std::size_t d = 0; d < c.dies.size(); ++d)
    if (!c.dies[d].stl_file.empty())
      lines.push_back("dies[" + std::to_string(d) + "].stl contents = " + contents_hash(c.dies[d].stl_file));
  return lines;
}

std::vector<std::string> fingerprint_changes(const std::vector<std::string>& before,
                                             const std::vector<std::string>& now) {
  std::map<std::string, std::pair<std::string, std::string>> values; // key -> (before, now)
  const std::string absent = "(absent)";
  for (const std::string& line : before) {
    const auto [key, value] = key_value(line);
    values[key] = {value, absent};
  }
  for (const std::string& line : now) {
    const auto [key, value] = key_value(line);
    auto [it, inserted] = values.try_emplace(key, absent, value);
    if (!inserted) it->second.second = value;
  }
  std::vector<std::string> changes;
  for (const auto& [key, pair] : values)
    if (pair.first != pair.second)
      changes.push_back(key.size() > 9 && key.compare(key.size() - 9, 9, " contents") == 0
                            ? key.substr(0, key.size() - 9) + ": the file's contents changed"
                            : key + ": " + pair.first + " -> " + pair.second);
  return changes;
}

} // namespace anvil::scene
