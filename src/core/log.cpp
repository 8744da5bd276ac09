#include "anvil/core/log.h"

#include <cstdarg>

namespace anvil::log {
namespace {
std::FILE* mirror = nullptr;
bool quiet_terminal = false;
} // namespace

void open_file(const std::string& path, bool append) {
  close_file();
  mirror = std::fopen(path.c_str(), append ? "a" : "w");
}

void close_file() {
  if (mirror) std::fclose(mirror);
  mirror = nullptr;
}

void set_quiet(bool quiet) { quiet_terminal = quiet; }

void info(const char* format, ...) {
  char line[2048];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  if (!quiet_terminal) {
    std::fputs(line, stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
  }
  if (mirror) {
    std::fputs(line, mirror);
    std::fputc('\n', mirror);
  }
}

} // namespace anvil::log
