#pragma once

namespace cosmems::test {

/// Heap allocations made by this thread so far (allocation_counter.cpp interposes malloc).
long AllocationCount();

/// Runs `body` `repeats` times and returns the heap allocations it made.
template <typename F>
long AllocationsDuring(int repeats, F&& body) {
  const long before = AllocationCount();
  for (int i = 0; i < repeats; ++i) body();
  return AllocationCount() - before;
}

}  // namespace cosmems::test
