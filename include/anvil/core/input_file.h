// Input files (case, material cards, meshes, STL dies, checkpoints) are
// regular files of bounded size: a FIFO would block the first read for ever,
// a device (/dev/zero, /dev/urandom) never ends, a folder is no file, and a
// file far beyond any real input of its kind would take the machine's memory.
#pragma once
#include <cstdint>
#include <string>

namespace anvil {

/// Largest input files of each kind (bytes), stated in `anvil --schema`.
inline constexpr std::uintmax_t kMaxYamlBytes = 1u << 20;          ///< case files, material cards: 1 MiB
inline constexpr std::uintmax_t kMaxMeshBytes = 2ull << 30;        ///< mesh files: 2 GiB
inline constexpr std::uintmax_t kMaxStlBytes = 1ull << 30;         ///< STL dies: 1 GiB
inline constexpr std::uintmax_t kMaxCheckpointBytes = 64ull << 30; ///< checkpoint.h5: 64 GiB

/// Why `path` cannot be read as an input file of at most `max_bytes`
/// ("file not found", "is a folder, not a file", "is a FIFO ...", "is
/// 3.1 GB, more than ..."), or "" when it can. Never opens the file.
std::string input_file_problem(const std::string& path, std::uintmax_t max_bytes);

} // namespace anvil
