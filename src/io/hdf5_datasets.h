// Checked datasets and attributes of an HDF5 file, as the checkpoint
// writes and reads them: chunked and checksummed arrays, ragged vectors,
// scalar attributes; every read names the file and what is wrong with it.
#pragma once
#include <hdf5.h>

#include <string>
#include <vector>

namespace anvil::io::hdf5 {

/// Closes an HDF5 handle with the right call when it goes out of scope.
class Handle {
public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }

private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// HDF5 reports its own errors on stderr unless told not to: ours say it in our words.
void silence();

/// A rows × cols dataset (cols 0: one dimension), chunked and checksummed. Throws RunError.
void write_array(hid_t file, const char* name, hid_t type, const void* data, hsize_t rows, hsize_t cols);

/// Reads a dataset into `out` (resized), checking its element count (a
/// multiple of `per_row`, no more than the file's bytes). Throws InputError.
template <class T>
void read_array(hid_t file, const std::string& path, const char* name, hid_t type, std::vector<T>& out,
                hsize_t per_row);

/// read_array of numbers that must all be finite.
void read_finite_array(hid_t file, const std::string& path, const char* name, std::vector<double>& out,
                       hsize_t per_row);

/// Vectors of different lengths (one per die or body, empty where none):
/// `name` holds them one after the other, `name`_sizes their lengths.
void write_ragged(hid_t file, const std::string& name, const std::vector<std::vector<double>>& vectors);

/// What write_ragged wrote; empty when the file has no `name` (an older checkpoint).
std::vector<std::vector<double>> read_ragged(hid_t file, const std::string& path, const std::string& name);

void write_attribute(hid_t file, const char* name, hid_t type, const void* value);
void read_attribute(hid_t file, const std::string& path, const char* name, hid_t type, void* value);

} // namespace anvil::io::hdf5
