#include "anvil/mesh/flat_tet_mending.h"

#include "anvil/mesh/tet_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace anvil::mesh {
namespace {

/// Rings longer than this are left alone: the triangulations of the link
/// polygon are searched in O(m³), and a flat tet's edges have rings of 3-9.
constexpr int kLongestRing = 12;
/// Passes over the tets (each strictly raises the worst quality it touches).
constexpr int kPasses = 4;
/// Where a lifted split puts its node: the edge's midpoint moved off the
/// flat tet's plane by these shares of the edge's length, to either side.
constexpr double kLifts[] = {0.05, 0.1, 0.2, 0.3};

/// The tets around edge (a, c), in order: tet i is (a, c, link[i],
/// link[i+1]) up to orientation, which is `sigma` for all of them.
struct Ring {
  int a = -1, c = -1;
  std::vector<int> tets;
  std::vector<int> link;
  double sigma = 0.0;
  double worst = 0.0; ///< the worst quality of its tets
};

/// The ring of edge (a, c); nothing when it is open (the edge on the
/// boundary), reaches a tet before `first`, or is too long.
std::optional<Ring> ring_of(const TetMesh& mesh, const std::vector<std::vector<int>>& around,
                            const std::vector<char>& dead, int first, int a, int c) {
  Ring ring;
  ring.a = a;
  ring.c = c;
  std::vector<int> tets;
  std::vector<std::array<int, 2>> sides; // per tet of `tets`: its two nodes other than a and c
  for (int e : around[a]) {
    if (dead[e]) continue;
    const Tet& t = mesh.tets[e];
    if (std::find(t.begin(), t.end(), c) == t.end()) continue;
    if (e < first) return std::nullopt;
    std::array<int, 2> other{};
    int k = 0;
    for (int v : t)
      if (v != a && v != c) other[k++] = v;
    tets.push_back(e);
    sides.push_back(other);
  }
  const int m = static_cast<int>(sides.size());
  if (m < 3 || m > kLongestRing) return std::nullopt;
  // Walk the link: a closed ring passes each of its nodes twice.
  ring.tets = {tets[0]};
  ring.link = {sides[0][0], sides[0][1]};
  std::vector<char> used(m, 0);
  used[0] = 1;
  for (int step = 1; step < m; ++step) {
    int next = -1;
    for (int k = 0; k < m && next < 0; ++k)
      if (!used[k] && (sides[k][0] == ring.link.back() || sides[k][1] == ring.link.back())) next = k;
    if (next < 0) return std::nullopt;
    used[next] = 1;
    ring.tets.push_back(tets[next]);
    ring.link.push_back(sides[next][0] == ring.link.back() ? sides[next][1] : sides[next][0]);
  }
  if (ring.link.back() != ring.link.front()) return std::nullopt;
  ring.link.pop_back();
  std::vector<int> distinct = ring.link;
  std::sort(distinct.begin(), distinct.end());
  if (std::adjacent_find(distinct.begin(), distinct.end()) != distinct.end()) return std::nullopt;
  // The orientation from the largest tet: a flat one's sign is round-off.
  const std::vector<Point>& x = mesh.nodes;
  double largest = 0.0;
  ring.worst = std::numeric_limits<double>::infinity();
  for (int i = 0; i < m; ++i) {
    const double v = signed_volume(x[a], x[c], x[ring.link[i]], x[ring.link[(i + 1) % m]]);
    if (std::abs(v) > largest) largest = std::abs(v), ring.sigma = v > 0.0 ? 1.0 : -1.0;
    ring.worst = std::min(ring.worst, quality(mesh, ring.tets[i]));
  }
  return ring;
}

/// What a ring becomes: its new tets (positively oriented) and their worst
/// quality, with the new node's position for a lifted split.
struct Mending {
  std::vector<Tet> made;
  double worst = -std::numeric_limits<double>::infinity();
  std::optional<Point> new_node;
};

/// `t` with positive orientation when the ring's is `sigma`.
Tet oriented(Tet t, double sigma) {
  if (sigma < 0.0) std::swap(t[2], t[3]);
  return t;
}

/// Edge removal: the link polygon triangulated for the best worst quality
/// of the tets each triangle makes with a and with c (Klincsek's dynamic
/// programme). They fill the ring exactly when every one has the ring's
/// orientation (Shewchuk 2002, §3), which a positive worst quality says.
Mending edge_removal(const TetMesh& mesh, const Ring& ring) {
  const std::vector<Point>& x = mesh.nodes;
  const std::vector<int>& l = ring.link;
  const int m = static_cast<int>(l.size());
  auto joined = [&](int i, int j, int k) {
    return std::min(ring.sigma * quality(x[ring.a], x[l[i]], x[l[j]], x[l[k]]),
                    -ring.sigma * quality(x[ring.c], x[l[i]], x[l[j]], x[l[k]]));
  };
  const double none = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> best(m, std::vector<double>(m, none));
  std::vector<std::vector<int>> apex(m, std::vector<int>(m, -1));
  for (int span = 2; span < m; ++span)
    for (int i = 0; i + span < m; ++i) {
      const int k = i + span;
      best[i][k] = -none;
      for (int j = i + 1; j < k; ++j) {
        const double q = std::min({best[i][j], best[j][k], joined(i, j, k)});
        if (q > best[i][k]) best[i][k] = q, apex[i][k] = j;
      }
    }
  Mending out;
  out.worst = best[0][m - 1];
  // No valid triangulation (a sub-chain without one has no apex): nothing to make.
  if (!(out.worst > 0.0)) return out;
  std::vector<std::array<int, 2>> open{{0, m - 1}};
  while (!open.empty()) {
    const auto [i, k] = open.back();
    open.pop_back();
    if (k - i < 2) continue;
    const int j = apex[i][k];
    out.made.push_back(oriented({ring.a, l[i], l[j], l[k]}, ring.sigma));
    out.made.push_back(oriented({ring.c, l[k], l[j], l[i]}, ring.sigma));
    open.push_back({i, j});
    open.push_back({j, k});
  }
  return out;
}

/// Lifted split: a node s joined to every face of the ring's surface, tet i
/// giving (s, c, link i, link i+1) and (a, s, link i, link i+1), which fill
/// the ring when all have its orientation (s sees every face); s is the
/// edge's midpoint moved along `normal` by the lift that gives the best
/// worst quality.
Mending lifted_split(const TetMesh& mesh, const Ring& ring, const Point& normal) {
  const std::vector<Point>& x = mesh.nodes;
  const std::vector<int>& l = ring.link;
  const int m = static_cast<int>(l.size());
  const Point middle = 0.5 * (x[ring.a] + x[ring.c]);
  const double length = (x[ring.a] - x[ring.c]).norm();
  Mending out;
  for (double lift : kLifts)
    for (double side : {1.0, -1.0}) {
      const Point s = middle + side * lift * length * normal;
      double worst = std::numeric_limits<double>::infinity();
      for (int i = 0; i < m; ++i) {
        const Point &p = x[l[i]], &q = x[l[(i + 1) % m]];
        worst = std::min({worst, ring.sigma * quality(s, x[ring.c], p, q), ring.sigma * quality(x[ring.a], s, p, q)});
      }
      if (worst > out.worst) out.worst = worst, out.new_node = s;
    }
  const int s = mesh.node_count();
  for (int i = 0; i < m; ++i) {
    out.made.push_back(oriented({s, ring.c, l[i], l[(i + 1) % m]}, ring.sigma));
    out.made.push_back(oriented({ring.a, s, l[i], l[(i + 1) % m]}, ring.sigma));
  }
  return out;
}

/// The unit normal of tet `t`'s largest face: the plane of a flat tet.
Point flat_normal(const TetMesh& mesh, const Tet& t) {
  Point largest = Point::Zero();
  for (const auto& fv : kFaceVertices) {
    const Point n = area_vector(mesh, {t[fv[0]], t[fv[1]], t[fv[2]]});
    if (n.norm() > largest.norm()) largest = n;
  }
  return largest.normalized();
}

} // namespace

int mend_flat_tets(TetMesh& mesh, int first, double below) {
  std::vector<std::vector<int>> around; // built at the first poor tet: most regions have none
  std::vector<char> dead(mesh.tets.size(), 0);
  int mended = 0;
  // New tets can be poor too (only better than their ring): a later pass
  // looks at them again, not this one: within one pass, lifted splits of
  // the tets it makes can chain without end, each a little better than the
  // last and a node more.
  bool changed = true;
  for (int pass = 0; pass < kPasses && changed; ++pass) {
    changed = false;
    const int pass_end = mesh.tet_count();
    for (int e = first; e < pass_end; ++e) {
      if (dead[e] || quality(mesh, e) >= below) continue;
      if (around.empty()) around = tets_around_nodes(mesh);
      const Tet t = mesh.tets[e];
      std::vector<Ring> rings;
      for (int p = 0; p < 4; ++p)
        for (int q = p + 1; q < 4; ++q)
          if (std::optional<Ring> ring = ring_of(mesh, around, dead, first, t[p], t[q])) rings.push_back(*ring);
      const Ring* chosen_ring = nullptr;
      Mending chosen;
      auto consider = [&](const Ring& ring, Mending candidate) {
        if (candidate.worst > std::max(ring.worst, 0.0) && candidate.worst > chosen.worst)
          chosen = std::move(candidate), chosen_ring = &ring;
      };
      for (const Ring& ring : rings)
        consider(ring, edge_removal(mesh, ring));
      // An edge removal adds no node: a lifted split only where none helps.
      if (!chosen_ring) {
        const Point normal = flat_normal(mesh, t);
        for (const Ring& ring : rings)
          consider(ring, lifted_split(mesh, ring, normal));
      }
      if (!chosen_ring) continue;
      for (int r : chosen_ring->tets)
        dead[r] = 1;
      if (chosen.new_node) {
        mesh.nodes.push_back(*chosen.new_node);
        around.emplace_back();
      }
      for (const Tet& made : chosen.made) {
        for (int v : made)
          around[v].push_back(mesh.tet_count());
        mesh.tets.push_back(made);
        dead.push_back(0);
      }
      ++mended;
      changed = true;
    }
  }
  if (mended > 0) {
    std::vector<Tet> alive;
    for (int e = 0; e < mesh.tet_count(); ++e)
      if (!dead[e]) alive.push_back(mesh.tets[e]);
    mesh.tets = std::move(alive);
  }
  return mended;
}

} // namespace anvil::mesh
