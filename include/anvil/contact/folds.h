// Folds and laps (docs/reading-a-run.md §5): a body's surface meeting
// itself, where a forging defect forms (material folded over onto its own
// surface leaves a lap, a crack-like seam in the part).
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <span>
#include <vector>

namespace anvil::contact {

/// One fold: the faces of a body that meet each other, joined through
/// their nodes and through the faces they meet.
struct Fold {
  int body = 0;
  mesh::Point centre = mesh::Point::Zero(); ///< area-weighted (mm)
  double area = 0.0;                        ///< mm², of its faces, both sides
  int faces = 0;
};

struct FoldScan {
  std::vector<char> faces; ///< per boundary face: 1 on a fold
  std::vector<Fold> folds; ///< largest first
};

/// The folds of the bodies of `mesh`: a boundary face folds where it meets
/// another face of its own body, one that shares no node with it and faces
/// it (outward normals opposing, n·n' < −½), its centre within a tenth of
/// `edge` (mm, the mesh's edge length: surfaces that touch) of that face, or
/// behind it (inside the body) by at most half of `edge` (a fold gone
/// through itself). Faces flagged in `skip` (on a symmetry plane) are
/// neither looked from nor at. A flash or a web thinner than a tenth of an
/// edge would count too: no mesh resolves one.
FoldScan find_folds(const mesh::TetMesh& mesh, std::span<const mesh::MeshRange> bodies, const std::vector<char>& skip,
                    double edge);

} // namespace anvil::contact
