// The tets CGAL is given for a region's remesh. CGAL's passes scan every
// cell they are given, the kept ones too (docs/libraries.md §2): a region of
// a few hundred tets given with the whole body pays for all of it. Its own
// soup builder takes only a ball, so the region goes with the tets around
// it, as a mesh of their own, when those form one; else with the body.
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/remesh/remesh_body.h"

#include <optional>
#include <span>
#include <vector>

namespace anvil::remesh {

/// A region with the kept tets around it, cut out of a body.
struct RegionWindow {
  /// The tets, in the body's order, and their nodes, in the body's order;
  /// the faces it shares with the rest of the body are boundary faces of
  /// their own tag, which CGAL neither moves nor remeshes (kept tets only).
  mesh::TetMesh soup;
  std::vector<int> body_node; ///< per node of `soup`: the body's node
  std::vector<char> rebuilt;  ///< per tet of `soup`: in the region
};

/// The region `rebuilt` flags (one flag per tet of `body`) with the tets
/// that share a node with it, and a layer more at a time (up to three) until
/// they form a ball; nothing when they do not, or hold over half the body.
std::optional<RegionWindow> region_window(const mesh::TetMesh& body, std::span<const char> rebuilt);

/// The body remeshed: `inner`, remesh_region's result on the window with
/// its surface kept, put into the body with remesh_region's order (the
/// kept tets of the body first, in its order, on its nodes bit for bit,
/// then the new ones; the body's boundary face for face).
RegionRemesh merge_window(const mesh::TetMesh& body, std::span<const char> rebuilt, const RegionWindow& window,
                          const RegionRemesh& inner);

} // namespace anvil::remesh
