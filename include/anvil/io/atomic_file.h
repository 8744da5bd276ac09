// Result files are written to "<name>.tmp", flushed to the disk, then renamed
// into place, so a reader (or a crash, or a full disk) never leaves a
// half-written file under its final name.
#pragma once
#include <string>

namespace anvil::io {

/// Writes `text` to `path` atomically. Throws RunError naming the file and the
/// system's reason when the disk refuses (the temporary file is removed).
void write_file_atomically(const std::string& path, const std::string& text);

/// Flushes `<path>.tmp` to the disk and renames it onto `path`; throws
/// RunError on failure (the temporary file is removed, `path` untouched).
void commit_temporary(const std::string& path);

/// Removes `<path>.tmp`, if there is one, after a failed write. Never throws.
void discard_temporary(const std::string& path) noexcept;

/// Appends `text` to `path` as one piece: when the disk refuses part of it,
/// the file is cut back to its length before, so it never ends in a torn
/// line. Throws RunError naming the file and the reason.
void append_whole(const std::string& path, const std::string& text);

} // namespace anvil::io
