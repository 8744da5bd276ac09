// Energy presses (hammer, screw press) against the 1D energy balance of a
// blow. A block squeezed between frictionless dies flows homogeneously, so
// its load is known at every height and speed
// (material::homogeneous_compression_load), and a blow of energy E on a ram
// of mass M ends where ½ M v² = E − ∫ F(s, v) ds reaches zero: an ODE in the
// stroke s, integrated here with RK4 far finer than any run.
#include "run_outputs.h"

#include "anvil/material/homogeneous_compression.h"
#include "anvil/scene/Scene.h"

#include <cmath>

namespace {

constexpr double kHeight = 10.0;                      // mm, the block's
constexpr double kVolume = 20.0 * 20.0 * kHeight;     // mm³, the whole block (the case is its quarter)
constexpr double kBlowEnergy = 0.2, kRamMass = 400.0; // kJ, kg: 1 m/s at impact
constexpr double kEnergy = kBlowEnergy * 1e6;         // mJ
constexpr double kMass = kRamMass * 1e-3;             // t

/// A quarter of a 20 × 20 × 10 mm C45 block between frictionless dies, the
/// top one `motion` (YAML lines of the die), stroke increment `increment` mm.
std::string energy_press_case(const std::string& name, const std::string& motion, double increment) {
  const std::string path = (std::filesystem::temp_directory_path() / (name + ".yaml")).string();
  std::ofstream(path) << "anvil: 1\n"
                         "title: blows on a block between frictionless dies\n"
                         "bodies:\n"
                         "  - name: block\n"
                         "    material: "
                      << source_path("materials/steel_c45_1100C.yaml") << "\n"
                      << "    mesh: {generate: box, size: [10, 10, 10], element_size: 2.5}\n"
                         "boundary:\n"
                         "  - {name: symmetry_x, type: symmetry, plane: {point: [0, 0, 0], normal: [1, 0, 0]}}\n"
                         "  - {name: symmetry_y, type: symmetry, plane: {point: [0, 0, 0], normal: [0, 1, 0]}}\n"
                         "dies:\n"
                         "  - name: ram\n"
                         "    plane: {point: [0, 0, 10], normal: [0, 0, -1]}\n"
                      << motion
                      << "    friction: {law: frictionless}\n"
                         "  - name: anvil\n"
                         "    plane: {point: [0, 0, 0], normal: [0, 0, 1]}\n"
                         "    friction: {law: frictionless}\n"
                         "time:\n"
                         "  stroke_increment: "
                      << increment << "\n";
  return path;
}

std::string hammer(int blows) {
  return "    motion: hammer\n    blow_energy: " + std::to_string(kBlowEnergy) +
         "\n    ram_mass: " + std::to_string(kRamMass) + "\n    blows: " + std::to_string(blows) + "\n    pause: 0.5\n";
}

/// The stroke (mm) of a blow of energy E (mJ) on mass M (t) from height H
/// (mm): dT/ds = −F(H0, H − s, sqrt(2T/M)), RK4 in s, the last step cut
/// where T reaches 0 (linearly within a 1e-4 mm step).
double exact_blow_stroke(const anvil::material::Material& law, double height, double temperature) {
  const auto rate = [&](double s, double kinetic) {
    const double speed = std::sqrt(2.0 * std::max(kinetic, 0.0) / kMass);
    return -anvil::material::homogeneous_compression_load(law, kVolume, height - s, kHeight, speed, temperature);
  };
  const double ds = 1e-4;
  double s = 0.0, kinetic = kEnergy;
  for (;;) {
    const double k1 = rate(s, kinetic), k2 = rate(s + ds / 2, kinetic + ds / 2 * k1),
                 k3 = rate(s + ds / 2, kinetic + ds / 2 * k2), k4 = rate(s + ds, kinetic + ds * k3);
    const double next = kinetic + ds / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    if (next <= 0.0) return s + ds * kinetic / (kinetic - next);
    kinetic = next, s += ds;
  }
}

/// Work (mJ) of the whole part's load over the increments first..last, from
/// loads.csv: row k holds the load solved on the geometry after k
/// increments, i.e. increment k + 1's, at its starting stroke.
double work_from_loads(const std::vector<LoadRow>& rows, int first, int last) {
  double work = 0.0;
  for (int k = first - 1; k < last; ++k)
    work += rows[k].whole_part_load * (rows[k + 1].stroke - rows[k].stroke);
  return work;
}

} // namespace

TEST_CASE("a hammer blow's stroke and energy balance agree with the 1D blow", "[verification]") {
  const anvil::scene::Case c = anvil::scene::read_case(energy_press_case("anvil_hammer_0.1", hammer(2), 0.1));
  anvil::Timers timers;
  const anvil::scene::Scene scene(c, timers);
  const anvil::material::Material& law = *scene.bodies.front().law;
  const double temperature = scene.bodies.front().state.temperature;
  const double exact1 = exact_blow_stroke(law, kHeight, temperature);
  const double exact2 = exact_blow_stroke(law, kHeight - exact1, temperature);

  const RunOutputs coarse = run_case(c, "anvil_hammer_0.1");
  const anvil::scene::RunState end = coarse.final_state();
  REQUIRE(end.blows.size() == 2);
  const std::vector<LoadRow> rows = coarse.loads("ram");
  for (const anvil::scene::BlowRecord& b : end.blows) {
    INFO("blow " << b.blow << ": energy " << b.energy << " mJ, work " << b.work << " mJ, increments "
                 << b.first_increment << ".." << b.last_increment);
    CHECK(b.over);
    // The balance: work done on the part = the blow's energy, to 1e-3.
    CHECK(std::abs(b.energy_left()) <= 1e-3 * b.energy);
    // The same from what the run wrote (loads.csv, 10 digits).
    CHECK(work_from_loads(rows, b.first_increment, b.last_increment) == Approx(b.energy).epsilon(1e-3));
  }
  // The second blow comes after the pause, at the impact speed again:
  // its first increment spans one stroke increment at 1 m/s.
  CHECK(end.blows[1].start_time - end.blows[0].end_time == Approx(0.5).epsilon(1e-12));
  CHECK(rows[end.blows[1].first_increment].time - rows[end.blows[1].first_increment - 1].time ==
        Approx(0.1 / 1000.0).epsilon(1e-9));

  // The loads are solved on the geometry at the start of each increment:
  // the work of a rising load is a left Riemann sum, and the stroke of a
  // blow overshoots by O(Δs). Measured: 0.64 % and 0.63 % at Δs 0.1 mm,
  // 0.33 % at 0.05 mm: first order. Asserted: within 1 % at 0.1 mm, and the
  // error at least a third smaller at half the stroke increment.
  const RunOutputs fine =
      run_case(anvil::scene::read_case(energy_press_case("anvil_hammer_0.05", hammer(1), 0.05)), "anvil_hammer_0.05");
  const double coarse1 = end.blows[0].stroke, coarse2 = end.blows[1].stroke,
               fine1 = fine.final_state().blows.at(0).stroke;
  INFO("blow 1: " << coarse1 << " mm at 0.1, " << fine1 << " mm at 0.05, exact " << exact1 << " mm; blow 2: " << coarse2
                  << " mm, exact " << exact2 << " mm");
  CHECK(std::abs(coarse1 / exact1 - 1.0) < 0.01);
  CHECK(std::abs(coarse2 / exact2 - 1.0) < 0.01);
  CHECK(std::abs(fine1 - exact1) < 0.67 * std::abs(coarse1 - exact1));
}

TEST_CASE("a screw press strikes as a hammer of its equivalent mass", "[verification]") {
  // I (2π/p)² = 400 kg with p = 2π mm per turn: I = 4e-4 kg m²; flywheel
  // energy 0.25 kJ at efficiency 0.8: 0.2 kJ reach the part, as the hammer's.
  const std::string screw = "    motion: screw_press\n    flywheel_energy: 0.25\n    efficiency: 0.8\n"
                            "    inertia: 4.0e-4\n    screw_pitch: 6.283185307179586\n";
  const RunOutputs press =
      run_case(anvil::scene::read_case(energy_press_case("anvil_screw_press", screw, 0.1)), "anvil_screw_press");
  const RunOutputs ram =
      run_case(anvil::scene::read_case(energy_press_case("anvil_hammer_one", hammer(1), 0.1)), "anvil_hammer_one");
  const anvil::scene::BlowRecord a = press.final_state().blows.at(0), b = ram.final_state().blows.at(0);
  INFO("screw press " << a.stroke << " mm, hammer " << b.stroke << " mm");
  // The same blow, to the round-off of the two masses and energies.
  CHECK(a.stroke == Approx(b.stroke).epsilon(1e-9));
  CHECK(a.peak_load == Approx(b.peak_load).epsilon(1e-9));
}

TEST_CASE("a screw press's load limit holds the load as its slip clutch would", "[verification]") {
  // The screw press above with a load limit below the free blow's peak: the
  // ram slows so that the load stays at the limit (Norton-Hoff: load ∝ v^m,
  // as Die::limit_speed scales it) and the energy is spent over a longer
  // stroke. The limit acts from the increment after the one that passes it.
  constexpr double kLimit = 60e3; // N, the whole block's; the free blow peaks at 72 kN
  const std::string screw = "    motion: screw_press\n    flywheel_energy: 0.25\n    efficiency: 0.8\n"
                            "    inertia: 4.0e-4\n    screw_pitch: 6.283185307179586\n    load_limit: 60000\n";
  const RunOutputs limited = run_case(
      anvil::scene::read_case(energy_press_case("anvil_screw_press_limited", screw, 0.1)), "anvil_screw_press_limited");
  const anvil::scene::BlowRecord blow = limited.final_state().blows.at(0);
  const std::vector<LoadRow> rows = limited.loads("ram");
  std::size_t first_above = rows.size();
  for (std::size_t k = 0; k < rows.size() && first_above == rows.size(); ++k)
    if (rows[k].whole_part_load > kLimit) first_above = k;
  REQUIRE(first_above < rows.size());
  double highest_after = 0.0;
  for (std::size_t k = first_above + 1; k + 1 < rows.size(); ++k) // the final row is the end geometry's
    highest_after = std::max(highest_after, rows[k].whole_part_load);
  INFO("first above the limit at row " << first_above << " (" << rows[first_above].whole_part_load
                                       << " N); highest after it " << highest_after << " N; stroke " << blow.stroke
                                       << " mm");
  // The limiter reads the last increment's load (its rate sensitivity m is
  // exact here: homogeneous flow, no hardening), so each load is above the
  // limit by what one increment adds: the contact area grows by Δs/H, 1.5 %
  // at the end of this blow (measured: 1.7 % at most). 2 % bounds it.
  CHECK(highest_after < 1.02 * kLimit);
  CHECK(std::abs(blow.energy_left()) <= 1e-3 * blow.energy);
  CHECK(blow.stroke > 3.0); // the free blow's 2.97 mm
}
