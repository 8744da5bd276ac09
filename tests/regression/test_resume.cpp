// Nothing lost: a run killed with SIGKILL part-way and resumed
// with --resume gives the same loads as an uninterrupted run, and its VTK
// series has no gap and no torn file.
#include "run_outputs.h"

#include "anvil/core/log.h"

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace {

/// Starts `anvil run <case> <mode> <dir>` quietly; returns its pid.
pid_t start_anvil(const std::string& case_file, const std::string& mode, const std::string& directory) {
  std::vector<std::string> args{ANVIL_EXECUTABLE, "run", case_file, mode, directory};
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  REQUIRE(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

int scene_increment(const std::string& checkpoint) {
  return anvil::io::read_checkpoint(checkpoint).increment;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// The final states of `case_file` with `settings` run whole, and run
/// stopped after `stop_at(whole run's final state)` increments
/// (time.max_increments) then resumed from its checkpoint (the stop is the
/// one change allowed).
std::pair<anvil::scene::RunState, anvil::scene::RunState>
whole_and_resumed(const std::string& case_file, const std::vector<std::string>& settings,
                  const std::function<int(const anvil::scene::RunState&)>& stop_at, const std::string& name) {
  anvil::log::set_quiet(true);
  const RunOutputs whole = run_case(anvil::scene::read_case(case_file, settings), name + "_whole");
  const int stop = stop_at(whole.final_state());
  std::vector<std::string> stopped = settings;
  stopped.push_back("time.max_increments=" + std::to_string(stop));
  const RunOutputs part = run_case(anvil::scene::read_case(case_file, stopped), name + "_part");
  REQUIRE(part.final_state().increment == stop);
  anvil::run::run(anvil::scene::read_case(case_file, settings), {part.directory, true, true});
  return {whole.final_state(), part.final_state()};
}

int after_4(const anvil::scene::RunState&) {
  return 4;
}

/// The remeshes, loads and ε̄ of the uninterrupted run `a` and the resumed `b`, equal bit for bit.
void require_same_remeshes(const anvil::scene::RunState& a, const anvil::scene::RunState& b) {
  REQUIRE(a.increment == b.increment);
  REQUIRE(a.remeshes.size() == b.remeshes.size());
  for (std::size_t r = 0; r < a.remeshes.size(); ++r) {
    INFO("remesh " << r + 1);
    CHECK(a.remeshes[r].increment == b.remeshes[r].increment);
    CHECK(a.remeshes[r].nodes_after == b.remeshes[r].nodes_after);
  }
  REQUIRE(a.loads.size() == b.loads.size());
  for (std::size_t i = 0; i < a.loads.size(); ++i) {
    INFO("load record " << i);
    CHECK(a.loads[i].force == b.loads[i].force); // the same operations on the same numbers
  }
  CHECK(a.equivalent_strain == b.equivalent_strain);
}

int first_remesh(const anvil::scene::RunState& whole) {
  return whole.remeshes.at(0).increment;
}

} // namespace

TEST_CASE("a run killed with SIGKILL and resumed gives the uninterrupted loads and a whole VTK series",
          "[regression]") {
  // Frictionless upsetting with a checkpoint every 4 increments.
  const std::string case_file = (std::filesystem::temp_directory_path() / "anvil_resume_case.yaml").string();
  {
    std::string text = read_text(source_path("cases/upsetting_frictionless.yaml"));
    text = std::regex_replace(text, std::regex("\\.\\./materials"), source_path("materials"));
    text = std::regex_replace(text, std::regex("\noutput: \\{[^\n]*"), ""); // its own output map replaces the case's
    std::ofstream(case_file) << text << "output: {checkpoint_every: 4}\n";
  }
  const auto whole = std::filesystem::temp_directory_path() / "anvil_resume_whole";
  const auto killed = std::filesystem::temp_directory_path() / "anvil_resume_killed";
  std::filesystem::remove_all(whole);
  std::filesystem::remove_all(killed);
  REQUIRE(WEXITSTATUS(wait_for(start_anvil(case_file, "-o", whole.string()))) == 0);

  // Kill once the second checkpoint (increment 8) exists, mid-way through the run.
  const pid_t pid = start_anvil(case_file, "-o", killed.string());
  const auto checkpoint = killed / "checkpoint.h5";
  for (int wait = 0; wait < 6000; ++wait) {
    if (std::filesystem::exists(checkpoint) && scene_increment(checkpoint.string()) >= 8) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(pid, SIGKILL);
  const int status = wait_for(pid);
  REQUIRE(WIFSIGNALED(status));
  const int resumed_from = scene_increment(checkpoint.string());
  INFO("killed after checkpoint of increment " << resumed_from);
  REQUIRE(resumed_from >= 8);
  REQUIRE(WEXITSTATUS(wait_for(start_anvil(case_file, "--resume", killed.string()))) == 0);

  // Loads: identical (same operations on the same numbers, so to round-off).
  const auto a = RunOutputs{whole.string()}.loads("top"), b = RunOutputs{killed.string()}.loads("top");
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].increment == b[i].increment);
    CHECK(a[i].stroke == Approx(b[i].stroke).epsilon(1e-12));
    CHECK(a[i].force.z() == Approx(b[i].force.z()).epsilon(1e-10));
  }
  // Series: the same .pvd entries, every file present, no temporary left.
  CHECK(read_text((whole / "anvil.pvd").string()) == read_text((killed / "anvil.pvd").string()));
  const std::string pvd = read_text((killed / "anvil.pvd").string());
  std::smatch m;
  int files = 0;
  for (auto it = pvd.cbegin(); std::regex_search(it, pvd.cend(), m, std::regex("file=\"([^\"]+)\""));
       it = m.suffix().first) {
    CHECK(std::filesystem::file_size(killed / m[1].str()) > 0);
    ++files;
  }
  // Body and two dies at every increment; loads.csv has one row more (the start).
  CHECK(files == 3 * static_cast<int>(a.size() - 1));
  for (const auto& entry : std::filesystem::directory_iterator(killed))
    CHECK(entry.path().extension() != ".tmp");
}

TEST_CASE("a thermal run resumed from a checkpoint continues with the same temperatures and heat budget",
          "[regression]") {
  // cases/hot_upsetting.yaml to 1.5 mm on a coarse mesh, whole and stopped
  // after 4 increments then resumed.
  const auto [a, b] = whole_and_resumed(
      source_path("cases/hot_upsetting.yaml"),
      {"bodies[0].mesh.element_size=2", "time.stop.stroke=1.5", "output.checkpoint_every=1", "output.vtk=false"},
      after_4, "anvil_thermal_resume");
  REQUIRE(a.increment == b.increment);
  REQUIRE(a.temperature.size() == b.temperature.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.temperature.size(); ++i)
    worst = std::max(worst, std::abs(a.temperature[i] - b.temperature[i]));
  INFO("largest temperature difference " << worst << " C");
  // The same operations on the same numbers: identical to round-off.
  CHECK(worst < 1e-9);
  CHECK(a.heat.stored == Approx(b.heat.stored).epsilon(1e-12));
  CHECK(a.heat.to_dies == Approx(b.heat.to_dies).epsilon(1e-12));
  CHECK(a.transfer_time == b.transfer_time);
}

TEST_CASE("a run resumed with --allow-changes lists each change of the case in anvil.log", "[regression]") {
  anvil::log::set_quiet(true);
  const std::string case_file = source_path("cases/upsetting_frictionless.yaml");
  const std::vector<std::string> short_run{"time.max_increments=2", "output.vtk=false"};
  const RunOutputs part = run_case(anvil::scene::read_case(case_file, short_run), "anvil_resume_allow_changes");
  // A stop that changes (allowed freely) and the top die's friction (a change).
  std::vector<std::string> changed{"time.max_increments=3", "output.vtk=false", "dies[0].friction.law=tresca"};
  changed.push_back("dies[0].friction.factor=0.2");
  anvil::run::run(anvil::scene::read_case(case_file, changed), {part.directory, true, true});
  const std::string log = read_text(part.directory + "/anvil.log");
  CHECK(log.find("resuming with 2 change(s) since the checkpoint (--allow-changes):") != std::string::npos);
  CHECK(log.find("  dies[0].friction.law: ") != std::string::npos);
  CHECK(log.find("  dies[0].friction.factor: ") != std::string::npos);
}

TEST_CASE("a run with damage resumed from a checkpoint carries each criterion's damage", "[regression]") {
  // cases/upsetting.yaml to 1.5 mm on a coarse mesh with two criteria, whole
  // and stopped after 4 increments then resumed.
  const auto [a, b] = whole_and_resumed(source_path("cases/upsetting.yaml"),
                                        {"bodies[0].mesh.element_size=2", "time.stop.stroke=1.5",
                                         "damage.cockcroft_latham=true", "damage.brozzo=true", "output.vtk=false"},
                                        after_4, "anvil_damage_resume");
  REQUIRE(a.increment == b.increment);
  REQUIRE(b.damage.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    REQUIRE(a.damage[k].size() == b.damage[k].size());
    double worst = 0.0, largest = 0.0;
    for (std::size_t e = 0; e < a.damage[k].size(); ++e)
      worst = std::max(worst, std::abs(a.damage[k][e] - b.damage[k][e])), largest = std::max(largest, a.damage[k][e]);
    INFO("criterion " << k << ": largest difference " << worst << " of D up to " << largest);
    CHECK(largest > 0.0);
    CHECK(worst < 1e-12); // the same operations on the same numbers
  }
}

TEST_CASE("a hammer run resumed between two blows strikes the second as the uninterrupted run", "[regression]") {
  // cases/hammer_upsetting.yaml on a coarse mesh, two smaller blows, whole
  // and stopped at the end of the first blow then resumed: the resumed run
  // starts with the pause (heat alone) and the second blow.
  const auto [a, b] = whole_and_resumed(
      source_path("cases/hammer_upsetting.yaml"),
      {"bodies[0].mesh.element_size=2", "dies[0].blow_energy=0.1", "dies[0].blows=2", "output.vtk=false"},
      [](const anvil::scene::RunState& whole) { return whole.blows.at(0).last_increment; }, "anvil_hammer_resume");
  REQUIRE(a.blows.size() == 2);
  REQUIRE(b.blows.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    INFO("blow " << k + 1);
    CHECK(a.blows[k].last_increment == b.blows[k].last_increment);
    CHECK(a.blows[k].start_time == b.blows[k].start_time);
    CHECK(a.blows[k].stroke == b.blows[k].stroke); // the same operations on the same numbers
    CHECK(a.blows[k].work == b.blows[k].work);
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < a.temperature.size(); ++i)
    worst = std::max(worst, std::abs(a.temperature[i] - b.temperature[i]));
  CHECK(worst < 1e-9);
}

TEST_CASE("a run with die wear resumed from a checkpoint carries the wear of each die vertex", "[regression]") {
  // cases/upsetting.yaml to 1.5 mm on a coarse mesh with both dies worn,
  // whole and stopped after 4 increments then resumed.
  const auto [a, b] = whole_and_resumed(source_path("cases/upsetting.yaml"),
                                        {"bodies[0].mesh.element_size=2", "time.stop.stroke=1.5",
                                         "dies[].wear.coefficient=1e-3", "dies[].wear.hardness=50", "output.vtk=false"},
                                        after_4, "anvil_wear_resume");
  REQUIRE(a.increment == b.increment);
  REQUIRE(a.wear.size() == 2);
  REQUIRE(b.wear.size() == 2);
  for (std::size_t d = 0; d < 2; ++d) {
    REQUIRE(a.wear[d].size() == b.wear[d].size());
    CHECK(*std::max_element(a.wear[d].begin(), a.wear[d].end()) > 0.0);
    CHECK(a.wear[d] == b.wear[d]); // the same operations on the same numbers
  }
}

TEST_CASE("a run stopped where a remesh was due and resumed further remeshes as the uninterrupted run",
          "[regression]") {
  // cases/upsetting_75.yaml on a coarse mesh, whole and stopped by
  // time.max_increments at the increment after which the whole run made its
  // last remesh (a whole one, the first of two); the stop puts that remesh
  // off and its checkpoint carries the check, which the resumed run makes
  // first.
  const auto [a, b] = whole_and_resumed(
      source_path("cases/upsetting_75.yaml"),
      {"bodies[0].mesh.element_size=2", "remeshing.element_size=2", "remeshing.check_load=false",
       "time.stop.stroke=8.4", "output.vtk=false"},
      [](const anvil::scene::RunState& whole) { return whole.remeshes.at(1).increment; }, "anvil_remesh_resume");
  require_same_remeshes(a, b);
}

TEST_CASE("a run stopped where a remesh around a sunk die corner was due and resumed keeps the contact nodes the "
          "uninterrupted run kept",
          "[regression]") {
  // cases/closed_die_flash.yaml to 2.5 mm, stopped at its first remesh: a
  // region around a die vertex sunk into the billet, rebuilt with its part of
  // the surface, the nodes pressing on a die held. Which nodes pressed comes
  // from the last increment's contact solution, which a resumed run has not
  // solved: the checkpoint at the stop carries it.
  const auto [a, b] = whole_and_resumed(source_path("cases/closed_die_flash.yaml"),
                                        {"remeshing.check_load=false", "time.stop.stroke=2.5", "output.vtk=false"},
                                        first_remesh, "anvil_remesh_contact_resume");
  require_same_remeshes(a, b);
}
