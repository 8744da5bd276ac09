#include "anvil/io/VtkSeries.h"

#include "anvil/core/error.h"
#include "anvil/io/atomic_file.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace anvil::io {
namespace {

vtkNew<vtkDoubleArray> to_vtk(const Field& f, std::size_t count) {
  if (f.values.size() != count * static_cast<std::size_t>(f.components))
    throw RunError("VTK output: field '" + f.name + "' has the wrong size");
  for (double v : f.values)
    if (!std::isfinite(v))
      throw RunError("VTK output: field '" + f.name + "' holds a non-finite value; nothing written");
  vtkNew<vtkDoubleArray> a;
  a->SetName(f.name.c_str());
  a->SetNumberOfComponents(f.components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(count));
  std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
  return a;
}

} // namespace

VtkSeries::VtkSeries(std::string directory, std::string name)
    : directory_(std::move(directory)), name_(std::move(name)) {
  // VTK prints its warnings and errors on stderr; ours say what failed.
  vtkObject::GlobalWarningDisplayOff();
}

void VtkSeries::write(int increment, double time, int body, const std::string& body_name, const mesh::TetMesh& mesh,
                      const std::vector<Field>& point_fields, const std::vector<Field>& cell_fields,
                      const std::vector<Field>& field_data) {
  std::vector<long> connectivity;
  connectivity.reserve(4 * mesh.tets.size());
  for (const mesh::Tet& t : mesh.tets)
    connectivity.insert(connectivity.end(), t.begin(), t.end());
  write_grid(increment, time, body, body_name, mesh.nodes, VTK_TETRA, 4, connectivity, point_fields, cell_fields,
             field_data);
}

void VtkSeries::write_surface(int increment, double time, int part, const std::string& part_name,
                              const std::vector<mesh::Point>& vertices, const std::vector<std::array<int, 3>>& faces,
                              const std::vector<Field>& point_fields) {
  std::vector<long> connectivity;
  connectivity.reserve(3 * faces.size());
  for (const auto& f : faces)
    connectivity.insert(connectivity.end(), f.begin(), f.end());
  write_grid(increment, time, part, part_name, vertices, VTK_TRIANGLE, 3, connectivity, point_fields, {}, {});
}

void VtkSeries::write_grid(int increment, double time, int part, const std::string& part_name,
                           const std::vector<mesh::Point>& nodes, int cell_type, int nodes_per_cell,
                           const std::vector<long>& connectivity_in, const std::vector<Field>& point_fields,
                           const std::vector<Field>& cell_fields, const std::vector<Field>& field_data) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), nodes[i].data());
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(connectivity_in.size()));
  for (std::size_t i = 0; i < connectivity_in.size(); ++i)
    connectivity->SetValue(static_cast<vtkIdType>(i), connectivity_in[i]);
  vtkNew<vtkCellArray> cells;
  cells->SetData(nodes_per_cell, connectivity);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(cell_type, cells);
  const std::size_t cell_count = connectivity_in.size() / static_cast<std::size_t>(nodes_per_cell);
  for (const Field& f : point_fields)
    grid->GetPointData()->AddArray(to_vtk(f, nodes.size()));
  for (const Field& f : cell_fields)
    grid->GetCellData()->AddArray(to_vtk(f, cell_count));
  for (const Field& f : field_data)
    grid->GetFieldData()->AddArray(to_vtk(f, f.values.size() / static_cast<std::size_t>(f.components)));

  char file[256];
  std::snprintf(file, sizeof file, "%s_%s_%06d.vtu", name_.c_str(), part_name.c_str(), increment);
  const std::string path = directory_ + "/" + file;
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName((path + ".tmp").c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(5);
  writer->SetHeaderTypeToUInt64();
  // VTK reports a full disk through its error code, not always through Write().
  if (writer->Write() == 0 || writer->GetErrorCode() != vtkErrorCode::NoError) {
    const unsigned long code = writer->GetErrorCode();
    discard_temporary(path);
    throw RunError(path + ": cannot write the file: " +
                   (code == vtkErrorCode::OutOfDiskSpaceError
                        ? std::string("no space left on the disk")
                        : std::string(vtkErrorCode::GetStringFromErrorCode(code))));
  }
  commit_temporary(path);

  entries_.push_back({time, part, file});
  write_collection();
}

void VtkSeries::resume(std::vector<Entry> entries, double time) {
  entries_.clear();
  for (Entry& e : entries)
    if (e.time <= time) entries_.push_back(std::move(e));
  write_collection();
}

void VtkSeries::write_collection() const {
  io::write_collection(directory_ + "/" + name_ + ".pvd", entries_);
}

void write_collection(const std::string& path, const std::vector<scene::OutputFrame>& entries) {
  std::ostringstream pvd;
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n";
  pvd.precision(17);
  for (const scene::OutputFrame& e : entries)
    pvd << "    <DataSet timestep=\"" << e.time << "\" group=\"\" part=\"" << e.part << "\" file=\"" << e.file
        << "\"/>\n";
  pvd << "  </Collection>\n</VTKFile>\n";
  write_file_atomically(path, pvd.str());
}

} // namespace anvil::io
