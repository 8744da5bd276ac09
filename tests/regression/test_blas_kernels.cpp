// `anvil run` started by hand, without tools/anvil's environment, computes
// with the OpenBLAS kernels the regression signatures were made with (AVX2,
// on every CPU that has AVX2 and FMA: core/blas_kernels.h), and a kernel
// family the user asks for is kept.
#include "test_common.h"

#include "anvil/core/subprocess.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>

namespace {

/// The kernels named in the log of `anvil run cases/patch_test.yaml` with
/// OPENBLAS_CORETYPE set to `core` (unset when empty).
std::string kernels_of_run(const std::string& core, const std::string& name) {
  const std::string directory = (std::filesystem::temp_directory_path() / name).string();
  std::filesystem::remove_all(directory);
  const std::optional<std::string> saved =
      std::getenv("OPENBLAS_CORETYPE") ? std::optional<std::string>(std::getenv("OPENBLAS_CORETYPE")) : std::nullopt;
  if (core.empty())
    unsetenv("OPENBLAS_CORETYPE");
  else
    setenv("OPENBLAS_CORETYPE", core.c_str(), 1);
  const int status =
      anvil::subprocess::run({ANVIL_EXECUTABLE, "run", source_path("cases/patch_test.yaml"), "-o", directory});
  if (saved)
    setenv("OPENBLAS_CORETYPE", saved->c_str(), 1);
  else
    unsetenv("OPENBLAS_CORETYPE");
  REQUIRE(status == 0);
  std::ifstream log(directory + "/anvil.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
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
