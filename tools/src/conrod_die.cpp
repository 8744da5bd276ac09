// Writes the closed dies of a connecting-rod-like forging as binary STL:
// two bosses of different heights (discs in plan) joined by a tapered shank
// of I section (a thin web between two ribs), drafted walls, rounded
// corners, a flash land all around the part at the parting plane and a
// gutter beyond it. Each die's working surface is a height field over the
// plan (x along the rod, y across), z = ±(half the flash gap + the cavity's
// depth there); the upper die is the lower one mirrored in the parting
// plane z = 0. Prints the part's volume, to size the billet.
//   anvil_conrod_die dies/conrod.yaml
// The STL files go next to the YAML file. Normals point out of the die.
#include "anvil/core/error.h"
#include "yaml_number.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using Point2 = Eigen::Vector2d; // (x, y), mm

struct Conrod {
  double big_radius, big_height;     ///< the large boss (centre at the origin): radius, height above the parting plane
  double small_radius, small_height; ///< the small boss (centre at x = centres)
  double centres;                    ///< distance between the boss centres
  double shank_big, shank_small;     ///< the shank's half-width where it meets each boss
  double web_height, rib_height, rib_width;
  double draft_deg, fillet;
  double flash_gap, land_width, gutter_depth, gutter_draft_deg;
  double x_min, x_max, y_min, y_max, spacing; ///< the dies' extent in plan and the grid spacing
};

/// Smooth maximum (and minimum) of a and b: their max, rounded over a band
/// of width k (a fillet of about that size where two surfaces meet).
double smooth_max(double a, double b, double k) {
  const double h = std::max(0.0, k - std::abs(a - b)) / k;
  return std::max(a, b) + 0.25 * k * h * h;
}
double smooth_min(double a, double b, double k) {
  return -smooth_max(-a, -b, k);
}

/// Signed distance (negative inside) to a segment-swept disc of varying
/// radius: the shank, from (0, 0) with half-width r0 to (c, 0) with r1.
double shank_distance(const Point2& p, double c, double r0, double r1) {
  const double t = std::clamp(p.x() / c, 0.0, 1.0);
  const double half = r0 + t * (r1 - r0);
  return std::max(std::abs(p.y()) - half, std::max(-p.x(), p.x() - c));
}

/// The height of the lower die's cavity below the parting plane at `p`
/// (mm, > 0 into the die): half the flash gap on the land, the part's half
/// height over its plan, the gutter beyond the land.
double depth(const Conrod& c, const Point2& p) {
  const double steep = 1.0 / std::tan(c.draft_deg * M_PI / 180.0); // height gained per mm inwards on a drafted wall
  const double big = p.norm() - c.big_radius, small = (p - Point2(c.centres, 0.0)).norm() - c.small_radius;
  const double shank = shank_distance(p, c.centres, c.shank_big, c.shank_small);
  const double rib = std::max(shank, -shank - c.rib_width);
  const double land = 0.5 * c.flash_gap;
  // Each feature rises through the land at its outline with the draft, to
  // its height (outside the outline it falls away below the land, where the
  // smooth maximum leaves the land as it is).
  auto feature = [&](double distance, double height) { return smooth_min(height, land - distance * steep, c.fillet); };
  double h = land;
  h = smooth_max(h, feature(shank, c.web_height), c.fillet);
  h = smooth_max(h, feature(rib, c.rib_height), c.fillet);
  h = smooth_max(h, feature(big, c.big_height), c.fillet);
  h = smooth_max(h, feature(small, c.small_height), c.fillet);
  // Beyond the land the gutter falls away at its own draft.
  const double outside = std::min({big, small, shank});
  const double gutter = std::min(c.gutter_depth, land + std::max(0.0, outside - c.land_width) /
                                                            std::tan(c.gutter_draft_deg * M_PI / 180.0));
  return std::max(h, gutter);
}

void write_stl(const std::string& path, const Conrod& c, bool upper) {
  const int nx = static_cast<int>(std::ceil((c.x_max - c.x_min) / c.spacing));
  const int ny = static_cast<int>(std::ceil((c.y_max - c.y_min) / c.spacing));
  auto at = [&](int i, int j) {
    const Point2 p(c.x_min + (c.x_max - c.x_min) * i / nx, c.y_min + (c.y_max - c.y_min) * j / ny);
    const double z = -depth(c, p);
    return Eigen::Vector3f(float(p.x()), float(p.y()), float(upper ? -z : z));
  };
  std::vector<Eigen::Vector3f> grid;
  grid.reserve(static_cast<std::size_t>((nx + 1) * (ny + 1)));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      grid.push_back(at(i, j));
  auto node = [&](int i, int j) { return grid[static_cast<std::size_t>(j * (nx + 1) + i)]; };
  std::ofstream out(path, std::ios::binary);
  if (!out) throw anvil::InputError(path + ": cannot write");
  char header[80] = {};
  std::snprintf(header, sizeof header, "anvil_conrod_die %s die", upper ? "upper" : "lower");
  out.write(header, sizeof header);
  const std::uint32_t count = static_cast<std::uint32_t>(2 * nx * ny);
  out.write(reinterpret_cast<const char*>(&count), 4);
  auto facet = [&](Eigen::Vector3f a, Eigen::Vector3f b, Eigen::Vector3f d) {
    if (upper) std::swap(b, d); // mirrored: the normals still point out of the die, towards the part
    const Eigen::Vector3f n = (b - a).cross(d - a).normalized();
    for (const Eigen::Vector3f& v : {n, a, b, d})
      out.write(reinterpret_cast<const char*>(v.data()), 12);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  };
  // Counter-clockwise seen from +z: normals up, out of the lower die.
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      facet(node(i, j), node(i + 1, j), node(i + 1, j + 1));
      facet(node(i, j), node(i + 1, j + 1), node(i, j + 1));
    }
  if (!out) throw anvil::InputError(path + ": write failed");
}

/// The part's volume (mm³) between the closed dies for y >= 0 (a half
/// model; the part is symmetric about y = 0), where the plan is inside the
/// part's outline (the flash excluded).
double half_part_volume(const Conrod& c) {
  const double step = 0.05;
  double volume = 0.0;
  for (double x = c.x_min + 0.5 * step; x < c.x_max; x += step)
    for (double y = 0.5 * step; y < c.y_max; y += step) {
      const Point2 p(x, y);
      const double big = p.norm() - c.big_radius, small = (p - Point2(c.centres, 0.0)).norm() - c.small_radius;
      if (std::min({big, small, shank_distance(p, c.centres, c.shank_big, c.shank_small)}) < 0.0)
        volume += 2.0 * depth(c, p) * step * step;
    }
  return volume;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "--help") {
    std::cerr << "usage: anvil_conrod_die DIES.yaml   (writes the STL files it names next to it)\n";
    return argc == 2 ? 0 : 2;
  }
  const std::string file = argv[1];
  try {
    const YAML::Node root = YAML::LoadFile(file);
    auto n = [&](const char* key) { return yaml_number(root, file, key); };
    const Conrod c{n("big_radius"),   n("big_height"),  n("small_radius"), n("small_height"), n("centres"),
                   n("shank_big"),    n("shank_small"), n("web_height"),   n("rib_height"),   n("rib_width"),
                   n("draft"),        n("fillet"),      n("flash_gap"),    n("land_width"),   n("gutter_depth"),
                   n("gutter_draft"), n("x_min"),       n("x_max"),        n("y_min"),        n("y_max"),
                   n("spacing")};
    const std::filesystem::path folder = std::filesystem::path(file).parent_path();
    for (const auto& [key, upper] : {std::pair{"lower", false}, std::pair{"upper", true}}) {
      const std::string stl = (folder / root[key].as<std::string>()).string();
      write_stl(stl, c, upper);
      std::printf("wrote %s\n", stl.c_str());
    }
    const double half = half_part_volume(c);
    std::printf("part (flash excluded): %.1f mm³ whole, %.1f mm³ for y >= 0 (a half model)\n", 2.0 * half, half);
  } catch (const YAML::Exception& e) {
    std::cerr << file << ":" << e.mark.line + 1 << ": " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
