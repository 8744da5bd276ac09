// The Krylov solver (FGMRES with the block preconditioner, both Schur
// approximations) gives the direct solver's answer where weak
// preconditioners fail: a near rigid-plastic law with a rigid zone, and
// scenes with contact penalty rows, friction, several bodies and elastic dies.
#include "run_outputs.h"

#include "anvil/mesh/generators.h"
#include "anvil/scene/BoundaryCondition.h"
#include "anvil/solver/IncrementSolver.h"

#include <cmath>
#include <utility>

using namespace anvil;

namespace {

/// A flat punch over half the top of a block on a sticking base: beside the
/// punch the block stays rigid, with a viscosity about 3e3 times that under
/// it (ε̄̇₀ = 1e-4 1/s against ε̄̇ ~ 0.1 1/s, ratio^(1−m)).
struct Punch {
  mesh::TetMesh mesh;
  scene::ImposedConditions imposed;
  std::vector<int> punch_nodes;
};

Punch punch_block() {
  Punch p{mesh::make_box(mesh::Point::Zero(), mesh::Point(20, 20, 10), {10, 10, 5}), {}, {}};
  scene::BoundaryCondition base, punch;
  base.kind = scene::BoundaryKind::sticking_plate;
  base.faces.tag = 5;
  base.velocity = {0.0, 0.0, 0.0};
  punch.kind = scene::BoundaryKind::velocity;
  punch.faces.plane_point = mesh::Point(0, 0, 10);
  punch.velocity = {0.0, 0.0, -1.0};
  p.imposed = scene::impose(p.mesh, {base});
  for (int node : scene::face_nodes(p.mesh, scene::select_faces(p.mesh, punch.faces)))
    if (p.mesh.nodes[node].x() <= 10.0 + 1e-9) {
      p.punch_nodes.push_back(node);
      for (int c = 0; c < 3; ++c)
        p.imposed.prescribed[4 * node + c] = 1, p.imposed.values[4 * node + c] = c == 2 ? -1.0 : 0.0;
    }
  return p;
}

/// Newton with at most `iterations` iterations, its log off.
solver::NewtonSettings quiet_newton(int iterations) {
  solver::NewtonSettings newton;
  newton.max_iterations = iterations;
  newton.verbose = false;
  return newton;
}

/// The tangent of `law` at `u` on the punch block (the prescribed dofs
/// decoupled) and its lumped pressure mass, assembled by `assembler`.
std::pair<fem::SparseMatrix, Eigen::VectorXd> punch_tangent(const Punch& p, fem::Assembler& assembler,
                                                            const material::Material& law, const fem::BodyUnknowns& u) {
  assembler.assemble(p.mesh, fem::ElementLaws(p.mesh.tet_count(), &law),
                     std::vector<material::PointState>(p.mesh.tet_count()), u, p.imposed.nodal_forces, {}, true);
  assembler.finish_tangent();
  return {assembler.tangent(), assembler.pressure_mass()};
}

/// Any right-hand side of `rows` rows, zero on the punch block's prescribed dofs.
Eigen::VectorXd any_right_hand_side(const Punch& p, Eigen::Index rows) {
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows);
  for (Eigen::Index d = 0; d < rows; ++d)
    if (!p.imposed.prescribed[d]) rhs[d] = std::sin(0.37 * static_cast<double>(d));
  return rhs;
}

} // namespace

TEST_CASE("Norton-Hoff m = 0.1 with a rigid zone: FGMRES gives MUMPS's punch load", "[verification]") {
  // Newton from rest to tolerance 1e-10: the loads of two solvers agree to
  // ~1e-9; asserted at 1e-7.
  const material::NortonHoff law(100.0, 0.1, 1e-4);
  const Punch p = punch_block();
  const auto& [mesh, imposed, punch_nodes] = p;
  using K = solver::LinearSolverKind;
  const std::vector<std::pair<std::string, solver::LinearSolverSettings>> solvers = {
      {"mumps", {K::mumps}},
      {"fgmres bfbt", {K::fgmres, solver::SchurApproximation::bfbt}},
      {"fgmres mass", {K::fgmres, solver::SchurApproximation::mass}}};
  double reference = 0.0;
  for (const auto& [name, settings] : solvers) {
    Timers timers;
    solver::IncrementSolver solver(mesh, imposed.prescribed, settings, timers);
    fem::BodyUnknowns u{imposed.values, Eigen::VectorXd::Zero(3 * mesh.tet_count())};
    solver::NewtonSettings newton = quiet_newton(60); // from rest, the damped phase alone takes about 25 iterations
    newton.tolerance = newton.increment_tolerance = 1e-10;
    const solver::NewtonReport report = solver.solve(mesh, law, {}, imposed.nodal_forces, {}, newton, u);
    INFO(name << ": " << report.failure);
    REQUIRE(report.converged);
    double load = 0.0;
    for (int node : punch_nodes)
      load += solver.residual()[4 * node + 2];
    if (name == "mumps") reference = load;
    INFO(name << ": punch load " << load << " N, mumps " << reference << " N, Krylov iterations "
              << report.linear_iterations);
    CHECK(std::abs(load - reference) <= 1e-7 * std::abs(reference));
  }
}

TEST_CASE("The predictor's preconditioner is set up again for the law's tangent", "[verification]") {
  // From rest, a nonlinear law is first solved as the Newtonian law of its
  // secant viscosity (uniform): that set-up does not see the rigid zone, and
  // kept, the first Newton solve took three times the Krylov iterations
  // (42 against 14 at 13k nodes). Predictor and one Newton iteration: two set-ups.
  const material::NortonHoff law(100.0, 0.1, 1e-4);
  const Punch p = punch_block();
  Timers timers;
  solver::IncrementSolver solver(p.mesh, p.imposed.prescribed, {solver::LinearSolverKind::fgmres}, timers);
  fem::BodyUnknowns u{p.imposed.values, Eigen::VectorXd::Zero(3 * p.mesh.tet_count())};
  solver.solve(p.mesh, law, {}, p.imposed.nodal_forces, {}, quiet_newton(1), u);
  CHECK(solver.linear_solver().setups() == 2);
}

TEST_CASE("contact, friction, several bodies, elastic dies: FGMRES gives MUMPS's loads", "[verification]") {
  // Three bodies in mutual quasi-symmetric contact with Tresca friction and
  // rigid dies; a billet between elastic H13 dies (ν = 0.3 in velocity form).
  // Both solvers converge each increment to Newton tolerance 1e-10, so the
  // loads agree to ~1e-9 of the load over a few increments; asserted at 1e-6
  // (the active sets must also come out the same).
  const auto [file, surface, stop] = GENERATE(table<std::string, std::string, std::string>(
      {{"cases/three_blocks.yaml", "top", "time.stop.stroke=0.6"},
       {"cases/forging_elastic_dies.yaml", "press", "time.stop.time=0.045"}}));
  std::vector<std::vector<LoadRow>> loads;
  for (const std::string solver_kind : {"mumps", "fgmres"}) {
    const scene::Case c =
        scene::read_case(source_path(file), {stop, "solver.linear_solver=" + solver_kind, "solver.tolerance=1e-10",
                                             "solver.increment_tolerance=1e-10", "output.vtk=false"});
    loads.push_back(run_case(c, "anvil_solvers_" + solver_kind).loads(surface));
  }
  REQUIRE(loads[0].size() == loads[1].size());
  REQUIRE(loads[0].size() >= 3);
  for (std::size_t i = 0; i < loads[0].size(); ++i) {
    INFO(file << " increment " << i + 1 << ": mumps " << loads[0][i].force.z() << " N, fgmres " << loads[1][i].force.z()
              << " N");
    CHECK(std::abs(loads[1][i].force.z() - loads[0][i].force.z()) <= 1e-6 * std::abs(loads[0][i].force.z()));
  }
}

TEST_CASE("A kept preconditioner gone stale is stopped at its budget and set up again", "[verification]") {
  // The budget's mechanism (its gain is measured on whole runs:
  // docs/linear-solve.md). The punch block's tangent under a uniform
  // viscosity, then under Norton-Hoff m = 0.1 at its solution (the rigid
  // zone beside the punch): the second solve takes 49 iterations on the
  // first set-up and on one of its own. With a set-up's cost set at 4
  // iterations, the budget (what the first solve took, 36, plus two
  // set-ups' cost) falls short of it: the solve is stopped there and done
  // again on a new set-up, to the tolerance. With a cost of 16000 it runs
  // to the end on the kept set-up.
  const material::NortonHoff uniform(100.0, 1.0, 1e-4), rigid_plastic(100.0, 0.1, 1e-4);
  const Punch p = punch_block();
  const fem::Partition partition = fem::partition_mesh(p.mesh, 1, 0);
  fem::BodyUnknowns u{p.imposed.values, Eigen::VectorXd::Zero(3 * p.mesh.tet_count())};
  {
    Timers timers;
    solver::IncrementSolver flow(p.mesh, p.imposed.prescribed, {solver::LinearSolverKind::mumps}, timers);
    REQUIRE(flow.solve(p.mesh, rigid_plastic, {}, p.imposed.nodal_forces, {}, quiet_newton(60), u).converged);
  }
  fem::Assembler assembler(p.mesh, fem::DofMap(p.imposed.prescribed), partition);
  const auto [first, first_mass] = punch_tangent(p, assembler, uniform, u);
  const auto [second, second_mass] = punch_tangent(p, assembler, rigid_plastic, u);
  const Eigen::VectorXd rhs = any_right_hand_side(p, first.rows());
  Eigen::VectorXd x;
  constexpr double kTolerance = 1e-6;
  struct Solves {
    int first, second, setups;
  };
  // `setups` set-ups on `first` then (kept or not) on `second`, or on `second` alone.
  auto solves = [&](double setup_cost, bool from_first) {
    Timers timers;
    solver::LinearSolverSettings settings{solver::LinearSolverKind::fgmres};
    settings.setup_cost = setup_cost;
    solver::LinearSolver solver(settings, static_cast<int>(rhs.size()), partition, timers);
    Solves out{0, 0, 0};
    if (from_first) {
      REQUIRE(solver.factorize(first, {p.mesh.nodes, first_mass, {}}));
      REQUIRE(solver.solve(rhs, x, kTolerance));
      out.first = solver.iterations();
    }
    REQUIRE(solver.factorize(second, {p.mesh.nodes, second_mass, {}}));
    REQUIRE(solver.solve(rhs, x, kTolerance));
    REQUIRE(solver.kind() == solver::LinearSolverKind::fgmres);
    CHECK((rhs - second * x).norm() <= 10.0 * kTolerance * rhs.norm()); // to the tolerance, up to round-off
    out.second = solver.iterations();
    out.setups = solver.setups();
    return out;
  };
  const Solves fresh = solves(4.0, false), wide = solves(16000.0, true), tight = solves(4.0, true);
  INFO("first solve " << wide.first << " iterations; on the stale set-up to the end " << wide.second
                      << "; stopped and set up again " << tight.second << ", of which the new set-up's "
                      << fresh.second);
  CHECK(wide.setups == 1);
  CHECK(tight.setups == 2);
  const int before_stop = tight.second - fresh.second; // the new set-up's solve is the fresh one
  CHECK(before_stop <= tight.first + 2 * 4 + 1);
  CHECK(before_stop < wide.second);
}

TEST_CASE("A long Newton step has the kept preconditioner set up again", "[verification]") {
  // LinearSolver::newton_step: after a step that changed the velocity by
  // 1 % the set-up is kept; after one of 5 % (above kLongNewtonStep, 3 %)
  // the next factorize() sets it up anew. The set-up's cost is set high so
  // that the iteration count cannot renew it.
  const material::NortonHoff law(100.0, 0.1, 1e-4);
  const Punch p = punch_block();
  const fem::Partition partition = fem::partition_mesh(p.mesh, 1, 0);
  fem::BodyUnknowns u{p.imposed.values, Eigen::VectorXd::Zero(3 * p.mesh.tet_count())};
  fem::Assembler assembler(p.mesh, fem::DofMap(p.imposed.prescribed), partition);
  const auto [tangent, mass] = punch_tangent(p, assembler, law, u);
  const Eigen::VectorXd rhs = any_right_hand_side(p, tangent.rows());
  Eigen::VectorXd x;
  Timers timers;
  solver::LinearSolverSettings settings{solver::LinearSolverKind::fgmres};
  settings.setup_cost = 16000.0;
  solver::LinearSolver solver(settings, static_cast<int>(rhs.size()), partition, timers);
  const solver::SaddlePointData data{p.mesh.nodes, mass, {}};
  REQUIRE(solver.factorize(tangent, data));
  REQUIRE(solver.solve(rhs, x, 1e-6));
  solver.newton_step(0.01);
  REQUIRE(solver.factorize(tangent, data));
  CHECK(solver.kept_preconditioner());
  CHECK(solver.setups() == 1);
  REQUIRE(solver.solve(rhs, x, 1e-6));
  solver.newton_step(0.05);
  REQUIRE(solver.factorize(tangent, data));
  CHECK_FALSE(solver.kept_preconditioner());
  CHECK(solver.setups() == 2);
}

TEST_CASE("Facet contact between bodies: the velocity AMG's defaults keep facet near nodal contact's Krylov "
          "iterations, same answer",
          "[verification]") {
  // The unit-cube patch test, 2 cells under 16, quasi-symmetric facet
  // contact: the fine cube's facet rows couple each node weakly with many
  // nodes of the coarse one. With facet contact ML aggregates on the nodes'
  // geometry and smooths with SOR. Measured (tools/patch_test --krylov):
  // 47 Krylov iterations on those defaults, 61 with ML's matrix aggregation
  // (-fieldsplit_0_pc_ml_Aux false), 78 with point-block Jacobi smoothing
  // (-fieldsplit_0_mg_levels_pc_type pbjacobi), 56 for nodal contact on its
  // defaults. The test asks for a tenth fewer than either alternative and
  // at most issue 45's 1.3 times nodal contact's. All solves reach the
  // Newton tolerance of this linear problem, so the support force agrees to
  // 1e-6 of it.
  auto run = [](std::vector<std::string> overrides, const std::string& name) { // the caller's come last, and win
    overrides.insert(overrides.begin(), {"solver.linear_solver=fgmres", "bodies[0].mesh.element_size=0.5",
                                         "bodies[1].mesh.element_size=0.0625", "contact_pairs[0].integration=facet",
                                         "output.picture=false"});
    return run_case(scene::read_case(source_path("cases/patch_test_cubes.yaml"), overrides), name);
  };
  const double nodal_before =
      run({"contact_pairs[0].integration=nodal"}, "anvil_solvers_nodal").summary_number("krylov_iterations");
  const RunOutputs defaults = run({}, "anvil_solvers_facet");
  const RunOutputs matrix = run({"solver.petsc_options=-fieldsplit_0_pc_ml_Aux false"}, "anvil_solvers_matrix");
  const RunOutputs jacobi =
      run({"solver.petsc_options=-fieldsplit_0_mg_levels_pc_type pbjacobi"}, "anvil_solvers_pbjacobi");
  const double its = defaults.summary_number("krylov_iterations");
  const double matrix_its = matrix.summary_number("krylov_iterations");
  const double jacobi_its = jacobi.summary_number("krylov_iterations");
  INFO("Krylov iterations: facet on the defaults " << its << ", matrix aggregation " << matrix_its
                                                   << ", point-block Jacobi " << jacobi_its << ", nodal "
                                                   << nodal_before);
  CHECK(its <= 0.9 * matrix_its);
  CHECK(its <= 0.9 * jacobi_its);
  CHECK(its <= 1.3 * nodal_before);
  const double f = defaults.loads("support").back().force.z();
  for (const RunOutputs* other : {&matrix, &jacobi})
    CHECK(std::abs(other->loads("support").back().force.z() - f) <= 1e-6 * std::abs(f));
  // The options were the facet run's alone: nodal contact in the same
  // process aggregates on the matrix and smooths with point-block Jacobi as
  // before it (56 iterations).
  CHECK(run({"contact_pairs[0].integration=nodal"}, "anvil_solvers_nodal").summary_number("krylov_iterations") ==
        nodal_before);
}
