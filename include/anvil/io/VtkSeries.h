// VTK output (DESIGN §7): one .vtu per written increment (binary appended,
// zlib-compressed, UInt64 headers) and one .pvd collection pointing at them,
// rewritten after every output so it is always valid for ParaView.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace anvil::io {

/// One field: `components` values per node or per element, row by row.
struct Field {
  std::string name;
  int components;
  std::vector<double> values;
};

class VtkSeries {
public:
  /// Files go to `directory` (created beforehand); the collection is `<name>.pvd`.
  VtkSeries(std::string directory, std::string name);

  /// Writes `<name>_<body>_<increment>.vtu` and refreshes the .pvd. Throws
  /// RunError if VTK cannot write, or if a value is not finite (no NaN is
  /// ever written: the run stops before).
  void write(int increment, double time, int body, const std::string& body_name, const mesh::TetMesh& mesh,
             const std::vector<Field>& point_fields, const std::vector<Field>& cell_fields);

private:
  struct Entry {
    double time;
    int part;
    std::string file;
  };
  std::string directory_, name_;
  std::vector<Entry> entries_;
};

} // namespace anvil::io
