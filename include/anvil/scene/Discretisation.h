// Everything built on the current mesh of a run: the law of each element,
// what the boundary conditions impose on its dofs, the material state of each
// element, the contact terms and the linear solver. Rebuilt (discretise) at
// the start, on resume and after a remesh; between those the mesh's nodes
// move but its elements do not change.
#pragma once
#include "anvil/contact/BodyContact.h"
#include "anvil/contact/RigidContact.h"
#include "anvil/core/Timers.h"
#include "anvil/fem/Assembler.h"
#include "anvil/mesh/QualityGuard.h"
#include "anvil/scene/Heat.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"
#include "anvil/solver/IncrementSolver.h"

#include <memory>
#include <vector>

namespace anvil::scene {

struct Discretisation {
  /// Per element, its body's law as the case gives it (an elastic body in
  /// velocity form is solved with the law of each increment's Δt instead).
  fem::ElementLaws element_laws;
  ImposedConditions imposed;                      ///< on the dofs of the whole mesh
  std::vector<material::PointState> point_states; ///< per element: T, ε̄ and carried σ of the run state
  /// Die contact and body-pair contact: the Newton terms of the increment
  /// being solved, and after it, which nodes touch what.
  contact::RigidContact die_contact;
  std::unique_ptr<contact::BodyContact> pair_contact; ///< only when the case has contact pairs
  mesh::QualityGuard projection_guard;                ///< elements around each node, for the contact projection
  std::unique_ptr<solver::IncrementSolver> solver;    ///< keeps its preconditioner between increments
  std::vector<char> symmetry_faces;                   ///< per boundary face: on a symmetry plane of its body
  std::unique_ptr<Heat> heat;                         ///< only in a thermal scene

  /// What moves heat besides conduction in the increment just solved, with solution `nodal`.
  HeatContacts heat_contacts(const Scene& scene, const Eigen::VectorXd& nodal) const {
    return {scene.dies.empty() ? nullptr : &die_contact, pair_contact.get(), symmetry_faces, &nodal};
  }

  /// The Newton terms of the contacts `scene` has.
  std::vector<solver::NodalTerm*> contact_terms(const Scene& scene);
  /// Per node of the mesh: the die it presses on at `nodal`, the solution
  /// the die contact was last solved for, or −1.
  std::vector<int> touching_die(const Eigen::VectorXd& nodal) const;
};

/// Builds the discretisation of `state`'s mesh and sets the prescribed
/// values into state.unknowns (the boundary conditions of a remeshed body
/// are chosen again on its new mesh, by tag or by plane).
Discretisation discretise(const Scene& scene, RunState& state, Timers& timers);

} // namespace anvil::scene
