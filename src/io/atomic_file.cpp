#include "anvil/io/atomic_file.h"

#include "anvil/core/error.h"

#include <cstdio>
#include <fstream>

namespace anvil::io {

void write_file_atomically(const std::string& path, const std::string& text) {
  {
    std::ofstream out(path + ".tmp", std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw RunError(path + ".tmp: cannot write (disk full or no permission?)");
  }
  commit_temporary(path);
}

void commit_temporary(const std::string& path) {
  if (std::rename((path + ".tmp").c_str(), path.c_str()) != 0)
    throw RunError(path + ": cannot rename the temporary file into place");
}

} // namespace anvil::io
