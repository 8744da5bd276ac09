// Which BLAS kernels a run computes with. Debian's OpenBLAS picks its
// kernels by CPU (its SSE3 ones on a Xeon with AVX-512 it does not know), and
// each family rounds otherwise: through a remesh that round-off becomes
// another mesh (docs/parallel-runs.md, "Threads and round-off"). So a run
// asks for the AVX2 kernels on every CPU that has AVX2 and FMA, whether it
// was started by tools/anvil, by hand or by mpirun (tools/lib/blas_env.sh
// asks alike for the test programs, which have no start of their own).
#pragma once
#include <string>

namespace anvil::blas_kernels {

/// On a CPU with AVX2 and FMA, with OpenBLAS loaded on other kernels and
/// OPENBLAS_CORETYPE unset: sets OPENBLAS_CORETYPE=Haswell and starts this
/// program again with `argv` (OpenBLAS reads the variable when it is loaded,
/// before main). Returns otherwise, and when the program cannot be started
/// again (said on stderr: the run goes on with the kernels it has).
void pin(char** argv);

/// The kernels in use, for the run's log: "OpenBLAS Haswell kernels", or
/// "not OpenBLAS" when another BLAS is behind libblas.so.3.
std::string in_use();

} // namespace anvil::blas_kernels
