// The processes of a run (`mpirun -n N anvil run`, docs/design.md §2): every process
// holds the whole mesh and runs the same time loop; the system is assembled
// and solved by all of them (fem::Partition), and what one process decides
// alone (rank 0's output) reaches the others through these calls, so that
// every process takes the same branch and none waits for a partner that has
// left. One process (no mpirun, or MPI not started) is the plain case: every
// call is then free.
#pragma once
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace anvil::processes {

int rank();  ///< this process, 0 … count() − 1
int count(); ///< processes of the run
inline bool root() {
  return rank() == 0;
}

/// values[i] ← Σ over the processes of values[i], the same sums on every
/// process (reduced on rank 0, then broadcast: an all-reduce may round
/// differently on different processes).
void sum(std::span<double> values);
/// compute(i, values + i × width) for every item i in [0, items) (its
/// values start at zero), the items dealt out among the processes in turn;
/// every process gets all the values, the same bits whatever the number of
/// processes (each is computed once and the others add zeros). For work
/// every process would otherwise repeat (a measurement of the replicated
/// mesh). Every process calls it together, or rank 0 alone inside on_root's
/// work, which computes them all.
std::vector<double> share_out(int items, int width, const std::function<void(int, double*)>& compute);
/// The smallest of `value` over the processes.
int minimum(int value);
/// The largest of `value` over the processes.
int maximum(int value);

/// Runs `work` on rank 0 alone (writing a file, remeshing); an InputError or
/// RunError it throws is thrown on every process with the same message, so
/// all of them stop alike.
void on_root(const std::function<void()>& work);
/// The same for work with a yes-or-no answer: rank 0's answer on every process.
bool on_root_answer(const std::function<bool()>& work);

/// Every process's `values`, in rank order, on rank 0 (empty on the others).
std::vector<std::vector<double>> gather(std::span<const double> values);
/// `bytes` from rank 0 to every process (resized on the others).
void broadcast(std::string& bytes);
/// `values` from rank 0 to every process (of the same size on each).
void broadcast(std::vector<double>& values);

/// After a run ended on this process with exit `code`: true when every
/// process reached the same point within `seconds` (they ended together:
/// the run finished, or failed alike on all); false when some process is
/// still inside the run, stuck waiting for this one.
bool all_ended(double seconds);
/// Ends every process of the run at once with `code` (MPI_Abort).
[[noreturn]] void abort_all(int code);

/// True in a process that an MPI launcher (mpirun) started.
bool under_launcher();
/// The cores this process may run on (its CPU affinity): the processes a
/// run uses when the command line and ANVIL_PROCESSES say nothing.
int available_cores();
/// Threads each process may run at once (TBB's assembly): the cores it
/// may run on shared among the run's processes on its machine, at least one.
int threads_per_process();

} // namespace anvil::processes
