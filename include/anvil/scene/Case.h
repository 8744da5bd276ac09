// A case file (scene) as read and checked, before anything is built.
#pragma once
#include "anvil/material/Material.h"
#include "anvil/scene/BoundaryCondition.h"
#include "anvil/solver/IncrementSolver.h"

#include <memory>
#include <string>
#include <vector>

namespace anvil::scene {

struct MeshSpec {
  std::string file;     ///< absolute or relative to the working directory, resolved from the case's folder
  std::string generate; ///< "box", "cylinder" or empty
  mesh::Point origin = mesh::Point::Zero(), size = mesh::Point::Zero();
  double radius = 0.0, height = 0.0, element_size = 0.0; ///< mm
  std::string source;   ///< "file:line" of the mesh key
};

struct BodySpec {
  std::string name;
  std::string material_file;
  MeshSpec mesh;
};

struct Case {
  std::string path;  ///< the case file
  std::string title;
  std::string output_directory; ///< empty = out/<case name>
  bool write_vtk = true;
  solver::NewtonSettings newton;
  solver::LinearSolverKind linear_solver = solver::LinearSolverKind::automatic;
  std::vector<BodySpec> bodies;
  std::vector<BoundaryCondition> boundary;
  std::vector<int> boundary_body; ///< body index of each boundary condition
};

/// Reads and checks a case file. Throws InputError naming file, line, key.
Case read_case(const std::string& path);

/// Reads a material card, requiring a source for every number.
std::unique_ptr<material::Material> read_material(const std::string& path);

} // namespace anvil::scene
