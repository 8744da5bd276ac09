#include "anvil/io/RunResults.h"

#include "anvil/core/error.h"
#include "anvil/mesh/tet_geometry.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

namespace anvil::io {

namespace {

/// Calls `parse(columns)` for each data row of the CSV file `path` (header
/// skipped); a row without `count` (or `older_count`) columns, or that
/// `parse` cannot read, is an InputError naming file, line and the `header`
/// expected.
template <class Parse>
void for_each_csv_row(const std::string& path, std::size_t count, const char* header, Parse parse,
                      std::size_t older_count = 0) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  std::string line;
  std::getline(in, line); // header
  for (int number = 2; std::getline(in, line); ++number) {
    const std::vector<std::string> cols = csv_fields(line);
    try {
      if (cols.size() != count && cols.size() != older_count) throw std::invalid_argument("columns");
      parse(cols);
    } catch (const std::exception&) {
      throw InputError(where(path, number) + ": expected " + header + ", got '" + line + "'");
    }
  }
}

/// A fill column: empty when not measured.
double optional_number(const std::vector<std::string>& columns, std::size_t k) {
  return k < columns.size() && !columns[k].empty() ? std::stod(columns[k]) : std::numeric_limits<double>::quiet_NaN();
}

} // namespace

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
    fields.push_back(line.substr(start, comma - start));
  fields.push_back(line.substr(start));
  return fields;
}

std::vector<LoadRow> read_loads(const std::string& directory, const std::string& surface) {
  std::vector<LoadRow> rows;
  for_each_csv_row(
      directory + "/loads.csv", kLoadsColumns, kLoadsHeader,
      [&](const std::vector<std::string>& c) {
        if (c[2] == surface)
          rows.push_back({std::stoi(c[0]),
                          std::stod(c[1]),
                          std::stod(c[3]),
                          {std::stod(c[4]), std::stod(c[5]), std::stod(c[6])},
                          std::stod(c[7]),
                          optional_number(c, 8),
                          optional_number(c, 9)});
      },
      kLoadsColumnsWithoutFill);
  return rows;
}

std::vector<std::string> read_load_surfaces(const std::string& directory) {
  std::vector<std::string> surfaces;
  for_each_csv_row(
      directory + "/loads.csv", kLoadsColumns, kLoadsHeader,
      [&](const std::vector<std::string>& c) {
        if (std::find(surfaces.begin(), surfaces.end(), c[2]) == surfaces.end()) surfaces.push_back(c[2]);
      },
      kLoadsColumnsWithoutFill);
  return surfaces;
}

std::vector<SeriesEntry> read_series(const std::string& directory) {
  const std::string pvd = directory + "/anvil.pvd";
  std::ifstream in(pvd);
  if (!in) throw InputError(pvd + ": cannot open the file (was output.vtk off?)");
  std::vector<SeriesEntry> series;
  std::string line;
  auto attribute = [&line](const std::string& name) {
    const auto at = line.find(name + "=\"");
    if (at == std::string::npos) return std::string();
    const auto first = at + name.size() + 2;
    return line.substr(first, line.find('"', first) - first);
  };
  while (std::getline(in, line)) {
    const std::string part = attribute("part"), file = attribute("file");
    if (part.empty() || file.empty()) continue;
    if (part == "0") {
      // <name>_<bodies>_<increment>.vtu (VtkSeries)
      const auto underscore = file.rfind('_'), dot = file.rfind('.');
      series.push_back(
          {std::stoi(file.substr(underscore + 1, dot - underscore - 1)), std::stod(attribute("timestep")), {}});
    }
    if (series.empty()) throw InputError(pvd + ": a die's file comes before the bodies'");
    series.back().parts.push_back(file);
  }
  if (series.empty()) throw InputError(pvd + ": no body file listed");
  return series;
}

std::vector<InterfaceRow> read_interface(const std::string& directory) {
  std::vector<InterfaceRow> rows;
  for_each_csv_row(directory + "/interface.csv", 13,
                   "pair,body,node,x_mm,y_mm,z_mm,area_mm2,gap_mm,gap_rate_mm_s,normal_stress_MPa,vx,vy,vz",
                   [&](const std::vector<std::string>& c) {
                     rows.push_back({c[0],
                                     c[1],
                                     std::stoi(c[2]),
                                     {std::stod(c[3]), std::stod(c[4]), std::stod(c[5])},
                                     std::stod(c[6]),
                                     std::stod(c[7]),
                                     std::stod(c[8]),
                                     std::stod(c[9]),
                                     {std::stod(c[10]), std::stod(c[11]), std::stod(c[12])}});
                   });
  return rows;
}

vtkSmartPointer<vtkUnstructuredGrid> read_grid(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (!grid || grid->GetNumberOfCells() == 0) throw InputError(path + ": no cells read");
  return grid;
}

std::vector<double> read_last_cell_field(const std::string& directory, const std::string& name, int components) {
  const std::string path = directory + "/" + read_series(directory).back().parts.front();
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(path);
  vtkDataArray* array = grid->GetCellData()->GetArray(name.c_str());
  if (!array || array->GetNumberOfComponents() != components)
    throw InputError(path + ": no cell field '" + name + "' of " + std::to_string(components) + " components");
  std::vector<double> values(static_cast<std::size_t>(array->GetNumberOfTuples() * components));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    for (int c = 0; c < components; ++c)
      values[static_cast<std::size_t>(i * components + c)] = array->GetComponent(i, c);
  return values;
}

std::vector<WrittenIncrement> read_written_increments(const std::string& directory) {
  std::vector<WrittenIncrement> out;
  for (const SeriesEntry& entry : read_series(directory)) {
    WrittenIncrement w;
    w.increment = entry.increment;
    w.time = entry.time;
    const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(directory + "/" + entry.parts.front());
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
      vtkIdType count = 0;
      const vtkIdType* ids = nullptr;
      grid->GetCellPoints(c, count, ids);
      mesh::Point x[4];
      for (int a = 0; a < 4; ++a)
        grid->GetPoint(ids[a], x[a].data());
      w.volume += mesh::signed_volume(x[0], x[1], x[2], x[3]);
    }
    if (vtkDataArray* strain = grid->GetCellData()->GetArray("equivalent_strain"))
      for (vtkIdType i = 0; i < strain->GetNumberOfTuples(); ++i)
        w.max_equivalent_strain = std::max(w.max_equivalent_strain, strain->GetComponent(i, 0));
    out.push_back(w);
  }
  return out;
}

std::vector<double> read_summary_numbers(const std::string& directory, const std::string& key) {
  const std::string path = directory + "/summary.json";
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string quoted = "\"" + key + "\": ";
  std::vector<double> numbers;
  for (auto at = text.find(quoted); at != std::string::npos; at = text.find(quoted, at + quoted.size())) {
    try {
      numbers.push_back(std::stod(text.substr(at + quoted.size(), 40)));
    } catch (const std::exception&) {
      throw InputError(path + ": key '" + key + "' is not a number");
    }
  }
  return numbers;
}

double read_summary_number(const std::string& directory, const std::string& key) {
  const std::vector<double> numbers = read_summary_numbers(directory, key);
  if (numbers.empty()) throw InputError(directory + "/summary.json: no key '" + key + "'");
  return numbers.front();
}

} // namespace anvil::io
