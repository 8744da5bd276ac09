// The material card's keys (schema.h).
#include "anvil/scene/schema.h"

#include "schema_keys.h"

namespace anvil::scene {

using namespace schema_keys;

const std::vector<KeySpec>& material_schema() {
  using T = KeyType;
  static const std::vector<KeySpec> schema = {
      required(range(key("format", T::integer, "material card format version"), 1, 1)),
      required(key("name", T::string, "material name and condition")),
      required(choices(key("law", T::string, "constitutive law"),
                       {"newtonian", "norton_hoff", "hansel_spittel", "linear_elastic"})),
      range(key("temperature", T::number, "temperature at which the numbers hold", "°C"), kAbsoluteZero, kHottest,
            true),
      range(key("viscosity", T::number, "newtonian: viscosity η", "MPa.s"), 0, kInf, true),
      range(key("consistency", T::number, "norton_hoff: consistency K", "MPa.s^m"), 0, kInf, true),
      range(key("sensitivity", T::number, "norton_hoff: strain-rate sensitivity m", "-"), 0, 1, true),
      with_default(range(key("regularisation_rate", T::number,
                             "norton_hoff: ε̄̇₀ in sqrt(ε̄̇² + ε̄̇₀²), keeps rigid zones finite", "1/s"),
                         0, kInf, true),
                   "1e-4"),
      range(key("A", T::number, "hansel_spittel: A", "MPa"), 0, kInf, true),
      key("m1", T::number, "hansel_spittel: temperature exponent m1 (T in °C)", "1/°C"),
      key("m2", T::number, "hansel_spittel: strain exponent m2", "-"),
      key("m3", T::number, "hansel_spittel: strain-rate exponent m3", "-"),
      key("m4", T::number, "hansel_spittel: m4 in exp(m4/ε̄)", "-"),
      key("m5", T::number, "hansel_spittel: m5 in (1+ε̄)^(m5 T)", "1/°C"),
      key("m7", T::number, "hansel_spittel: m7 in exp(m7 ε̄)", "-"),
      key("m8", T::number, "hansel_spittel: m8 in ε̄̇^(m8 T)", "1/°C"),
      key("m9", T::number, "hansel_spittel: m9 in T^m9", "-"),
      with_default(
          range(key("minimum_strain", T::number, "hansel_spittel: ε̄ floor (ε̄^m2 and exp(m4/ε̄) are singular at 0)", "-"),
                0, 1, true),
          "0.01"),
      key("activation_temperature", T::number,
          "norton_hoff: β of K(T) = K exp(β (1/T − 1/T_ref)), T in kelvin, T_ref the card's temperature", "K"),
      range(key("conductivity", T::numbers,
                "thermal: k, one value or one per thermal_temperatures (from insulators' 0.01 to beyond silver's 429)",
                "W/(m.K)"),
            0.01, 1000),
      range(key("specific_heat", T::numbers,
                "thermal: c, one value or one per thermal_temperatures (from below lead's 129 to beyond lithium's "
                "3582)",
                "J/(kg.K)"),
            50, 10000),
      range(key("thermal_temperatures", T::numbers, "thermal: temperatures of the k and c tables, increasing", "°C"),
            kAbsoluteZero, kHottest, true),
      range(key("density", T::number, "thermal: ρ (from foams' 100 to beyond osmium's 22,590)", "kg/m3"), 100, 30000),
      range(key("emissivity", T::number, "thermal: ε of the surface (radiation to the air)", "-"), 0, 1),
      range(key("hardness", T::numbers,
                "die steels: Rockwell C hardness, one value or one per hardness_temperatures (die wear: the die's "
                "hardness at its temperature)",
                "HRC"),
            1, 80),
      range(
          key("hardness_temperatures", T::numbers, "die steels: temperatures of the hardness table, increasing", "°C"),
          kAbsoluteZero, kHottest, true),
      range(key("young_modulus", T::number, "linear_elastic: E", "MPa"), 0, kInf, true),
      range(key("poisson_ratio", T::number, "linear_elastic: ν (0.5 allowed: u-p form)", "-"), -1, 0.5, true),
      required(key("sources", T::map, "where each number comes from: one entry per numeric key")),
  };
  // One "sources.<key>" entry per numeric key, so the two lists cannot drift apart.
  static const std::vector<KeySpec> with_sources = [] {
    std::vector<KeySpec> all = schema;
    for (const KeySpec& k : schema)
      if (k.type == T::number || k.type == T::numbers)
        all.push_back(key("sources." + k.path, T::string, "source (or reason) of " + k.path));
    return all;
  }();
  return with_sources;
}

} // namespace anvil::scene
