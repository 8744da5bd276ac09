// Damages a checkpoint.h5 in one named way, for the malformed-input corpus
// (tests/corpus/corpus.py): the checkpoint reader must answer each with one
// clear input error. Writes through HDF5, so data checksums stay valid and
// only the reader's own checks can catch the damage.
//   anvil_corrupt_checkpoint FILE MODE
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

/// Reads dataset `name`, lets `change` edit its values and dimensions, and
/// writes it back (recreated with the same creation properties when the
/// dimensions change).
template <class T>
bool edit(hid_t file, const char* name, hid_t type, const std::function<void(std::vector<T>&, hsize_t*)>& change) {
  const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
  if (set < 0) return false;
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  const hsize_t count = rank == 2 ? dims[0] * dims[1] : dims[0];
  std::vector<T> values(count);
  if (count > 0) H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  const hsize_t before[2] = {dims[0], dims[1]};
  change(values, dims);
  if (dims[0] == before[0] && dims[1] == before[1]) {
    const bool ok = H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0;
    H5Sclose(space);
    H5Dclose(set);
    return ok;
  }
  const hid_t create = H5Dget_create_plist(set);
  H5Sclose(space);
  H5Dclose(set);
  H5Ldelete(file, name, H5P_DEFAULT);
  const hid_t new_space = H5Screate_simple(rank, dims, nullptr);
  const hid_t plain = H5Pcreate(H5P_DATASET_CREATE);
  // The old chunking may not fit the new size: a contiguous dataset holds any.
  const hid_t new_set = H5Dcreate2(file, name, type, new_space, H5P_DEFAULT, plain, H5P_DEFAULT);
  const bool ok = new_set >= 0 && H5Dwrite(new_set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0;
  H5Pclose(plain);
  H5Pclose(create);
  H5Sclose(new_space);
  if (new_set >= 0) H5Dclose(new_set);
  return ok;
}

bool set_int_attribute(hid_t file, const char* name, int value) {
  const hid_t attribute = H5Aopen(file, name, H5P_DEFAULT);
  if (attribute < 0) return false;
  const bool ok = H5Awrite(attribute, H5T_NATIVE_INT, &value) >= 0;
  H5Aclose(attribute);
  return ok;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fputs("usage: anvil_corrupt_checkpoint FILE MODE\n", stderr);
    return 2;
  }
  const std::string path = argv[1], mode = argv[2];
  if (mode == "remove") return std::filesystem::remove(path) ? 0 : 1;
  if (mode == "text") {
    std::ofstream(path, std::ios::trunc) << "this is not an HDF5 file\n";
    return 0;
  }
  if (mode == "truncate") { // the superblock and part of the metadata stay
    std::filesystem::resize_file(path, std::min<std::uintmax_t>(std::filesystem::file_size(path) / 2, 4096));
    return 0;
  }
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) return 1;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  long long nodes = 0;
  {
    const hid_t set = H5Dopen2(file, "nodes", H5P_DEFAULT);
    const hid_t space = H5Dget_space(set);
    hsize_t dims[2];
    H5Sget_simple_extent_dims(space, dims, nullptr);
    nodes = static_cast<long long>(dims[0]);
    H5Sclose(space);
    H5Dclose(set);
  }
  bool ok = false;
  using Ints = std::vector<long long>;
  using Doubles = std::vector<double>;
  if (mode == "tet_index")
    ok = edit<long long>(file, "tets", H5T_NATIVE_LLONG, [&](Ints& v, hsize_t*) { v[0] = nodes + 5; });
  else if (mode == "tet_negative")
    ok = edit<long long>(file, "tets", H5T_NATIVE_LLONG, [](Ints& v, hsize_t*) { v[1] = -3; });
  else if (mode == "face_index")
    ok = edit<long long>(file, "boundary_faces", H5T_NATIVE_LLONG, [&](Ints& v, hsize_t*) { v[2] = nodes + 100; });
  else if (mode == "load_surface")
    ok = edit<double>(file, "loads", H5T_NATIVE_DOUBLE, [](Doubles& v, hsize_t*) { v[2] = 17; });
  else if (mode == "nan_node")
    ok = edit<double>(file, "nodes", H5T_NATIVE_DOUBLE, [&](Doubles& v, hsize_t*) { v[0] = nan; });
  else if (mode == "inf_nodal")
    ok = edit<double>(file, "nodal", H5T_NATIVE_DOUBLE, [&](Doubles& v, hsize_t*) { v[1] = inf; });
  else if (mode == "body_ranges")
    ok = edit<int>(file, "body_ranges", H5T_NATIVE_INT, [](std::vector<int>& v, hsize_t*) { v[1] += 10; });
  else if (mode == "extra_die")
    ok = edit<double>(file, "dies", H5T_NATIVE_DOUBLE, [](Doubles& v, hsize_t* dims) {
      v.insert(v.end(), v.begin(), v.begin() + static_cast<long>(dims[1]));
      ++dims[0];
    });
  else if (mode == "output_part")
    ok = edit<double>(file, "outputs", H5T_NATIVE_DOUBLE, [](Doubles& v, hsize_t*) { v[1] = 99; });
  else if (mode == "negative_increment")
    ok = set_int_attribute(file, "increment", -5);
  else if (mode == "format_9")
    ok = set_int_attribute(file, "format", 9);
  else if (mode == "drop_tets")
    ok = H5Ldelete(file, "tets", H5P_DEFAULT) >= 0;
  else
    std::fprintf(stderr, "anvil_corrupt_checkpoint: unknown mode %s\n", mode.c_str());
  H5Fclose(file);
  return ok ? 0 : 1;
}
