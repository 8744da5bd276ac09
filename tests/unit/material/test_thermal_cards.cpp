// Thermal properties of the material cards and the case keys of heat:
// tables interpolate, SI units convert, and what does not belong is refused.
#include "test_common.h"

#include "anvil/core/error.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/MaterialCard.h"

#include <filesystem>
#include <fstream>

using namespace anvil;

TEST_CASE("thermal cards: tables in T and the units the solver uses", "[unit]") {
  const scene::MaterialCard steel = scene::read_material(source_path("materials/steel_c45_hansel_spittel.yaml"));
  REQUIRE(steel.thermal);
  // EN 1993-1-2: k = 54 − 3.33e-2 T below 800 °C, 27.3 above; c = 650 above 900 °C.
  CHECK(steel.thermal->conductivity.at(1100.0) == Approx(27.3));
  CHECK(steel.thermal->conductivity.at(300.0) == Approx(0.5 * (47.3 + 40.7)));
  CHECK(steel.thermal->conductivity.at(-50.0) == Approx(53.3)); // held beyond the table
  // ρc = 7850 kg/m³ × 650 J/(kg·K) = 5.1e6 J/(m³·K) = 5.1 mJ/(mm³·K).
  CHECK(steel.thermal->capacity(1100.0) == Approx(5.1025));
  CHECK(steel.thermal->emissivity == 0.7);
  for (const char* card : {"materials/steel_c45_1100C.yaml", "materials/die_steel_h13.yaml",
                           "materials/aluminium_6061_hansel_spittel.yaml"})
    CHECK(scene::read_material(source_path(card)).thermal);
  CHECK_FALSE(scene::read_material(source_path("materials/aluminium_6061_450C.yaml")).thermal);
}

TEST_CASE("Norton-Hoff K(T): the card's K at its temperature, Arrhenius softening around it", "[unit]") {
  const scene::MaterialCard card = scene::read_material(source_path("materials/steel_c45_1100C.yaml"));
  material::PointState state;
  state.temperature = 1100.0;
  CHECK(card.law->consistency(state) == Approx(36.67));
  CHECK(card.law->depends_on_temperature());
  // Shida: σf ∝ exp(5000 K / T): from 1100 °C to 1000 °C, × exp(5000 (1/1273.15 − 1/1373.15)) = 1.331.
  state.temperature = 1000.0;
  CHECK(card.law->consistency(state) / 36.67 == Approx(std::exp(5000.0 * (1.0 / 1273.15 - 1.0 / 1373.15))));
}

namespace {

/// The InputError message of reading `text` as a case beside the materials folder.
std::string case_error(const std::string& text) {
  const std::string path = source_path("cases/.thermal_key_test.yaml");
  std::ofstream(path) << text;
  std::string message;
  try {
    scene::read_case(path);
  } catch (const InputError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

const char* kBody = R"(anvil: 1
bodies:
  - {name: billet, material: ../materials/steel_c45_hansel_spittel.yaml, mesh: {generate: box, size: [1, 1, 1], element_size: 0.5}}
)";

} // namespace

TEST_CASE("heat keys: a die in a thermal scene needs its temperature and h, and an isothermal scene refuses them",
          "[unit]") {
  const std::string die = "dies:\n  - {name: top, plane: {point: [0, 0, 1], normal: [0, 0, -1]}, motion: constant, "
                          "velocity: [0, 0, -1]";
  const std::string time = "time: {stroke_increment: 0.1, stop: {stroke: 0.5}}\n";
  CHECK_THAT(case_error(kBody + die + ", temperature: 250}\n" + time),
             Catch::Contains("key 'dies[0].temperature': does not apply to an isothermal scene"));
  CHECK_THAT(case_error(kBody + die + "}\nthermal: {}\n" + time),
             Catch::Contains("key 'dies[0].temperature': missing"));
  CHECK_THAT(case_error(kBody + die + ", temperature: 250}\nthermal: {}\n" + time),
             Catch::Contains("key 'dies[0].heat_transfer': missing"));
  CHECK_THAT(case_error(kBody + die + ", temperature: 250, heat_transfer: [1, 10], heat_transfer_pressure: [0]}\n" +
                        "thermal: {}\n" + time),
             Catch::Contains("2 values need as many entries in 'heat_transfer_pressure' (1 given)"));
  CHECK_THAT(case_error(kBody + die + ", temperature: 250, heat_transfer: 10}\nthermal: {}\n"),
             Catch::Contains("heat needs a 'time' section"));
  CHECK(case_error(kBody + die + ", temperature: 250, heat_transfer: 10}\nthermal: {}\n" + time).empty());
}

TEST_CASE("a property table integrates exactly over its linear pieces and its constant ends", "[unit]") {
  const thermal::PropertyTable c({100.0, 200.0, 300.0}, {1.0, 3.0, 2.0});
  CHECK(c.integral(0.0) == 0.0);
  CHECK(c.integral(100.0) == Approx(100.0)); // constant 1 below the table
  CHECK(c.integral(150.0) == Approx(100.0 + 0.5 * (1.0 + 2.0) * 50.0));
  CHECK(c.integral(300.0) == Approx(100.0 + 200.0 + 250.0));
  CHECK(c.integral(400.0) == Approx(550.0 + 200.0)); // constant 2 above
  CHECK(c.integral(-50.0) == Approx(-50.0));
  CHECK(thermal::PropertyTable(650.0).integral(1100.0) == Approx(650.0 * 1100.0));
}
