#include "hdf5_datasets.h"

#include "anvil/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace anvil::io::hdf5 {

void silence() {
  static const bool silenced = [] { return H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0; }();
  (void)silenced;
}

void write_array(hid_t file, const char* name, hid_t type, const void* data, hsize_t rows, hsize_t cols) {
  const hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(cols ? 2 : 1, dims, nullptr), H5Sclose);
  // Chunked and checksummed when not empty (a chunk cannot have a zero extent).
  Handle create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (rows > 0) {
    const hsize_t chunk[2] = {std::min<hsize_t>(rows, 1 << 16), cols};
    if (H5Pset_chunk(create, cols ? 2 : 1, chunk) < 0 || H5Pset_fletcher32(create) < 0)
      throw RunError(std::string("checkpoint: cannot set up dataset ") + name);
  }
  Handle set(H5Dcreate2(file, name, type, space, H5P_DEFAULT, create, H5P_DEFAULT), H5Dclose);
  if (!set.valid() || (rows > 0 && H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0))
    throw RunError(std::string("checkpoint: cannot write dataset ") + name);
}

template <class T>
void read_array(hid_t file, const std::string& path, const char* name, hid_t type, std::vector<T>& out,
                hsize_t per_row) {
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0) throw InputError(path + ": checkpoint has no dataset '" + name + "'");
  Handle set(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
  if (!set.valid()) throw InputError(path + ": checkpoint dataset '" + name + "' cannot be opened (damaged file)");
  Handle space(H5Dget_space(set), H5Sclose);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count < 0 || (per_row && count % static_cast<hssize_t>(per_row)))
    throw InputError(path + ": checkpoint dataset '" + name + "' has a wrong size");
  // A damaged size must not allocate the machine away: no dataset holds more
  // elements than the file has bytes.
  hsize_t file_size = 0;
  if (H5Fget_filesize(file, &file_size) < 0 || static_cast<hsize_t>(count) > file_size)
    throw InputError(path + ": checkpoint dataset '" + name + "' claims more values than the file holds");
  out.resize(static_cast<std::size_t>(count));
  if (count > 0 && H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw InputError(path + ": checkpoint dataset '" + name +
                     "' cannot be read (its checksum does not match: the file is damaged)");
}

void read_finite_array(hid_t file, const std::string& path, const char* name, std::vector<double>& out,
                       hsize_t per_row) {
  read_array(file, path, name, H5T_NATIVE_DOUBLE, out, per_row);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i]))
      throw InputError(path + ": checkpoint dataset '" + name + "', value " + std::to_string(i + 1) +
                       ": not a finite number (damaged file)");
}

void write_ragged(hid_t file, const std::string& name, const std::vector<std::vector<double>>& vectors) {
  std::vector<double> values, sizes;
  for (const std::vector<double>& v : vectors) {
    values.insert(values.end(), v.begin(), v.end());
    sizes.push_back(static_cast<double>(v.size()));
  }
  write_array(file, name.c_str(), H5T_NATIVE_DOUBLE, values.data(), values.size(), 0);
  write_array(file, (name + "_sizes").c_str(), H5T_NATIVE_DOUBLE, sizes.data(), sizes.size(), 0);
}

std::vector<std::vector<double>> read_ragged(hid_t file, const std::string& path, const std::string& name) {
  std::vector<std::vector<double>> vectors;
  const std::string sizes_name = name + "_sizes";
  if (H5Lexists(file, sizes_name.c_str(), H5P_DEFAULT) <= 0) return vectors;
  std::vector<double> values, sizes;
  read_finite_array(file, path, name.c_str(), values, 1);
  read_finite_array(file, path, sizes_name.c_str(), sizes, 1);
  std::size_t first = 0;
  for (double n : sizes) {
    if (!(n >= 0.0 && n <= static_cast<double>(values.size() - first) && n == std::floor(n)))
      throw InputError(path + ": checkpoint dataset '" + sizes_name + "' does not match '" + name + "' (damaged file)");
    const auto count = static_cast<std::size_t>(n);
    vectors.emplace_back(values.begin() + long(first), values.begin() + long(first + count));
    first += count;
  }
  if (first != values.size())
    throw InputError(path + ": checkpoint dataset '" + sizes_name + "' does not match '" + name + "' (damaged file)");
  return vectors;
}

void write_attribute(hid_t file, const char* name, hid_t type, const void* value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute, type, value) < 0)
    throw RunError(std::string("checkpoint: cannot write attribute ") + name);
}

void read_attribute(hid_t file, const std::string& path, const char* name, hid_t type, void* value) {
  if (H5Aexists(file, name) <= 0) throw InputError(path + ": checkpoint has no attribute '" + name + "'");
  Handle attribute(H5Aopen(file, name, H5P_DEFAULT), H5Aclose);
  if (!attribute.valid() || H5Aread(attribute, type, value) < 0)
    throw InputError(path + ": checkpoint has no attribute '" + name + "'");
}

template void read_array<int>(hid_t, const std::string&, const char*, hid_t, std::vector<int>&, hsize_t);
template void read_array<long long>(hid_t, const std::string&, const char*, hid_t, std::vector<long long>&, hsize_t);
template void read_array<double>(hid_t, const std::string&, const char*, hid_t, std::vector<double>&, hsize_t);
template void read_array<char>(hid_t, const std::string&, const char*, hid_t, std::vector<char>&, hsize_t);

} // namespace anvil::io::hdf5
