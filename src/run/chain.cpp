#include "anvil/run/chain.h"

#include "anvil/core/error.h"
#include "anvil/core/log.h"
#include "anvil/core/processes.h"
#include "anvil/io/Checkpoint.h"
#include "anvil/io/JsonWriter.h"
#include "anvil/io/RunResults.h"
#include "anvil/io/VtkSeries.h"
#include "anvil/io/atomic_file.h"
#include "anvil/run/place_part.h"
#include "anvil/run/trim.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace anvil::run {
namespace {

/// What the chain's summary.json says of one operation, read from the
/// operation's own summary.json.
struct OperationFigures {
  std::string folder;
  double start = 0.0;     ///< s, chain time when it began
  double duration = 0.0;  ///< s
  double peak_load = 0.0; ///< N, whole part, largest over its dies
  double work = 0.0;      ///< J, the press's work on the whole part
  double temperature_min = std::numeric_limits<double>::quiet_NaN(), temperature_max = temperature_min; ///< °C
  int increments = 0;
};

OperationFigures read_figures(const std::string& out, const std::string& folder, double start) {
  const std::string dir = out + "/" + folder;
  OperationFigures f;
  f.folder = folder;
  f.start = start;
  f.duration = io::read_summary_number(dir, "time_s");
  f.increments = static_cast<int>(io::read_summary_number(dir, "increments"));
  for (double peak : io::read_summary_numbers(dir, "peak_whole_part"))
    f.peak_load = std::max(f.peak_load, peak);
  for (double work : io::read_summary_numbers(dir, "work_whole_part_J"))
    f.work += work;
  for (double t : io::read_summary_numbers(dir, "temperature_min_C"))
    f.temperature_min = std::isnan(f.temperature_min) ? t : std::min(f.temperature_min, t);
  for (double t : io::read_summary_numbers(dir, "temperature_max_C"))
    f.temperature_max = std::isnan(f.temperature_max) ? t : std::max(f.temperature_max, t);
  return f;
}

void write_chain_summary(const std::string& out, const scene::Chain& chain,
                         const std::vector<OperationFigures>& figures) {
  io::JsonWriter json;
  json.begin_object()
      .member("case", chain.path)
      .member("operations_done", static_cast<int>(figures.size()))
      .member("operations_total", static_cast<int>(chain.operations.size()))
      .key("operations")
      .begin_array();
  double time = 0.0;
  for (std::size_t k = 0; k < figures.size(); ++k) {
    const OperationFigures& f = figures[k];
    json.begin_object()
        .member("name", chain.operations[k].name)
        .member("type", scene::to_string(chain.operations[k].kind))
        .member("folder", f.folder)
        .member("start_s", f.start)
        .member("duration_s", f.duration)
        .member("increments", f.increments)
        .member("peak_load_N", f.peak_load)
        .member("press_work_J", f.work);
    if (!std::isnan(f.temperature_min))
      json.member("part_temperature_min_C", f.temperature_min).member("part_temperature_max_C", f.temperature_max);
    json.end_object();
    time = f.start + f.duration;
  }
  json.end_array().member("time_s", time).end_object();
  io::write_file_atomically(out + "/summary.json", json.str());
}

/// Adds the VTK series of an operation to the chain's: its times after
/// `start`, its dies after those of the operations before (`die_base`), its
/// files in its folder. At a time two operations share (a trim at the end
/// of a stroke) the later one's frame is kept.
void add_frames(std::vector<scene::OutputFrame>& frames, const std::vector<scene::OutputFrame>& own,
                const std::string& folder, double start, int die_base) {
  std::vector<scene::OutputFrame> added;
  for (const scene::OutputFrame& e : own)
    added.push_back({start + e.time, e.part == 0 ? 0 : e.part + die_base, folder + "/" + e.file});
  std::erase_if(frames, [&](const scene::OutputFrame& e) {
    return std::any_of(added.begin(), added.end(), [&](const scene::OutputFrame& a) { return a.time == e.time; });
  });
  frames.insert(frames.end(), added.begin(), added.end());
}

/// The wear of the dies of operation `from` carried to those of `to` of
/// the same name (a die used again wears on).
std::vector<std::vector<double>> carried_wear(const scene::Case& from, const scene::Case& to,
                                              const std::vector<std::vector<double>>& wear) {
  std::vector<std::vector<double>> out(to.dies.size());
  for (std::size_t d = 0; d < to.dies.size(); ++d)
    for (std::size_t e = 0; e < from.dies.size() && e < wear.size(); ++e)
      if (from.dies[e].name == to.dies[d].name) out[d] = wear[e];
  return out;
}

} // namespace

std::string operation_folder(const scene::Chain& chain, int k) {
  char number[16];
  std::snprintf(number, sizeof number, "%02d-", k + 1);
  return number + chain.operations[k].name;
}

RunEnd run_chain(const scene::Chain& chain, const RunOptions& options) {
  const std::string out = output_directory(chain.operations.front().input, options);
  const int count = static_cast<int>(chain.operations.size());
  int done = 0;
  if (options.resume) {
    if (!std::filesystem::exists(out + "/summary.json"))
      throw InputError(out + "/summary.json: not found: no chain to resume in " + out);
    done = static_cast<int>(io::read_summary_number(out, "operations_done"));
    if (done >= count) throw InputError(out + ": the chain is complete (" + std::to_string(count) + " operations)");
  }
  processes::on_root([&] {
    std::filesystem::create_directories(out);
    if (!options.resume) // a checkpoint of an earlier run would be taken for this one's
      for (int k = 0; k < count; ++k)
        std::filesystem::remove(out + "/" + operation_folder(chain, k) + "/checkpoint.h5");
  });
  std::vector<OperationFigures> figures;
  std::vector<scene::OutputFrame> frames;
  scene::RunState part;
  int die_base = 0;
  double time = 0.0; // s, of the chain
  RunEnd end;
  for (int k = 0; k < count; ++k) {
    const scene::Operation& op = chain.operations[k];
    const std::string folder = operation_folder(chain, k), dir = out + "/" + folder;
    const std::string checkpoint = dir + "/checkpoint.h5";
    if (k < done) {
      part = io::read_checkpoint(checkpoint);
    } else {
      if (k > 0) {
        part.wear = carried_wear(chain.operations[k - 1].input, op.input, part.wear);
        place_part(op.place, op.input, part, op.source);
      }
      log::info("operation %d/%d '%s' (%s) into %s/", k + 1, count, op.name.c_str(), scene::to_string(op.kind),
                dir.c_str());
      RunOptions own = options;
      own.output_directory = dir;
      own.resume = options.resume && k == done && std::filesystem::exists(checkpoint);
      end = op.kind == scene::OperationKind::trim ? trim(op, own, part) : run(op.input, own, &part);
      if (end.signal || !end.complete) {
        end.stop = "operation '" + op.name + "': " + end.stop;
        processes::on_root([&] { write_chain_summary(out, chain, figures); });
        return end;
      }
      // The next operation starts from what the checkpoint holds, as a
      // resumed chain does: the two cannot part.
      if (std::filesystem::exists(checkpoint)) part = io::read_checkpoint(checkpoint);
    }
    figures.push_back(read_figures(out, folder, time));
    add_frames(frames, part.outputs, folder, time, die_base);
    die_base += static_cast<int>(op.input.dies.size());
    time += part.time;
    processes::on_root([&] {
      io::write_collection(out + "/anvil.pvd", frames);
      write_chain_summary(out, chain, figures);
    });
  }
  log::info("chain of %d operations done, t = %.6g s; results in %s/ (anvil.pvd over the chain, summary.json)", count,
            time, out.c_str());
  end.stop = "chain done: " + end.stop;
  return end;
}

} // namespace anvil::run
