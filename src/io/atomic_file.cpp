#include "anvil/io/atomic_file.h"

#include "anvil/core/error.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace anvil::io {
namespace {

std::string reason(int error) {
  return error == ENOSPC ? "no space left on the disk" : std::strerror(error);
}

/// Writes all of `text` to `fd`; false (errno set) when the system refuses.
bool write_all(int fd, const std::string& text) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      if (written == 0) errno = ENOSPC;
      return false;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return true;
}

/// fsync of the file at `path`; false (errno set) on failure.
bool flush_to_disk(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool synced = ::fsync(fd) == 0;
  const int error = errno;
  ::close(fd);
  errno = error;
  return synced;
}

} // namespace

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw RunError(temporary + ": cannot create the file: " + reason(errno));
  const bool written = write_all(fd, text) && ::fsync(fd) == 0;
  const int error = errno;
  if (::close(fd) != 0 || !written) {
    discard_temporary(path);
    throw RunError(path + ": cannot write the file: " + reason(written ? errno : error));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_error = errno;
    discard_temporary(path);
    throw RunError(path + ": cannot rename the temporary file into place: " + reason(rename_error));
  }
}

void commit_temporary(const std::string& path) {
  const std::string temporary = path + ".tmp";
  if (!flush_to_disk(temporary) || std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    discard_temporary(path);
    throw RunError(path + ": cannot write the file: " + reason(error));
  }
}

void discard_temporary(const std::string& path) noexcept {
  std::remove((path + ".tmp").c_str());
}

void append_whole(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) throw RunError(path + ": cannot open the file to append: " + reason(errno));
  struct stat before {};
  const bool sized = ::fstat(fd, &before) == 0;
  const bool written = sized && write_all(fd, text) && ::fsync(fd) == 0;
  const int error = errno;
  if (!written && sized) (void)!::ftruncate(fd, before.st_size); // back to the last whole line
  if (::close(fd) != 0 || !written) throw RunError(path + ": cannot append to the file: " + reason(error));
}

} // namespace anvil::io
