// The time loop (DESIGN §4): search contacts → choose Δt → Newton on (v, p)
// → update geometry (contact nodes put back on the dies) and ε̄ → outputs,
// checkpoint. A case without a `time` section is one increment on the
// initial geometry.
#include "anvil/scene/Simulation.h"

#include "anvil/contact/RigidContact.h"
#include "anvil/core/Timers.h"
#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/fem/mini_element.h"
#include "anvil/io/VtkSeries.h"
#include "anvil/io/atomic_file.h"
#include "anvil/mesh/generators.h"
#include "anvil/mesh/mesh_io.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/scene/Die.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/effects.h"

#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace anvil::scene {
namespace {

using Clock = std::chrono::steady_clock;

mesh::TetMesh build_mesh(const MeshSpec& spec) {
  if (!spec.file.empty()) return mesh::read_mesh(spec.file);
  mesh::TetMesh m = spec.generate == "box"              ? mesh::make_box(spec.origin, spec.size, spec.element_size)
                     : spec.generate == "cylinder"       ? mesh::make_cylinder(spec.radius, spec.height, spec.element_size)
                     : spec.generate == "quarter_cylinder" ? mesh::make_quarter_cylinder(spec.radius, spec.height, spec.element_size)
                                                        : mesh::make_quarter_ring(spec.radius, spec.inner_radius, spec.height,
                                                                                  spec.element_size);
  mesh::validate(m, spec.source + " (generated " + spec.generate + ")");
  return m;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string clock_text(double seconds) {
  char text[32];
  const long s = std::lround(seconds);
  std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return text;
}

/// Element-centre fields of the current solution.
struct ElementFields {
  std::vector<double> rate;      ///< ε̄̇ (1/s)
  std::vector<material::Vec6> stress; ///< Cauchy, Mandel (MPa)
};

ElementFields element_fields(const mesh::TetMesh& mesh, const material::Material& law,
                             const std::vector<material::PointState>& states, const fem::BodyUnknowns& u) {
  ElementFields out;
  out.rate.resize(mesh.tets.size());
  out.stress.resize(mesh.tets.size());
  fem::MiniElementInput in;
  for (int e = 0; e < mesh.tet_count(); ++e) {
    const mesh::Tet& t = mesh.tets[e];
    for (int a = 0; a < 4; ++a) {
      in.vertices[a] = mesh.nodes[t[a]];
      in.nodal_velocity[a] = u.nodal.segment<3>(4 * t[a]);
      in.nodal_pressure[a] = u.nodal[4 * t[a] + 3];
    }
    in.state = states[e];
    const fem::MiniElementFields f = fem::mini_element_fields(in, law);
    out.rate[e] = f.equivalent_strain_rate;
    out.stress[e] = f.stress;
  }
  return out;
}

/// Mean length of the edges at each node (mm): the local element size.
std::vector<double> local_size(const mesh::TetMesh& mesh) {
  std::vector<double> sum(mesh.nodes.size(), 0.0), count(mesh.nodes.size(), 0.0);
  for (const mesh::Tet& t : mesh.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const double l = (mesh.nodes[t[a]] - mesh.nodes[t[b]]).norm();
        sum[t[a]] += l, sum[t[b]] += l;
        count[t[a]] += 1.0, count[t[b]] += 1.0;
      }
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] /= count[i];
  return sum;
}

double mean_boundary_edge(const mesh::TetMesh& mesh) {
  double sum = 0.0;
  for (const mesh::Triangle& f : mesh.boundary_faces)
    for (int k = 0; k < 3; ++k) sum += (mesh.nodes[f[k]] - mesh.nodes[f[(k + 1) % 3]]).norm();
  return sum / (3.0 * static_cast<double>(mesh.boundary_faces.size()));
}

/// The load surfaces of loads.csv: the dies, then the velocity conditions.
struct LoadSurface {
  std::string name;
  int die = -1;       ///< index into dies, or −1
  int condition = -1; ///< index into the body's conditions, or −1
};

/// Vertical distance (mm) between the two dies at zero displacement: lowest
/// point of the upper die above the highest point of the lower one.
double initial_die_gap(const std::vector<Die>& dies, int& upper) {
  auto z_range = [](const Die& d) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const mesh::Point& p : d.surface->triangles().vertices) low = std::min(low, p.z()), high = std::max(high, p.z());
    return std::pair{low, high};
  };
  const auto a = z_range(dies[0]), b = z_range(dies[1]);
  upper = a.first + a.second > b.first + b.second ? 0 : 1;
  return upper == 0 ? a.first - b.second : b.first - a.second;
}

class Run {
public:
  Run(const Case& c, const RunOptions& options) : case_(c), options_(options) {}
  void execute();

private:
  void setup();
  void log_header() const;
  double choose_time_step(double nominal);
  bool try_increment(double time_step, solver::NewtonReport& report);
  /// Loads on every surface at the converged solution, recorded as increment `increment` ending at `time`.
  void record_loads(int increment, double time);
  void write_outputs(bool force);
  void write_summary(double total) const;
  std::string stop_reason() const;
  double progress() const;
  /// Distance between the two dies along z (mm), for the gap stop criterion.
  double die_gap() const;
  /// Speed of the fastest moving part at the current press time (mm/s).
  double press_speed() const;
  /// Per-node σ₀ and K for friction, the penalty and the force scale, from
  /// the last increment's solution.
  void set_contact_scales();
  /// x ← x + Δt v, dies moved, contact nodes projected, loads recorded.
  /// False (with `failure`) when an element would invert.
  bool update_geometry(double dt, std::string& failure);

  /// What an increment changes before it is accepted, to go back to when it
  /// fails (topology, ε̄ and time change only after).
  struct IncrementStart {
    std::vector<mesh::Point> nodes;
    fem::BodyUnknowns unknowns;
    std::vector<DieState> dies;
    std::size_t load_count;
  };

  const Case& case_;
  const RunOptions& options_;
  Timers timers_;
  std::string out_;
  material::PointState body_state_;
  std::unique_ptr<material::Material> law_;
  std::vector<BoundaryCondition> conditions_;
  ImposedConditions imposed_;
  std::vector<std::string> effects_;
  std::vector<Die> dies_;
  std::vector<LoadSurface> surfaces_;
  int upper_die_ = 0;
  double die_gap0_ = 0.0;
  double reference_velocity_ = 0.0; ///< mm/s
  double reference_length_ = 0.0;   ///< mm, mean boundary edge of the initial mesh
  double body_size_ = 0.0;          ///< mm
  double penalty_ = 0.0;            ///< MPa·s/mm
  double reference_force_ = 0.0;    ///< N, mean flow stress × body area
  bool compensate_volume_ = false;
  double nominal_step_ = 0.0;       ///< s, Δt from the stroke increment alone
  Eigen::VectorXd external_;        ///< external vector of the increment (forces, compensation)

  RunState state_;
  std::vector<material::PointState> states_;
  std::unique_ptr<solver::IncrementSolver> solver_;
  contact::RigidContact contact_;
  std::vector<double> node_flow_stress_, node_consistency_;
  std::vector<double> solved_rates_; ///< ε̄̇ per element of the last converged increment
  std::unique_ptr<io::VtkSeries> series_;
  solver::NewtonReport last_report_;
  Clock::time_point start_ = Clock::now();
  double resumed_time_ = 0.0;
  int last_written_ = -1, last_checkpoint_ = -1;
};

void Run::setup() {
  const BodySpec& body = case_.bodies.front();
  MaterialCard card = read_material(body.material_file);
  law_ = std::move(card.law);
  body_state_.temperature = body.temperature.value_or(card.temperature.value_or(20.0));
  mesh::TetMesh initial = build_mesh(body.mesh);
  for (std::size_t i = 0; i < case_.boundary.size(); ++i)
    if (case_.boundary_body[i] == 0) conditions_.push_back(case_.boundary[i]);
  {
    Timers::Scope scope(timers_, "effect boundary_conditions");
    imposed_ = impose(initial, conditions_);
  }
  effects_ = resolve_effects(case_, {law_.get()});
  compensate_volume_ = std::find(effects_.begin(), effects_.end(), "volume_compensation") != effects_.end();

  // Reference scales from the initial mesh (also on resume, so a resumed run
  // uses the very same numbers).
  mesh::Point low = initial.nodes.front(), high = low;
  for (const auto& x : initial.nodes) low = low.cwiseMin(x), high = high.cwiseMax(x);
  body_size_ = (high - low).norm();
  reference_length_ = mean_boundary_edge(initial);
  {
    Timers::Scope scope(timers_, "effect rigid_dies (setup)");
    for (const DieSpec& spec : case_.dies) dies_.push_back(build_die(spec, body_size_));
  }
  for (std::size_t d = 0; d < dies_.size(); ++d) surfaces_.push_back({dies_[d].name, int(d), -1});
  for (std::size_t i = 0; i < conditions_.size(); ++i)
    if (conditions_[i].prescribes_velocity() && conditions_[i].kind != BoundaryKind::symmetry)
      surfaces_.push_back({conditions_[i].name, -1, int(i)});
  if (case_.time.final_gap > 0.0) die_gap0_ = initial_die_gap(dies_, upper_die_);

  // Speed at t = 0 over a short probe step (an increment is far longer).
  const double probe = 1e-3 * std::max(case_.time.stroke_increment, 1e-6);
  for (const Die& d : dies_) reference_velocity_ = std::max(reference_velocity_, d.velocity(DieState{}, probe).norm());
  for (int k = 0; k < imposed_.values.size(); ++k)
    if (imposed_.prescribed[k] && k % 4 != 3) reference_velocity_ = std::max(reference_velocity_, std::abs(imposed_.values[k]));
  if (case_.time.enabled && !(reference_velocity_ > 0.0))
    throw InputError(case_.path + ": nothing moves at t = 0 (no moving die, no prescribed velocity): the time loop "
                                  "needs a motion");

  if (options_.resume) {
    state_ = read_checkpoint(output_directory(case_, options_) + "/checkpoint.h5");
    if (state_.dies.size() != dies_.size())
      throw InputError("checkpoint: " + std::to_string(state_.dies.size()) + " dies, the case has " +
                       std::to_string(dies_.size()));
    if (state_.mesh.tets.size() != initial.tets.size() || state_.mesh.nodes.size() != initial.nodes.size())
      throw InputError("checkpoint: the mesh does not match the case's (was the case changed?)");
  } else {
    state_.mesh = std::move(initial);
    state_.unknowns = {imposed_.values, Eigen::VectorXd::Zero(3 * state_.mesh.tet_count())};
    state_.equivalent_strain.assign(state_.mesh.tets.size(), 0.0);
    state_.dies.assign(dies_.size(), DieState{});
    state_.volume.initial = mesh::volume(state_.mesh);
  }
  states_.assign(state_.mesh.tets.size(), body_state_);
  for (int e = 0; e < state_.mesh.tet_count(); ++e) states_[e].equivalent_strain = state_.equivalent_strain[e];
  for (int k = 0; k < imposed_.values.size(); ++k)
    if (imposed_.prescribed[k]) state_.unknowns.nodal[k] = imposed_.values[k];
}

void Run::log_header() const {
  const BodySpec& body = case_.bodies.front();
  log::info("anvil %s — %s%s", ANVIL_VERSION, case_.path.c_str(), options_.resume ? " (resumed)" : "");
  if (!case_.title.empty()) log::info("  %s", case_.title.c_str());
  for (const std::string& change : case_.overrides) log::info("  --set %s", change.c_str());
  log::info("body '%s': %d nodes, %d tetrahedra, volume %.6g mm3", body.name.c_str(), state_.mesh.node_count(),
            state_.mesh.tet_count(), mesh::volume(state_.mesh));
  log::info("  material %s: %s, at %g C", body.material_file.c_str(), law_->describe().c_str(), body_state_.temperature);
  for (std::size_t i = 0; i < conditions_.size(); ++i)
    log::info("  boundary '%s': %zu nodes", conditions_[i].name.c_str(), imposed_.nodes_of_condition[i].size());
  for (const Die& d : dies_)
    log::info("  die '%s': %s; %s; friction %s%s", d.name.c_str(), d.surface->describe().c_str(),
              d.kinematics ? d.kinematics->describe().c_str() : "fixed", contact::describe(d.friction).c_str(),
              std::isfinite(d.load_limit) ? (", load limit " + std::to_string(d.load_limit) + " N").c_str() : "");
  if (!dies_.empty())
    log::info("  contact: penalty %g x mean flow stress / %.4g mm/s (set each increment), friction regularisation "
              "%.3g mm/s", case_.contact.penalty, reference_velocity_, case_.contact.regularisation * reference_velocity_);
  std::string effect_list;
  for (const auto& e : effects_) effect_list += " " + e;
  log::info("effects:%s", effect_list.c_str());
  log::info("unknowns: %d (velocity and pressure, after %d prescribed)", solver_->free_count(),
            static_cast<int>(imposed_.prescribed.size()) - solver_->free_count());
  log::info("solver: %s (asked: %s), Newton tolerance %.1e, %d threads",
            solver::to_string(solver_->linear_solver()).c_str(), solver::to_string(case_.linear_solver).c_str(),
            case_.newton.tolerance, tbb::info::default_concurrency());
}

double Run::choose_time_step(double nominal) {
  const TimeSpec& t = case_.time;
  double dt = nominal;
  // Largest nodal displacement per increment relative to the local element size
  // (velocity of the last increment; none yet at the start).
  const std::vector<double> size = local_size(state_.mesh);
  for (int i = 0; i < state_.mesh.node_count(); ++i) {
    const double speed = state_.unknowns.nodal.segment<3>(4 * i).norm();
    if (speed > 0.0) dt = std::min(dt, t.max_displacement * size[i] / speed);
  }
  // Stop criteria are met exactly rather than overshot.
  if (std::isfinite(t.end_time)) dt = std::min(dt, t.end_time - state_.time);
  if (std::isfinite(t.final_stroke)) {
    const double speed = dies_[t.stroke_die].velocity(state_.dies[t.stroke_die], dt).norm();
    if (speed > 0.0) dt = std::min(dt, (t.final_stroke - state_.dies[t.stroke_die].stroke) / speed);
  }
  if (t.final_gap > 0.0) {
    const int lower = 1 - upper_die_;
    const double closing = dies_[lower].velocity(state_.dies[lower], dt).z() -
                           dies_[upper_die_].velocity(state_.dies[upper_die_], dt).z();
    if (closing > 0.0) dt = std::min(dt, (die_gap() - t.final_gap) / closing);
  }
  return dt;
}

bool Run::try_increment(double dt, solver::NewtonReport& report) {
  if (!dies_.empty()) {
    // Candidates: boundary nodes that can reach a die within the increment.
    std::vector<contact::DieView> views;
    double die_speed = 0.0;
    for (std::size_t d = 0; d < dies_.size(); ++d) {
      const Eigen::Vector3d v = dies_[d].velocity(state_.dies[d], dt);
      die_speed = std::max(die_speed, v.norm());
      views.push_back({dies_[d].surface.get(), state_.dies[d].displacement, v, dies_[d].friction});
    }
    double body_speed = 0.0;
    for (int i = 0; i < state_.mesh.node_count(); ++i)
      body_speed = std::max(body_speed, state_.unknowns.nodal.segment<3>(4 * i).norm());
    const double reach = 2.0 * (die_speed + std::max(body_speed, die_speed)) * dt + 0.05 * reference_length_;
    {
      Timers::Scope scope(timers_, "search");
      contact_.search(state_.mesh, views, reach);
    }
    // Gap tolerance: a penetration velocity of 1e-4 of the reference speed is
    // 1e-4 of the stroke over the run, and projection removes it anyway.
    contact_.set_increment({dt, penalty_, case_.contact.regularisation * reference_velocity_,
                            1e-4 * reference_velocity_, &node_flow_stress_, &node_consistency_});
  }
  // Volume compensation: the flow of this increment is asked to restore the
  // volume lost so far (explicit update error, O(Δt) over a run, and contact
  // projection): ∫ q div v = ∫ q g with g = (V₀ − V)/(V Δt), entered as the
  // pressure rows of the external vector (r_p = −∫N (div v − g)).
  external_ = imposed_.nodal_forces;
  if (compensate_volume_) {
    const double volume = mesh::volume(state_.mesh);
    // Restored over at least the nominal increment, so a short increment
    // (a stop criterion, a cut) does not get a large dilatation.
    const double g = (state_.volume.initial - volume) / (volume * std::max(dt, nominal_step_));
    for (int e = 0; e < state_.mesh.tet_count(); ++e) {
      const double quarter = 0.25 * mesh::signed_volume(state_.mesh, e);
      for (int node : state_.mesh.tets[e]) external_[4 * node + 3] -= g * quarter;
    }
  }
  const solver::IncrementProblem problem{*law_, states_, external_, {}, dies_.empty() ? nullptr : &contact_,
                                         reference_velocity_, reference_force_};
  Timers::Scope scope(timers_, "newton");
  report = solver_->solve(problem, case_.newton, state_.unknowns);
  return report.converged;
}

void Run::record_loads(int increment, double time) {
  const std::vector<Eigen::Vector3d> die_force =
      dies_.empty() ? std::vector<Eigen::Vector3d>{} : contact_.die_forces(state_.unknowns.nodal);
  for (std::size_t s = 0; s < surfaces_.size(); ++s) {
    const LoadSurface& surface = surfaces_[s];
    Eigen::Vector3d force;
    double stroke = 0.0;
    if (surface.die >= 0) {
      force = die_force[surface.die];
      stroke = state_.dies[surface.die].stroke;
    } else {
      // Force on the plate: minus the reaction on the body.
      force = -reaction(imposed_, surface.condition, solver_->residual());
      const auto& v = conditions_[surface.condition].velocity;
      stroke = time * std::sqrt(std::pow(v[0].value_or(0.0), 2) + std::pow(v[1].value_or(0.0), 2) +
                                       std::pow(v[2].value_or(0.0), 2));
    }
    state_.loads.push_back({increment, time, int(s), stroke, force});
  }
}

void Run::write_outputs(bool force) {
  Timers::Scope scope(timers_, "output");
  std::ostringstream loads;
  loads << "increment,time_s,surface,stroke_mm,Fx_N,Fy_N,Fz_N\n";
  loads.precision(10);
  for (const LoadRecord& r : state_.loads)
    loads << r.increment << "," << r.time << "," << surfaces_[r.surface].name << "," << r.stroke << "," << r.force.x()
          << "," << r.force.y() << "," << r.force.z() << "\n";
  io::write_file_atomically(out_ + "/loads.csv", loads.str());

  const bool vtk_due = case_.write_vtk && (force || state_.increment % case_.vtk_every == 0);
  if (vtk_due && last_written_ != state_.increment) {
    const mesh::TetMesh& mesh = state_.mesh;
    const bool elastic = law_->is_elastic();
    const ElementFields fields = element_fields(mesh, *law_, states_, state_.unknowns);
    io::Field velocity{elastic ? "displacement" : "velocity", 3, {}}, pressure{"pressure", 1, {}};
    io::Field contact_status{"contact_status", 1, std::vector<double>(mesh.nodes.size(), 0.0)};
    io::Field contact_pressure{"contact_pressure", 1, std::vector<double>(mesh.nodes.size(), 0.0)};
    io::Field gap{"gap", 1, std::vector<double>(mesh.nodes.size(), -1.0)};
    for (int i = 0; i < mesh.node_count(); ++i) {
      for (int k = 0; k < 3; ++k) velocity.values.push_back(state_.unknowns.nodal[4 * i + k]);
      pressure.values.push_back(state_.unknowns.nodal[4 * i + 3]);
    }
    if (!dies_.empty()) {
      // Status: 0 far from dies, 1 candidate (near a die), 2 in contact. Gap at
      // the start of the increment (mm), −1 where no die is near.
      const auto& candidates = contact_.candidates();
      for (std::size_t i = 0; i < candidates.size(); ++i) {
        const int node = candidates[i].node;
        const double p = contact_.pressure(int(i), state_.unknowns.nodal);
        contact_status.values[node] = p > 0.0 ? 2.0 : 1.0;
        contact_pressure.values[node] = p;
        gap.values[node] = std::max(candidates[i].gap, 0.0);
      }
    }
    io::Field stress{"stress", 6, {}}, rate{elastic ? "equivalent_strain" : "equivalent_strain_rate", 1, {}},
        strain{"equivalent_strain", 1, {}}, body_id{"body_id", 1, {}}, quality{"element_quality", 1, {}};
    for (int e = 0; e < mesh.tet_count(); ++e) {
      const material::Vec6 s = material::to_components(fields.stress[e]);
      stress.values.insert(stress.values.end(), s.data(), s.data() + 6);
      rate.values.push_back(fields.rate[e]);
      strain.values.push_back(state_.equivalent_strain[e]);
      body_id.values.push_back(0);
      quality.values.push_back(mesh::quality(mesh, e));
    }
    std::vector<io::Field> cell_fields{stress, rate, body_id, quality};
    if (!elastic && case_.time.enabled) cell_fields.push_back(strain);
    std::vector<io::Field> point_fields{velocity, pressure};
    if (!dies_.empty()) point_fields.insert(point_fields.end(), {contact_status, contact_pressure, gap});
    series_->write(state_.increment, state_.time, 0, case_.bodies.front().name, mesh, point_fields, cell_fields);
    for (std::size_t d = 0; d < dies_.size(); ++d) {
      const die::SurfaceTriangles& t = dies_[d].surface->triangles();
      std::vector<mesh::Point> moved = t.vertices;
      for (auto& p : moved) p += state_.dies[d].displacement;
      series_->write_surface(state_.increment, state_.time, int(d) + 1, dies_[d].name, moved, t.faces);
    }
    state_.outputs = series_->entries();
    last_written_ = state_.increment;
  }
  const bool checkpoint_due = case_.time.enabled && case_.checkpoint_every > 0 &&
                              (force || state_.increment % case_.checkpoint_every == 0);
  if (checkpoint_due && last_checkpoint_ != state_.increment) {
    Timers::Scope checkpoint(timers_, "checkpoint");
    write_checkpoint(out_ + "/checkpoint.h5", state_);
    last_checkpoint_ = state_.increment;
  }
}

std::string Run::stop_reason() const {
  const TimeSpec& t = case_.time;
  const double tolerance = 1e-9;
  if (state_.time >= t.end_time * (1.0 - tolerance)) return "end time reached";
  if (std::isfinite(t.final_stroke) && state_.dies[t.stroke_die].stroke >= t.final_stroke * (1.0 - tolerance))
    return "final stroke reached";
  if (t.final_gap > 0.0 && die_gap() <= t.final_gap * (1.0 + tolerance)) return "final die gap reached";
  if (std::isfinite(t.max_load))
    for (auto r = state_.loads.rbegin(); r != state_.loads.rend() && r->increment == state_.increment; ++r)
      if (r->force.norm() >= t.max_load) return "maximum load reached";
  for (std::size_t d = 0; d < dies_.size(); ++d)
    if (state_.dies[d].speed_factor < 1e-3) return "press stalled at its load limit (die '" + dies_[d].name + "')";
  if (state_.increment >= t.max_increments) return "maximum number of increments reached";
  return "";
}

double Run::progress() const {
  const TimeSpec& t = case_.time;
  double f = 0.0;
  if (std::isfinite(t.end_time)) f = std::max(f, state_.time / t.end_time);
  if (std::isfinite(t.final_stroke)) f = std::max(f, state_.dies[t.stroke_die].stroke / t.final_stroke);
  if (t.final_gap > 0.0) f = std::max(f, (die_gap0_ - die_gap()) / (die_gap0_ - t.final_gap));
  return f;
}

double Run::die_gap() const {
  return die_gap0_ + state_.dies[upper_die_].displacement.z() - state_.dies[1 - upper_die_].displacement.z();
}

double Run::press_speed() const {
  // The fastest die over a short probe step (an increment is far longer).
  const double probe = 1e-3 * case_.time.stroke_increment / reference_velocity_;
  double speed = reference_velocity_;
  for (std::size_t d = 0; d < dies_.size(); ++d) speed = std::max(speed, dies_[d].velocity(state_.dies[d], probe).norm());
  return speed;
}

void Run::set_contact_scales() {
  // Friction needs σ₀ and K at the contact nodes: taken from the last
  // increment's solution (frozen within the increment, so the tangent stays exact).
  const ElementFields fields = element_fields(state_.mesh, *law_, states_, state_.unknowns);
  // The penalty and the force scale use σ₀ at the process rate v_ref / body
  // size instead: a billet left at rest by the dies has almost no strain
  // rate, and scales taken from it would shrink with every increment at rest.
  const double reference_rate = reference_velocity_ / body_size_;
  std::vector<double> weight(state_.mesh.nodes.size(), 0.0);
  std::fill(node_flow_stress_.begin(), node_flow_stress_.end(), 0.0);
  std::fill(node_consistency_.begin(), node_consistency_.end(), 0.0);
  double process_flow_stress = 0.0;
  for (int e = 0; e < state_.mesh.tet_count(); ++e) {
    const double rate = fields.rate[e] > 0.0 ? fields.rate[e] : reference_rate;
    const double flow = law_->flow_stress(rate, states_[e]), k = law_->consistency(states_[e]);
    for (int node : state_.mesh.tets[e]) node_flow_stress_[node] += flow, node_consistency_[node] += k, weight[node] += 1.0;
    process_flow_stress += law_->flow_stress(reference_rate, states_[e]) / state_.mesh.tet_count();
  }
  for (std::size_t i = 0; i < weight.size(); ++i) node_flow_stress_[i] /= weight[i], node_consistency_[i] /= weight[i];
  // Penalty ρ = factor × σ₀/v_ref: the penetration velocity σn/ρ is then
  // about 1/factor of the press speed, whatever the flow stress does
  // (hardening, temperature) along the stroke.
  penalty_ = case_.contact.penalty * process_flow_stress / reference_velocity_;
  reference_force_ = process_flow_stress * std::pow(mesh::volume(state_.mesh), 2.0 / 3.0);
}

bool Run::update_geometry(double dt, std::string& failure) {
  Timers::Scope scope(timers_, "update");
  // Strain rates of the solution on the geometry it was solved on, for ε̄.
  solved_rates_ = element_fields(state_.mesh, *law_, states_, state_.unknowns).rate;
  // x ← x + Δt v; contact nodes back onto the die at its new position.
  const double volume_before = mesh::volume(state_.mesh);
  for (int i = 0; i < state_.mesh.node_count(); ++i) state_.mesh.nodes[i] += dt * state_.unknowns.nodal.segment<3>(4 * i);
  for (std::size_t d = 0; d < dies_.size(); ++d) dies_[d].advance(state_.dies[d], dt);
  record_loads(state_.increment + 1, state_.time + dt);
  const double volume_flow = mesh::volume(state_.mesh);
  for (std::size_t i = 0; i < contact_.candidates().size(); ++i) {
    const contact::ContactCandidate& c = contact_.candidates()[i];
    const Eigen::Vector3d& shift = state_.dies[c.die].displacement;
    const die::SurfaceProjection p = dies_[c.die].surface->project(state_.mesh.nodes[c.node] - shift);
    if (contact_.pressure(int(i), state_.unknowns.nodal) > 0.0 || p.distance < 0.0)
      state_.mesh.nodes[c.node] = p.point + shift;
  }
  for (int e = 0; e < state_.mesh.tet_count(); ++e)
    if (mesh::signed_volume(state_.mesh, e) <= 0.0) {
      failure = "element " + std::to_string(e + 1) + " would invert";
      return false;
    }
  const double volume_after = mesh::volume(state_.mesh);
  state_.volume.solver += volume_flow - volume_before;
  if (compensate_volume_) // g V Δt, with g as set in try_increment()
    state_.volume.compensation += (state_.volume.initial - volume_before) * std::min(1.0, dt / nominal_step_);
  state_.volume.projection += volume_after - volume_flow;
  state_.volume.largest_increment =
      std::max(state_.volume.largest_increment, std::abs(volume_after - volume_before) / volume_before);
  return true;
}

void Run::execute() {
  setup();
  out_ = output_directory(case_, options_);
  std::filesystem::create_directories(out_);
  log::open_file(out_ + "/anvil.log", options_.resume);
  solver_ = std::make_unique<solver::IncrementSolver>(state_.mesh, imposed_.prescribed, case_.linear_solver, timers_);
  log_header();
  series_ = std::make_unique<io::VtkSeries>(out_, "anvil");
  if (options_.resume) {
    series_->resume(state_.outputs, state_.time);
    log::info("resumed from %s/checkpoint.h5 at increment %d, t = %.6g s", out_.c_str(), state_.increment, state_.time);
    last_written_ = last_checkpoint_ = state_.increment;
  }
  node_flow_stress_.assign(state_.mesh.nodes.size(), 0.0);
  node_consistency_.assign(state_.mesh.nodes.size(), 0.0);

  if (!case_.time.enabled) {
    // One increment on the initial geometry.
    state_.increment = 1;
    log::info("increment 1");
    solver::NewtonReport report;
    if (!try_increment(1.0, report)) throw RunError("increment 1 of body '" + case_.bodies.front().name + "': " + report.failure);
    state_.newton_iterations = static_cast<int>(report.iterations.size());
    last_report_ = report;
    record_loads(1, 0.0);
    for (std::size_t s = 0; s < surfaces_.size(); ++s) {
      const Eigen::Vector3d& f = state_.loads[s].force;
      log::info("  load on '%s': Fx %.6g N  Fy %.6g N  Fz %.6g N", surfaces_[s].name.c_str(), f.x(), f.y(), f.z());
    }
    write_outputs(true);
    write_summary(seconds_since(start_));
    return;
  }

  const TimeSpec& t = case_.time;
  log::info("time loop: stroke increment %g mm, nodal displacement <= %g x element size, stop: %s%s%s%s",
            t.stroke_increment, t.max_displacement,
            std::isfinite(t.final_stroke) ? ("stroke " + std::to_string(t.final_stroke) + " mm of '" +
                                             dies_[t.stroke_die].name + "' ").c_str() : "",
            t.final_gap > 0.0 ? ("gap " + std::to_string(t.final_gap) + " mm ").c_str() : "",
            std::isfinite(t.max_load) ? ("load " + std::to_string(t.max_load) + " N ").c_str() : "",
            std::isfinite(t.end_time) ? ("time " + std::to_string(t.end_time) + " s").c_str() : "");
  resumed_time_ = seconds_since(start_);
  const double progress_at_start = progress();
  std::string reason;
  while ((reason = stop_reason()).empty()) {
    if (!dies_.empty()) set_contact_scales();
    nominal_step_ = t.stroke_increment / press_speed();
    double dt = choose_time_step(nominal_step_);
    const double nominal = dt;
    const IncrementStart saved{state_.mesh.nodes, state_.unknowns, state_.dies, state_.loads.size()};
    solver::NewtonReport report;
    int cuts = 0;
    for (;;) {
      bool ok = try_increment(dt, report);
      // A free node reaching a die inside the increment ends it there (contact event).
      if (ok && !dies_.empty()) {
        const double touch = contact_.first_contact_time(state_.unknowns.nodal, 1e-3 * reference_length_);
        if (touch < dt && touch > t.min_step_fraction * nominal) {
          dt = touch;
          state_.unknowns = saved.unknowns;
          ok = try_increment(dt, report);
        }
      }
      std::string failure = report.failure;
      if (ok && update_geometry(dt, failure)) break;
      // Failure: back to the last good state, halve Δt.
      state_.mesh.nodes = saved.nodes;
      state_.unknowns = saved.unknowns;
      state_.dies = saved.dies;
      state_.loads.resize(saved.load_count);
      if (++cuts > t.max_cuts) {
        write_outputs(true);
        write_summary(seconds_since(start_));
        throw RunError("increment " + std::to_string(state_.increment + 1) + " at t = " + std::to_string(state_.time) +
                       " s: " + failure + " after " + std::to_string(t.max_cuts) +
                       " time-step cuts; the last good increment (" + std::to_string(state_.increment) +
                       ") is written and checkpointed in " + out_);
      }
      dt *= 0.5;
      log::info("  increment %d: %s; retrying with dt = %.4g s (cut %d of %d)", state_.increment + 1, failure.c_str(),
                dt, cuts, t.max_cuts);
    }
    ++state_.increment;
    state_.time += dt;
    state_.newton_iterations += static_cast<int>(report.iterations.size());
    last_report_ = report;
    // ε̄ += Δt ε̄̇ per element, with the rates of the converged increment on the geometry it was solved on.
    for (int e = 0; e < state_.mesh.tet_count(); ++e) {
      state_.equivalent_strain[e] += dt * solved_rates_[e];
      states_[e].equivalent_strain = state_.equivalent_strain[e];
    }
    // A load-limited press slows down for the next increment.
    for (std::size_t d = 0; d < dies_.size(); ++d) {
      const Eigen::Vector3d v = dies_[d].velocity(state_.dies[d], dt);
      if (v.norm() == 0.0) continue;
      const Eigen::Vector3d& f = state_.loads[state_.loads.size() - surfaces_.size() + d].force;
      dies_[d].limit_speed(state_.dies[d], f.dot(-v.normalized()), law_->rate_sensitivity(states_.front()));
    }
    // Progress line.
    const LoadRecord& lead = state_.loads[state_.loads.size() - surfaces_.size()];
    // Time left: this run's pace over the progress made in it (stop criteria fraction).
    const double done = progress(), elapsed = seconds_since(start_) - resumed_time_;
    const double eta = done > progress_at_start ? elapsed / (done - progress_at_start) * (1.0 - done) : 0.0;
    log::info("inc %4d  t %.5g s  stroke %.4g mm  dt %.3g s  load(%s) %.5g kN  newton %zu  contact %d  volume %+.3f%%  "
              "left ~%s",
              state_.increment, state_.time, lead.stroke, dt, surfaces_[lead.surface].name.c_str(),
              lead.force.norm() / 1e3, report.iterations.size(), dies_.empty() ? 0 : contact_.active_count(),
              100.0 * (mesh::volume(state_.mesh) / state_.volume.initial - 1.0), clock_text(eta).c_str());
    write_outputs(false);
  }
  log::info("stop: %s at increment %d, t = %.6g s", reason.c_str(), state_.increment, state_.time);
  write_outputs(true);
  write_summary(seconds_since(start_));
}

void Run::write_summary(double total) const {
  const BodySpec& body = case_.bodies.front();
  std::ostringstream summary;
  summary.precision(10);
  const double volume_end = mesh::volume(state_.mesh);
  summary << "{\n  \"case\": " << json_string(case_.path) << ",\n  \"title\": " << json_string(case_.title) << ",\n"
          << "  \"anvil_version\": " << json_string(ANVIL_VERSION) << ",\n"
          << "  \"bodies\": [{\"name\": " << json_string(body.name) << ", \"nodes\": " << state_.mesh.node_count()
          << ", \"elements\": " << state_.mesh.tet_count() << ", \"unknowns\": " << solver_->free_count()
          << ", \"volume_mm3\": " << volume_end << "}],\n"
          << "  \"increments\": " << state_.increment << ",\n  \"time_s\": " << state_.time << ",\n"
          << "  \"newton_iterations\": " << state_.newton_iterations << ",\n";
  if (!last_report_.iterations.empty())
    summary << "  \"final_residual\": {\"force\": " << last_report_.iterations.back().force_residual
            << ", \"div\": " << last_report_.iterations.back().flux_residual << "},\n";
  summary << "  \"volume_mm3\": {\"start\": " << state_.volume.initial << ", \"end\": " << volume_end
          << ", \"change_solver\": " << state_.volume.solver << ", \"of_which_compensation\": "
          << state_.volume.compensation << ", \"change_contact_projection\": "
          << state_.volume.projection << ", \"largest_relative_change_per_increment\": "
          << state_.volume.largest_increment << ", \"relative_change\": "
          << (state_.volume.initial > 0 ? volume_end / state_.volume.initial - 1.0 : 0.0) << "},\n";
  summary << "  \"dies\": [";
  for (std::size_t d = 0; d < dies_.size(); ++d)
    summary << (d ? ", " : "") << "{\"name\": " << json_string(dies_[d].name) << ", \"stroke_mm\": " << state_.dies[d].stroke
            << "}";
  summary << "],\n  \"effects\": [";
  for (std::size_t i = 0; i < effects_.size(); ++i) summary << (i ? ", " : "") << json_string(effects_[i]);
  summary << "],\n  \"wall_time_s\": {";
  for (const auto& [phase, seconds] : timers_.all()) summary << json_string(phase) << ": " << seconds << ", ";
  summary << "\"total\": " << total << "}\n}\n";
  io::write_file_atomically(out_ + "/summary.json", summary.str());
  log::info("done in %.2f s (search %.2f s, assembly %.2f s, contact %.2f s, solve %.2f s, update %.2f s, output %.2f s, "
            "checkpoint %.2f s); results in %s/",
            total, timers_.seconds("search"), timers_.seconds("assembly"), timers_.seconds("contact"),
            timers_.seconds("solve"), timers_.seconds("update"), timers_.seconds("output"),
            timers_.seconds("checkpoint"), out_.c_str());
  log::close_file();
}

} // namespace

std::string output_directory(const Case& c, const RunOptions& options) {
  if (!options.output_directory.empty()) return options.output_directory;
  if (!c.output_directory.empty()) return c.output_directory;
  return "out/" + std::filesystem::path(c.path).stem().string();
}

void run(const Case& c, const RunOptions& options) { Run(c, options).execute(); }

} // namespace anvil::scene
