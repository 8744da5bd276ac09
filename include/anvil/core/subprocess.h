// External programs (ImageMagick, ffmpeg, gnuplot, xvfb-run) started with an
// argument vector and never through a shell: a file or folder name is one
// argument whatever characters it holds, and nothing in it is ever run.
#pragma once
#include <string>
#include <vector>

namespace anvil::subprocess {

struct Options {
  std::string directory;    ///< working directory of the program; empty: ours
  std::string input;        ///< written to its standard input, then closed
  bool quiet_output = true; ///< standard output to /dev/null
  bool quiet_errors = true; ///< standard error to /dev/null
};

/// Runs `arguments` (arguments[0] looked up on PATH) and waits for it.
/// Returns its exit status, or -1 when it could not be started or was killed
/// by a signal.
int run(const std::vector<std::string>& arguments, const Options& options = {});

/// True when `program` is an executable file on PATH.
bool on_path(const std::string& program);

} // namespace anvil::subprocess
