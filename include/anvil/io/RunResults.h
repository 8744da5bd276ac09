// Reading back what a run wrote (loads.csv, summary.json): for the tests and
// for tools/study, which judge runs by their outputs as a user would.
#pragma once
#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

class vtkUnstructuredGrid;
template <class T> class vtkSmartPointer;

namespace anvil::io {

/// The columns of loads.csv: the forces on the model (a symmetry model's
/// share of the part), the press load of the whole part, then a die's fill
/// of the model (empty where not asked for: the die_fill effect).
inline constexpr const char* kLoadsHeader = "increment,time_s,surface,stroke_mm,model_Fx_N,model_Fy_N,model_Fz_N,"
                                            "whole_part_press_load_N,model_die_contact_area_mm2,die_fill";
inline constexpr std::size_t kLoadsColumns = 10;
/// Runs written before the fill columns.
inline constexpr std::size_t kLoadsColumnsWithoutFill = 8;

/// One row of loads.csv.
struct LoadRow {
  int increment = 0;
  double time = 0.0;                               ///< s, at which the load was solved
  double stroke = 0.0;                             ///< mm, of the surface, at which the load was solved
  Eigen::Vector3d force = Eigen::Vector3d::Zero(); ///< N, on the body's model (quarter model: a quarter)
  double whole_part_load = 0.0;                    ///< N, the press load of the whole part
  double contact_area =
      std::numeric_limits<double>::quiet_NaN(); ///< mm², of the die touching the model; NaN: not measured
  double fill =
      std::numeric_limits<double>::quiet_NaN(); ///< share of the die's fill region touching; NaN: not measured
};

/// The comma-separated fields of `line`, empty ones included ("1,,2," has four).
std::vector<std::string> csv_fields(const std::string& line);

/// The rows of `directory`/loads.csv for one surface, in order. Throws
/// InputError naming file and line when the file is missing or malformed.
std::vector<LoadRow> read_loads(const std::string& directory, const std::string& surface);

/// The load surfaces of `directory`/loads.csv, in the order of its rows.
std::vector<std::string> read_load_surfaces(const std::string& directory);

/// One written increment of `directory`/anvil.pvd.
struct SeriesEntry {
  int increment = 0;
  double time = 0.0;              ///< s
  std::vector<std::string> parts; ///< file of each part, relative to the directory: part 0 the bodies, then the dies
};

/// Every written increment of `directory`/anvil.pvd, in order. Throws InputError.
std::vector<SeriesEntry> read_series(const std::string& directory);

/// One file of the series (a body's or a die's .vtu). Throws InputError when it holds no cells.
vtkSmartPointer<vtkUnstructuredGrid> read_grid(const std::string& path);

/// One row of interface.csv: a node on a body-pair interface.
struct InterfaceRow {
  std::string pair, body;
  int node = 0;                                       ///< 1-based, in its body
  Eigen::Vector3d position = Eigen::Vector3d::Zero(); ///< mm
  double area = 0.0;                                  ///< mm², tributary, on the faces looking at the other body
  double gap = 0.0;                                   ///< mm, signed distance to the other body (< 0 penetrating)
  double gap_rate = 0.0;                              ///< mm/s, opening rate (< 0 closing; mm for elastic bodies)
  double normal_stress = 0.0;                         ///< MPa, transmitted (compressive > 0)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); ///< mm/s (mm for elastic bodies)
};

/// The rows of `directory`/interface.csv (written by runs with contact pairs).
std::vector<InterfaceRow> read_interface(const std::string& directory);

/// Cell field `name` of the last .vtu of `directory`/anvil.pvd, `components`
/// values per cell (e.g. "stress", 6: xx yy zz xy yz zx). Throws InputError.
std::vector<double> read_last_cell_field(const std::string& directory, const std::string& name, int components);

/// One written increment of the bodies' VTK series (part 0 of anvil.pvd).
struct WrittenIncrement {
  int increment = 0;
  double time = 0.0;                  ///< s
  double volume = 0.0;                ///< mm³, of all bodies
  double max_equivalent_strain = 0.0; ///< of cell field equivalent_strain (0 when the run writes none)
};

/// Every written increment of `directory`/anvil.pvd, in order. Throws InputError.
std::vector<WrittenIncrement> read_written_increments(const std::string& directory);

/// The first number after "key": in `directory`/summary.json. Throws
/// InputError when the key is absent.
double read_summary_number(const std::string& directory, const std::string& key);

/// Every number after "key": in `directory`/summary.json, in order (e.g.
/// "load_jump" of each remesh); empty when the key is absent.
std::vector<double> read_summary_numbers(const std::string& directory, const std::string& key);

} // namespace anvil::io
