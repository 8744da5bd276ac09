// The blows of energy presses (hammer, screw press: die/EnergyPress.h) in the
// time loop. Each accepted increment's work F·v Δt is taken from its blow's
// energy and the ram goes on at the mean speed the energy left gives over the
// next stroke increment; an increment that would spend more than is left is
// solved again, shorter, so that it spends it exactly; the next blow is
// struck after its pause, which is heat alone.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/run/Increment.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <optional>
#include <string>

namespace anvil::run {

/// Share of a blow's energy within which it counts as spent: the energy
/// balance of a blow holds to this.
inline constexpr double kBlowTolerance = 1e-4;

/// The blow of die `d` under way or last struck; null for a die that is no
/// energy press.
const scene::BlowRecord* current_blow(const scene::RunState& state, int d);

/// A new run's first blow of every energy press, struck at t = 0.
void first_blows(const scene::Scene& scene, scene::RunState& state);

/// Δt (s) that spends exactly what is left of a blow, when the solved
/// increment `inc` would spend more than that (beyond kBlowTolerance);
/// nothing otherwise.
std::optional<double> step_spending_blow(const scene::Scene& scene, const scene::RunState& state,
                                         const IncrementOutcome& inc);

/// After an accepted increment in which energy die `d` moved `stroke` mm
/// against `resisting` N (the whole part's): the work taken from its blow,
/// and the speed of the next increment, the load limit's if lower. A blow
/// whose energy is spent ends: the ram stops.
void spend_blow_energy(const scene::Scene& scene, int d, double resisting, double stroke, scene::RunState& state);

/// True when die `d` is an energy press between blows or past its last.
bool between_blows(const scene::RunState& state, int d);
/// True when every energy press has struck all its blows (false without one).
bool blows_struck(const scene::Scene& scene, const scene::RunState& state);
/// Share of the energy presses' blows done (for the progress estimate); 0 without one.
double blows_progress(const scene::Scene& scene, const scene::RunState& state);

/// The next blow of each energy press whose last one is over, after its
/// pause: the pause as heat alone (thermal scenes; heat_alone), then the blow
/// struck at full energy. Nothing when no blow is due.
void strike_next_blows(const scene::Scene& scene, scene::Discretisation& disc, scene::RunState& state, Timers& timers);

/// The progress line's part: each energy press's blow, ram speed and share
/// of the blow's energy left.
std::string blows_text(const scene::Scene& scene, const scene::RunState& state);

} // namespace anvil::run
