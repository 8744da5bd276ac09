// The time loop (docs/design.md §4): choose Δt → solve the increment → accept it →
// write its frame → remesh if due → checkpoint. A case without a `time`
// section is one increment on the initial geometry.
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
#include "anvil/run/blows.h"
#include "anvil/run/fold_watch.h"
#include "anvil/run/load_check.h"
#include "anvil/run/run_log.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/Scene.h"
#include "anvil/scene/fingerprint.h"
#include "anvil/solver/PetscSession.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <span>
#include <utility>

namespace anvil::run {

using namespace scene; // the loop runs on the scene's types throughout
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void finish(const Scene& scene, const Discretisation& disc, RunState& state, io::RunWriter& writer,
            const solver::NewtonReport& last, Timers& timers, Clock::time_point start) {
  // The checkpoint at a stop carries the preconditioner the next increment
  // would keep, so that --resume goes on exactly (solver/KeptSetUp.h).
  if (disc.solver) state.kept_setup = solver::gather_kept(disc.solver->kept_set_up());
  writer.write(scene, disc, state, true, timers);
  state.kept_setup = {};
  state.remesh_check_at_stop = {};
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

RunEnd run(const Case& c, const RunOptions& options, RunState* part) {
  const solver::ScopedPetscOptions petsc_options(c.petsc_options, c.path + ": solver.petsc_options");
  const Clock::time_point start = Clock::now();
  Timers timers;
  const RunState* carried = part && part->mesh.node_count() > 0 ? part : nullptr;
  const Scene scene(c, timers, carried);
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
    state = initial_state(scene, carried);
    first_blows(scene, state);
  }
  processes::on_root([&] { prepare_output_folder(out); });
  log::open_file(out + "/anvil.log", options.resume);
  Discretisation disc = discretise(scene, state, timers);
  if (options.resume && disc.solver) disc.solver->resume_with(std::move(state.kept_setup));
  state.kept_setup = {}; // a chain's next operation starts with a solver of its own
  log_header(scene, disc, state, options);
  const auto hand_over = [&] {
    if (part) *part = std::move(state);
  };
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
    hand_over();
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
  Stop stop;
  // SIGINT or SIGTERM: the increment under way is abandoned, the last
  // accepted one written and checkpointed (core/interrupt).
  auto interrupted = [&](int signal) {
    log::info("interrupted by %s during increment %d: increment %d (t = %.6g s) is the last accepted one",
              interrupt::name(signal), state.increment + 1, state.increment, state.time);
    finish(scene, disc, state, writer, last, timers, start);
    hand_over();
    return RunEnd{std::string("interrupted by ") + interrupt::name(signal), false, signal, c.checkpoint_every > 0};
  };
  if (scene.heat_only) {
    // Nothing moves (cooling, dwell, transfer): heat alone, in equal steps
    // of at most time.heat_step to the end time (steps of heat_step when
    // only a temperature ends it).
    const double step = c.time.heat_step > 0.0 ? c.time.heat_step : c.time.end_time / 50.0;
    while (!(stop = clock.stop(state))) {
      if (const int signal = interrupt::requested()) return interrupted(signal);
      const double left = c.time.end_time - state.time;
      const double dt = std::isfinite(left) ? left / std::ceil(left / step - 1e-9) : step;
      heat_alone(scene, disc, state, dt, 1, timers);
      ++state.increment;
      state.time += dt;
      log_heat_step(state, dt, time_left.update(clock.progress(state), seconds_since(start)));
      writer.write(scene, disc, state, false, timers);
    }
    log::info("stop: %s at increment %d, t = %.6g s", stop.reason.c_str(), state.increment, state.time);
    finish(scene, disc, state, writer, last, timers, start);
    hand_over();
    return {stop.reason, true};
  }
  // After every increment but the one that meets the stop criterion, whose
  // check a checkpoint at the stop carries for a run resumed past it, with
  // the die each node pressed on (`touching_at_stop`; otherwise from this
  // increment's contact solution).
  const auto remesh_if_due = [&](double time_step, std::span<const double> rate,
                                 const std::vector<int>* touching_at_stop) {
    const std::vector<remesh::RemeshDue> due = remesh::remesh_due(scene, state, time_step);
    if (due.empty()) return;
    const std::vector<int> touching_die =
        touching_at_stop ? *touching_at_stop : disc.touching_die(state.unknowns.nodal);
    remesh_checking_load(scene, state, due, touching_die, rate, clock.next_step(state), timers);
    disc = discretise(scene, state, timers);
  };
  if (!state.remesh_check_at_stop.empty() && !clock.stop(state)) {
    const RemeshCheck check = std::exchange(state.remesh_check_at_stop, {});
    if (c.remeshing.enabled) remesh_if_due(check.time_step, check.rate, &check.touching_die);
  }
  double last_step = clock.next_step(state).length; // s, of the last increment accepted
  while (!(stop = clock.stop(state))) {
    if (const int signal = interrupt::requested()) return interrupted(signal);
    strike_next_blows(scene, disc, state, timers);
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
    disc.solver->increment_ended();
    last = inc.report;
    last_step = inc.time_step;
    const double heat_before = timers.seconds("effect heat");
    if (disc.heat) {
      try {
        advance_heat(scene, disc, inc, state, timers);
      } catch (const RunError& failure) {
        // The increment's flow is taken and its heat is not: the results so
        // far are written, not a checkpoint of this state (the last one stays exact).
        writer.stop_checkpoints();
        finish(scene, disc, state, writer, last, timers, start);
        throw RunError("increment " + std::to_string(state.increment) + " at t = " + std::to_string(state.time) +
                       " s: " + failure.what() + "; the results so far are written in " + out +
                       " (its last frame with the temperatures of increment " + std::to_string(state.increment - 1) +
                       ")" + (c.checkpoint_every > 0 ? "; --resume continues from its last checkpoint" : ""));
      }
    }
    log_progress(scene, disc, state, inc, time_left.update(clock.progress(state), seconds_since(start)),
                 (timers.seconds("effect heat") - heat_before) / seconds_since(increment_start));
    if (c.detect_folds) watch_folds(scene, disc, state, timers);
    writer.write_frame(scene, disc, state, timers); // before a remesh renumbers the nodes the contact names
    if (c.remeshing.enabled) {
      if (clock.stop(state))
        state.remesh_check_at_stop = {inc.time_step, inc.fields.rate, disc.touching_die(state.unknowns.nodal)};
      else
        remesh_if_due(inc.time_step, inc.fields.rate, nullptr);
    }
    // The periodic checkpoint carries no preconditioner: the run sets its own
    // up anew after it, as a run resumed from it does, and --resume stays exact.
    if (writer.write(scene, disc, state, false, timers)) disc.solver->restart_linear_solver();
  }
  log::info("stop: %s at increment %d, t = %.6g s", stop.reason.c_str(), state.increment, state.time);
  record_final_loads(scene, disc, state, last_step, timers);
  finish(scene, disc, state, writer, last, timers, start);
  hand_over();
  if (!stop.complete)
    return {"stopped at increment " + std::to_string(state.increment) + ": " + stop.reason +
                "; the results so far are in " + out,
            false};
  return {stop.reason, true};
}

} // namespace anvil::run
