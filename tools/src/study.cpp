// anvil_study: what accuracy costs in time.
//
// Runs a case over lists of values of case keys (mesh size, stroke increment,
// any other key of the case file), one key at a time with the other varied
// keys at their finest value (the last one listed), and records each run's
// error and wall time in DIR/study.csv; tools/study plots it (DIR/study.png).
// Each run is `anvil run` (the binary beside this one), as a user runs the
// case: every core by default, its log in the run's folder.
//
// The error of a run is the worst relative error of its press load over the
// stroke, on the die whose stroke stops the run:
//   exact-upsetting  against frictionless homogeneous compression,
//                    F = (V/H) σ₀(v/H, ln(H0/H)), with V and H0 of the
//                    nominal body (cylinder or box, not its mesh), at the
//                    height where each increment is solved (its start);
//   finest           against the run with every key at its finest value, at
//                    19 strokes evenly spaced over the stroke, relative to
//                    that run's peak load: a Hansel-Spittel load starts near
//                    zero (e^(m4/ε̄)) and a pointwise ratio there would
//                    measure only how an increment samples the first rise;
//   remesh-jump      the worst press-load jump across a remesh at equal
//                    geometry (remeshing.check_load: the increment after a
//                    remesh solved on the old mesh and on the new), aimed
//                    below 3 %: no reference run;
//   closure          the press load at the final stroke (a closed die's
//                    closure: the number that picks the press) against its
//                    converged value, estimated by Richardson extrapolation
//                    over the first key's three finest values (a mesh size
//                    refined by a constant ratio r): F(h) = F∞ + C h^p,
//                    p = ln((F1 − F2)/(F2 − F3)) / ln r,
//                    F∞ = F3 + (F3 − F2)/(r^p − 1). Where the three loads do
//                    not converge monotonically there is no estimate: the
//                    finest run is the reference, and the study says so
//                    (the finest run that reached closure, when one of the
//                    three stopped short of it).
#include "anvil/core/error.h"
#include "anvil/core/subprocess.h"
#include "anvil/io/RunResults.h"
#include "anvil/io/atomic_file.h"
#include "anvil/material/homogeneous_compression.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/MaterialCard.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace anvil;

constexpr const char* kUsage = R"(anvil_study — error against wall time over lists of case settings

usage: anvil_study CASE.yaml --vary KEY=V1,V2,... [--vary KEY=...] [--set KEY=VALUE ...]
                   [--error exact-upsetting|finest|remesh-jump|closure] [-o DIR]

  --vary KEY=V1,V2,...  values of one case key, coarse to fine (the last one is
                        the finest); KEY as for 'anvil run --set', e.g.
                        bodies[].mesh.element_size=2,1.5,1 or time.stroke_increment=0.5,0.25
  --set KEY=VALUE       a change applied to every run (VTK output is off unless
                        --set output.vtk=true)
  --error exact-upsetting   frictionless upsetting of a generated cylinder or box
                            against the exact homogeneous load (default when every die
                            is frictionless)
  --error finest            against the run with every key at its finest value,
                            relative to its peak load
  --error remesh-jump       the worst press-load jump across a remesh at equal
                            geometry (each run with remeshing.check_load)
  --error closure           the load at the final stroke against its converged
                            value (Richardson over the first --vary key's three
                            finest values, which must refine by one ratio)
  -o DIR                out/study_<case name> by default

Writes DIR/study.csv (key, value, error, wall time, increments, Newton
iterations, nodes, remeshes, run folder) and the runs in DIR/runs/.
)";

enum class ErrorKind { exact_upsetting, finest, remesh_jump, closure };

struct Parameter {
  std::string key;
  std::vector<std::string> values; ///< coarse to fine
};

/// A press-load curve as solved: the load of each increment at the stroke
/// where it was solved (the start of the increment).
struct LoadCurve {
  std::vector<double> stroke, load; // mm, N: the whole part's press load
  int symmetry_copies = 1;          // the model is this share of the whole part
  double at(double s) const {
    if (s <= stroke.front()) return load.front();
    for (std::size_t i = 1; i < stroke.size(); ++i)
      if (stroke[i] >= s) {
        const double w = (s - stroke[i - 1]) / (stroke[i] - stroke[i - 1]);
        return (1.0 - w) * load[i - 1] + w * load[i];
      }
    return load.back();
  }
};

struct Run {
  std::string directory;
  double wall_time = 0.0; ///< s
  int increments = 0, newton_iterations = 0, nodes = 0;
  LoadCurve curve;
  std::vector<double> load_jumps; ///< relative, one per remesh (with remeshing.check_load)
  std::size_t remeshes = 0;
  std::string stopped; ///< why the run stopped short of its stop criterion; empty when it got there
};

LoadCurve read_curve(const std::string& directory, const std::string& die) {
  const std::vector<io::LoadRow> rows = io::read_loads(directory, die);
  LoadCurve curve;
  curve.symmetry_copies = static_cast<int>(io::read_summary_number(directory, "symmetry_copies"));
  for (const io::LoadRow& row : rows) { // each load at the stroke it was solved at
    curve.stroke.push_back(row.stroke);
    curve.load.push_back(row.whole_part_load);
  }
  return curve;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, separator);)
    parts.push_back(part);
  return parts;
}

/// Nominal volume (mm³) of a generated body: the shape, not its polygonal mesh.
double nominal_volume(const scene::MeshSpec& m) {
  using std::numbers::pi;
  if (m.generate == "cylinder") return pi * m.radius * m.radius * m.height;
  if (m.generate == "quarter_cylinder") return pi * m.radius * m.radius * m.height / 4.0;
  if (m.generate == "box") return m.size.x() * m.size.y() * m.size.z();
  throw InputError(m.source + ": --error exact-upsetting needs a generated cylinder, quarter_cylinder or box body");
}

/// The first die of `c` with friction, or null.
const scene::DieSpec* die_with_friction(const scene::Case& c) {
  const auto found = std::find_if(c.dies.begin(), c.dies.end(), [](const scene::DieSpec& d) {
    return d.friction.kind != contact::FrictionKind::frictionless;
  });
  return found == c.dies.end() ? nullptr : &*found;
}

/// The exact homogeneous-compression error of a run of case `c`.
class ExactUpsetting {
public:
  explicit ExactUpsetting(const scene::Case& c) {
    const scene::BodySpec& body = c.bodies.front();
    const scene::DieSpec& die = c.dies.at(c.time.stroke_die);
    if (const scene::DieSpec* d = die_with_friction(c))
      throw InputError(d->source + ": --error exact-upsetting needs frictionless dies; die '" + d->name +
                       "' has friction");
    if (die.motion != "constant")
      throw InputError(die.source + ": --error exact-upsetting needs a die at constant velocity");
    card_ = scene::read_material(body.material_file);
    volume_ = nominal_volume(body.mesh);
    height_ = body.mesh.generate == "box" ? body.mesh.size.z() : body.mesh.height;
    speed_ = die.velocity.norm();
    temperature_ = body.temperature.value_or(card_.temperature.value_or(20.0));
  }
  double error(const LoadCurve& curve) const {
    double worst = 0.0;
    for (std::size_t i = 0; i < curve.stroke.size(); ++i) {
      // The generated body is the model (a quarter cylinder is a quarter of the part).
      const double exact =
          curve.symmetry_copies * material::homogeneous_compression_load(*card_.law, volume_, height_ - curve.stroke[i],
                                                                         height_, speed_, temperature_);
      worst = std::max(worst, std::abs(curve.load[i] - exact) / exact);
    }
    return worst;
  }

private:
  scene::MaterialCard card_;
  double volume_ = 0.0, height_ = 0.0, speed_ = 0.0, temperature_ = 0.0;
};

/// Worst difference to `reference` at 19 strokes over its range, relative
/// to the reference's peak load.
double error_against(const LoadCurve& curve, const LoadCurve& reference, double final_stroke) {
  const double peak = *std::max_element(reference.load.begin(), reference.load.end());
  double worst = 0.0;
  for (int k = 1; k < 20; ++k) {
    const double s = final_stroke * k / 20.0;
    worst = std::max(worst, std::abs(curve.at(s) - reference.at(s)) / peak);
  }
  return worst;
}

/// The converged value of F(h) = F∞ + C h^p from three runs at sizes
/// h1 > h2 > h3 with h1/h2 = h2/h3 = r; empty when the loads do not
/// converge monotonically ((F1 − F2)/(F2 − F3) ≤ 0 or p ≤ 0).
struct Richardson {
  double converged, order;
};
/// The MINI element's load converges at first to second order in h. An
/// observed order far outside that says the three runs are not yet in the
/// asymptotic range (e.g. remeshes that move the load by more than the
/// refinement does). Above kHighestOrder the extrapolation stays near the
/// finest run and is kept as rough; below kLowestOrder it divides the last
/// step by r^p − 1 → 0 and lands anywhere (near 0, at many times the runs'
/// load), so it is not made.
constexpr double kLowestOrder = 0.5, kHighestOrder = 3.0;
std::optional<Richardson> richardson(double ratio, double f1, double f2, double f3) {
  const double q = (f1 - f2) / (f2 - f3);
  if (!(q > 1.0) || !std::isfinite(q)) return std::nullopt; // q > 1: p > 0
  const double p = std::log(q) / std::log(ratio);
  return Richardson{f3 + (f3 - f2) / (std::pow(ratio, p) - 1.0), p};
}

/// The largest |jump| of a run's remeshes; empty for a run without one.
std::optional<double> worst_jump(const std::vector<double>& jumps) {
  if (jumps.empty()) return std::nullopt;
  double worst = 0.0;
  for (double j : jumps)
    worst = std::max(worst, std::abs(j));
  return worst;
}

class Study {
public:
  Study(std::string case_file, std::vector<Parameter> parameters, std::vector<std::string> fixed, std::string out)
      : case_file_(std::move(case_file)), parameters_(std::move(parameters)), fixed_(std::move(fixed)),
        out_(std::move(out)) {}

  /// The run with every varied key at its finest value except `key` = `value`,
  /// made by `anvil run` as a user runs it (every core by default). A run that
  /// stops short of its stop criterion is a result too: kept, with the reason.
  const Run& run(const std::string& key, const std::string& value) {
    std::vector<std::string> overrides{"output.vtk=false"};
    overrides.insert(overrides.end(), fixed_.begin(), fixed_.end());
    std::string label;
    for (const Parameter& p : parameters_) {
      const std::string& v = p.key == key ? value : p.values.back();
      overrides.push_back(p.key + "=" + v);
      label += (label.empty() ? "" : " ") + p.key + "=" + v;
    }
    if (auto found = runs_.find(label); found != runs_.end()) return found->second;

    const scene::Case c = scene::read_case(case_file_, overrides);
    Run r;
    r.directory = out_ + "/runs/run_" + std::to_string(runs_.size() + 1);
    std::filesystem::remove_all(r.directory);
    std::vector<std::string> command{anvil_, "run", case_file_, "-o", r.directory};
    for (const std::string& o : overrides) {
      command.push_back("--set");
      command.push_back(o);
    }
    subprocess::Options options;
    options.errors_file = r.directory + ".stderr";
    std::printf("run %zu: %s (%s/anvil.log) ... ", runs_.size() + 1, label.c_str(), r.directory.c_str());
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    const int status = subprocess::run(command, options);
    r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // anvil run's exit codes (README): 3 an input error, 4 a run stopped with
    // its results so far written; its last line says why ("anvil: KIND: why").
    const std::string said = last_line(options.errors_file);
    const std::string why = std::regex_replace(said, std::regex("^anvil: (input error|run stopped): "), "");
    if (status == 3) throw InputError(why);
    if (status == 4)
      r.stopped = why;
    else if (status != 0)
      throw std::runtime_error(anvil_ + " run exited with " + std::to_string(status) + ": " + said);
    r.increments = static_cast<int>(io::read_summary_number(r.directory, "increments"));
    r.newton_iterations = static_cast<int>(io::read_summary_number(r.directory, "newton_iterations"));
    r.nodes = static_cast<int>(io::read_summary_number(r.directory, "nodes"));
    const std::string& die = c.dies.at(c.time.stroke_die).name;
    r.curve = read_curve(r.directory, die);
    if (r.curve.load.empty() && r.stopped.empty())
      throw RunError(r.directory + "/loads.csv: no load rows for die '" + die + "'");
    r.load_jumps = io::read_summary_numbers(r.directory, "load_jump");
    r.remeshes = io::read_summary_numbers(r.directory, "nodes_after").size(); // one per remesh
    std::printf("%.1f s, %d increments, %d nodes, %zu remeshes%s%s\n", r.wall_time, r.increments, r.nodes, r.remeshes,
                r.stopped.empty() ? "" : ", stopped: ", r.stopped.c_str());
    std::fflush(stdout);
    return runs_.emplace(label, std::move(r)).first->second;
  }

private:
  /// The last line `path` holds, or empty.
  static std::string last_line(const std::string& path) {
    std::ifstream in(path);
    std::string line, last;
    while (std::getline(in, line))
      if (!line.empty()) last = line;
    return last;
  }

  std::string anvil_ = subprocess::beside_this_program("anvil");
  std::string case_file_;
  std::vector<Parameter> parameters_;
  std::vector<std::string> fixed_;
  std::string out_;
  std::map<std::string, Run> runs_;
};

struct Row {
  std::string key, value;
  std::optional<double> error; ///< empty for the reference run, a run without a remesh (remesh-jump), a stopped run
  const Run* run;
};

/// What a row without an error stands for.
std::string no_error_label(const Row& r, ErrorKind kind) {
  if (!r.run->stopped.empty()) {
    char text[64];
    std::snprintf(text, sizeof text, "stopped at %.2f mm",
                  r.run->curve.stroke.empty() ? 0.0 : r.run->curve.stroke.back());
    return text;
  }
  return kind == ErrorKind::remesh_jump ? "no remesh" : "reference";
}

std::string format_row_csv(const Row& r, ErrorKind kind) {
  char text[512];
  const std::string error = r.error ? std::to_string(100.0 * *r.error) : no_error_label(r, kind);
  std::snprintf(text, sizeof text, "%s,%s,%s,%.3f,%d,%d,%d,%zu,%s\n", r.key.c_str(), r.value.c_str(), error.c_str(),
                r.run->wall_time, r.run->increments, r.run->newton_iterations, r.run->nodes, r.run->remeshes,
                r.run->directory.c_str());
  return text;
}

/// The cheapest run whose error is below `bound`, as one line.
std::string cheapest_below(const std::vector<Row>& rows, double bound) {
  const Row* best = nullptr;
  for (const Row& r : rows)
    if (r.error && *r.error < bound && (!best || r.run->wall_time < best->run->wall_time)) best = &r;
  char text[300];
  if (!best) {
    std::snprintf(text, sizeof text, "no run is within %g %%", 100.0 * bound);
  } else {
    std::snprintf(text, sizeof text, "%s = %s (the other keys at their finest value): error %.3f %%, %.1f s",
                  best->key.c_str(), best->value.c_str(), 100.0 * *best->error, best->run->wall_time);
  }
  return text;
}

int study(int argc, char** argv) {
  std::string case_file, out, error_name;
  std::vector<Parameter> parameters;
  std::vector<std::string> fixed;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if ((arg == "--vary" || arg == "--set" || arg == "--error" || arg == "-o") && !has_value)
      throw InputError(arg + " needs a value (see --help)");
    if (arg == "--vary") {
      const std::string text = argv[++i];
      const auto equals = text.find('=');
      if (equals == std::string::npos || equals + 1 == text.size())
        throw InputError("--vary '" + text + "': expected KEY=V1,V2,..., e.g. time.stroke_increment=0.5,0.25");
      parameters.push_back({text.substr(0, equals), split(text.substr(equals + 1), ',')});
    } else if (arg == "--set")
      fixed.emplace_back(argv[++i]);
    else if (arg == "--error")
      error_name = argv[++i];
    else if (arg == "-o")
      out = argv[++i];
    else if (!arg.empty() && arg[0] != '-' && case_file.empty())
      case_file = arg;
    else
      throw InputError("unexpected argument '" + arg + "' (see --help)");
  }
  if (case_file.empty() || parameters.empty())
    throw InputError("needs a case file and at least one --vary (see --help)");

  // The case at the finest settings: it names the die and checks every key.
  std::vector<std::string> finest = fixed;
  for (const Parameter& p : parameters)
    finest.push_back(p.key + "=" + p.values.back());
  const scene::Case c = scene::read_case(case_file, finest);
  if (c.dies.empty() || !c.time.enabled)
    throw InputError(case_file + ": the study needs a case with dies and a time section");
  if (error_name.empty()) error_name = die_with_friction(c) ? "finest" : "exact-upsetting";
  const std::map<std::string, ErrorKind> kinds{{"exact-upsetting", ErrorKind::exact_upsetting},
                                               {"finest", ErrorKind::finest},
                                               {"remesh-jump", ErrorKind::remesh_jump},
                                               {"closure", ErrorKind::closure}};
  const auto named = kinds.find(error_name);
  if (named == kinds.end())
    throw InputError("--error '" + error_name + "': expected exact-upsetting, finest, remesh-jump or closure");
  const ErrorKind kind = named->second;
  if (kind == ErrorKind::remesh_jump) {
    if (!c.remeshing.enabled) throw InputError(case_file + ": --error remesh-jump needs a case with remeshing");
    // The jump it measures; the cases leave it off (three more solves a remesh).
    fixed.emplace_back("remeshing.check_load=true");
  }
  std::optional<ExactUpsetting> exact;
  if (kind == ErrorKind::exact_upsetting) exact.emplace(c);
  if (out.empty()) out = "out/study_" + std::filesystem::path(case_file).stem().string();
  std::filesystem::create_directories(out + "/runs");

  std::printf("study of %s, error: %s, results in %s/\n", case_file.c_str(), error_name.c_str(), out.c_str());
  Study runs(case_file, parameters, fixed, out);
  const Run* reference = nullptr; // --error finest: the finest run; closure: the run standing for the converged load
  if (kind == ErrorKind::finest) {
    reference = &runs.run(parameters.front().key, parameters.front().values.back());
    if (!reference->stopped.empty())
      throw RunError("the finest run, the reference of --error finest, stopped: " + reference->stopped);
  }
  // --error closure: the converged closure load from the first key's three finest runs.
  std::optional<double> converged;
  std::string closure_note;
  if (kind == ErrorKind::closure) {
    const Parameter& p = parameters.front();
    if (p.values.size() < 3) throw InputError("--error closure needs three values or more of the first --vary key");
    const std::size_t n = p.values.size();
    double h[3], f[3];
    std::string stopped; // the three finest runs that stopped short of closure
    for (int k = 0; k < 3; ++k) {
      h[k] = std::stod(p.values[n - 3 + k]);
      const Run& r = runs.run(p.key, p.values[n - 3 + k]);
      f[k] = r.curve.load.empty() ? 0.0 : r.curve.load.back();
      if (!r.stopped.empty()) stopped += (stopped.empty() ? "" : ", ") + p.values[n - 3 + k];
    }
    const double r1 = h[0] / h[1], r2 = h[1] / h[2];
    if (!(std::abs(r1 / r2 - 1.0) < 0.02))
      throw InputError("--error closure: the three finest values of " + p.key + " must refine by one ratio (" +
                       std::to_string(r1) + " and " + std::to_string(r2) + ")");
    char text[500];
    const std::optional<Richardson> rich =
        stopped.empty() ? richardson(std::sqrt(r1 * r2), f[0], f[1], f[2]) : std::nullopt;
    if (rich && rich->order >= kLowestOrder) {
      converged = rich->converged;
      std::snprintf(text, sizeof text,
                    "Richardson over %s = %s, %s, %s (%.5g, %.5g, %.5g kN): closure load %.5g kN, observed order "
                    "%.2f%s",
                    p.key.c_str(), p.values[n - 3].c_str(), p.values[n - 2].c_str(), p.values[n - 1].c_str(),
                    f[0] / 1e3, f[1] / 1e3, f[2] / 1e3, rich->converged / 1e3, rich->order,
                    rich->order <= kHighestOrder ? ""
                                                 : " (above the element's 0.5-3: the runs are not in the asymptotic "
                                                   "range, the estimate is rough)");
    } else if (stopped.empty()) {
      reference = &runs.run(p.key, p.values[n - 1]);
      converged = f[2];
      // The loads change direction, move one way by a larger step at each
      // refinement, or by nearly the same step: none leaves an order to
      // extrapolate with.
      char why[120] = "do not converge monotonically";
      if (rich)
        std::snprintf(why, sizeof why,
                      "move by nearly the same step at each refinement (observed order %.2f, below %g)", rich->order,
                      kLowestOrder);
      else if ((f[0] - f[1]) * (f[1] - f[2]) > 0.0)
        std::snprintf(why, sizeof why, "move further apart as the mesh is refined");
      std::snprintf(text, sizeof text,
                    "the closure loads at %s = %s, %s, %s (%.5g, %.5g, %.5g kN) %s: no Richardson estimate, the finest "
                    "run is the reference",
                    p.key.c_str(), p.values[n - 3].c_str(), p.values[n - 2].c_str(), p.values[n - 1].c_str(),
                    f[0] / 1e3, f[1] / 1e3, f[2] / 1e3, why);
    } else {
      // The finest run that reached closure is the reference.
      const std::string* finest_closed = nullptr;
      for (const std::string& v : p.values)
        if (runs.run(p.key, v).stopped.empty()) finest_closed = &v;
      if (!finest_closed) throw RunError("every run of the study stopped short of closure");
      reference = &runs.run(p.key, *finest_closed);
      converged = reference->curve.load.back();
      std::snprintf(text, sizeof text,
                    "the run at %s = %s stopped short of closure: no Richardson estimate, the finest run that reached "
                    "it (%s) is the reference",
                    p.key.c_str(), stopped.c_str(), finest_closed->c_str());
    }
    closure_note = text;
  }
  std::vector<Row> rows;
  for (const Parameter& p : parameters)
    for (const std::string& value : p.values) {
      const Run& r = runs.run(p.key, value);
      // A stopped run has no error: its curve falls short of the others (the row says where it stopped).
      std::optional<double> error;
      if (r.stopped.empty()) {
        if (exact)
          error = exact->error(r.curve);
        else if (kind == ErrorKind::remesh_jump)
          error = worst_jump(r.load_jumps);
        else if (kind == ErrorKind::closure && &r != reference)
          error = std::abs(r.curve.load.back() / *converged - 1.0);
        else if (&r != reference)
          error = error_against(r.curve, reference->curve, reference->curve.stroke.back());
      }
      rows.push_back({p.key, value, error, &r});
    }

  std::string csv = "key,value,error_percent,wall_time_s,increments,newton_iterations,nodes,remeshes,run_directory\n";
  for (const Row& r : rows)
    csv += format_row_csv(r, kind);
  io::write_file_atomically(out + "/study.csv", csv);

  const char* measure = kind == ErrorKind::remesh_jump ? "worst load jump"
                        : kind == ErrorKind::closure   ? "closure load error"
                                                       : "load error";
  std::printf("\n| key | value | %s | wall time | increments | nodes | remeshes |\n|---|---|---|---|---|---|---|\n",
              measure);
  for (const Row& r : rows) {
    char error[64];
    std::snprintf(error, sizeof error, "%s", no_error_label(r, kind).c_str());
    if (r.error) std::snprintf(error, sizeof error, "%.3g %%", 100.0 * *r.error);
    std::printf("| %s | %s | %s | %.1f s | %d | %d | %zu |\n", r.key.c_str(), r.value.c_str(), error, r.run->wall_time,
                r.run->increments, r.run->nodes, r.run->remeshes);
  }
  for (const Row& r : rows)
    if (!r.run->stopped.empty())
      std::printf("\n%s = %s stopped: %s\n", r.key.c_str(), r.value.c_str(), r.run->stopped.c_str());
  if (kind == ErrorKind::closure)
    std::printf("\n%s\nfor 2 %%: %s\nfor 1 %%: %s\n", closure_note.c_str(), cheapest_below(rows, 0.02).c_str(),
                cheapest_below(rows, 0.01).c_str());
  else if (kind == ErrorKind::remesh_jump)
    std::printf("\nfor 3 %%: %s\n", cheapest_below(rows, 0.03).c_str());
  else
    std::printf("\nfor 1 %%:   %s\nfor 0.1 %%: %s\n", cheapest_below(rows, 0.01).c_str(),
                cheapest_below(rows, 0.001).c_str());
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  try {
    return study(argc, argv);
  } catch (const InputError& e) {
    std::fprintf(stderr, "anvil_study: input error: %s\n", e.what());
    return 3;
  } catch (const RunError& e) {
    std::fprintf(stderr, "anvil_study: a run stopped: %s\n", e.what());
    return 4;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "anvil_study: internal error: %s\n", e.what());
    return 5;
  }
}
