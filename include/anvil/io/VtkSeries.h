// VTK output (docs/design.md §7): one .vtu per written increment (binary appended,
// zlib-compressed, UInt64 headers) and one .pvd collection pointing at them,
// rewritten after every output so it is always valid for ParaView.
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/scene/RunState.h"

#include <Eigen/Core>
#include <array>
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

  /// Writes `<name>_<body>_<increment>.vtu` and refreshes the .pvd, with
  /// `field_data` on the whole dataset. Throws RunError if VTK cannot
  /// write, or if a value is not finite (no NaN is ever written: the run
  /// stops before).
  void write(int increment, double time, int body, const std::string& body_name, const mesh::TetMesh& mesh,
             const std::vector<Field>& point_fields, const std::vector<Field>& cell_fields,
             const std::vector<Field>& field_data = {});

  /// Writes a triangulated surface (a die) as `<name>_<part_name>_<increment>.vtu`,
  /// with fields on its vertices.
  void write_surface(int increment, double time, int part, const std::string& part_name,
                     const std::vector<mesh::Point>& vertices, const std::vector<std::array<int, 3>>& faces,
                     const std::vector<Field>& point_fields = {});

  /// One dataset of the collection.
  using Entry = scene::OutputFrame;
  const std::vector<Entry>& entries() const { return entries_; }
  /// Continues an earlier series (resumed run): keeps the entries up to and
  /// including `time` and rewrites the .pvd.
  void resume(std::vector<Entry> entries, double time);

private:
  /// Writes one grid file and records it in the collection.
  void write_grid(int increment, double time, int part, const std::string& part_name,
                  const std::vector<mesh::Point>& points, int cell_type, int nodes_per_cell,
                  const std::vector<long>& connectivity, const std::vector<Field>& point_fields,
                  const std::vector<Field>& cell_fields, const std::vector<Field>& field_data);
  void write_collection() const;

  std::string directory_, name_;
  std::vector<Entry> entries_;
};

/// Writes the collection (.pvd) of `entries` to `path`, atomically.
void write_collection(const std::string& path, const std::vector<scene::OutputFrame>& entries);

} // namespace anvil::io
