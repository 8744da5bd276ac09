#include "anvil/core/log.h"

#include "anvil/core/processes.h"

#include <cstdarg>

namespace anvil::log {
namespace {
std::FILE* mirror = nullptr;
bool quiet_terminal = false;
bool verbose_terminal = false;
/// This thread's Holding target, if any.
thread_local std::vector<HeldLine>* held = nullptr;

void write_line(bool to_terminal, const char* line) {
  if (to_terminal && !quiet_terminal) {
    std::fputs(line, stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
  }
  if (mirror) {
    std::fputs(line, mirror);
    std::fputc('\n', mirror);
  }
}

void write(bool to_terminal, const char* format, va_list args) {
  if (!processes::root()) return; // one log per run: rank 0's
  char line[2048];
  std::vsnprintf(line, sizeof line, format, args);
  if (held)
    held->push_back({to_terminal, line});
  else
    write_line(to_terminal, line);
}

} // namespace

void open_file(const std::string& path, bool append) {
  close_file();
  if (!processes::root()) return;
  mirror = std::fopen(path.c_str(), append ? "a" : "w");
}

void close_file() {
  if (mirror) std::fclose(mirror);
  mirror = nullptr;
}

void set_quiet(bool quiet) {
  quiet_terminal = quiet;
}

void set_verbose(bool verbose) {
  verbose_terminal = verbose;
}

void info(const char* format, ...) {
  va_list args;
  va_start(args, format);
  write(true, format, args);
  va_end(args);
}

void detail(const char* format, ...) {
  va_list args;
  va_start(args, format);
  write(verbose_terminal, format, args);
  va_end(args);
}

Holding::Holding(std::vector<HeldLine>& into) : before_(held) {
  held = &into;
}

Holding::~Holding() {
  held = before_;
}

void write_held(const std::vector<HeldLine>& lines) {
  for (const HeldLine& line : lines)
    write_line(line.terminal, line.text.c_str());
}

} // namespace anvil::log
