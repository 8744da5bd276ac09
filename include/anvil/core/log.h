// Run log: one sink (stdout, optionally mirrored to a file in the output
// directory). Plain printf-style formatting keeps hot code free of streams.
// With several processes (mpirun) rank 0 alone logs.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace anvil::log {

/// Mirror every line into `path` (the run's log file) from now on.
void open_file(const std::string& path, bool append = false);
void close_file();
/// Silence the terminal (tests); the file mirror, if open, still receives lines.
void set_quiet(bool quiet);
/// Show detail lines on the terminal too (`anvil run --verbose`).
void set_verbose(bool verbose);

/// A line for the terminal and the file.
void info(const char* format, ...) __attribute__((format(printf, 1, 2)));
/// A line for the file, and for the terminal only when verbose (Newton
/// iterations, per-increment mesh quality).
void detail(const char* format, ...) __attribute__((format(printf, 1, 2)));

/// A line held back (Holding) and whether it goes to the terminal.
struct HeldLine {
  bool terminal = true;
  std::string text;
};

/// While alive, the lines the constructing thread logs go into `into`
/// instead of out: tasks run side by side write their lines afterwards, one
/// task after the other (write_held), in the same order on any number of
/// threads.
class Holding {
public:
  explicit Holding(std::vector<HeldLine>& into);
  ~Holding();
  Holding(const Holding&) = delete;
  Holding& operator=(const Holding&) = delete;

private:
  std::vector<HeldLine>* before_;
};

/// Writes lines a Holding held.
void write_held(const std::vector<HeldLine>& lines);

} // namespace anvil::log
