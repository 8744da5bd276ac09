// Remeshing one body with CGAL's isotropic tetrahedral remeshing (docs/libraries.md
// §2). The body's boundary is split into patches so that CGAL keeps flat
// faces flat and sharp edges sharp: without them it rounds edges and the body
// loses volume (4 % on a unit cube, docs/libraries.md §2).
#pragma once
#include "anvil/mesh/TetMesh.h"
#include "anvil/mesh/grid_snap.h"

#include <chrono>
#include <functional>
#include <span>
#include <stop_token>

namespace anvil::remesh {

struct RemeshSettings {
  double edge_length = 1.0;    ///< mm, target edge length (uniform)
  double feature_angle = 40.0; ///< degrees: adjacent boundary faces whose normals differ more are on different patches
  int iterations = 3;          ///< CGAL remeshing passes (split, collapse, flip, smooth)
  /// Size field (mm): the edge length wanted at a point, between
  /// smallest_edge_length and edge_length; empty: uniform. CGAL 5.5 takes
  /// one target length per call (docs/libraries.md §2), so the field is met in
  /// levels: after the pass at edge_length, passes at lengths shrinking by
  /// ¾ each remesh the cells whose centroid wants less than the level before.
  /// A jump of ¾ between neighbours keeps the cells between levels fair; one
  /// of ½ left slivers (q 0.08) there.
  std::function<double(const mesh::Point&)> size;
  double smallest_edge_length = 0.0;
  /// A CGAL pass still at work after this is stopped (RemeshStopped), and
  /// the finer levels of `size` are not started after it.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  /// A stop asked here stops the pass at work (RemeshStopped): a try that is
  /// no longer needed.
  std::stop_token stop;
  /// A CGAL pass that has looked at its cells more than this many times per
  /// cell and pass fails (a RunError): one that ends looks 17-80 times (the
  /// 238 CGAL calls of closed_die_flash, its adaptive run,
  /// hot_closed_die_flash and 45 increments of conrod). A local region of
  /// hot_closed_die_flash on two processes kept CGAL's smoothing busy in its
  /// search for the surface normals until remeshing.time_limit (120 s). A
  /// count, not a time, so that the same input gives the same mesh on a busy
  /// machine too.
  std::size_t most_looks_per_cell_pass = 1000;
  double quality_floor =
      0.0; ///< putting a node back onto the old surface may not leave an element below this (or below what it was)
  /// CGAL is given the nodes rounded to this grid (mesh/grid_snap.h), so
  /// that the same body carried by other round-off gives the same mesh; the
  /// nodes it leaves where they were get their own coordinates back. A
  /// spacing of 0: as they are.
  mesh::Grid grid;
};

/// The deadline `seconds` from now (a RemeshSettings::deadline).
inline std::chrono::steady_clock::time_point deadline_in(double seconds) {
  return std::chrono::steady_clock::now() +
         std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

/// Thrown from inside a CGAL pass by remesh_body and remesh_region when
/// RemeshSettings::stop was asked or its deadline passed. Not a RunError:
/// neither is a failure of the mesh that another length could mend.
struct RemeshStopped {
  bool out_of_time; ///< the deadline passed (else the stop was asked)
};

/// A new mesh of the volume of `body` (one connected body, a topological ball:
/// CGAL 5.5 builds its triangulation from a tet soup only for those).
/// Boundary patches: faces of one tag, joined across edges where the normals
/// turn by less than `feature_angle`; patch borders are protected features.
/// Each new boundary face carries the tag of the patch it lies on.
/// Throws RunError when CGAL cannot take the mesh or its result has a fault
/// (an inverted element: the caller keeps the old mesh).
mesh::TetMesh remesh_body(const mesh::TetMesh& body, const RemeshSettings& settings);

/// A body remeshed in a region, the rest kept as it was.
struct RegionRemesh {
  /// The kept tets first, in the body's order and with its node coordinates
  /// bit for bit, then the region's new tets; the nodes that stay (those of
  /// kept tets, and of the boundary when it is kept) first, in the body's
  /// order, then the others.
  mesh::TetMesh mesh;
  std::vector<int> old_node; ///< per node of `mesh`: its index in the body where it is that node unmoved, else −1
  int kept_tets = 0;         ///< tets [0, kept_tets) are the body's tets not rebuilt, in order
};

/// What a local remesh does with the body's surface in its region.
enum class RegionSurface {
  kept,    ///< frozen: the surface keeps its nodes and faces (the contact surface stays where it is)
  rebuilt, ///< remeshed with the region, new nodes put back onto the old surface, its volume kept
};

/// Remeshes the tets of `body` that `rebuilt` flags (one flag per tet) at
/// settings.edge_length. The region's border with the kept tets keeps its
/// nodes and faces, so the kept tets fit the new ones; so does the body's
/// surface in the region unless `surface` is RegionSurface::rebuilt. Throws
/// RunError when CGAL cannot take the mesh, changes the border (then the
/// border faces it changed, as sorted node triples, into `changed_border`
/// when given) or its result has a fault.
RegionRemesh remesh_region(const mesh::TetMesh& body, std::span<const char> rebuilt, const RemeshSettings& settings,
                           RegionSurface surface = RegionSurface::kept, std::span<const char> pinned = {},
                           std::vector<std::array<int, 3>>* changed_border = nullptr);

/// The part of remesh_region's result the region leaves: the nodes that
/// stay (those of the tets `rebuilt` does not flag, and of the boundary when
/// `surface` is kept), in the body's order, and those tets, in the body's
/// order. `number` gets each body node's index in it, −1 where it goes.
RegionRemesh kept_part(const mesh::TetMesh& body, std::span<const char> rebuilt, RegionSurface surface,
                       std::vector<int>& number);

/// Patch number (from 1) of each boundary face of `body`, as remesh_body sets
/// them: faces of one boundary tag whose normals turn by less than
/// `feature_angle` (deg) between neighbours, a patch of less than
/// `smallest_area` (mm²) joined to its neighbour of the longest shared border.
std::vector<int> boundary_patches(const mesh::TetMesh& body, double feature_angle, double smallest_area);

} // namespace anvil::remesh
