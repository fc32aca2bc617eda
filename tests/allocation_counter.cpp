// Interposes malloc, calloc and realloc (forwarding to glibc's own), so that every heap
// allocation of the no-allocation tests counts: Eigen's, operator new's and CHOLMOD's C ones.
// Linked only into that executable, which is built only without sanitizers (they interpose the
// allocator themselves).
#include "allocation_counter.hpp"

#include <cstddef>

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);

static thread_local long g_allocations = 0;

void* malloc(std::size_t size) {
  ++g_allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  ++g_allocations;
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) {
  ++g_allocations;
  return __libc_realloc(pointer, size);
}
}

namespace cosmems::test {

long AllocationCount() { return g_allocations; }

}  // namespace cosmems::test
