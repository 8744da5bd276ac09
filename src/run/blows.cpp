#include "anvil/run/blows.h"

#include "anvil/core/log.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace anvil::run {

using namespace scene; // the loop runs on the scene's types throughout
namespace {

template <class State> auto* latest_blow(State& state, int d) {
  for (auto b = state.blows.rbegin(); b != state.blows.rend(); ++b)
    if (b->die == d) return &*b;
  return decltype(&*state.blows.rbegin()){nullptr};
}

/// Strikes blow `number` of die `d` now: full energy, the ram at its impact speed.
void strike(const Scene& scene, int d, int number, RunState& state) {
  state.blows.push_back({.die = d,
                         .blow = number,
                         .first_increment = state.increment + 1,
                         .start_time = state.time,
                         .energy = scene.dies[d].energy->energy()});
  state.dies[d].speed_factor = 1.0;
}

} // namespace

const BlowRecord* current_blow(const RunState& state, int d) {
  return latest_blow(state, d);
}

void first_blows(const Scene& scene, RunState& state) {
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    if (scene.dies[d].energy) strike(scene, static_cast<int>(d), 1, state);
}

std::optional<double> step_spending_blow(const Scene& scene, const RunState& state, const IncrementOutcome& inc) {
  double share = 1.0;
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    const BlowRecord* blow = current_blow(state, static_cast<int>(d));
    if (!blow || blow->over) continue;
    const Eigen::Vector3d v = scene.dies[d].velocity(state.dies[d], inc.time_step);
    if (v.norm() == 0.0) continue;
    const double work = scene.symmetry_copies * inc.forces[d].dot(-v.normalized()) * v.norm() * inc.time_step;
    if (work > blow->energy_left() + kBlowTolerance * blow->energy)
      share = std::min(share, std::max(blow->energy_left(), 0.0) / work);
  }
  if (share < 1.0) return share * inc.time_step;
  return std::nullopt;
}

void spend_blow_energy(const Scene& scene, int d, double resisting, double stroke, RunState& state) {
  BlowRecord& blow = *latest_blow(state, d);
  blow.work += resisting * stroke;
  blow.stroke += stroke;
  blow.load = resisting;
  blow.peak_load = std::max(blow.peak_load, resisting);
  blow.last_increment = state.increment;
  blow.end_time = state.time;
  DieState& die = state.dies[d];
  const die::EnergyPress& press = *scene.dies[d].energy;
  if (blow.energy_left() <= kBlowTolerance * blow.energy) {
    blow.over = true;
    die.speed_factor = 0.0;
    log::info("  blow %d of %d of die '%s' over: %.5g kJ spent over %.4g mm (%.3g %% of its energy left), peak load "
              "%.5g kN",
              blow.blow, press.blows(), scene.dies[d].name.c_str(), blow.work * 1e-6, blow.stroke,
              100.0 * blow.energy_left() / blow.energy, blow.peak_load * 1e-3);
    return;
  }
  const double speed =
      press.mean_speed(blow.energy_left(), resisting, scene.input.time.stroke_increment) / press.impact_speed();
  // A screw press's load limit (die.speed_factor just limited) holds the ram back further.
  die.speed_factor = std::isfinite(scene.dies[d].load_limit) ? std::min(die.speed_factor, speed) : speed;
}

bool between_blows(const RunState& state, int d) {
  const BlowRecord* blow = current_blow(state, d);
  return blow && blow->over;
}

bool blows_struck(const Scene& scene, const RunState& state) {
  bool any = false;
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    if (!scene.dies[d].energy) continue;
    const BlowRecord* blow = current_blow(state, static_cast<int>(d));
    if (!blow->over || blow->blow < scene.dies[d].energy->blows()) return false;
    any = true;
  }
  return any;
}

double blows_progress(const Scene& scene, const RunState& state) {
  double share = 0.0;
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    if (scene.dies[d].energy) {
      const BlowRecord& blow = *current_blow(state, static_cast<int>(d));
      const double done = blow.over ? 1.0 : std::clamp(blow.work / blow.energy, 0.0, 1.0);
      share = std::max(share, (blow.blow - 1 + done) / scene.dies[d].energy->blows());
    }
  return share;
}

void strike_next_blows(const Scene& scene, Discretisation& disc, RunState& state, Timers& timers) {
  double pause = 0.0;
  std::vector<int> due;
  for (std::size_t d = 0; d < scene.dies.size(); ++d) {
    const int die = static_cast<int>(d);
    if (scene.dies[d].energy && between_blows(state, die) &&
        current_blow(state, die)->blow < scene.dies[d].energy->blows()) {
      due.push_back(die);
      pause = std::max(pause, scene.dies[d].energy->pause());
    }
  }
  if (due.empty()) return;
  if (pause > 0.0) {
    if (disc.heat) {
      const int steps = scene.input.thermal.transfer_steps;
      heat_alone(scene, disc, state, pause / steps, steps, timers);
    }
    state.time += pause;
  }
  for (int d : due) {
    strike(scene, d, current_blow(state, d)->blow + 1, state);
    log::info("blow %d of %d of die '%s' at t = %.6g s%s", state.blows.back().blow, scene.dies[d].energy->blows(),
              scene.dies[d].name.c_str(), state.time,
              pause > 0.0 ? (" after a pause of " + std::to_string(pause) + " s").c_str() : "");
  }
}

std::string blows_text(const Scene& scene, const RunState& state) {
  std::string text;
  for (std::size_t d = 0; d < scene.dies.size(); ++d)
    if (scene.dies[d].energy) {
      const BlowRecord& blow = *current_blow(state, static_cast<int>(d));
      const die::EnergyPress& press = *scene.dies[d].energy;
      char part[96];
      std::snprintf(part, sizeof part, "  blow %d/%d v %.3g m/s E %.0f %%", blow.blow, press.blows(),
                    1e-3 * press.impact_speed() * state.dies[d].speed_factor,
                    100.0 * std::max(blow.energy_left(), 0.0) / blow.energy);
      text += part;
    }
  return text;
}

} // namespace anvil::run
