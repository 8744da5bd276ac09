#include "anvil/scene/Case.h"

#include "checked_yaml.h"

#include <filesystem>

namespace anvil::scene {
namespace {

std::string relative_to(const std::string& base_file, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute()) return path;
  return (std::filesystem::path(base_file).parent_path() / p).lexically_normal().string();
}

BoundaryKind boundary_kind(const std::string& type) {
  if (type == "velocity") return BoundaryKind::velocity;
  if (type == "symmetry") return BoundaryKind::symmetry;
  if (type == "sticking_plate") return BoundaryKind::sticking_plate;
  if (type == "frictionless_plate") return BoundaryKind::frictionless_plate;
  if (type == "traction") return BoundaryKind::traction;
  return BoundaryKind::pressure;
}

} // namespace

Case read_case(const std::string& path) {
  const CheckedYaml doc(path, case_schema());
  const YAML::Node& root = doc.root();
  Case c;
  c.path = path;
  c.title = doc.text(root, "title", "title");
  const YAML::Node output = root["output"] ? root["output"] : YAML::Node(YAML::NodeType::Map);
  c.output_directory = doc.text(output, "directory", "output.directory");
  c.write_vtk = doc.boolean(output, "vtk", "output.vtk");
  const YAML::Node solver = root["solver"] ? root["solver"] : YAML::Node(YAML::NodeType::Map);
  c.newton.tolerance = doc.number(solver, "tolerance", "solver.tolerance");
  c.newton.max_iterations = doc.integer(solver, "max_iterations", "solver.max_iterations");
  c.linear_solver = solver::linear_solver_kind(doc.text(solver, "linear_solver", "solver.linear_solver"));

  const YAML::Node bodies = root["bodies"];
  if (bodies.size() > 1)
    doc.fail(bodies, "bodies", "this release solves one body; several bodies need contact, which comes with a later release");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const YAML::Node b = bodies[i];
    const std::string shown = "bodies[" + std::to_string(i) + "]";
    BodySpec body;
    body.name = doc.text(b, "name", "bodies[].name");
    body.material_file = relative_to(path, doc.text(b, "material", "bodies[].material"));
    const YAML::Node m = b["mesh"];
    MeshSpec& mesh = body.mesh;
    mesh.source = doc.at(m);
    const bool has_file = static_cast<bool>(m["file"]), has_generate = static_cast<bool>(m["generate"]);
    if (has_file == has_generate)
      doc.fail(m, shown + ".mesh", "give exactly one of 'file' (a mesh file) or 'generate' (box or cylinder)");
    if (has_file) mesh.file = relative_to(path, m["file"].Scalar());
    else {
      mesh.generate = m["generate"].Scalar();
      mesh.element_size = doc.number(m, "element_size", "bodies[].mesh.element_size");
      if (mesh.generate == "box") {
        mesh.origin = doc.vector(m, "origin", "bodies[].mesh.origin");
        mesh.size = doc.vector(m, "size", "bodies[].mesh.size");
        if ((mesh.size.array() <= 0.0).any()) doc.fail(m["size"], shown + ".mesh.size", "every edge length must be > 0 mm");
      } else {
        mesh.radius = doc.number(m, "radius", "bodies[].mesh.radius");
        mesh.height = doc.number(m, "height", "bodies[].mesh.height");
      }
    }
    for (const BodySpec& other : c.bodies)
      if (other.name == body.name) doc.fail(b["name"], shown + ".name", "body '" + body.name + "' is defined twice");
    c.bodies.push_back(body);
  }

  const YAML::Node boundary = root["boundary"];
  for (std::size_t i = 0; boundary && i < boundary.size(); ++i) {
    const YAML::Node n = boundary[i];
    const std::string shown = "boundary[" + std::to_string(i) + "]";
    BoundaryCondition bc;
    bc.name = doc.text(n, "name", "boundary[].name");
    bc.source = doc.at(n);
    bc.kind = boundary_kind(doc.text(n, "type", "boundary[].type"));
    int body = 0;
    if (n["body"]) {
      body = -1;
      for (std::size_t b = 0; b < c.bodies.size(); ++b)
        if (c.bodies[b].name == n["body"].Scalar()) body = static_cast<int>(b);
      if (body < 0) doc.fail(n["body"], shown + ".body", "no body is named '" + n["body"].Scalar() + "'");
    }
    if (static_cast<bool>(n["tag"]) == static_cast<bool>(n["plane"]))
      doc.fail(n, shown, "give exactly one face selection: 'tag' or 'plane'");
    if (n["tag"]) bc.faces.tag = doc.integer(n, "tag", "boundary[].tag");
    else {
      const YAML::Node plane = n["plane"];
      bc.faces.plane_point = doc.vector(plane, "point", "boundary[].plane.point");
      bc.faces.plane_normal = doc.vector(plane, "normal", "boundary[].plane.normal");
      if (bc.faces.plane_normal.norm() == 0.0) doc.fail(plane["normal"], shown + ".plane.normal", "the normal must not be zero");
      bc.faces.tolerance = doc.number(plane, "tolerance", "boundary[].plane.tolerance");
    }
    auto require = [&](const char* key, const char* why) {
      if (!n[key]) doc.fail(n, shown + "." + key, std::string("missing: ") + why);
    };
    auto forbid = [&](const char* key) {
      if (n[key]) doc.fail(n[key], shown + "." + key, "does not apply to type '" + n["type"].Scalar() + "'");
    };
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
      } else bc.velocity = {0.0, 0.0, 0.0};
      forbid("traction"), forbid("pressure");
      break;
    }
    case BoundaryKind::symmetry: forbid("velocity"), forbid("traction"), forbid("pressure"); break;
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
  }
  return c;
}

std::unique_ptr<material::Material> read_material(const std::string& path) {
  const CheckedYaml doc(path, material_schema());
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
    if (!root[key]) doc.fail(root, key, "missing: law '" + law + "' needs it");
    return doc.number(root, key, key);
  };
  if (law == "newtonian") return std::make_unique<material::NortonHoff>(needed("viscosity"), 1.0, 0.0);
  if (law == "norton_hoff")
    return std::make_unique<material::NortonHoff>(needed("consistency"), needed("sensitivity"),
                                                  doc.number(root, "regularisation_rate", "regularisation_rate"));
  return std::make_unique<material::LinearElastic>(needed("young_modulus"), needed("poisson_ratio"));
}

} // namespace anvil::scene
