#include "anvil/core/subprocess.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace anvil::subprocess {

std::vector<char*> argument_vector(std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (std::string& a : arguments)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  return argv;
}

int run(const std::vector<std::string>& arguments, const Options& options) {
  if (arguments.empty()) return -1;
  std::vector<std::string> copy = arguments;
  const std::vector<char*> argv = argument_vector(copy);

  int pipe_ends[2] = {-1, -1};
  const bool feed = !options.input.empty();
  if (feed && pipe2(pipe_ends, O_CLOEXEC) != 0) return -1;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (feed) posix_spawn_file_actions_adddup2(&actions, pipe_ends[0], 0);
  if (options.quiet_output) posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  if (!options.errors_file.empty())
    posix_spawn_file_actions_addopen(&actions, 2, options.errors_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  else if (options.quiet_errors)
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  if (!options.directory.empty()) posix_spawn_file_actions_addchdir_np(&actions, options.directory.c_str());
  pid_t child = 0;
  const int started = posix_spawnp(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (feed) {
    close(pipe_ends[0]);
    if (started == 0) {
      // A program that stops reading early must not kill us with SIGPIPE.
      struct sigaction ignore = {}, previous = {};
      ignore.sa_handler = SIG_IGN;
      sigaction(SIGPIPE, &ignore, &previous);
      const char* data = options.input.data();
      std::size_t left = options.input.size();
      while (left > 0) {
        const ssize_t n = write(pipe_ends[1], data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        data += n, left -= static_cast<std::size_t>(n);
      }
      sigaction(SIGPIPE, &previous, nullptr);
    }
    close(pipe_ends[1]);
  }
  if (started != 0) return -1;
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

namespace {
volatile sig_atomic_t relay_child = 0, relayed = 0;
void relay(int signal) {
  if (relay_child <= 0) return;
  kill(relay_child, relayed ? SIGTERM : SIGUSR1);
  if (!relayed) relayed = signal;
}
} // namespace

int run_relaying_interrupts(const std::vector<std::string>& arguments) {
  if (arguments.empty()) return -1;
  std::vector<std::string> copy = arguments;
  const std::vector<char*> argv = argument_vector(copy);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSID);
  pid_t child = 0;
  const int started = posix_spawnp(&child, argv[0], nullptr, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  if (started != 0) return -1;
  relay_child = child;
  relayed = 0;
  struct sigaction handler = {}, previous_int = {}, previous_term = {};
  handler.sa_handler = relay;
  sigemptyset(&handler.sa_mask);
  sigaction(SIGINT, &handler, &previous_int);
  sigaction(SIGTERM, &handler, &previous_term);
  int status = 0;
  pid_t waited = 0;
  while ((waited = waitpid(child, &status, 0)) < 0 && errno == EINTR) {
  }
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
  relay_child = 0;
  if (waited < 0) return -1;
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  if (!WIFEXITED(status)) return -1;
  // Stopped by the SIGUSR1 we sent: the exit of the signal we received.
  return relayed && WEXITSTATUS(status) == 128 + SIGUSR1 ? 128 + relayed : WEXITSTATUS(status);
}

std::string beside_this_program(const std::string& program) {
  return (std::filesystem::read_symlink("/proc/self/exe").parent_path() / program).string();
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::istringstream folders(path);
  for (std::string folder; std::getline(folders, folder, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / program;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) && access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

} // namespace anvil::subprocess
