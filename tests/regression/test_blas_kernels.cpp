// `anvil run` started by hand, without tools/anvil's environment, computes
// with the OpenBLAS kernels the regression signatures were made with (AVX2,
// on every CPU that has AVX2 and FMA: core/blas_kernels.h), and a kernel
// family the user asks for is kept.
#include "test_common.h"

#include "anvil/core/subprocess.h"

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

namespace {

/// The kernels named in the log of `anvil run cases/patch_test.yaml` with
/// OPENBLAS_CORETYPE set to `core` (unset when empty), through env(1), so
/// that this process's environment stays as it is.
std::string kernels_of_run(const std::string& core, const std::string& name) {
  const std::string directory = (std::filesystem::temp_directory_path() / name).string();
  std::filesystem::remove_all(directory);
  std::vector<std::string> command = {"env"};
  if (core.empty())
    command.insert(command.end(), {"-u", "OPENBLAS_CORETYPE"});
  else
    command.push_back("OPENBLAS_CORETYPE=" + core);
  command.insert(command.end(), {ANVIL_EXECUTABLE, "run", source_path("cases/patch_test.yaml"), "-o", directory});
  REQUIRE(anvil::subprocess::run(command) == 0);
  const std::string text = file_text(directory + "/anvil.log");
  std::smatch kernels;
  REQUIRE(std::regex_search(text, kernels, std::regex("solver: .*, (OpenBLAS \\S+ kernels|not OpenBLAS)")));
  return kernels[1];
}

} // namespace

TEST_CASE(
    "anvil run started without OPENBLAS_CORETYPE computes with OpenBLAS's AVX2 kernels where the CPU has them, and "
    "a family the user sets is kept",
    "[regression]") {
  const std::string unset = kernels_of_run("", "anvil_kernels_unset");
  if (unset == "not OpenBLAS") {
    WARN("the BLAS behind libblas.so.3 is not OpenBLAS: nothing to pin");
    return;
  }
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    CHECK(unset == "OpenBLAS Haswell kernels");
  else
    WARN("this CPU has no AVX2 and FMA: OpenBLAS's own choice is kept (" << unset << ")");
  CHECK(kernels_of_run("Prescott", "anvil_kernels_prescott") == "OpenBLAS Prescott kernels");
}
