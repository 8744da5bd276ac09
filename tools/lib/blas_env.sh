# Sourced by the scripts that run Anvil: the BLAS settings that make a run
# the same from one run, and one machine, to the next.
# - One BLAS and OpenMP thread: PETSc's vector operations call BLAS, and a
#   second OpenBLAS thread spins between the calls on the core TBB assembles
#   with (an 18k-node run: the same wall time, 30 % more CPU; on 2 processes,
#   4 % more wall time).
# - OpenBLAS's AVX2 kernels wherever the CPU has them: Debian's OpenBLAS picks
#   its kernels by CPU (its SSE3 ones on a Xeon with AVX-512 it does not
#   know), each family rounds otherwise, and through a remesh that round-off
#   becomes another mesh (hot_conrod's load after 10 increments: 9682.27 N
#   with the AVX2 kernels, the regression signature; 9684.52 N with the SSE3
#   ones, 9684.96 N with the AVX-512 ones). Only read at the library's
#   start, so set before the program starts. `anvil run` sets it itself
#   (core/blas_kernels.h); the test programs need it from here.
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1} OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
if [ -z "${OPENBLAS_CORETYPE:-}" ] && grep -qw avx2 /proc/cpuinfo 2>/dev/null && grep -qw fma /proc/cpuinfo; then
  export OPENBLAS_CORETYPE=Haswell
fi
