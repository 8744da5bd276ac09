// A trim operation of a chain (docs/chains.md): the part cut by a closed
// trim line extruded along the press axis, or by a closed surface; what is
// inside is kept with its fields, the cut remeshed where it left poor
// elements.
#pragma once
#include "anvil/run/Simulation.h"
#include "anvil/run/place_part.h"
#include "anvil/scene/Chain.h"
#include "anvil/scene/RunState.h"

#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

namespace anvil::run {

/// Where the cut is: φ(x) (mm), the signed distance to it, negative on the
/// side kept; and the point of the cut nearest x.
struct Cut {
  std::function<double(const mesh::Point&)> distance;
  std::function<mesh::Point(const mesh::Point&)> nearest;
};

/// The cut of `spec`: a line's distance is taken in the plane normal to z.
Cut make_cut(const scene::TrimSpec& spec, const std::string& where, double size);

/// A part cut by a trim.
struct CutPart {
  scene::RunState part;         ///< what is kept, with its fields
  std::vector<double> removed;  ///< mm³ per body: the volume the cut takes off the part as it was (the exact split)
  std::vector<double> reshaped; ///< mm³ per body: the kept volume's change by the nodes put onto the cut
};

/// `part` cut by `cut`: the elements the cut crosses split along it
/// (mesh::cut_by_level_set), those on the far side removed; a node next to
/// a crossing, where the split would leave a sliver, first put onto the cut
/// (along the part's surface for a surface node) when that spoils no
/// element around it, and again for the pieces still poor. Every field
/// kept: an element's values go to its pieces, a node's are interpolated
/// along its edge. A node on a symmetry plane of `planes` stays on it.
/// Elements next to the cut may be poor (never inverted): the caller
/// remeshes them.
CutPart cut_part(const scene::RunState& part, const Cut& cut, std::span<const SymmetryPlane> planes);

/// Runs trim operation `op` into options.output_directory: the part cut,
/// remeshed where the cut left elements below remeshing.quality, written
/// (VTK, checkpoint.h5, summary.json with the volume and mass removed).
/// `part` is the part it cuts and, on return, the part it leaves.
RunEnd trim(const scene::Operation& op, const RunOptions& options, scene::RunState& part);

} // namespace anvil::run
