// Result files are written to "<name>.tmp" and renamed into place, so a
// reader (or a crash) never sees a half-written file.
#pragma once
#include <string>

namespace anvil::io {

/// Writes `text` to `path` atomically. Throws RunError when the disk refuses.
void write_file_atomically(const std::string& path, const std::string& text);

/// Renames `<path>.tmp` onto `path`; throws RunError on failure.
void commit_temporary(const std::string& path);

} // namespace anvil::io
