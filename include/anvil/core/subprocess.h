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
  std::string errors_file;  ///< standard error to this file instead (made anew); empty: as quiet_errors says
};

/// execve's argv over `arguments` (which must outlive it), null-terminated.
std::vector<char*> argument_vector(std::vector<std::string>& arguments);

/// Runs `arguments` (arguments[0] looked up on PATH) and waits for it.
/// Returns its exit status, or -1 when it could not be started or was killed
/// by a signal.
int run(const std::vector<std::string>& arguments, const Options& options = {});

/// Runs `arguments` in a session of its own (the terminal's Ctrl-C reaches
/// this process alone) and waits for it, relaying interrupts: the first
/// SIGINT or SIGTERM here reaches it as SIGUSR1 (a run started under mpirun
/// stops at its next safe point and checkpoints, see interrupt.h: mpirun
/// passes SIGUSR1 on, where its own SIGTERM would kill the processes a
/// second later), a second one as SIGTERM. Returns its exit status (128 +
/// the signal received here when it stopped for the SIGUSR1 passed on, as
/// if it had received that signal), 128 + the signal that killed it, or -1
/// when it could not be started.
int run_relaying_interrupts(const std::vector<std::string>& arguments);

/// The path of `program` in the folder of the running program: build/ holds
/// anvil, anvil_render and the tools side by side.
std::string beside_this_program(const std::string& program);

/// True when `program` is an executable file on PATH.
bool on_path(const std::string& program);

} // namespace anvil::subprocess
