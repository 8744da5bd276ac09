#include "anvil/core/blas_kernels.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <strings.h>

namespace anvil::blas_kernels {
namespace {

/// OpenBLAS's name of its kernels, or nullptr when OpenBLAS is not the BLAS
/// loaded (found at run time: libblas.so.3 is Debian's choice, alternatives).
const char* openblas_core() {
  using CoreName = char* (*)();
  auto core = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  return core ? core() : nullptr;
}

constexpr const char* kCore = "Haswell";

} // namespace

void pin(char** argv) {
  if (std::getenv("OPENBLAS_CORETYPE")) return; // the user's choice, or set before this start
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) return;
  const char* core = openblas_core();
  if (!core || strcasecmp(core, kCore) == 0) return;
  setenv("OPENBLAS_CORETYPE", kCore, 1);
  execv("/proc/self/exe", argv);
  std::fprintf(stderr,
               "anvil: warning: could not start again with OpenBLAS's %s kernels (%s): the run uses its %s ones\n",
               kCore, std::strerror(errno), core);
}

std::string in_use() {
  const char* core = openblas_core();
  return core ? std::string("OpenBLAS ") + core + " kernels" : "not OpenBLAS";
}

} // namespace anvil::blas_kernels
