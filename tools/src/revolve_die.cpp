// Writes die surfaces of revolution as ASCII STL: a profile (r, z) of the
// lower die's working surface, corners rounded to a fillet radius, swept over
// a sector about the z axis. The upper die is the same profile mirrored in
// z = 0 (the parting plane). Prints the volume the closed dies enclose
// inside each profile radius, to size the billet.
//   anvil_revolve_die dies/hub_flange.yaml
// The STL files go next to the YAML file. Normals point out of the die.
#include "anvil/core/error.h"
#include "yaml_number.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using Point2 = Eigen::Vector2d; // (r, z), mm

constexpr double pi = 3.14159265358979323846;

/// The profile with each interior corner replaced by a circular arc of
/// radius `fillet` (smaller where the neighbouring segments are short),
/// one point per 10° of turn.
std::vector<Point2> rounded(const std::vector<Point2>& profile, double fillet) {
  if (fillet <= 0.0) return profile;
  std::vector<Point2> out{profile.front()};
  for (std::size_t k = 1; k + 1 < profile.size(); ++k) {
    const Point2 corner = profile[k];
    const Point2 to_previous = (profile[k - 1] - corner).normalized(), to_next = (profile[k + 1] - corner).normalized();
    const double opening = std::acos(std::clamp(to_previous.dot(to_next), -1.0, 1.0)); // π: straight on
    if (pi - opening < 1e-6) {
      out.push_back(corner);
      continue;
    }
    // Tangent points at distance t from the corner, at most 45 % of either segment.
    const double reach = 0.45 * std::min((profile[k - 1] - corner).norm(), (profile[k + 1] - corner).norm());
    const double t = std::min(fillet / std::tan(0.5 * opening), reach);
    const double radius = t * std::tan(0.5 * opening);
    const Point2 centre = corner + (to_previous + to_next).normalized() * radius / std::sin(0.5 * opening);
    const Point2 first = corner + t * to_previous, last = corner + t * to_next;
    const double a0 = std::atan2(first.y() - centre.y(), first.x() - centre.x());
    double sweep = std::atan2(last.y() - centre.y(), last.x() - centre.x()) - a0;
    if (sweep > pi) sweep -= 2 * pi;
    if (sweep < -pi) sweep += 2 * pi;
    const int segments = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) / (pi / 18))));
    for (int s = 0; s <= segments; ++s) {
      const double a = a0 + sweep * s / segments;
      out.push_back(centre + radius * Point2(std::cos(a), std::sin(a)));
    }
  }
  out.push_back(profile.back());
  return out;
}

/// Volume between the lower die and its mirror, inside radius r_k of the
/// profile (full revolution): 2π ∫ r (−2 z) dr, exact on each straight
/// segment (r·z is quadratic there, Simpson's rule integrates it exactly).
std::vector<double> enclosed_volumes(const std::vector<Point2>& profile) {
  std::vector<double> volume{0.0};
  for (std::size_t k = 1; k < profile.size(); ++k) {
    const Point2 a = profile[k - 1], b = profile[k];
    const Point2 m = 0.5 * (a + b);
    const double integral = (b.x() - a.x()) / 6.0 * (a.x() * a.y() + 4 * m.x() * m.y() + b.x() * b.y());
    volume.push_back(volume.back() + 2 * pi * (-2.0 * integral));
  }
  return volume;
}

void write_stl(const std::string& path, const std::string& name, const std::vector<Point2>& profile, double from_deg,
               double to_deg, double segment_deg, bool mirror) {
  const int segments = std::max(1, static_cast<int>(std::ceil((to_deg - from_deg) / segment_deg)));
  auto at = [&](const Point2& p, int j) {
    const double a = (from_deg + (to_deg - from_deg) * j / segments) * pi / 180.0;
    return Eigen::Vector3d(p.x() * std::cos(a), p.x() * std::sin(a), mirror ? -p.y() : p.y());
  };
  std::ofstream out(path);
  if (!out) throw anvil::InputError(path + ": cannot write");
  out.precision(9);
  out << "solid " << name << "\n";
  auto facet = [&](Eigen::Vector3d a, Eigen::Vector3d b, Eigen::Vector3d c) {
    if (mirror) std::swap(b, c); // mirrored in z: keep the normals out of the die
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() < 1e-14) return; // on the axis
    const Eigen::Vector3d u = n.normalized();
    out << "  facet normal " << u.x() << " " << u.y() << " " << u.z() << "\n    outer loop\n";
    for (const Eigen::Vector3d& v : {a, b, c})
      out << "      vertex " << v.x() << " " << v.y() << " " << v.z() << "\n";
    out << "    endloop\n  endfacet\n";
  };
  // Along the profile then around the axis: (t_profile × t_angle) points
  // up on a floor, out of the lower die.
  for (std::size_t i = 0; i + 1 < profile.size(); ++i)
    for (int j = 0; j < segments; ++j) {
      facet(at(profile[i], j), at(profile[i + 1], j), at(profile[i + 1], j + 1));
      facet(at(profile[i], j), at(profile[i + 1], j + 1), at(profile[i], j + 1));
    }
  out << "endsolid " << name << "\n";
  if (!out) throw anvil::InputError(path + ": write failed");
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "--help") {
    std::cerr << "usage: anvil_revolve_die DIES.yaml   (writes the STL files it lists next to it)\n";
    return argc == 2 ? 0 : 2;
  }
  const std::string file = argv[1];
  try {
    const YAML::Node root = YAML::LoadFile(file);
    std::vector<Point2> profile;
    for (const YAML::Node& p : root["profile"])
      profile.emplace_back(p[0].as<double>(), p[1].as<double>());
    if (profile.size() < 2) throw anvil::InputError(file + ": 'profile' needs at least two [r, z] points");
    for (std::size_t k = 1; k < profile.size(); ++k)
      if (profile[k].x() < profile[k - 1].x() - 1e-12 || (profile[k] - profile[k - 1]).norm() < 1e-9)
        throw anvil::InputError(file + ": 'profile' point " + std::to_string(k + 1) +
                                " goes back towards the axis or repeats the one before (r must not decrease)");
    const std::vector<Point2> surface = rounded(profile, root["fillet"] ? root["fillet"].as<double>() : 0.0);
    const YAML::Node sector = root["sector"];
    const double from = sector[0].as<double>(), to = sector[1].as<double>();
    const double segment = yaml_number(root, file, "segment_angle");
    const std::filesystem::path folder = std::filesystem::path(file).parent_path();
    for (const YAML::Node& die : root["dies"]) {
      const std::string stl = (folder / die["stl"].as<std::string>()).string();
      write_stl(stl, std::filesystem::path(stl).stem().string(), surface, from, to, segment, die["mirror"].as<bool>());
      std::printf("wrote %s\n", stl.c_str());
    }
    const std::vector<double> volume = enclosed_volumes(surface);
    std::printf("closed dies, volume inside radius r (full revolution, fillets included):\n");
    for (const Point2& corner : profile) {
      std::size_t k = 0;
      while (k + 1 < surface.size() && surface[k + 1].x() <= corner.x())
        ++k;
      const double span = k + 1 < surface.size() ? surface[k + 1].x() - surface[k].x() : 0.0;
      const double w = span > 0.0 ? (corner.x() - surface[k].x()) / span : 0.0;
      std::printf("  r %7.3f mm  volume %10.2f mm³\n", corner.x(),
                  (1 - w) * volume[k] + w * volume[std::min(k + 1, volume.size() - 1)]);
    }
  } catch (const YAML::Exception& e) {
    std::cerr << file << ":" << e.mark.line + 1 << ": " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
