// The part of a body's mesh that lies inside a rigid die. Contact is nodal:
// it keeps the body's nodes out of a die, not a die's fillet or corner out
// of the faces between them, so the mesh can overlap a die by up to 1 % of
// its volume in a closing flash (closed-die case). That part is not
// material: a remesh's put-back takes it off at once, and the volume
// compensation, which restores the volume the material has lost, must not
// count it.
#pragma once
#include "anvil/die/DieSurface.h"
#include "anvil/mesh/TetMesh.h"

#include <Eigen/Core>

namespace anvil::die {

/// Volume (mm³) of the part of `body` in `mesh` inside `surface` displaced
/// by `shift`: over each boundary face the die reaches, the depth of the die
/// below the face, along the face's normal, integrated by the midpoint rule
/// on 16 sub-triangles (the depth is piecewise linear, with kinks where a
/// die edge crosses). Points deeper than `deepest` (mm) are the far side of
/// an open die surface, not overlap; where the die's surface is more than 60°
/// from facing the face, the face cuts across the overlap rather than
/// bounding it (a symmetry plane), and adds nothing. The faces are shared out
/// among the processes (processes::share_out).
double overlap_volume(const mesh::TetMesh& mesh, const mesh::MeshRange& body, const DieSurface& surface,
                      const Eigen::Vector3d& shift, double deepest);

/// overlap_volume of the whole mesh `after` less that of `before` (mm³),
/// from the boundary faces one has and the other not (the same corners'
/// coordinates make the same face): a remesh that changes a few faces of a
/// body's surface changes only their share, and the faces it keeps need no
/// search. On rank 0 alone (a remesh's).
double overlap_change(const mesh::TetMesh& before, const mesh::TetMesh& after, const DieSurface& surface,
                      const Eigen::Vector3d& shift, double deepest);

} // namespace anvil::die
