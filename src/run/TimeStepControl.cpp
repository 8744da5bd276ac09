#include "anvil/run/TimeStepControl.h"

#include "anvil/run/blows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace anvil::run {

using namespace scene; // the loop runs on the scene's types throughout
namespace {

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
  for (std::size_t i = 0; i < sum.size(); ++i)
    sum[i] /= count[i];
  return sum;
}

/// The largest press load of the whole part (N) in the latest load records.
double latest_press_load(const Scene& scene, const RunState& state) {
  double load = 0.0;
  const int latest = state.loads.empty() ? 0 : state.loads.back().increment;
  for (auto r = state.loads.rbegin(); r != state.loads.rend() && r->increment == latest; ++r)
    load = std::max(load, scene.whole_part_load(*r));
  return load;
}

} // namespace

TimeStepControl::TimeStepControl(const Scene& scene) : scene_(scene), time_(scene.input.time) {}

double TimeStepControl::press_speed(const RunState& state) const {
  // The fastest die over a short probe step (an increment is far longer).
  // At least the speed at the start, so that a die slowed by its load limit
  // makes shorter strokes; an energy press's ram, slowing down as its blow's
  // energy runs out, makes the same stroke increments to the end.
  const double probe = 1e-3 * time_.stroke_increment / scene_.reference_velocity;
  const bool energy = std::any_of(scene_.dies.begin(), scene_.dies.end(), [](const Die& d) { return d.energy; });
  double speed = energy ? 0.0 : scene_.reference_velocity;
  for (std::size_t d = 0; d < scene_.dies.size(); ++d)
    speed = std::max(speed, scene_.dies[d].velocity(state.dies[d], probe).norm());
  return speed > 0.0 ? speed : scene_.reference_velocity;
}

TimeStep TimeStepControl::next_step(const RunState& state) const {
  TimeStep step;
  step.nominal = time_.stroke_increment / press_speed(state);
  double dt = step.nominal;
  const std::vector<double> size = local_size(state.mesh);
  for (int i = 0; i < state.mesh.node_count(); ++i) {
    const double speed = state.unknowns.nodal.segment<3>(4 * i).norm();
    if (speed > 0.0) dt = std::min(dt, time_.max_displacement * size[i] / speed);
  }
  // A stop less than 1¼ steps away is reached in two equal steps: Δt ≪
  // nominal would make gap/Δt in the contact terms and the volume
  // compensation stiff.
  double to_stop = std::numeric_limits<double>::infinity();
  if (std::isfinite(time_.end_time)) to_stop = time_.end_time - state.time;
  if (std::isfinite(time_.final_stroke)) {
    const int d = time_.stroke_die;
    const double speed = scene_.dies[d].velocity(state.dies[d], dt).norm();
    if (speed > 0.0) to_stop = std::min(to_stop, (time_.final_stroke - state.dies[d].stroke) / speed);
  }
  if (time_.final_gap > 0.0) {
    const int upper = scene_.upper_die, lower = 1 - upper;
    const double closing =
        scene_.dies[lower].velocity(state.dies[lower], dt).z() - scene_.dies[upper].velocity(state.dies[upper], dt).z();
    if (closing > 0.0) to_stop = std::min(to_stop, (scene_.die_gap(state.dies) - time_.final_gap) / closing);
  }
  if (to_stop <= dt * (1.0 + 1e-9)) // a stop one step away (to rounding) in one step
    dt = to_stop;
  else if (to_stop < 1.25 * dt)
    dt = 0.5 * to_stop;
  step.planned = step.length = dt;
  return step;
}

std::optional<double> TimeStepControl::cut(double length, int cuts_done) const {
  if (cuts_done >= time_.max_cuts) return std::nullopt;
  return 0.5 * length;
}

bool TimeStepControl::ends_at_contact(const TimeStep& step, double touch) const {
  const double sliver = time_.min_step_fraction * step.planned;
  return touch > sliver && touch < step.length - sliver;
}

Stop TimeStepControl::stop(const RunState& state) const {
  const double tolerance = 1e-9;
  if (state.time >= time_.end_time * (1.0 - tolerance)) return {"end time reached"};
  if (std::isfinite(time_.stop_temperature) &&
      *std::max_element(state.temperature.begin(), state.temperature.end()) <= time_.stop_temperature) {
    char text[80];
    std::snprintf(text, sizeof text, "cooled to %g C", time_.stop_temperature);
    return {text};
  }
  if (std::isfinite(time_.final_stroke) &&
      state.dies[time_.stroke_die].stroke >= time_.final_stroke * (1.0 - tolerance))
    return {"final stroke reached"};
  if (time_.final_gap > 0.0 && scene_.die_gap(state.dies) <= time_.final_gap * (1.0 + tolerance))
    return {"final die gap reached"};
  if (std::isfinite(time_.max_load) && latest_press_load(scene_, state) >= time_.max_load)
    return {"maximum load reached"};
  if (blows_struck(scene_, state)) return {"all blows struck"};
  for (std::size_t d = 0; d < scene_.dies.size(); ++d)
    if (state.dies[d].speed_factor < 1e-3 && !between_blows(state, static_cast<int>(d)))
      return {"press stalled at its load limit (die '" + scene_.dies[d].name + "')"};
  // A motion over for good (a table past its last time) can no longer meet
  // a stroke or gap stop.
  const auto describe = [&](const std::string& what) {
    return Stop{what + " before the stop criterion (" + describe_stop(state) + ")", false};
  };
  if (std::isfinite(time_.final_stroke) && scene_.dies[time_.stroke_die].at_rest_for_good(state.dies[time_.stroke_die]))
    return describe("die '" + scene_.dies[time_.stroke_die].name + "' has come to rest for good");
  if (time_.final_gap > 0.0 && scene_.dies[0].at_rest_for_good(state.dies[0]) &&
      scene_.dies[1].at_rest_for_good(state.dies[1]))
    return describe("both dies have come to rest for good");
  if (state.increment >= time_.max_increments)
    return describe("time.max_increments (" + std::to_string(time_.max_increments) + ") reached");
  return {};
}

std::string TimeStepControl::describe_stop(const RunState& state) const {
  std::vector<std::string> criteria;
  char text[200];
  if (std::isfinite(time_.final_stroke)) {
    std::snprintf(text, sizeof text, "final stroke %g mm of die '%s', at %.4g mm", time_.final_stroke,
                  scene_.dies[time_.stroke_die].name.c_str(), state.dies[time_.stroke_die].stroke);
    criteria.push_back(text);
  }
  if (time_.final_gap > 0.0) {
    std::snprintf(text, sizeof text, "final die gap %g mm, at %.4g mm", time_.final_gap, scene_.die_gap(state.dies));
    criteria.push_back(text);
  }
  if (std::isfinite(time_.max_load)) {
    std::snprintf(text, sizeof text, "press load %g N, at %.4g N", time_.max_load, latest_press_load(scene_, state));
    criteria.push_back(text);
  }
  if (std::isfinite(time_.end_time)) {
    std::snprintf(text, sizeof text, "end time %g s, at %.4g s", time_.end_time, state.time);
    criteria.push_back(text);
  }
  for (std::size_t d = 0; d < scene_.dies.size(); ++d)
    if (scene_.dies[d].energy) {
      const BlowRecord& blow = *current_blow(state, static_cast<int>(d));
      std::snprintf(text, sizeof text, "%d blows of die '%s', at blow %d%s", scene_.dies[d].energy->blows(),
                    scene_.dies[d].name.c_str(), blow.blow, blow.over ? " (over)" : "");
      criteria.push_back(text);
    }
  std::string all;
  for (const std::string& c : criteria)
    all += (all.empty() ? "" : "; ") + c;
  return all;
}

double TimeStepControl::progress(const RunState& state) const {
  double f = 0.0;
  if (std::isfinite(time_.end_time)) f = std::max(f, state.time / time_.end_time);
  if (std::isfinite(time_.final_stroke)) f = std::max(f, state.dies[time_.stroke_die].stroke / time_.final_stroke);
  if (time_.final_gap > 0.0)
    f = std::max(f, (scene_.die_gap0 - scene_.die_gap(state.dies)) / (scene_.die_gap0 - time_.final_gap));
  return std::max(f, blows_progress(scene_, state));
}

} // namespace anvil::run
