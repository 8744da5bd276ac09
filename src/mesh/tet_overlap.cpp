#include "anvil/mesh/tet_overlap.h"

#include "anvil/mesh/tet_geometry.h"

#include <cmath>

namespace anvil::mesh {
namespace {

constexpr int max_pieces = 81; // 3 pieces per tet per plane, 4 planes

struct Pieces {
  std::array<TetCorners, max_pieces> tets;
  int count = 0;
  void add(const Point& p0, const Point& p1, const Point& p2, const Point& p3) { tets[count++] = {p0, p1, p2, p3}; }
  /// A triangular prism, a_i joined to b_i by planar quads, as three tets.
  void add_prism(const Point& a0, const Point& a1, const Point& a2, const Point& b0, const Point& b1, const Point& b2) {
    add(a0, a1, a2, b0);
    add(a1, a2, b0, b1);
    add(a2, b0, b1, b2);
  }
};

/// A plane n·x = offset; the kept side is n·x ≤ offset.
struct HalfSpace {
  Point normal;
  double offset;
  double distance(const Point& x) const { return normal.dot(x) - offset; }
};

/// The part of `t` on the kept side of `h`, added to `out`.
void clip(const TetCorners& t, const HalfSpace& h, Pieces& out) {
  std::array<double, 4> d{};
  std::array<int, 4> in{}, outside{};
  int n_in = 0, n_out = 0;
  for (int k = 0; k < 4; ++k) {
    d[k] = h.distance(t[k]);
    if (d[k] <= 0.0)
      in[n_in++] = k;
    else
      outside[n_out++] = k;
  }
  // Where the edge from kept vertex i to cut vertex o crosses the plane (d_o > 0 ≥ d_i).
  auto cut = [&](int i, int o) { return Point(t[i] + d[i] / (d[i] - d[o]) * (t[o] - t[i])); };
  switch (n_in) {
  case 4:
    out.add(t[0], t[1], t[2], t[3]);
    break;
  case 3: { // the tet less a corner: prism between the kept face and the cut
    const int o = outside[0];
    out.add_prism(t[in[0]], t[in[1]], t[in[2]], cut(in[0], o), cut(in[1], o), cut(in[2], o));
    break;
  }
  case 2: { // a wedge along the kept edge
    const int i = in[0], j = in[1], a = outside[0], b = outside[1];
    out.add_prism(t[i], cut(i, a), cut(i, b), t[j], cut(j, a), cut(j, b));
    break;
  }
  case 1:
    out.add(t[in[0]], cut(in[0], outside[0]), cut(in[0], outside[1]), cut(in[0], outside[2]));
    break;
  default:
    break; // all cut away
  }
}

} // namespace

Overlap tet_overlap(const TetCorners& a, const TetCorners& b) {
  Pieces buffers[2];
  int current = 0;
  buffers[current].add(a[0], a[1], a[2], a[3]);
  for (int face = 0; face < 4 && buffers[current].count > 0; ++face) {
    // The plane through the three corners other than `face`, oriented away from it.
    const Point& p = b[(face + 1) % 4];
    HalfSpace h{(b[(face + 2) % 4] - p).cross(b[(face + 3) % 4] - p), 0.0};
    if (h.normal.dot(b[face] - p) > 0.0) h.normal = -h.normal;
    h.offset = h.normal.dot(p);
    Pieces& next = buffers[1 - current];
    next.count = 0;
    for (int k = 0; k < buffers[current].count; ++k)
      clip(buffers[current].tets[k], h, next);
    current = 1 - current;
  }
  Overlap o;
  for (int k = 0; k < buffers[current].count; ++k) {
    const TetCorners& t = buffers[current].tets[k];
    const double v = std::abs(signed_volume(t[0], t[1], t[2], t[3]));
    o.volume += v;
    o.centroid += 0.25 * v * (t[0] + t[1] + t[2] + t[3]);
  }
  if (o.volume > 0.0) o.centroid /= o.volume;
  return o;
}

} // namespace anvil::mesh
