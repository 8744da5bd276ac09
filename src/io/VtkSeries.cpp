#include "anvil/io/VtkSeries.h"

#include "anvil/core/error.h"
#include "anvil/io/atomic_file.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
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
    if (!std::isfinite(v)) throw RunError("VTK output: field '" + f.name + "' holds a non-finite value; nothing written");
  vtkNew<vtkDoubleArray> a;
  a->SetName(f.name.c_str());
  a->SetNumberOfComponents(f.components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(count));
  std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
  return a;
}

} // namespace

VtkSeries::VtkSeries(std::string directory, std::string name) : directory_(std::move(directory)), name_(std::move(name)) {}

void VtkSeries::write(int increment, double time, int body, const std::string& body_name, const mesh::TetMesh& mesh,
                      const std::vector<Field>& point_fields, const std::vector<Field>& cell_fields) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i) points->SetPoint(i, mesh.nodes[i].data());
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(4 * static_cast<vtkIdType>(mesh.tet_count()));
  for (int e = 0; e < mesh.tet_count(); ++e)
    for (int a = 0; a < 4; ++a) connectivity->SetValue(4 * e + a, mesh.tets[e][a]);
  vtkNew<vtkCellArray> cells;
  cells->SetData(4, connectivity);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(VTK_TETRA, cells);
  for (const Field& f : point_fields) grid->GetPointData()->AddArray(to_vtk(f, mesh.nodes.size()));
  for (const Field& f : cell_fields) grid->GetCellData()->AddArray(to_vtk(f, mesh.tets.size()));

  char file[256];
  std::snprintf(file, sizeof file, "%s_%s_%06d.vtu", name_.c_str(), body_name.c_str(), increment);
  const std::string path = directory_ + "/" + file;
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName((path + ".tmp").c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(5);
  writer->SetHeaderTypeToUInt64();
  if (writer->Write() == 0) throw RunError(path + ": VTK could not write the file");
  commit_temporary(path);

  entries_.push_back({time, body, file});
  std::ostringstream pvd;
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n";
  pvd.precision(12);
  for (const Entry& e : entries_)
    pvd << "    <DataSet timestep=\"" << e.time << "\" group=\"\" part=\"" << e.part << "\" file=\"" << e.file << "\"/>\n";
  pvd << "  </Collection>\n</VTKFile>\n";
  write_file_atomically(directory_ + "/" + name_ + ".pvd", pvd.str());
}

} // namespace anvil::io
