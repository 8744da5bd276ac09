// Hot loops allocate nothing (STYLE): the element loop of the assembly makes
// no heap allocation, so a mesh with 8 times the elements costs the same
// number of allocations (those of the returned vectors and the thread pool's
// bookkeeping, made once per call).
#include "box_assembly.h"

// Not under AddressSanitizer (tools/sanitize): its own malloc must serve
// every allocation, and a malloc defined here would come before it and run
// before its shadow memory exists, crashing the test program on start. The
// plain build counts.
#ifndef __SANITIZE_ADDRESS__

#include <catch2/catch.hpp>

#include <atomic>
#include <cstddef>

namespace {
std::atomic<long> allocations{0};
} // namespace

// Every malloc, calloc and realloc of this test binary and the libraries it
// loads is counted (glibc: the executable's definitions interpose, and pass
// on to glibc's own): std::vector through operator new, Eigen's dynamic
// matrices and TBB alike.
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t size) {
  ++allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  ++allocations;
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  ++allocations;
  return __libc_realloc(p, size);
}
}

using namespace anvil;

namespace {

/// Heap allocations of one assemble() with tangent on a box of `cells`³ cubes
/// (6 tets each), after a first call that may set up caches.
long allocations_of_assembly(int cells) {
  BoxAssembly block(cells);
  block.assemble();
  const long before = allocations.load();
  const fem::AssemblyResult r = block.assemble();
  const long made = allocations.load() - before;
  REQUIRE(r.bad_element < 0);
  return made;
}

} // namespace

TEST_CASE("The assembly's element loop allocates nothing", "[unit][fem]") {
  const long small = allocations_of_assembly(4), large = allocations_of_assembly(8); // 384 and 3072 elements
  INFO("allocations per assemble(): " << small << " at 384 elements, " << large << " at 3072");
  // One allocation per element would add 2688; per colour or per thread
  // task a few tens. The same count is what allocation-free means here.
  CHECK(large == small);
  CHECK(small < 64);
}

#endif // __SANITIZE_ADDRESS__
