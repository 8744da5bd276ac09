// Die fill (docs/reading-a-run.md §3): how much of a die's cavity the part
// touches, and how far each point of the die still is from the part. The
// forging engineer's question "did the cavity fill" asked of the geometry.
#pragma once
#include "anvil/die/DieSurface.h"
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Geometry>

#include <limits>
#include <memory>
#include <vector>

namespace anvil::contact {

class SurfaceSearch;

/// The boundary of the bodies, for distance queries from a die.
class PartSurface {
public:
  /// The boundary faces of `mesh` (outward normals), at its nodes as they are.
  explicit PartSurface(const mesh::TetMesh& mesh);
  ~PartSurface();
  PartSurface(PartSurface&&) noexcept;
  PartSurface& operator=(PartSurface&&) noexcept;

  /// Distance (mm) from `x` to the part: 0 inside it, else to its nearest
  /// boundary point. Inside is told by the nearest face's outward normal.
  double distance(const mesh::Point& x) const;
  /// distance(x) ≤ `tolerance`, answered by a box query alone where no face
  /// is within `reach` (≥ tolerance) of x (most of a die): x is then far
  /// outside or, deeper than `reach` inside, counted as outside.
  bool within(const mesh::Point& x, double tolerance, double reach) const;

private:
  struct Nearest {
    double distance; ///< to the nearest of the faces (mm)
    bool inside;     ///< behind it
  };
  Nearest nearest(const mesh::Point& x, const std::vector<int>& faces) const;

  const mesh::TetMesh* mesh_;
  std::unique_ptr<SurfaceSearch> search_;
  mutable std::vector<int> around_; ///< scratch: the faces at an edge or a corner
};

/// Where on a die its fill is asked for, in the die's start position: a box,
/// a cylinder about the press axis (z), or both; neither: the whole die.
struct FillRegion {
  Eigen::AlignedBox3d box;                                 ///< mm; empty: no bound
  double radius = std::numeric_limits<double>::infinity(); ///< mm, from `axis`
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();          ///< mm, (x, y) of the cylinder's axis
  bool contains(const mesh::Point& x) const {
    return (box.isEmpty() || box.contains(x)) && (x.head<2>() - axis).norm() <= radius;
  }
};

/// A die's fill at one geometry.
struct DieFill {
  double region_area = 0.0;  ///< mm², of the die surface inside the fill region
  double contact_area = 0.0; ///< mm², of that area within the tolerance of the part
  /// Filled share of the region: contact_area / region_area (0 for an empty region).
  double fraction() const { return region_area > 0.0 ? contact_area / region_area : 0.0; }
  /// Per die vertex (die::SurfaceTriangles order): distance to the part, mm,
  /// a vertex past a symmetry plane measured as its mirror image (when asked
  /// for; the underfill field of the VTK series).
  std::vector<double> underfill;
};

/// Where a die's fill is measured: its surface (die frame, at rest) cut into
/// pieces with no edge longer than a spacing (die::refine), the centroids of
/// those in the fill region, each standing for its piece's area.
struct FillSamples {
  std::vector<mesh::Point> points; ///< mm
  std::vector<double> areas;       ///< mm²
};

/// The samples of `die` in `region` at `spacing` (mm), made once per die.
FillSamples fill_samples(const die::SurfaceTriangles& die, const FillRegion& region, double spacing);

/// The fill of a die moved by `displacement`, over a model of the part cut
/// by symmetry planes to `model_side`: each of the die's `samples` on the
/// model's side counts towards region_area (a die drawn past a symmetry
/// plane is the mirror image's there), and towards contact_area when it is
/// within `tolerance` (mm) of the part or inside it by less than `reach`
/// (a die sunk deeper into the part is a run that has already gone wrong:
/// remeshing.die_penetration remeshes at a quarter of an element). The
/// underfill, when asked for, at the vertices of `die` (its surface, die
/// frame). The samples and vertices are shared out among the processes
/// (processes::share_out).
DieFill measure_die_fill(const FillSamples& samples, const die::SurfaceTriangles& die,
                         const Eigen::Vector3d& displacement, const Eigen::AlignedBox3d& model_side,
                         const PartSurface& part, double tolerance, double reach, bool with_underfill);

} // namespace anvil::contact
