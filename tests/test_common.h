// The one place that includes Catch2 (v2 on bookworm; v3 renames the header).
#pragma once
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

/// Absolute path of a file in the source tree.
inline std::string source_path(const std::string& relative) {
  return std::string(ANVIL_SOURCE_DIR) + "/" + relative;
}

/// The whole text of a file (empty when it cannot be read).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
