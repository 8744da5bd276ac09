// An energy-driven press: a hammer or a screw press. The ram meets the part
// with the kinetic energy of one blow, and the forging decelerates it by the
// work it absorbs, ½ M v² = E − ∫ F ds (docs/method.md, "Hammers and screw
// presses"); the blow ends when the energy is spent. Gravity and the drive
// acting during the blow are left out: the blow energy is what reaches the part.
#pragma once
#include <string>

namespace anvil::die {

class EnergyPress {
public:
  /// `energy` (mJ = N·mm) each blow brings to the part, with its efficiency
  /// already applied; `mass` (t, so that mJ/t = mm²/s²) the ram's, or a
  /// screw press's equivalent mass; `blows` struck `pause` s apart.
  EnergyPress(std::string kind, double energy, double mass, int blows, double pause);

  /// A hammer: blow energy (kJ) × efficiency, ram mass (kg).
  static EnergyPress hammer(double blow_energy_kj, double efficiency, double ram_mass_kg, int blows, double pause);
  /// A screw press: a flywheel of inertia I (kg·m²) turning a screw of pitch
  /// p (mm per turn) moves the ram at v = ω p / 2π, so the flywheel counts
  /// as a mass I (2π/p)² on the ram (plus the ram's own). Its energy is
  /// given (kJ) or follows from its speed (rpm), ½ I ω², × efficiency.
  static EnergyPress screw_press(double flywheel_energy_kj, double flywheel_rpm, double inertia, double pitch_mm,
                                 double efficiency, double ram_mass_kg, int blows, double pause);

  double energy() const { return energy_; } ///< mJ per blow, reaching the part
  double mass() const { return mass_; }     ///< t
  int blows() const { return blows_; }
  double pause() const { return pause_; } ///< s between blows
  /// Ram speed at impact, sqrt(2E/M) (mm/s).
  double impact_speed() const;
  /// The ram's mean speed (mm/s) over the next `stroke` mm, with
  /// `energy_left` mJ and the last increment's load `load` (N) taken as
  /// constant over it: (v₀ + v₁)/2 with ½Mv₁² = E − F Δs (v₁ = 0 when
  /// the load spends the energy within the stroke). Exact for a constant load.
  double mean_speed(double energy_left, double load, double stroke) const;
  std::string describe() const;

private:
  std::string kind_;
  double energy_, mass_;
  int blows_;
  double pause_;
};

} // namespace anvil::die
