// The 75 % upsetting, the closed-die forging with flash and the connecting
// rod run to their stroke with remeshing, and each remesh keeps the volume,
// ε̄ and the load curve.
#include "test_common.h"

#include "anvil/core/log.h"
#include "anvil/mesh/tet_geometry.h"
#include "anvil/remesh/remesh_due.h"
#include "run_outputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace anvil;

namespace {

struct RemeshedRun {
  scene::Case c;
  RunOutputs out;
  scene::RunState end;
};

RemeshedRun run_remeshed(const std::string& case_file, const std::string& name,
                         const std::vector<std::string>& overrides = {}) {
  log::set_quiet(true);
  scene::Case c = scene::read_case(source_path(case_file), overrides);
  RunOutputs out = run_case(c, name);
  scene::RunState end = out.final_state();
  return RemeshedRun{std::move(c), std::move(out), std::move(end)};
}

/// To the final stroke without an inverted element; every remesh keeps the
/// volume (below 0.1 % per remesh) and ∫ε̄ dV (within 2 %); a remesh for
/// quality improves it (remesh::quality_due_below: another trigger may come
/// first while an element the last remesh left below the floor waits).
void check_remeshes_keep_volume_and_strain(const RemeshedRun& run) {
  CHECK(run.end.dies[0].stroke == Approx(run.c.time.final_stroke).epsilon(1e-9));
  for (int e = 0; e < run.end.mesh.tet_count(); ++e)
    REQUIRE(mesh::quality(run.end.mesh, e) > 0.0);
  REQUIRE(run.end.remeshes.size() >= 1);
  double left = 1.0; // the worst quality the last remesh left
  for (const scene::RemeshRecord& r : run.end.remeshes) {
    INFO("remesh after increment " << r.increment << ": worst quality " << r.worst_quality_before << " -> "
                                   << r.worst_quality_after);
    CHECK(std::abs(r.volume_change) < 1e-3);
    REQUIRE(std::isfinite(r.material_change)); // the mesh less its overlap with the dies, put-back included
    CHECK(std::abs(r.material_change) < 1e-3);
    CHECK(std::abs(r.strain_integral_change) < 0.02);
    if (r.worst_quality_before < remesh::quality_due_below(left, run.c.remeshing.quality))
      CHECK(r.worst_quality_after > r.worst_quality_before);
    left = r.worst_quality_after;
  }
}

/// The volume changes by less than `bound` over the run: the
/// material's (the mesh less its overlap with the dies), which the volume
/// compensation holds, and the mesh's, which carries that overlap besides.
void check_run_volume(const RemeshedRun& run, double bound = 0.01) {
  const double material = std::abs(run.out.summary_number("material_relative_change"));
  const double mesh_volume = std::abs(run.out.summary_number("relative_change"));
  INFO("volume change over the run: material " << 100.0 * material << " %, mesh " << 100.0 * mesh_volume << " %");
  CHECK(material < bound);
  CHECK(mesh_volume < bound);
}

/// The material's volume within 1 %, as check_run_volume; the mesh also
/// holds what lies inside the dies, which the overlap trigger
/// (remeshing.die_overlap) takes back by a whole remesh once it passes its
/// share of the initial volume: at the end, at most that share and what
/// the last increment added (no larger than the run's largest change of
/// volume in one increment).
void check_run_volume_with_overlap(const RemeshedRun& run) {
  const double material = run.out.summary_number("material_relative_change");
  const double mesh_volume = run.out.summary_number("relative_change");
  const double overlap_bound =
      run.c.remeshing.die_overlap + run.out.summary_number("largest_relative_change_per_increment");
  INFO("volume change over the run: material " << 100.0 * material << " %, mesh " << 100.0 * mesh_volume
                                               << " %; inside the dies at most " << 100.0 * overlap_bound << " %");
  CHECK(std::abs(material) < 0.01);
  CHECK(mesh_volume - material < overlap_bound);
}

/// Max ε̄ within 2 % across each remesh. The transfer keeps old peaks in the
/// new element that holds them, so the change is 0 unless that rule breaks.
void check_max_strain(const RemeshedRun& run) {
  for (const scene::RemeshRecord& r : run.end.remeshes) {
    INFO("remesh after increment " << r.increment);
    CHECK(std::abs(r.strain_max_change) < 0.02);
  }
}

/// No jump above `bound` in the load-stroke curve at a remesh (3 % is the
/// aim; a case short of it is bounded at its measured worst). The jump
/// at equal geometry (remeshing.check_load): the press load of the increment
/// after the remesh, solved on the old mesh and on the new one at the same
/// die positions and Δt. Newton stops at a residual far below 3 % of the load.
/// A split of sunk edges right after a remesh of the same body is measured
/// with it: the first record of the step carries the step's jump.
void check_load_jump(const RemeshedRun& run, double bound) {
  REQUIRE(run.c.remeshing.check_load);
  for (std::size_t k = 0; k < run.end.remeshes.size(); ++k) {
    const scene::RemeshRecord& r = run.end.remeshes[k];
    if (k > 0 && run.end.remeshes[k - 1].increment == r.increment && run.end.remeshes[k - 1].body == r.body) continue;
    INFO("remesh after increment " << r.increment << ": press load " << r.load_old_mesh << " N on the old mesh, "
                                   << r.load_new_mesh << " N on the new");
    REQUIRE(std::isfinite(r.load_old_mesh));
    REQUIRE(std::isfinite(r.load_new_mesh));
    CHECK(std::abs(r.load_jump()) < bound);
  }
}

/// The load on `surface` just after each remesh within `bound` of the straight
/// line through the two loads before: the jump and the curve's own bend
/// over one increment together. A remesh right after another has no two
/// loads before it on one mesh (the line would run through the other's
/// jump): check_load_jump alone judges it.
void check_load_trend(const RemeshedRun& run, const std::string& surface, double bound) {
  const std::vector<LoadRow> load = run.out.loads(surface);
  for (const scene::RemeshRecord& r : run.end.remeshes) {
    const std::size_t k = static_cast<std::size_t>(r.increment) - 1; // row of the remesh increment
    if (k < 1 || k + 1 >= load.size()) continue;
    const bool after_another =
        std::any_of(run.end.remeshes.begin(), run.end.remeshes.end(),
                    [&](const scene::RemeshRecord& o) { return o.increment == r.increment - 1; });
    if (after_another) continue;
    const LoadRow &a = load[k - 1], &b = load[k], &after = load[k + 1];
    const double predicted =
        b.force.z() + (b.force.z() - a.force.z()) / (b.stroke - a.stroke) * (after.stroke - b.stroke);
    INFO("remesh after increment " << r.increment << ": load " << after.force.z() << " N, trend " << predicted << " N");
    CHECK(std::abs(after.force.z() / predicted - 1.0) < bound);
  }
}

} // namespace

// Each case runs once (one test case: ctest runs every test case in its own
// process). The load jump at equal geometry is bounded at 3.5 %, above the
// 3 % aimed at: round-off (BLAS threads, linear solver) moves the remeshes
// by a few increments, and the worst jump of a run lies between 1.4 and
// 3.4 % over such variants.
TEST_CASE("Upsetting to 75 % remeshes and keeps volume and strain integral", "[hard][remesh]") {
  const RemeshedRun run =
      run_remeshed("cases/upsetting_75.yaml", "anvil_hard_upsetting_75", {"remeshing.check_load=true"}); // 20 s
  check_remeshes_keep_volume_and_strain(run);
  check_run_volume(run);
  check_max_strain(run);
  check_load_jump(run, 0.035);
  check_load_trend(run, "top", 0.03);
}

// The aim for a remesh's load jump at equal geometry is 3 %; this case is
// bounded above its measured worst instead, so that a regression fails.
// The worst jump comes at a whole remesh that puts back onto the dies the
// material their fillets had sunk into (0.3-1 % of the volume), and moves
// with the flow's round-off (each remesh's mesh changes with it; a run is
// reproducible on a given number of processes): 3.3 % in this one-process
// run, 4.9 % on two processes, 7.9 % on one with MUMPS (Newton's answer
// differs within its tolerance), bounded at 8 %; the trend just after a
// remesh, 4.6 %, 5.7 % and 5.6 %, bounded at 7 % (measured 2026-11-29).
// Over remesh paths (stroke increment 0.1, 0.1001 and 0.0999 mm, one
// process) the largest jump was 3.34, 7.38 and 3.39 % (2026-12-03), so a
// change that moves Newton's path can cross the bound by where its whole
// remeshes fall: a velocity test on Newton's estimated error made 8.30,
// 4.24 and 4.57 % and was not kept (docs/performance.md). The jump is the
// difference between two meshes of one body at h 1 mm (two fresh meshes
// differ by 1.5-4.9 % between themselves); finer meshes lower
// it at a cost beyond the suite's (docs/remeshing.md). Full stroke is asserted: a node the
// put-back leaves inside a die is pushed out over the nominal step or longer
// (ContactIncrement::closing_time), so a Δt cut can save its elements.
TEST_CASE("Closed-die forging with flash (STL dies) reaches full stroke, remeshes keep volume and strain integral",
          "[hard][remesh]") {
  const RemeshedRun run = run_remeshed("cases/closed_die_flash.yaml", "anvil_hard_closed_die_flash",
                                       {"remeshing.check_load=true"}); // 1.5 min
  check_remeshes_keep_volume_and_strain(run);
  check_run_volume_with_overlap(run);
  check_max_strain(run);
  check_load_jump(run, 0.08);
  check_load_trend(run, "upper", 0.07);
}

TEST_CASE("Closed-die forging with the adaptive size field reaches closure, remeshes keep volume and strain integral",
          "[hard][remesh]") {
  const RemeshedRun run = run_remeshed("cases/closed_die_flash.yaml", "anvil_hard_closed_die_flash_adaptive",
                                       {"remeshing.size=adaptive", "remeshing.check_load=false"}); // 7 min
  check_remeshes_keep_volume_and_strain(run);
  // 0.3 % is aimed at for the volume over the run and for what lies inside
  // the dies at closure (the mesh's volume is the material's plus that).
  // The material meets it (-0.03 to -0.08 % in the runs below). What lies
  // inside the dies at closure is taken back only by a whole remesh in the
  // last increments (the split of sunk edges the adaptive size field turns
  // on slows its growth; without it 0.38 %), so it moves with the remesh
  // path: over stroke increments of 0.1, 0.1001 and 0.0999 mm on one
  // process, 0.17, 0.25 and 0.24 % at bc1a20a, 0.35, 0.25 and 0.18 % with
  // Newton's own directions (measured 2026-12-02). The aim lies inside that
  // spread: bounded at 0.4 %, above the measured worst, so that a
  // regression fails. The uniform run: mesh +1.10 %, material +0.14 %,
  // about 1 % inside (the overlap trigger's share); its mesh is bounded by
  // that trigger above.
  const double material = run.out.summary_number("material_relative_change");
  const double inside = run.out.summary_number("inside_dies_end") / run.out.summary_number("start");
  INFO("material volume change over the run " << 100.0 * material << " %, inside the dies at closure " << 100.0 * inside
                                              << " % of the volume");
  CHECK(std::abs(material) < 0.003);
  CHECK(inside < 0.004);
  check_max_strain(run);
}

// The connecting rod (cases/conrod.yaml): dies with edges along its ribs and
// bosses, not a body of revolution. To 3.6 mm: sunk die edges split from the
// fifth increment, local and whole remeshes, creases pressed by the die
// edges (a whole remesh takes off the flat tets CGAL leaves on them,
// mesh/boundary_slivers.h). Solved by MUMPS: FGMRES with the three
// translations as ML's near-null space needed about 70 Krylov iterations a
// Newton iteration on this part, twice the time on one process (its
// default, the six rigid-body modes, takes fewer); the run to closure, over
// half an hour on one process (cases/conrod.yaml), is beyond the tier. The
// load jump at equal geometry is bounded above its measured worst, as for
// the closed-die forging above. It follows the remesh path: in this run
// 0.89 % at worst (a split), -0.41 % at its one whole remesh, which a split
// follows; on other paths to this stroke whole remeshes gave 3.4 % (two
// processes), 4.4 % (FGMRES) and 5.7 %, and later in the run to closure
// about 10 % (docs/remeshing.md).
// Bounded at 6 %, above every path measured to this stroke.
TEST_CASE("The connecting rod to 3.6 mm: every remesh improves its worst element and keeps volume and strain integral",
          "[hard][remesh]") {
  const RemeshedRun run =
      run_remeshed("cases/conrod.yaml", "anvil_hard_conrod",
                   {"time.stop.stroke=3.6", "solver.linear_solver=mumps", "remeshing.check_load=true"}); // 3.5 min
  check_remeshes_keep_volume_and_strain(run);
  check_run_volume(run);
  check_max_strain(run);
  check_load_jump(run, 0.06);
}

// The hot connecting rod with the adaptive size field splits its sunk edges
// from the sixth increment on. A split's halves carry the temperature field
// exactly, and the heat of the volume its midpoints take into a die leaves
// with that volume: given to the midpoints instead, it heated them to
// 1224-1276 °C within 1 mm. The billet starts at 1150 °C and its hottest
// node is at 1127 °C after the 3 s transfer; by 1 mm the plastic work
// (β σ̄ ε̄ / ρc, about 9 K at ε̄ = 0.5 and 100 MPa) cannot bring any node
// back to its starting temperature. 20 s on one process.
TEST_CASE("The hot connecting rod's splits and local remeshes do not heat the nodes they add", "[hard][remesh]") {
  const RemeshedRun run = run_remeshed("cases/hot_conrod.yaml", "anvil_hard_hot_conrod_splits",
                                       {"remeshing.size=adaptive", "time.stop.stroke=1"});
  const std::string log = file_text(run.out.directory + "/anvil.log");
  REQUIRE(log.find("elements split") != std::string::npos);
  // The increments' lines: "inc ... T low..high C" (whole degrees).
  int increments = 0;
  for (std::size_t line = log.find("\ninc "); line != std::string::npos; line = log.find("\ninc ", line + 1)) {
    const std::size_t at = log.find("  T ", line);
    REQUIRE(at < log.find('\n', line + 1));
    int low = 0, high = 0;
    REQUIRE(std::sscanf(log.c_str() + at, "  T %d..%d C", &low, &high) == 2);
    INFO("increment " << increments + 1 << ": hottest node " << high << " C");
    CHECK(high < 1150);
    ++increments;
  }
  CHECK(increments == run.end.increment);
}
