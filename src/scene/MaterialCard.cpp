#include "anvil/scene/MaterialCard.h"

#include "anvil/scene/schema.h"

#include "checked_yaml.h"

#include <algorithm>

namespace anvil::scene {
namespace {
std::unique_ptr<material::Material> read_law(const CheckedYaml& doc) {
  const YAML::Node& root = doc.root();
  const std::string law = root["law"].Scalar();
  // Every number given must say where it comes from.
  for (const auto& entry : root) {
    const std::string key = entry.first.Scalar();
    if (key == "format" || key == "name" || key == "law" || key == "sources") continue;
    if (!root["sources"][key])
      doc.fail(entry.first, key, "has no entry under 'sources': every number in a material card cites its source");
  }
  auto needed = [&](const char* key) {
    doc.require(root, key, "", "law '" + law + "' needs it");
    return doc.number(root, key, key);
  };
  if (law == "hansel_spittel") {
    material::HanselSpittel::Coefficients k;
    k.A = needed("A");
    auto optional = [&](const char* key) { return root[key] ? doc.number(root, key, key) : 0.0; };
    k.m1 = optional("m1"), k.m2 = optional("m2"), k.m3 = optional("m3"), k.m4 = optional("m4");
    k.m5 = optional("m5"), k.m7 = optional("m7"), k.m8 = optional("m8"), k.m9 = optional("m9");
    return std::make_unique<material::HanselSpittel>(k, doc.number(root, "minimum_strain", "minimum_strain"),
                                                     doc.number(root, "regularisation_rate", "regularisation_rate"));
  }
  if (law == "newtonian") return std::make_unique<material::NortonHoff>(needed("viscosity"), 1.0, 0.0);
  if (law != "norton_hoff") doc.forbid(root, "activation_temperature", "", "law '" + law + "'");
  if (law == "norton_hoff") {
    material::NortonHoff::Softening softening;
    if (root["activation_temperature"]) {
      doc.require(root, "temperature", "", "K(T) holds K at the card's temperature");
      softening = {doc.number(root, "activation_temperature", "activation_temperature"),
                   doc.number(root, "temperature", "temperature")};
    }
    return std::make_unique<material::NortonHoff>(needed("consistency"), needed("sensitivity"),
                                                  doc.number(root, "regularisation_rate", "regularisation_rate"),
                                                  softening);
  }
  return std::make_unique<material::LinearElastic>(needed("young_modulus"), needed("poisson_ratio"));
}

} // namespace

MaterialCard read_material(const std::string& path) {
  const CheckedYaml doc(path, material_schema());
  MaterialCard card{read_law(doc), std::nullopt, std::nullopt, std::nullopt};
  const YAML::Node& root = doc.root();
  if (root["temperature"]) card.temperature = doc.number(root, "temperature", "temperature");
  const std::vector<std::string> thermal_keys{"conductivity", "specific_heat", "density"};
  if (std::any_of(thermal_keys.begin(), thermal_keys.end(), [&](const std::string& k) { return bool(root[k]); })) {
    for (const std::string& key : thermal_keys)
      doc.require(root, key, "", "thermal properties need conductivity, specific_heat and density");
    thermal::ThermalMaterial& t = card.thermal.emplace();
    t.conductivity = read_table(doc, root, "conductivity", "thermal_temperatures", "");
    t.specific_heat = read_table(doc, root, "specific_heat", "thermal_temperatures", "");
    t.density = doc.number(root, "density", "density");
    t.emissivity = root["emissivity"] ? doc.number(root, "emissivity", "emissivity") : 0.0;
  } else {
    for (const char* key : {"emissivity", "thermal_temperatures"})
      doc.forbid(root, key, "", "a card without thermal properties (conductivity, specific_heat, density)");
  }
  if (root["hardness"])
    card.hardness = read_table(doc, root, "hardness", "hardness_temperatures", "");
  else
    doc.forbid(root, "hardness_temperatures", "", "a card without 'hardness'");
  return card;
}

} // namespace anvil::scene
