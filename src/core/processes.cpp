#include "anvil/core/processes.h"

#include "anvil/core/error.h"

#include <mpi.h>

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <thread>
#include <vector>

namespace anvil::processes {
namespace {
bool started() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

/// Rank 0 inside on_root's work: the other processes are not listening.
bool working_alone = false;
} // namespace

int rank() {
  int r = 0;
  if (started()) MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int count() {
  int n = 1;
  if (started()) MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

void sum(std::span<double> values) {
  if (count() == 1 || values.empty()) return;
  // MPI counts are int: large vectors go in pieces.
  constexpr std::size_t kPiece = std::size_t{1} << 28;
  std::vector<double> total(std::min(values.size(), kPiece));
  for (std::size_t first = 0; first < values.size(); first += kPiece) {
    const int n = static_cast<int>(std::min(kPiece, values.size() - first));
    MPI_Reduce(values.data() + first, total.data(), n, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    if (root()) std::copy_n(total.data(), n, values.data() + first);
    MPI_Bcast(values.data() + first, n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  }
}

std::vector<double> share_out(int items, int width, const std::function<void(int, double*)>& compute) {
  std::vector<double> values(static_cast<std::size_t>(items) * width, 0.0);
  const bool together = count() > 1 && !working_alone;
  const int first = together ? rank() : 0, stride = together ? count() : 1;
  for (int i = first; i < items; i += stride)
    compute(i, values.data() + static_cast<std::size_t>(i) * width);
  if (together) sum(values); // each value plus exact zeros
  return values;
}

int minimum(int value) {
  if (count() == 1) return value;
  int smallest = value;
  MPI_Allreduce(&value, &smallest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return smallest;
}

int maximum(int value) {
  if (count() == 1) return value;
  int largest = value;
  MPI_Allreduce(&value, &largest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return largest;
}

void broadcast(std::string& bytes) {
  if (count() == 1) return;
  std::uint64_t size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  bytes.resize(size);
  constexpr std::uint64_t kPiece = std::uint64_t{1} << 30;
  for (std::uint64_t first = 0; first < size; first += kPiece)
    MPI_Bcast(bytes.data() + first, static_cast<int>(std::min(kPiece, size - first)), MPI_CHAR, 0, MPI_COMM_WORLD);
}

void broadcast(std::vector<double>& values) {
  if (count() == 1) return;
  MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

std::vector<std::vector<double>> gather(std::span<const double> values) {
  std::vector<std::vector<double>> all;
  if (root()) all.emplace_back(values.begin(), values.end());
  if (count() == 1) return all;
  constexpr std::size_t kPiece = std::size_t{1} << 28; // MPI counts are int: large vectors go in pieces
  auto piece = [](std::size_t size, std::size_t first) {
    return static_cast<int>(size - first < kPiece ? size - first : kPiece);
  };
  if (!root()) {
    std::uint64_t size = values.size();
    MPI_Send(&size, 1, MPI_UINT64_T, 0, 0, MPI_COMM_WORLD);
    for (std::size_t first = 0; first < values.size(); first += kPiece)
      MPI_Send(values.data() + first, piece(values.size(), first), MPI_DOUBLE, 0, 0, MPI_COMM_WORLD);
    return all;
  }
  for (int from = 1; from < count(); ++from) {
    std::uint64_t size = 0;
    MPI_Recv(&size, 1, MPI_UINT64_T, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::vector<double>& got = all.emplace_back(size);
    for (std::size_t first = 0; first < got.size(); first += kPiece)
      MPI_Recv(got.data() + first, piece(got.size(), first), MPI_DOUBLE, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
  return all;
}

void on_root(const std::function<void()>& work) {
  on_root_answer([&] {
    work();
    return true;
  });
}

namespace {
/// Waits for `request`, asleep between tests: an MPI wait polls and keeps
/// its core busy. False when `deadline` passes first.
bool wait_asleep(MPI_Request& request, std::chrono::steady_clock::time_point deadline, std::chrono::milliseconds nap) {
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return true;
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(nap);
  }
}
} // namespace

bool on_root_answer(const std::function<bool()>& work) {
  if (count() == 1) return work();
  // Outcome: 'y' or 'n' answered, 'i' InputError, 'r' RunError, then the message.
  std::string outcome = "n";
  if (root()) {
    struct Alone {
      Alone() { working_alone = true; }
      ~Alone() { working_alone = false; }
    } alone;
    try {
      outcome[0] = work() ? 'y' : 'n';
    } catch (const InputError& e) {
      outcome = std::string("i") + e.what();
    } catch (const RunError& e) {
      outcome = std::string("r") + e.what();
    }
  }
  // The others wait asleep, leaving their cores to rank 0's work (a
  // remesh's tries run side by side on the cores rank 0 may use).
  MPI_Request arrived;
  MPI_Ibarrier(MPI_COMM_WORLD, &arrived);
  wait_asleep(arrived, std::chrono::steady_clock::time_point::max(), std::chrono::milliseconds(1));
  broadcast(outcome);
  if (outcome[0] == 'i') throw InputError(outcome.substr(1));
  if (outcome[0] == 'r') throw RunError(outcome.substr(1));
  return outcome[0] == 'y';
}

bool all_ended(double seconds) {
  if (count() == 1) return true;
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  const auto deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
  return wait_asleep(request, deadline, std::chrono::milliseconds(5));
}

void abort_all(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

bool under_launcher() {
  // Open MPI's mpirun sets the first, PMIx-based launchers the second, MPICH's Hydra the third.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

int threads_per_process() {
  if (count() == 1) return available_cores();
  MPI_Comm here;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &here);
  int sharing = 1;
  MPI_Comm_size(here, &sharing);
  MPI_Comm_free(&here);
  return std::max(1, available_cores() / sharing);
}

} // namespace anvil::processes
