#include "anvil/io/RunResults.h"

#include "anvil/core/error.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <fstream>
#include <iterator>
#include <sstream>

namespace anvil::io {

std::vector<LoadRow> read_loads(const std::string& directory, const std::string& surface) {
  const std::string path = directory + "/loads.csv";
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  std::vector<LoadRow> rows;
  std::string line;
  std::getline(in, line); // header
  for (int number = 2; std::getline(in, line); ++number) {
    std::vector<std::string> cols;
    std::istringstream split(line);
    for (std::string col; std::getline(split, col, ',');) cols.push_back(col);
    try {
      if (cols.size() != 7) throw std::invalid_argument("columns");
      if (cols[2] != surface) continue;
      rows.push_back({std::stoi(cols[0]), std::stod(cols[1]), std::stod(cols[3]),
                      {std::stod(cols[4]), std::stod(cols[5]), std::stod(cols[6])}});
    } catch (const std::exception&) {
      throw InputError(where(path, number) +
                       ": expected increment,time_s,surface,stroke_mm,Fx_N,Fy_N,Fz_N, got '" + line + "'");
    }
  }
  return rows;
}

std::vector<InterfaceRow> read_interface(const std::string& directory) {
  const std::string path = directory + "/interface.csv";
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  std::vector<InterfaceRow> rows;
  std::string line;
  std::getline(in, line); // header
  for (int number = 2; std::getline(in, line); ++number) {
    std::vector<std::string> cols;
    std::istringstream split(line);
    for (std::string col; std::getline(split, col, ',');) cols.push_back(col);
    try {
      if (cols.size() != 10) throw std::invalid_argument("columns");
      rows.push_back({cols[0], cols[1], std::stoi(cols[2]), {std::stod(cols[3]), std::stod(cols[4]), std::stod(cols[5])},
                      std::stod(cols[6]), {std::stod(cols[7]), std::stod(cols[8]), std::stod(cols[9])}});
    } catch (const std::exception&) {
      throw InputError(where(path, number) + ": expected pair,body,node,x_mm,y_mm,z_mm,normal_stress_MPa,vx,vy,vz, got '" +
                       line + "'");
    }
  }
  return rows;
}

std::vector<double> read_last_cell_field(const std::string& directory, const std::string& name, int components) {
  // The last body file listed in the series (dies are written as other parts).
  const std::string pvd = directory + "/anvil.pvd";
  std::ifstream in(pvd);
  if (!in) throw InputError(pvd + ": cannot open the file");
  std::string line, file;
  while (std::getline(in, line))
    if (const auto at = line.find("file=\""); at != std::string::npos && line.find("part=\"0\"") != std::string::npos)
      file = line.substr(at + 6, line.find('"', at + 6) - at - 6);
  if (file.empty()) throw InputError(pvd + ": no body file listed");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((directory + "/" + file).c_str());
  reader->Update();
  vtkDataArray* array = reader->GetOutput()->GetCellData()->GetArray(name.c_str());
  if (!array || array->GetNumberOfComponents() != components)
    throw InputError(directory + "/" + file + ": no cell field '" + name + "' of " + std::to_string(components) +
                     " components");
  std::vector<double> values(static_cast<std::size_t>(array->GetNumberOfTuples() * components));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    for (int c = 0; c < components; ++c) values[static_cast<std::size_t>(i * components + c)] = array->GetComponent(i, c);
  return values;
}

double read_summary_number(const std::string& directory, const std::string& key) {
  const std::string path = directory + "/summary.json";
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string quoted = "\"" + key + "\": ";
  const auto at = text.find(quoted);
  if (at == std::string::npos) throw InputError(path + ": no key '" + key + "'");
  try {
    return std::stod(text.substr(at + quoted.size()));
  } catch (const std::exception&) {
    throw InputError(path + ": key '" + key + "' is not a number");
  }
}

} // namespace anvil::io
