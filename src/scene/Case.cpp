#include "anvil/scene/Case.h"

#include "anvil/core/input_file.h"
#include "anvil/solver/PetscSession.h"

#include "case_document.h"
#include "checked_yaml.h"
#include "remeshing_section.h"

#include <algorithm>
#include <filesystem>
#include <tuple>

namespace anvil::scene {
namespace {

BoundaryKind boundary_kind(const std::string& type) {
  if (type == "velocity") return BoundaryKind::velocity;
  if (type == "symmetry") return BoundaryKind::symmetry;
  if (type == "sticking_plate") return BoundaryKind::sticking_plate;
  if (type == "frictionless_plate") return BoundaryKind::frictionless_plate;
  if (type == "traction") return BoundaryKind::traction;
  return BoundaryKind::pressure;
}

/// `plane: {point, normal}` under `spec` (e.g. "dies[].plane"); the normal must not be zero.
std::pair<mesh::Point, Eigen::Vector3d> read_plane(const CheckedYaml& doc, const YAML::Node& plane,
                                                   const std::string& spec, const std::string& shown) {
  const mesh::Point point = doc.vector(plane, "point", spec + ".point");
  const Eigen::Vector3d normal = doc.vector(plane, "normal", spec + ".normal");
  if (normal.norm() == 0.0) doc.fail(plane["normal"], shown + ".normal", "the normal must not be zero");
  return {point, normal};
}

/// The map `key` of `parent`, or an empty map when it is absent (its keys then take their defaults).
YAML::Node section(const YAML::Node& parent, const char* key) {
  return parent[key] ? parent[key] : YAML::Node(YAML::NodeType::Map);
}

/// Fails when `item`'s name is already used in `defined` (bodies, dies).
template <class Spec>
void check_unique_name(const CheckedYaml& doc, const std::vector<Spec>& defined, const YAML::Node& item,
                       const std::string& shown, const std::string& what) {
  for (const Spec& other : defined)
    if (other.name == item["name"].Scalar())
      doc.fail(item["name"], shown + ".name", what + " '" + other.name + "' is defined twice");
}

/// The `friction` map of a die or a contact pair; `list` is "dies" or "contact_pairs" (schema keys).
contact::FrictionLaw read_friction(const CheckedYaml& doc, const YAML::Node& item, const std::string& list,
                                   const std::string& shown) {
  using contact::FrictionKind;
  contact::FrictionLaw law;
  const YAML::Node f = item["friction"];
  if (!f) return law;
  const std::string spec = list + "[].friction.";
  const std::string name = doc.text(f, "law", spec + "law");
  const std::string context = "friction law '" + name + "'";
  auto need = [&](const char* key) {
    doc.require(f, key, shown + ".friction", context + " needs it");
    return doc.number(f, key, spec + key);
  };
  auto forbid = [&](const char* key) { doc.forbid(f, key, shown + ".friction", context); };
  if (name == "frictionless" || name == "sticking") {
    law.kind = name == "sticking" ? FrictionKind::sticking : FrictionKind::frictionless;
    forbid("factor"), forbid("coefficient"), forbid("exponent");
  } else if (name == "tresca") {
    law.kind = FrictionKind::tresca;
    law.tresca_factor = need("factor");
    forbid("coefficient"), forbid("exponent");
  } else if (name == "coulomb") {
    law.kind = FrictionKind::coulomb;
    law.coefficient = need("coefficient");
    law.tresca_factor = f["factor"] ? need("factor") : 0.0;
    forbid("exponent");
  } else {
    law.kind = FrictionKind::norton;
    law.coefficient = need("coefficient");
    law.exponent = need("exponent");
    forbid("factor");
  }
  return law;
}

/// Index of the body named by `item[key]`.
int body_index(const CheckedYaml& doc, const Case& c, const YAML::Node& item, const char* key,
               const std::string& shown) {
  const std::string name = item[key].Scalar();
  for (std::size_t b = 0; b < c.bodies.size(); ++b)
    if (c.bodies[b].name == name) return static_cast<int>(b);
  doc.fail(item[key], shown + "." + key, "no body is named '" + name + "'");
}

void read_contact_pairs(const CheckedYaml& doc, Case& c) {
  for_each_entry(doc.root()["contact_pairs"], "contact_pairs", [&](const YAML::Node& n, const std::string& shown) {
    ContactPairSpec pair;
    pair.master = body_index(doc, c, n, "master", shown);
    pair.slave = body_index(doc, c, n, "slave", shown);
    for (const ContactPairSpec& other : c.contact_pairs)
      if (std::minmax(other.master, other.slave) == std::minmax(pair.master, pair.slave))
        doc.fail(n, shown,
                 "bodies '" + c.bodies[pair.master].name + "' and '" + c.bodies[pair.slave].name +
                     "' already form a contact pair");
    pair.method.formulation = contact::pair_formulation(doc.text(n, "formulation", "contact_pairs[].formulation"));
    pair.method.integration = contact::pair_integration(doc.text(n, "integration", "contact_pairs[].integration"));
    pair.method.quadrature =
        contact::facet_quadrature(doc.text(n, "facet_quadrature", "contact_pairs[].facet_quadrature"));
    pair.method.facet_subdivision = doc.integer(n, "facet_subdivision", "contact_pairs[].facet_subdivision");
    if (pair.master == pair.slave) { // self-contact: symmetric and nodal (contact::BodyPair)
      for (const char* key : {"formulation", "integration", "facet_quadrature", "facet_subdivision"})
        if (n[key])
          doc.fail(n[key], shown + "." + key,
                   "a body's contact with itself (master and slave '" + c.bodies[pair.master].name +
                       "') is symmetric and nodal: leave out '" + key + "'");
      pair.method = {.formulation = contact::PairFormulation::symmetric,
                     .integration = contact::PairIntegration::nodal};
    }
    pair.friction = read_friction(doc, n, "contact_pairs", shown);
    pair.source = doc.at(n);
    c.contact_pairs.push_back(pair);
  });
}

/// A `wear` section of a die ("dies[]") or a meshed die ("bodies[]"). A
/// rigid die needs its hardness or a card; a meshed die may read its own card.
WearSpec read_wear(const CheckedYaml& doc, const YAML::Node& wear, const std::string& at, const std::string& owner,
                   bool rigid) {
  WearSpec w;
  w.enabled = true;
  doc.require(wear, "coefficient", at, "the Archard coefficient K of w = ∫ K p^a v^b / H^c dt");
  w.law.coefficient = doc.number(wear, "coefficient", owner + ".wear.coefficient");
  w.law.pressure_exponent = doc.number(wear, "pressure_exponent", owner + ".wear.pressure_exponent");
  w.law.velocity_exponent = doc.number(wear, "velocity_exponent", owner + ".wear.velocity_exponent");
  w.law.hardness_exponent = doc.number(wear, "hardness_exponent", owner + ".wear.hardness_exponent");
  if (wear["hardness"] && wear["material"])
    doc.fail(wear, at, "give the die's hardness: 'hardness' (HRC) or 'material' (a card with a hardness table)");
  if (rigid && !wear["hardness"] && !wear["material"])
    doc.fail(wear, at, "give the die's hardness: 'hardness' (HRC) or 'material' (a card with a hardness table)");
  if (!rigid) doc.forbid(wear, "material", at, "a meshed die (its own material card gives the hardness table)");
  if (wear["hardness"]) {
    w.law.hardness = doc.number(wear, "hardness", owner + ".wear.hardness");
    doc.forbid(wear, "temperature", at, "a die given its 'hardness' (the temperature reads a card's table)");
  } else {
    if (rigid) w.card = doc.input_file(wear, "material", at, kMaxYamlBytes);
    if (wear["temperature"]) w.temperature = doc.number(wear, "temperature", owner + ".wear.temperature");
  }
  return w;
}

void read_dies(const CheckedYaml& doc, Case& c) {
  for_each_entry(doc.root()["dies"], "dies", [&](const YAML::Node& n, const std::string& shown) {
    DieSpec d;
    d.name = doc.text(n, "name", "dies[].name");
    d.source = doc.at(n);
    check_unique_name(doc, c.dies, n, shown, "die");
    if (static_cast<bool>(n["stl"]) == static_cast<bool>(n["plane"]))
      doc.fail(n, shown, "give exactly one surface: 'stl' (a file) or 'plane'");
    if (n["stl"]) {
      d.stl_file = doc.input_file(n, "stl", shown, kMaxStlBytes);
      if (n["offset"]) d.stl_offset = doc.vector(n, "offset", "dies[].offset");
    } else {
      doc.forbid(n, "offset", shown, "a plane die (its 'point' places it)");
      const YAML::Node plane = n["plane"];
      std::tie(d.plane_point, d.plane_normal) = read_plane(doc, plane, "dies[].plane", shown + ".plane");
      d.plane_normal.normalize();
      d.plane_half_size = doc.number(plane, "half_size", "dies[].plane.half_size");
    }
    d.motion = doc.text(n, "motion", "dies[].motion");
    const std::string context = "motion '" + d.motion + "'";
    auto need = [&](const char* key) { doc.require(n, key, shown, context + " needs it"); };
    auto allow_only = [&](std::vector<std::string> keys) {
      for (const char* key : {"velocity", "direction", "time", "speed", "displacement", "crank_radius", "rod_length",
                              "rpm", "start_angle", "load_limit", "blow_energy", "efficiency", "ram_mass",
                              "flywheel_energy", "flywheel_speed", "inertia", "screw_pitch", "blows", "pause"})
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) doc.forbid(n, key, shown, context);
    };
    if (d.motion == "fixed")
      allow_only({});
    else if (d.motion == "constant" || d.motion == "hydraulic") {
      need("velocity");
      d.velocity = doc.vector(n, "velocity", "dies[].velocity");
      if (d.motion == "hydraulic") {
        need("load_limit");
        d.load_limit = doc.number(n, "load_limit", "dies[].load_limit");
        allow_only({"velocity", "load_limit"});
      } else
        allow_only({"velocity"});
    } else if (d.motion == "table") {
      need("time");
      d.table_time = doc.numbers(n, "time");
      if (static_cast<bool>(n["speed"]) == static_cast<bool>(n["displacement"]))
        doc.fail(n, shown, "a table motion needs exactly one of 'speed' (mm/s) or 'displacement' (mm)");
      d.table_is_speed = static_cast<bool>(n["speed"]);
      d.table_values = doc.numbers(n, d.table_is_speed ? "speed" : "displacement");
      if (d.table_values.size() != d.table_time.size())
        doc.fail(n[d.table_is_speed ? "speed" : "displacement"],
                 shown + (d.table_is_speed ? ".speed" : ".displacement"),
                 "has " + std::to_string(d.table_values.size()) + " values but 'time' has " +
                     std::to_string(d.table_time.size()));
      for (std::size_t k = 1; k < d.table_time.size(); ++k)
        if (!(d.table_time[k] > d.table_time[k - 1]))
          doc.fail(n["time"], shown + ".time", "times must increase strictly (entry " + std::to_string(k + 1) + ")");
      d.direction = doc.vector(n, "direction", "dies[].direction");
      allow_only({"time", "speed", "displacement", "direction"});
    } else if (d.motion == "hammer" || d.motion == "screw_press") {
      const bool hammer = d.motion == "hammer";
      d.direction = doc.vector(n, "direction", "dies[].direction");
      d.efficiency = doc.number(n, "efficiency", "dies[].efficiency");
      d.blows = doc.integer(n, "blows", "dies[].blows");
      d.pause = doc.number(n, "pause", "dies[].pause");
      if (hammer) {
        need("blow_energy"), need("ram_mass");
        d.blow_energy = doc.number(n, "blow_energy", "dies[].blow_energy");
        d.ram_mass = doc.number(n, "ram_mass", "dies[].ram_mass");
        allow_only({"blow_energy", "efficiency", "ram_mass", "blows", "pause", "direction"});
      } else {
        need("inertia"), need("screw_pitch");
        if (static_cast<bool>(n["flywheel_energy"]) == static_cast<bool>(n["flywheel_speed"]))
          doc.fail(n, shown, "a screw press needs exactly one of 'flywheel_energy' (kJ) or 'flywheel_speed' (rpm)");
        if (n["flywheel_energy"]) d.blow_energy = doc.number(n, "flywheel_energy", "dies[].flywheel_energy");
        if (n["flywheel_speed"]) d.flywheel_speed = doc.number(n, "flywheel_speed", "dies[].flywheel_speed");
        d.inertia = doc.number(n, "inertia", "dies[].inertia");
        d.screw_pitch = doc.number(n, "screw_pitch", "dies[].screw_pitch");
        if (n["ram_mass"]) d.ram_mass = doc.number(n, "ram_mass", "dies[].ram_mass");
        if (n["load_limit"]) d.load_limit = doc.number(n, "load_limit", "dies[].load_limit");
        allow_only({"flywheel_energy", "flywheel_speed", "inertia", "screw_pitch", "efficiency", "ram_mass", "blows",
                    "pause", "load_limit", "direction"});
      }
    } else {
      need("crank_radius"), need("rod_length"), need("rpm");
      d.crank_radius = doc.number(n, "crank_radius", "dies[].crank_radius");
      d.rod_length = doc.number(n, "rod_length", "dies[].rod_length");
      if (!(d.rod_length > d.crank_radius))
        doc.fail(n["rod_length"], shown + ".rod_length", "the connecting rod must be longer than the crank radius");
      d.rpm = doc.number(n, "rpm", "dies[].rpm");
      d.start_angle = doc.number(n, "start_angle", "dies[].start_angle");
      d.direction = doc.vector(n, "direction", "dies[].direction");
      allow_only({"crank_radius", "rod_length", "rpm", "start_angle", "direction"});
    }
    if (d.direction.norm() == 0.0) doc.fail(n["direction"], shown + ".direction", "the direction must not be zero");
    d.friction = read_friction(doc, n, "dies", shown);
    if (const YAML::Node wear = n["wear"]) d.wear = read_wear(doc, wear, shown + ".wear", "dies[]", true);
    if (const YAML::Node fill = n["fill"]) {
      d.fill = true;
      if (const YAML::Node region = fill["region"]) {
        if (static_cast<bool>(region["min"]) != static_cast<bool>(region["max"]))
          doc.fail(region, shown + ".fill.region", "a box needs both 'min' and 'max'");
        if (!region["min"] && !region["radius"])
          doc.fail(region, shown + ".fill.region", "give a box ('min' and 'max'), a 'radius', or both");
        if (region["min"]) {
          const mesh::Point low = doc.vector(region, "min", "dies[].fill.region.min");
          const mesh::Point high = doc.vector(region, "max", "dies[].fill.region.max");
          if (!(low.array() < high.array()).all())
            doc.fail(region, shown + ".fill.region", "'min' must be below 'max' in x, y and z");
          d.fill_region.box = Eigen::AlignedBox3d(low, high);
        }
        if (region["radius"]) {
          d.fill_region.radius = doc.number(region, "radius", "dies[].fill.region.radius");
          const std::vector<double> axis = doc.numbers(region, "axis");
          if (!axis.empty() && axis.size() != 2)
            doc.fail(region["axis"], shown + ".fill.region.axis",
                     "needs 2 numbers (x, y), not " + std::to_string(axis.size()));
          if (axis.size() == 2) d.fill_region.axis = {axis[0], axis[1]};
        } else
          doc.forbid(region, "axis", shown + ".fill.region", "a region without a 'radius'");
      }
      if (fill["tolerance"]) d.fill_tolerance = doc.number(fill, "tolerance", "dies[].fill.tolerance");
    }
    c.dies.push_back(d);
  });
}

/// The heat exchange keys of the dies and contact pairs: read in a thermal
/// scene, refused in an isothermal one.
void read_contact_heat(const CheckedYaml& doc, Case& c) {
  const std::vector<std::string> die_keys{"temperature", "heat_transfer", "heat_transfer_pressure",
                                          "friction_heat_to_body"};
  for_each_entry(doc.root()["dies"], "dies", [&](const YAML::Node& n, const std::string& shown) {
    DieSpec& d = c.dies[std::stoul(shown.substr(5))];
    if (!c.thermal.enabled) {
      for (const std::string& key : die_keys)
        doc.forbid(n, key, shown, "an isothermal scene (the case has no 'thermal' section)");
      return;
    }
    doc.require(n, "temperature", shown, "a thermal scene holds each die at its temperature (°C)");
    doc.require(n, "heat_transfer", shown,
                "a thermal scene needs the die-body heat transfer coefficient (hot forging under pressure: 5-20 "
                "kW/(m2.K))");
    d.temperature = doc.number(n, "temperature", "dies[].temperature");
    d.heat = {read_table(doc, n, "heat_transfer", "heat_transfer_pressure", shown), true};
    d.friction_heat_to_body = doc.number(n, "friction_heat_to_body", "dies[].friction_heat_to_body");
  });
  for_each_entry(doc.root()["contact_pairs"], "contact_pairs", [&](const YAML::Node& n, const std::string& shown) {
    ContactPairSpec& pair = c.contact_pairs[std::stoul(shown.substr(14))];
    if (!c.thermal.enabled) {
      for (const char* key : {"heat_transfer", "heat_transfer_pressure"})
        doc.forbid(n, key, shown, "an isothermal scene (the case has no 'thermal' section)");
      return;
    }
    pair.heat = n["heat_transfer"]
                    ? ContactHeatSpec{read_table(doc, n, "heat_transfer", "heat_transfer_pressure", shown), true}
                    : ContactHeatSpec{thermal::PropertyTable(1000.0), false};
  });
}

/// damage: each criterion asked for (true), Oyane's with its constant.
void read_damage(const CheckedYaml& doc, Case& c) {
  const YAML::Node d = doc.root()["damage"];
  if (!d) return;
  if (!c.time.enabled)
    doc.fail(d, "damage", "damage is integrated over the deformation: the case needs a 'time' section");
  for (const auto& [name, criterion] : material::damage_criterion_names()) {
    if (!doc.boolean(d, name, "damage." + name)) continue;
    material::DamageModel& m = c.damage.emplace_back();
    m.criterion = criterion;
    if (criterion == material::DamageCriterion::oyane) {
      doc.require(d, "oyane_a", "damage", "Oyane's criterion needs the material's constant a (damage.oyane_a)");
      m.oyane_a = doc.number(d, "oyane_a", "damage.oyane_a");
    }
  }
  if (c.damage.empty())
    doc.fail(d, "damage", "no criterion asked for: set one or more of cockcroft_latham, oyane, ayada, brozzo to true");
  c.damage_on_progress = doc.boolean(d, "progress", "damage.progress");
}

void read_thermal(const CheckedYaml& doc, Case& c) {
  const YAML::Node t = doc.root()["thermal"];
  if (t) {
    ThermalSpec& s = c.thermal;
    s.enabled = true;
    s.source = doc.at(t);
    s.taylor_quinney = doc.number(t, "taylor_quinney", "thermal.taylor_quinney");
    const YAML::Node air = section(t, "environment");
    s.environment_temperature = doc.number(air, "temperature", "thermal.environment.temperature");
    s.convection = doc.number(air, "convection", "thermal.environment.convection");
    s.transfer_time = doc.number(t, "transfer_time", "thermal.transfer_time");
    s.transfer_steps = doc.integer(t, "transfer_steps", "thermal.transfer_steps");
    s.coupling_tolerance = doc.number(t, "coupling_tolerance", "thermal.coupling_tolerance");
    if (!c.time.enabled) doc.fail(t, "thermal", "heat needs a 'time' section (it is solved over time)");
  }
  read_contact_heat(doc, c);
}

bool root_has_thermal(const CheckedYaml& doc) {
  return static_cast<bool>(doc.root()["thermal"]);
}

void read_time(const CheckedYaml& doc, Case& c) {
  const YAML::Node t = doc.root()["time"];
  if (!t) return;
  TimeSpec& time = c.time;
  time.enabled = true;
  if (t["stroke_increment"]) time.stroke_increment = doc.number(t, "stroke_increment", "time.stroke_increment");
  if (t["heat_step"]) time.heat_step = doc.number(t, "heat_step", "time.heat_step");
  time.max_displacement = doc.number(t, "max_displacement", "time.max_displacement");
  time.min_step_fraction = doc.number(t, "min_step_fraction", "time.min_step_fraction");
  time.max_cuts = doc.integer(t, "max_cuts", "time.max_cuts");
  time.max_increments = doc.integer(t, "max_increments", "time.max_increments");
  time.max_increments_given = static_cast<bool>(t["max_increments"]);
  time.source = doc.at(t);
  time.volume_compensation = doc.boolean(t, "volume_compensation", "time.volume_compensation");
  const YAML::Node stop = t["stop"];
  // An energy press stops the run after its blows when nothing else does.
  const bool blows_stop = std::any_of(
      c.dies.begin(), c.dies.end(), [](const DieSpec& d) { return d.motion == "hammer" || d.motion == "screw_press"; });
  if ((!stop || stop.size() == 0) && !blows_stop)
    doc.fail(t, "time.stop",
             "missing: give at least one stop criterion (stroke, gap, load or time; a hammer or screw press stops "
             "after its blows)");
  if (!stop) return;
  if (stop["stroke"]) {
    time.final_stroke = doc.number(stop, "stroke", "time.stop.stroke");
    time.stroke_die = -1;
    for (std::size_t d = 0; d < c.dies.size(); ++d)
      if (stop["die"] ? c.dies[d].name == stop["die"].Scalar() : c.dies[d].motion != "fixed") {
        time.stroke_die = static_cast<int>(d);
        break;
      }
    if (time.stroke_die < 0)
      doc.fail(stop["die"] ? stop["die"] : stop, "time.stop.die",
               stop["die"] ? "no die is named '" + stop["die"].Scalar() + "'" : "a stroke needs a moving die");
  } else if (stop["die"])
    doc.fail(stop["die"], "time.stop.die", "only used with 'stroke'");
  if (stop["gap"]) {
    time.final_gap = doc.number(stop, "gap", "time.stop.gap");
    if (c.dies.size() != 2) doc.fail(stop["gap"], "time.stop.gap", "a die gap needs exactly two dies");
  }
  if (stop["load"]) time.max_load = doc.number(stop, "load", "time.stop.load");
  if (stop["time"]) time.end_time = doc.number(stop, "time", "time.stop.time");
  if (stop["temperature"]) {
    if (!root_has_thermal(doc))
      doc.fail(stop["temperature"], "time.stop.temperature", "a temperature stop needs a 'thermal' section");
    time.stop_temperature = doc.number(stop, "temperature", "time.stop.temperature");
  }
}

} // namespace

Case read_case(const std::string& path, const std::vector<std::string>& overrides) {
  const CheckedYaml doc(path, case_schema(), overrides);
  if (doc.root()["operations"])
    throw InputError(doc.at(doc.root()["operations"]) + ": a chain of operations: read it with read_chain");
  return read_case_document(doc, overrides);
}

Case read_case_document(const CheckedYaml& doc, const std::vector<std::string>& overrides) {
  const YAML::Node& root = doc.root();
  const std::string& path = doc.path();
  Case c;
  c.path = path;
  c.overrides = overrides;
  c.settings = flatten(root);
  c.title = doc.text(root, "title", "title");
  const YAML::Node output = section(root, "output");
  c.output_directory = doc.text(output, "directory", "output.directory");
  c.write_vtk = doc.boolean(output, "vtk", "output.vtk");
  c.write_picture = doc.boolean(output, "picture", "output.picture");
  c.picture_mirror = doc.boolean(output, "picture_mirror", "output.picture_mirror");
  c.vtk_every = doc.integer(output, "vtk_every", "output.vtk_every");
  c.checkpoint_every = doc.integer(output, "checkpoint_every", "output.checkpoint_every");
  c.detect_folds = doc.boolean(output, "folds", "output.folds");
  if (const YAML::Node lines = output["flow_lines"]) {
    if (!root["time"])
      doc.fail(lines, "output.flow_lines", "flow lines follow the material over time: the case needs a 'time' section");
    c.flow_line_axis = doc.text(lines, "axis", "output.flow_lines.axis")[0] - 'x';
    c.flow_line_count = doc.integer(lines, "count", "output.flow_lines.count");
  }
  const YAML::Node solver = section(root, "solver");
  c.newton.tolerance = doc.number(solver, "tolerance", "solver.tolerance");
  c.newton.increment_tolerance = doc.number(solver, "increment_tolerance", "solver.increment_tolerance");
  c.newton.max_iterations = doc.integer(solver, "max_iterations", "solver.max_iterations");
  c.newton.krylov_tolerance_max = doc.number(solver, "krylov_tolerance", "solver.krylov_tolerance");
  c.quadrature_degree = doc.integer(solver, "quadrature_degree", "solver.quadrature_degree");
  c.linear_solver.kind = solver::linear_solver_kind(doc.text(solver, "linear_solver", "solver.linear_solver"));
  c.linear_solver.reuse_preconditioner = doc.boolean(solver, "reuse_preconditioner", "solver.reuse_preconditioner");
  c.linear_solver.schur = solver::schur_approximation(doc.text(solver, "schur", "solver.schur"));
  c.petsc_options = doc.text(solver, "petsc_options", "solver.petsc_options");
  if (!c.petsc_options.empty()) // checked now, so a bad text stops the run before it starts
    solver::parse_petsc_options(c.petsc_options, doc.at(solver["petsc_options"]) + ": key 'solver.petsc_options'");

  const YAML::Node bodies = root["bodies"];
  for_each_entry(bodies, "bodies", [&](const YAML::Node& b, const std::string& shown) {
    BodySpec body;
    body.name = doc.text(b, "name", "bodies[].name");
    body.material_file = doc.input_file(b, "material", shown, kMaxYamlBytes);
    if (b["temperature"]) body.temperature = doc.number(b, "temperature", "bodies[].temperature");
    body.source = doc.at(b);
    if (const YAML::Node wear = b["wear"]) body.wear = read_wear(doc, wear, shown + ".wear", "bodies[]", false);
    const YAML::Node m = b["mesh"];
    MeshSpec& mesh = body.mesh;
    mesh.source = doc.at(m);
    const bool has_file = static_cast<bool>(m["file"]), has_generate = static_cast<bool>(m["generate"]);
    if (has_file == has_generate)
      doc.fail(m, shown + ".mesh", "give exactly one of 'file' (a mesh file) or 'generate' (box or cylinder)");
    if (has_file)
      mesh.file = doc.input_file(m, "file", shown + ".mesh", kMaxMeshBytes);
    else {
      mesh.generate = m["generate"].Scalar();
      mesh.element_size = doc.number(m, "element_size", "bodies[].mesh.element_size");
      if (mesh.generate == "box") {
        mesh.origin = doc.vector(m, "origin", "bodies[].mesh.origin");
        mesh.size = doc.vector(m, "size", "bodies[].mesh.size");
        if ((mesh.size.array() <= 0.0).any())
          doc.fail(m["size"], shown + ".mesh.size", "every edge length must be > 0 mm");
      } else {
        mesh.radius = doc.number(m, "radius", "bodies[].mesh.radius");
        if (mesh.generate == "quarter_ring") {
          mesh.inner_radius = doc.number(m, "inner_radius", "bodies[].mesh.inner_radius");
          if (!(mesh.inner_radius < mesh.radius))
            doc.fail(m["inner_radius"], shown + ".mesh.inner_radius", "must be smaller than the radius");
        }
        mesh.height = doc.number(m, "height", "bodies[].mesh.height");
      }
    }
    check_unique_name(doc, c.bodies, b, shown, "body");
    c.bodies.push_back(body);
  });

  for_each_entry(root["boundary"], "boundary", [&](const YAML::Node& n, const std::string& shown) {
    BoundaryCondition bc;
    bc.name = doc.text(n, "name", "boundary[].name");
    bc.source = doc.at(n);
    bc.kind = boundary_kind(doc.text(n, "type", "boundary[].type"));
    int body = 0;
    if (n["body"])
      body = body_index(doc, c, n, "body", shown);
    else if (c.bodies.size() > 1)
      doc.fail(n, shown, "the case has " + std::to_string(c.bodies.size()) + " bodies: say which one with 'body'");
    if (static_cast<bool>(n["tag"]) == static_cast<bool>(n["plane"]))
      doc.fail(n, shown, "give exactly one face selection: 'tag' or 'plane'");
    if (n["tag"])
      bc.faces.tag = doc.integer(n, "tag", "boundary[].tag");
    else {
      const YAML::Node plane = n["plane"];
      std::tie(bc.faces.plane_point, bc.faces.plane_normal) =
          read_plane(doc, plane, "boundary[].plane", shown + ".plane");
      bc.faces.tolerance = doc.number(plane, "tolerance", "boundary[].plane.tolerance");
    }
    auto require = [&](const char* key, const char* why) { doc.require(n, key, shown, why); };
    auto forbid = [&](const char* key) { doc.forbid(n, key, shown, "type '" + n["type"].Scalar() + "'"); };
    switch (bc.kind) {
    case BoundaryKind::velocity:
      require("velocity", "a velocity condition needs velocity: [vx, vy, vz] (mm/s, ~ for a free component)");
      bc.velocity = doc.partial_vector(n, "velocity");
      forbid("traction"), forbid("pressure");
      break;
    case BoundaryKind::sticking_plate:
    case BoundaryKind::frictionless_plate: {
      if (n["velocity"]) {
        const mesh::Point v = doc.vector(n, "velocity", "boundary[].velocity");
        bc.velocity = {v.x(), v.y(), v.z()};
      } else
        bc.velocity = {0.0, 0.0, 0.0};
      forbid("traction"), forbid("pressure");
      break;
    }
    case BoundaryKind::symmetry:
      forbid("velocity"), forbid("traction"), forbid("pressure");
      break;
    case BoundaryKind::traction:
      require("traction", "a traction condition needs traction: [tx, ty, tz] (MPa)");
      bc.traction = doc.vector(n, "traction", "boundary[].traction");
      forbid("velocity"), forbid("pressure");
      break;
    case BoundaryKind::pressure:
      require("pressure", "a pressure condition needs pressure: p (MPa)");
      bc.pressure = doc.number(n, "pressure", "boundary[].pressure");
      forbid("velocity"), forbid("traction");
      break;
    }
    c.boundary.push_back(bc);
    c.boundary_body.push_back(body);
  });
  read_dies(doc, c);
  read_contact_pairs(doc, c);
  c.linear_solver.velocity_block.facet_contact =
      std::any_of(c.contact_pairs.begin(), c.contact_pairs.end(),
                  [](const ContactPairSpec& p) { return p.method.integration == contact::PairIntegration::facet; });
  const YAML::Node contact = section(root, "contact");
  c.contact.penalty = doc.number(contact, "penalty", "contact.penalty");
  c.contact.regularisation = doc.number(contact, "regularisation", "contact.regularisation");
  read_time(doc, c);
  read_thermal(doc, c);
  read_remeshing(doc, c);
  if (!c.dies.empty() && !c.time.enabled)
    doc.fail(root["dies"], "dies", "dies need a 'time' section (stroke increment and stop criteria)");
  read_damage(doc, c);
  return c;
}

} // namespace anvil::scene
