#include "anvil/core/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

namespace anvil {
namespace {

std::string megabytes(std::uintmax_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g MB", static_cast<double>(bytes) / 1e6);
  return text;
}

} // namespace

std::string input_file_problem(const std::string& path, std::uintmax_t max_bytes) {
  struct stat info = {};
  if (stat(path.c_str(), &info) != 0)
    return errno == ENOENT || errno == ENOTDIR ? "file not found" : std::string("cannot open: ") + std::strerror(errno);
  if (S_ISDIR(info.st_mode)) return "is a folder, not a file";
  if (!S_ISREG(info.st_mode)) {
    const char* kind = S_ISFIFO(info.st_mode)   ? "a FIFO (named pipe)"
                       : S_ISCHR(info.st_mode)  ? "a character device"
                       : S_ISBLK(info.st_mode)  ? "a block device"
                       : S_ISSOCK(info.st_mode) ? "a socket"
                                                : "not a regular file";
    return std::string("is ") + kind + ", not a regular file: give a file";
  }
  if (static_cast<std::uintmax_t>(info.st_size) > max_bytes)
    return "is " + megabytes(static_cast<std::uintmax_t>(info.st_size)) + ", more than the " + megabytes(max_bytes) +
           " an input of this kind may have";
  return "";
}

} // namespace anvil
