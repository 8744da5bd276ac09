#include "anvil/run/run_log.h"

#include "anvil/run/blows.h"

#include "anvil/core/blas_kernels.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/scene/damage_peak.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace anvil::run {

using namespace scene; // the log speaks of the scene's types throughout

namespace {

std::string clock_text(double seconds) {
  char text[32];
  const long s = std::lround(seconds);
  std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return text;
}

} // namespace

double TimeLeft::update(double progress, double now) {
  if (++updates_ <= kSettling) return std::numeric_limits<double>::quiet_NaN();
  points_.push_back({progress, now});
  if (points_.size() > kWindow + 1) points_.pop_front();
  if (points_.size() <= kFirst) return std::numeric_limits<double>::quiet_NaN();
  const auto& [p0, t0] = points_.front();
  if (progress <= p0) return std::numeric_limits<double>::quiet_NaN();
  return (now - t0) / (progress - p0) * (1.0 - progress);
}

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
              d.energy       ? d.energy->describe().c_str()
              : d.kinematics ? d.kinematics->describe().c_str()
                             : "fixed",
              contact::describe(d.friction).c_str(),
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
  // The threads a process may use (main's tbb::global_control: its share
  // of the cores), not the machine's default.
  const int threads = static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  log::info("solver: %s (asked: %s), Newton tolerance %.1e (|dv|/|v| %.1e), %d process%s x %d thread%s, %s",
            solver::to_string(disc.solver->linear_solver().kind()).c_str(),
            solver::to_string(c.linear_solver.kind).c_str(), c.newton.tolerance, c.newton.increment_tolerance,
            processes::count(), processes::count() > 1 ? "es" : "", threads, threads > 1 ? "s" : "",
            blas_kernels::in_use().c_str());
  if (disc.solver->linear_solver().kind() == solver::LinearSolverKind::fgmres && scene.free_rotations)
    log::info("  a body's rotation is held by contact alone (fewer than two symmetry planes): ML's near-null space "
              "is the six rigid-body modes, not only the translations, less the directions contact holds");
  if (c.time.enabled) {
    const TimeSpec& t = c.time;
    log::info(
        "time loop: stroke increment %g mm, nodal displacement <= %g x element size, stop: %s%s%s%s%s",
        t.stroke_increment, t.max_displacement,
        std::isfinite(t.final_stroke)
            ? ("stroke " + std::to_string(t.final_stroke) + " mm of '" + scene.dies[t.stroke_die].name + "' ").c_str()
            : "",
        t.final_gap > 0.0 ? ("gap " + std::to_string(t.final_gap) + " mm ").c_str() : "",
        std::isfinite(t.max_load) ? ("load " + std::to_string(t.max_load) + " N ").c_str() : "",
        std::isfinite(t.end_time) ? ("time " + std::to_string(t.end_time) + " s ").c_str() : "",
        std::any_of(scene.dies.begin(), scene.dies.end(), [](const Die& d) { return d.energy.has_value(); })
            ? "after the blows"
            : "");
  }
}

std::string temperature_text(const RunState& state, double heat_share) {
  if (state.temperature.empty()) return "";
  const auto [low, high] = std::minmax_element(state.temperature.begin(), state.temperature.end());
  char text[80];
  std::snprintf(text, sizeof text, "  T %.0f..%.0f C (heat %.0f %%)", *low, *high, 100.0 * heat_share);
  return text;
}

void log_heat_step(const RunState& state, double dt, double time_left) {
  log::info("inc %4d  t %.5g s  dt %.3g s  heat alone%s  left ~%s", state.increment, state.time, dt,
            temperature_text(state, 1.0).c_str(), std::isnan(time_left) ? "?" : clock_text(time_left).c_str());
}

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
  // damage.progress: each criterion's largest D so far.
  std::string damage;
  if (scene.input.damage_on_progress)
    for (std::size_t k = 0; k < state.damage.size(); ++k) {
      char text[64];
      std::snprintf(text, sizeof text, "  D %s %.3g", material::to_string(scene.input.damage[k].criterion).c_str(),
                    damage_peak(state, k).value);
      damage += text;
    }
  log::info("inc %4d  t %.5g s  stroke %.4g mm  dt %.3g s  load(%s) %.5g kN%s at %.4g mm  newton %zu%s  contact %d  "
            "volume %+.3f%% (%.3f%% inside dies)%s%s%s  left ~%s",
            state.increment, state.time, surface_stroke(scene, state.dies, lead.surface, state.time), inc.time_step,
            scene.surfaces[lead.surface].name.c_str(), scene.whole_part_load(lead) / 1e3, model, lead.stroke,
            inc.report.iterations.size(), krylov.c_str(), contacts,
            100.0 * (mesh::volume(state.mesh) / state.volume.initial - 1.0),
            100.0 * std::accumulate(state.inside_dies.begin(), state.inside_dies.end(), 0.0) / state.volume.initial,
            temperature_text(state, heat_share).c_str(), damage.c_str(), blows_text(scene, state).c_str(),
            std::isnan(time_left) ? "?" : clock_text(time_left).c_str());
}

} // namespace anvil::run
