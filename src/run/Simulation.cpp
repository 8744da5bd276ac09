// The time loop (docs/design.md §4): choose Δt → solve the increment → accept it →
// remesh if due → write. A case without a `time` section is one increment on
// the initial geometry.
#include "anvil/run/Simulation.h"

#include "anvil/core/Timers.h"
#include "anvil/core/error.h"
#include "anvil/core/interrupt.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/io/Checkpoint.h"
#include "anvil/io/RunWriter.h"
#include "anvil/io/load_plot.h"
#include "anvil/remesh/Remesher.h"
#include "anvil/run/Increment.h"
#include "anvil/run/TimeStepControl.h"
#include "anvil/run/fold_watch.h"
#include "anvil/run/load_check.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/Scene.h"
#include "anvil/scene/fingerprint.h"
#include "anvil/solver/PetscSession.h"

#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <deque>
#include <filesystem>
#include <limits>
#include <numeric>

namespace anvil::run {

using namespace scene; // the loop runs on the scene's types throughout
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string clock_text(double seconds) {
  char text[32];
  const long s = std::lround(seconds);
  std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return text;
}

/// The time a run has left (s): the pace (wall time per unit of progress)
/// over the last 10 increments, so that it follows the run as the contact
/// grows or the mesh is refined, and a remesh or a cut increment weighs one
/// in ten. The first 3 increments of a run (or of a resumed run) are left
/// out, their Newton counts are not the run's (the contact settles, the
/// first preconditioner is built); unknown (NaN) until 3 more are done.
class TimeLeft {
public:
  double update(double progress, double now) {
    if (++updates_ <= kSettling) return std::numeric_limits<double>::quiet_NaN();
    points_.push_back({progress, now});
    if (points_.size() > kWindow + 1) points_.pop_front();
    if (points_.size() <= kFirst) return std::numeric_limits<double>::quiet_NaN();
    const auto& [p0, t0] = points_.front();
    if (progress <= p0) return std::numeric_limits<double>::quiet_NaN();
    return (now - t0) / (progress - p0) * (1.0 - progress);
  }

private:
  static constexpr std::size_t kSettling = 4, kWindow = 10, kFirst = 3;
  std::size_t updates_ = 0;                      ///< calls so far: the start, then one per increment
  std::deque<std::pair<double, double>> points_; ///< (progress, wall time s) after each increment
};

void log_header(const Scene& scene, const Discretisation& disc, const RunState& state, const RunOptions& options) {
  const Case& c = scene.input;
  log::info("anvil %s — %s%s", ANVIL_VERSION, c.path.c_str(), options.resume ? " (resumed)" : "");
  if (!c.title.empty()) log::info("  %s", c.title.c_str());
  for (const std::string& change : c.overrides)
    log::info("  --set %s", change.c_str());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const Body& body = scene.bodies[b];
    log::info("body '%s': %d nodes, %d tetrahedra, volume %.6g mm3", body.name.c_str(), state.bodies[b].node_count,
              state.bodies[b].tet_count, mesh::volume(state.mesh, state.bodies[b]));
    log::info("  material %s: %s, at %g C", body.material_file.c_str(), body.law->describe().c_str(),
              body.state.temperature);
  }
  for (std::size_t i = 0; i < scene.conditions.size(); ++i)
    log::info("  boundary '%s': %zu nodes", scene.conditions[i].name.c_str(),
              disc.imposed.nodes_of_condition[i].size());
  for (const Die& d : scene.dies)
    log::info("  die '%s': %s; %s; friction %s%s", d.name.c_str(), d.surface->describe().c_str(),
              d.kinematics ? d.kinematics->describe().c_str() : "fixed", contact::describe(d.friction).c_str(),
              std::isfinite(d.load_limit) ? (", load limit " + std::to_string(d.load_limit) + " N").c_str() : "");
  for (std::size_t p = 0; p < c.contact_pairs.size(); ++p)
    log::info("  contact pair '%s' (master '%s', slave '%s'): %s; friction %s",
              disc.pair_contact->pairs()[p].name.c_str(), scene.bodies[c.contact_pairs[p].master].name.c_str(),
              scene.bodies[c.contact_pairs[p].slave].name.c_str(), contact::describe(c.contact_pairs[p].method).c_str(),
              contact::describe(c.contact_pairs[p].friction).c_str());
  if (scene.has_contact())
    log::info("  contact: penalty %g x 3 x secant viscosity of the softest body / scene size (set each increment), "
              "friction regularisation %.3g mm/s",
              c.contact.penalty, c.contact.regularisation * scene.reference_velocity);
  log::info("loads: %s", scene.model_text().c_str());
  std::string effect_list;
  for (const auto& e : scene.effects)
    effect_list += " " + e;
  log::info("effects:%s", effect_list.c_str());
  const int free = disc.solver->free_count();
  log::info("unknowns: %d (velocity and pressure, after %d prescribed)", free,
            static_cast<int>(disc.imposed.prescribed.size()) - free);
  log::info("solver: %s (asked: %s), Newton tolerance %.1e (|dv|/|v| %.1e), %d process%s x %d thread%s",
            solver::to_string(disc.solver->linear_solver().kind()).c_str(),
            solver::to_string(c.linear_solver.kind).c_str(), c.newton.tolerance, c.newton.increment_tolerance,
            processes::count(), processes::count() > 1 ? "es" : "", tbb::info::default_concurrency(),
            tbb::info::default_concurrency() > 1 ? "s" : "");
  if (c.time.enabled) {
    const TimeSpec& t = c.time;
    log::info(
        "time loop: stroke increment %g mm, nodal displacement <= %g x element size, stop: %s%s%s%s",
        t.stroke_increment, t.max_displacement,
        std::isfinite(t.final_stroke)
            ? ("stroke " + std::to_string(t.final_stroke) + " mm of '" + scene.dies[t.stroke_die].name + "' ").c_str()
            : "",
        t.final_gap > 0.0 ? ("gap " + std::to_string(t.final_gap) + " mm ").c_str() : "",
        std::isfinite(t.max_load) ? ("load " + std::to_string(t.max_load) + " N ").c_str() : "",
        std::isfinite(t.end_time) ? ("time " + std::to_string(t.end_time) + " s").c_str() : "");
  }
}

/// "  T 812..1143 C (heat 6 %)": the bodies' temperature range and the heat
/// step's share `heat_share` of the increment's wall time; empty when isothermal.
std::string temperature_text(const RunState& state, double heat_share) {
  if (state.temperature.empty()) return "";
  const auto [low, high] = std::minmax_element(state.temperature.begin(), state.temperature.end());
  char text[80];
  std::snprintf(text, sizeof text, "  T %.0f..%.0f C (heat %.0f %%)", *low, *high, 100.0 * heat_share);
  return text;
}

/// The progress line of an accepted increment: its columns are explained in the README.
void log_progress(const Scene& scene, const Discretisation& disc, const RunState& state, const IncrementOutcome& inc,
                  double time_left, double heat_share) {
  const LoadRecord& lead = state.loads[state.loads.size() - scene.surfaces.size()];
  const int contacts = (scene.dies.empty() ? 0 : disc.die_contact.active_count()) +
                       (disc.pair_contact ? disc.pair_contact->active_count() : 0);
  std::string krylov =
      disc.solver->linear_solver().iterative() ? " krylov " + std::to_string(inc.report.linear_iterations) : "";
  if (inc.couplings > 0) krylov += " coupled " + std::to_string(inc.couplings);
  // The load of the whole part, and of the model when it is a symmetry model's share.
  char model[48] = "";
  if (scene.symmetry_copies > 1)
    std::snprintf(model, sizeof model, " (%d x %.5g)", scene.symmetry_copies, lead.press_load() / 1e3);
  log::info("inc %4d  t %.5g s  stroke %.4g mm  dt %.3g s  load(%s) %.5g kN%s at %.4g mm  newton %zu%s  contact %d  "
            "volume %+.3f%% (%.3f%% inside dies)%s  left ~%s",
            state.increment, state.time, surface_stroke(scene, state.dies, lead.surface, state.time), inc.time_step,
            scene.surfaces[lead.surface].name.c_str(), scene.whole_part_load(lead) / 1e3, model, lead.stroke,
            inc.report.iterations.size(), krylov.c_str(), contacts,
            100.0 * (mesh::volume(state.mesh) / state.volume.initial - 1.0),
            100.0 * std::accumulate(state.inside_dies.begin(), state.inside_dies.end(), 0.0) / state.volume.initial,
            temperature_text(state, heat_share).c_str(), std::isnan(time_left) ? "?" : clock_text(time_left).c_str());
}

void finish(const Scene& scene, const Discretisation& disc, RunState& state, io::RunWriter& writer,
            const solver::NewtonReport& last, Timers& timers, Clock::time_point start) {
  writer.write(scene, disc, state, true, timers);
  const double total = seconds_since(start);
  processes::on_root([&] {
    if (scene.input.time.enabled) {
      std::vector<std::string> surfaces;
      for (const LoadSurface& s : scene.surfaces)
        surfaces.push_back(s.name);
      const std::string title = std::filesystem::path(scene.input.path).stem().string();
      if (const std::string why =
              io::write_load_plot(writer.directory(), title, surfaces, state.loads, scene.symmetry_copies);
          !why.empty())
        log::info("loads.png not written: %s", why.c_str());
    }
    writer.write_summary(scene, disc, state, last, timers, total);
  });
  log::info("done in %.2f s (search %.2f s, assembly %.2f s, contact %.2f s, solver setup %.2f s, solve %.2f s, "
            "update %.2f s, output %.2f s, checkpoint %.2f s); results in %s/",
            total, timers.seconds("search"), timers.seconds("assembly"), timers.seconds("contact"),
            timers.seconds("solver setup"), timers.seconds("solve"), timers.seconds("update"), timers.seconds("output"),
            timers.seconds("checkpoint"), writer.directory().c_str());
  log::close_file();
}

/// The changes of the case since the checkpoint at `path`: refused unless
/// the user allowed them; the lines to log (anvil.log is not open yet).
std::vector<std::string> compare_with_checkpoint(const Scene& scene, const std::string& path, bool allow_changes) {
  const std::vector<std::string> before = io::read_checkpoint_fingerprint(path);
  if (before.empty())
    return {"checkpoint written by an older anvil: the case is not compared with the run it continues"};
  const std::vector<std::string> changes = fingerprint_changes(before, scene.fingerprint);
  if (changes.empty()) return {};
  if (!allow_changes) {
    std::string list;
    for (std::size_t i = 0; i < changes.size() && i < 8; ++i)
      list += (i ? "; " : "") + changes[i];
    if (changes.size() > 8) list += "; and " + std::to_string(changes.size() - 8) + " more";
    throw InputError(path + ": the case changed since this checkpoint was written (" + list +
                     "); resume anyway with --allow-changes");
  }
  std::vector<std::string> lines = {"resuming with " + std::to_string(changes.size()) +
                                    " change(s) since the checkpoint (--allow-changes):"};
  for (const std::string& change : changes)
    lines.push_back("  " + change);
  return lines;
}

/// Creates the output folder `out`, or throws InputError saying why it cannot
/// be used: the last input check, so an input error leaves nothing behind.
void prepare_output_folder(const std::string& out) {
  std::error_code error;
  if (std::filesystem::exists(out, error) && !std::filesystem::is_directory(out, error))
    throw InputError(out + ": the output folder is not a folder (a file of that name exists)");
  std::filesystem::create_directories(out, error);
  if (error) throw InputError(out + ": cannot create the output folder: " + error.message());
  const std::string probe = out + "/.anvil_write_test";
  if (std::FILE* f = std::fopen(probe.c_str(), "w")) {
    std::fclose(f);
    std::remove(probe.c_str());
  } else {
    throw InputError(out + ": cannot write in the output folder (read-only?)");
  }
}

} // namespace

std::string output_directory(const Case& c, const RunOptions& options) {
  if (!options.output_directory.empty()) return options.output_directory;
  if (!c.output_directory.empty()) return c.output_directory;
  return "out/" + std::filesystem::path(c.path).stem().string();
}

RunEnd run(const Case& c, const RunOptions& options) {
  const solver::ScopedPetscOptions petsc_options(c.petsc_options, c.path + ": solver.petsc_options");
  const Clock::time_point start = Clock::now();
  Timers timers;
  const Scene scene(c, timers);
  const std::string out = output_directory(c, options);
  RunState state;
  std::vector<std::string> changes;
  if (options.resume) {
    const std::string checkpoint = out + "/checkpoint.h5";
    state = io::read_checkpoint(checkpoint);
    changes = compare_with_checkpoint(scene, checkpoint, options.allow_changes);
    check_resumable(scene, state, checkpoint);
    state.inside_dies = inside_dies(scene, state);
  } else {
    state = initial_state(scene);
  }
  processes::on_root([&] { prepare_output_folder(out); });
  log::open_file(out + "/anvil.log", options.resume);
  Discretisation disc = discretise(scene, state, timers);
  log_header(scene, disc, state, options);
  io::RunWriter writer(out, state, options.resume);
  if (options.resume)
    log::info("resumed from %s/checkpoint.h5 at increment %d, t = %.6g s", out.c_str(), state.increment, state.time);
  for (const std::string& line : changes)
    log::info("%s", line.c_str());

  if (!c.time.enabled) {
    log::info("increment 1");
    const IncrementOutcome inc =
        solve_increment(scene, disc, state, {.nominal = 0.0, .planned = 1.0, .length = 1.0}, timers);
    if (!inc.converged()) throw RunError("increment 1: " + inc.failure);
    accept_without_motion(scene, inc, state, timers);
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
      const Eigen::Vector3d& f = state.loads[s].force;
      log::info("  load on '%s': Fx %.6g N  Fy %.6g N  Fz %.6g N", scene.surfaces[s].name.c_str(), f.x(), f.y(), f.z());
    }
    finish(scene, disc, state, writer, inc.report, timers, start);
    return {"one increment solved", true};
  }

  if (scene.thermal && !options.resume)
    state.heat.initial_heat =
        thermal::stored_heat(state.mesh, mesh::whole_range(state.mesh), disc.heat->materials(), state.temperature);
  if (scene.thermal && state.transfer_time < c.thermal.transfer_time) {
    transfer(scene, disc, state, timers);
    log::info("transfer: %.4g s in air%s before the press moves%s", c.thermal.transfer_time,
              scene.dies.empty() ? "" : " and on the dies the bodies touch", temperature_text(state, 0.0).c_str());
  }
  const TimeStepControl clock(scene);
  TimeLeft time_left;
  time_left.update(clock.progress(state), seconds_since(start));
  solver::NewtonReport last;
  double last_step = clock.next_step(state).length; // s, of the last increment accepted
  Stop stop;
  // SIGINT or SIGTERM: the increment under way is abandoned, the last
  // accepted one written and checkpointed (core/interrupt).
  auto interrupted = [&](int signal) {
    log::info("interrupted by %s during increment %d: increment %d (t = %.6g s) is the last accepted one",
              interrupt::name(signal), state.increment + 1, state.increment, state.time);
    finish(scene, disc, state, writer, last, timers, start);
    return RunEnd{std::string("interrupted by ") + interrupt::name(signal), false, signal, c.checkpoint_every > 0};
  };
  while (!(stop = clock.stop(state))) {
    if (const int signal = interrupt::requested()) return interrupted(signal);
    const Clock::time_point increment_start = Clock::now();
    Advance advanced = advance(scene, disc, state, clock, clock.next_step(state), timers);
    if (advanced.end == Advance::End::interrupted) return interrupted(interrupt::requested());
    IncrementOutcome& inc = advanced.increment;
    if (advanced.end == Advance::End::failed) {
      finish(scene, disc, state, writer, last, timers, start);
      throw RunError("increment " + std::to_string(state.increment + 1) + " at t = " + std::to_string(state.time) +
                     " s: " + inc.failure + " after " + std::to_string(c.time.max_cuts) +
                     " time-step cuts, heading for the stop criterion (" + clock.describe_stop(state) +
                     "); the last good increment (" + std::to_string(state.increment) +
                     ") is written and checkpointed in " + out);
    }
    last = inc.report;
    last_step = inc.time_step;
    const double heat_before = timers.seconds("effect heat");
    if (disc.heat) advance_heat(scene, disc, inc, state, timers);
    log_progress(scene, disc, state, inc, time_left.update(clock.progress(state), seconds_since(start)),
                 (timers.seconds("effect heat") - heat_before) / seconds_since(increment_start));
    if (c.detect_folds) watch_folds(scene, disc, state, timers);
    if (c.remeshing.enabled && !clock.stop(state)) {
      const std::vector<remesh::RemeshDue> due = remesh::remesh_due(scene, state, inc.time_step);
      if (!due.empty()) {
        remesh_checking_load(scene, state, due, disc.touching_die(state.unknowns.nodal), inc.fields.rate,
                             clock.next_step(state), timers);
        disc = discretise(scene, state, timers);
      }
    }
    // A run resumed from a checkpoint starts with a new linear solver (no kept
    // preconditioner): so does this one, and --resume stays exact.
    if (writer.write(scene, disc, state, false, timers)) disc.solver->restart_linear_solver();
  }
  log::info("stop: %s at increment %d, t = %.6g s", stop.reason.c_str(), state.increment, state.time);
  record_final_loads(scene, disc, state, last_step, timers);
  finish(scene, disc, state, writer, last, timers, start);
  if (!stop.complete)
    return {"stopped at increment " + std::to_string(state.increment) + ": " + stop.reason +
                "; the results so far are in " + out,
            false};
  return {stop.reason, true};
}

} // namespace anvil::run
