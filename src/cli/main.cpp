// anvil: command-line entry point. Catches every error once, prints one
// clear message and exits non-zero (STYLE "Input and errors").
#include "anvil/core/blas_kernels.h"
#include "anvil/core/error.h"
#include "anvil/core/interrupt.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/core/subprocess.h"
#include "anvil/run/Simulation.h"
#include "anvil/run/chain.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/effects.h"
#include "anvil/scene/schema.h"
#include "anvil/solver/PetscSession.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <tbb/global_control.h>
#include <unistd.h>
#include <vector>

namespace {

constexpr const char* kUsage = R"(anvil — 3D metal-forming simulator (P1+/P1 velocity-pressure FEM)

usage:
  anvil run CASE.yaml [-o DIR]   run a case; results go to DIR (default: the
                                 case's output.directory, else out/<case name>)
  anvil run CASE.yaml --verbose  also show each Newton iteration and the mesh
                                 quality on the terminal (always in anvil.log)
  anvil run CASE.yaml --resume DIR [--allow-changes]
                                 continue a stopped or killed run from the last
                                 checkpoint in DIR (DIR/checkpoint.h5); a case,
                                 material card, mesh or die changed since is
                                 refused unless --allow-changes (then the log
                                 lists the changes); stop criteria, output and
                                 linear-solver keys may change freely
  anvil run CASE.yaml --set KEY=VALUE ...
                                 change a key of the case file for this run,
                                 e.g. --set time.stroke_increment=0.1
                                      --set dies[].friction.factor=0.1
                                 (dies[] = every die, dies[1] = the second)
  anvil run CASE.yaml --np N     the run on N processes (mpirun); by default
                                 as many as the cores this process may use
                                 (or ANVIL_PROCESSES); --np 1 keeps one
                                 process; without mpirun, one process
  mpirun -n N anvil run CASE.yaml ...
                                 the same on N processes of one machine or
                                 several, started by hand: rank 0 writes the
                                 results
  anvil output-dir CASE.yaml [-o DIR]
                                 print the folder a run would write to
  anvil run CASE.yaml ... -PETSC_OPTION [VALUE] ...
                                 PETSc options for experts, after the case
                                 file, e.g. -ksp_monitor -ksp_view
                                 -fieldsplit_0_pc_type gamg (fgmres solver)
                                 -direct_mat_mumps_icntl_14 50 (mumps solver);
                                 they win over the case's solver.petsc_options
  anvil render DIR [--field NAME] [--view iso|front|top] [--frames N]
                                 quick-look PNGs of a run's VTK series in
                                 DIR/render/ (headless: under xvfb-run when
                                 there is no display); a die field
                                 (--field underfill) colours the dies;
                                 --range LOW HIGH fixes the colour bar;
                                 --flow-lines draws a cut through the part
                                 with its flow lines (output.flow_lines);
                                 --operations: a chain's folder, the end of
                                 each operation (docs/chains.md)
  anvil --schema                 every case-file and material-card key: type,
                                 default, range, unit, meaning
  anvil --list                   the effects a scene can call for
  anvil --version
  anvil --help

Units: mm, s, MPa, N, °C. Outputs: anvil.pvd + .vtu (ParaView), loads.csv,
summary.json, anvil.log, checkpoint.h5 (time-stepping cases).
)";

int usage_error(const std::string& message) {
  std::fprintf(stderr, "anvil: %s\n(run 'anvil --help' for usage)\n", message.c_str());
  return 2;
}

/// The command line of anvil_render (beside this program) with `arguments`,
/// under xvfb-run when there is no X display.
std::vector<std::string> renderer_command(const std::vector<std::string>& arguments) {
  std::vector<std::string> args;
  if (!std::getenv("DISPLAY")) args = {"xvfb-run", "-a"};
  args.push_back(anvil::subprocess::beside_this_program("anvil_render"));
  args.insert(args.end(), arguments.begin(), arguments.end());
  return args;
}

/// `anvil render ...`: becomes anvil_render with the same arguments.
int render(int argc, char** argv) {
  std::vector<std::string> args = renderer_command(std::vector<std::string>(argv + 2, argv + argc));
  std::vector<char*> c_args = anvil::subprocess::argument_vector(args);
  execvp(c_args[0], c_args.data());
  return usage_error("cannot start " + args.front() + ": " + std::strerror(errno) +
                     (args.front() == "xvfb-run" ? " (tools/setup installs xvfb)" : ""));
}

/// After a run: DIR/final.png, the last increment, beside loads.png
/// (output.picture), the quarter model drawn whole when `mirror`
/// (output.picture_mirror). A picture that cannot be made is said, not fatal.
void final_picture(const std::string& directory, bool mirror) {
  std::vector<std::string> picture = {directory, "--out", directory + "/final.png"};
  if (mirror) picture.push_back("--mirror");
  anvil::subprocess::Options options;
  options.quiet_errors = false; // anvil render says why it failed
  const int status = anvil::subprocess::run(renderer_command(picture), options);
  if (status != 0)
    std::fprintf(stderr, "anvil: final.png not written (anvil render %s failed; output.picture: false skips it)\n",
                 directory.c_str());
}

/// Says what `e` is (when `say`) and returns the exit code that goes with
/// it: 3 input error, 4 the run stopped, 5 anything else.
int report(const std::exception& e, bool say) {
  if (dynamic_cast<const anvil::InputError*>(&e)) {
    if (say) std::fprintf(stderr, "anvil: input error: %s\n", e.what());
    return 3;
  }
  if (dynamic_cast<const anvil::RunError*>(&e)) {
    if (say) std::fprintf(stderr, "anvil: run stopped: %s\n", e.what());
    return 4;
  }
  if (say) std::fprintf(stderr, "anvil: internal error: %s\n", e.what());
  return 5;
}

/// `text` as one word for a POSIX shell: as it is when it holds only safe
/// characters, else in single quotes.
std::string shell_word(const std::string& text) {
  const bool safe = !text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                            "0123456789_-./=:,+[]") == std::string::npos;
  if (safe) return text;
  std::string quoted = "'";
  for (const char c : text)
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// What a run stopped by SIGINT or SIGTERM says: where its last accepted
/// increment is and the command that resumes it.
void say_interrupted(const anvil::run::RunEnd& end, const std::string& program, const std::string& case_file,
                     const std::vector<std::string>& overrides, const std::string& directory) {
  if (!end.checkpointed) {
    std::fprintf(stderr,
                 "anvil: %s; the results so far are in %s/, but no checkpoint was written (output.checkpoint_every: "
                 "0): the run cannot be resumed\n",
                 end.stop.c_str(), directory.c_str());
    return;
  }
  std::string command = shell_word(program) + " run " + shell_word(case_file);
  for (const std::string& o : overrides)
    command += " --set " + shell_word(o);
  command += " --resume " + shell_word(directory);
  std::fprintf(stderr,
               "anvil: %s; the last accepted increment is checkpointed in %s/checkpoint.h5; resume with:\n  %s\n",
               end.stop.c_str(), directory.c_str(), command.c_str());
}

/// The processes a run asks for: --np, else ANVIL_PROCESSES, else every core
/// this process may use. 0 after a usage error (said).
int processes_wanted(const std::string& option) {
  const char* environment = std::getenv("ANVIL_PROCESSES");
  const std::string text = !option.empty() ? option : environment ? environment : "";
  if (text.empty()) return anvil::processes::available_cores();
  const std::string source = !option.empty() ? "--np" : "ANVIL_PROCESSES";
  char* end = nullptr;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (end == text.c_str() || *end != '\0' || n < 1 || n > 4096) {
    usage_error(source + " needs a number of processes from 1 to 4096, not '" + text + "'");
    return 0;
  }
  return static_cast<int>(n);
}

/// `anvil run` on `processes` processes: this program again under mpirun
/// (each of its processes sees the launcher and runs the case), Ctrl-C
/// relayed so that the run checkpoints (subprocess::run_relaying_interrupts).
int run_on_processes(int processes, int argc, char** argv) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  // Not bound to a core each: rank 0 remeshes alone while the others wait
  // asleep, and runs its remesh's tries on their cores too (each process's
  // own threads are limited to its share: processes::threads_per_process).
  std::vector<std::string> command = {"mpirun", "-q", "-n", std::to_string(processes), "--bind-to", "none"};
  // More processes than cores share them (mpirun refuses otherwise).
  if (processes > anvil::processes::available_cores()) command.emplace_back("--oversubscribe");
  command.push_back(error ? std::string(argv[0]) : self.string());
  for (int i = 1; i < argc; ++i)
    command.emplace_back(argv[i]);
  // A process waiting in MPI yields its core rather than spin on it: with
  // another program busy on one of two cores, hot_closed_die_flash to 3 mm
  // took 13-167 s spinning and 8-11 s yielding over five runs each (6 s on
  // one process); on an idle machine the whole run took 23.0-23.8 s against
  // 23.4-23.9 s yielding, loads equal (docs/parallel-runs.md).
  setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
  // Open MPI refuses to start as root unless told (CI runs as root).
  if (geteuid() == 0) {
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
  }
  const int code = anvil::subprocess::run_relaying_interrupts(command);
  if (code < 0) std::fprintf(stderr, "anvil: could not start mpirun: %s\n", std::strerror(errno));
  return code < 0 ? 5 : code;
}

/// How long the processes of a run may take to reach its end one after the
/// other (s): rank 0 writes the last output while the others wait.
constexpr double kEndTogether = 10.0;
/// How long the others wait for rank 0's final picture (s).
constexpr double kPictureTime = 120.0;

} // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage_error("no command given");
  const std::string command = argv[1];
  if (command == "--help" || command == "-h") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (command == "--version") {
    std::printf("anvil %s\n", ANVIL_VERSION);
    return 0;
  }
  if (command == "--schema") {
    std::fputs(anvil::scene::schema_text().c_str(), stdout);
    return 0;
  }
  if (command == "--list") {
    std::puts("Effects (built only when a scene calls for them):");
    for (const auto& e : anvil::scene::effect_registry())
      std::printf("  %-20s %s\n", e.name.c_str(), e.doc.c_str());
    return 0;
  }
  if (command == "render") return render(argc, argv);
  if (command != "run" && command != "output-dir") return usage_error("unknown command '" + command + "'");
  if (command == "run") anvil::blas_kernels::pin(argv); // before anything else: it may start this program again

  std::string case_file;
  std::vector<std::string> overrides;
  std::vector<char*> petsc_arguments = {argv[0]}; // what PetscInitialize reads: PETSc's options only
  anvil::run::RunOptions options;
  std::string processes_option;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o" || arg == "--output") {
      if (i + 1 >= argc) return usage_error(arg + " needs a directory");
      options.output_directory = argv[++i];
    } else if (arg == "--verbose") {
      anvil::log::set_verbose(true);
    } else if (arg == "--resume") {
      if (i + 1 >= argc) return usage_error("--resume needs the directory of the run to continue");
      options.output_directory = argv[++i];
      options.resume = true;
    } else if (arg == "--np") {
      if (i + 1 >= argc) return usage_error("--np needs a number of processes, e.g. --np 2");
      processes_option = argv[++i];
    } else if (arg == "--allow-changes") {
      options.allow_changes = true;
    } else if (arg == "--set") {
      if (i + 1 >= argc) return usage_error("--set needs KEY=VALUE, e.g. --set time.stroke_increment=0.1");
      overrides.emplace_back(argv[++i]);
    } else if (arg.size() > 1 && arg[0] == '-' && arg[1] != '-') {
      // A PETSc option, with its value when the next argument is not an option.
      petsc_arguments.push_back(argv[i]);
      if (i + 1 < argc && !anvil::solver::is_petsc_option_name(argv[i + 1])) petsc_arguments.push_back(argv[++i]);
    } else if (!arg.empty() && arg[0] == '-') {
      return usage_error("unknown option '" + arg + "'");
    } else if (case_file.empty()) {
      case_file = arg;
    } else {
      return usage_error("more than one case file given");
    }
  }
  if (case_file.empty()) return usage_error("'" + command + "' needs a case file");
  // Outside a launcher the case is read before mpirun or PETSc starts (about
  // half a second on one process): an input error is said at once, and once.
  const bool launched = anvil::processes::under_launcher();
  const int processes = command == "run" && !launched ? processes_wanted(processes_option) : 1;
  if (processes == 0) return 2;
  std::optional<anvil::scene::Chain> chain_read;
  if (!launched || command == "output-dir") {
    try {
      chain_read = anvil::scene::read_chain(case_file, overrides);
    } catch (const std::exception& e) {
      return report(e, true);
    }
  }
  if (command == "output-dir") {
    std::puts(anvil::run::output_directory(chain_read->operations.front().input, options).c_str());
    return 0;
  }
  // Every core by default: a run not started by mpirun starts itself under it.
  if (processes > 1) {
    if (anvil::subprocess::on_path("mpirun")) return run_on_processes(processes, argc, argv);
    std::fprintf(stderr, "anvil: mpirun is not installed: the run uses one process (of the %d asked for)\n", processes);
  }

  int petsc_argc = static_cast<int>(petsc_arguments.size());
  petsc_arguments.push_back(nullptr);
  char** petsc_argv = petsc_arguments.data();
  std::optional<anvil::solver::PetscSession> petsc;
  try {
    petsc.emplace(petsc_argc, petsc_argv);
  } catch (const std::exception& e) {
    return report(e, true);
  }
  anvil::interrupt::install(); // after PETSc, whose own handlers it replaces
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                    static_cast<std::size_t>(anvil::processes::threads_per_process()));
  int code = 0;
  std::string picture_directory;
  bool picture_mirror = false;
  try {
    // Every process reads the case and runs the same time loop (docs/design.md §2).
    const anvil::scene::Chain chain =
        chain_read ? std::move(*chain_read) : anvil::scene::read_chain(case_file, overrides);
    const anvil::scene::Case& c = chain.operations.front().input;
    const anvil::run::RunEnd end =
        chain.is_chain() ? anvil::run::run_chain(chain, options) : anvil::run::run(c, options);
    // An interrupted run ends as soon as it can: no picture.
    if (c.write_picture && c.write_vtk && !end.signal) picture_directory = anvil::run::output_directory(c, options);
    picture_mirror = c.picture_mirror;
    if (anvil::processes::root())
      for (const std::string& unused : anvil::solver::PetscSession::unused_options())
        std::fprintf(stderr, "anvil: warning: PETSc option %s was not used by the solver of this run (misspelt?)\n",
                     unused.c_str());
    if (end.signal) {
      if (anvil::processes::root())
        say_interrupted(end, argv[0], case_file, overrides, anvil::run::output_directory(c, options));
      code = 128 + end.signal;
    } else if (!end.complete) {
      if (anvil::processes::root()) std::fprintf(stderr, "anvil: run stopped: %s\n", end.stop.c_str());
      code = 4;
    }
  } catch (const std::exception& e) {
    // An error every process met alike (input, a failed increment, rank 0's
    // output) is said once; one that left a process alone is said by it,
    // and the processes still inside the run are stopped.
    if (!anvil::processes::all_ended(kEndTogether)) {
      report(e, true);
      std::fprintf(stderr, "anvil: process %d of %d failed alone; stopping the others\n", anvil::processes::rank(),
                   anvil::processes::count());
      anvil::processes::abort_all(report(e, false));
    }
    code = report(e, anvil::processes::root());
  }
  if (code == 0 && !anvil::processes::all_ended(kEndTogether)) anvil::processes::abort_all(5);
  if (!picture_directory.empty()) {
    if (anvil::processes::root()) final_picture(picture_directory, picture_mirror);
    // The others wait for it: mpirun stops every process when one ends with
    // a non-zero code, rank 0 too, in the middle of its picture.
    anvil::processes::all_ended(kPictureTime);
  }
  return code;
}