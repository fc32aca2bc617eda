// The triple buffer hands the newest value across threads without tearing. The concurrent test
// also runs under ThreadSanitizer (cosmems_tsan_tests), which would flag any slot read while
// written.
#include "cosmems/haptics/triple_buffer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <thread>

namespace cosmems {
namespace {

TEST(TripleBufferTest, TheConsumerSeesTheNewestPublishedValue) {
  TripleBuffer<int> buffer(-1);
  EXPECT_FALSE(buffer.Update());
  EXPECT_EQ(buffer.Front(), -1);
  buffer.Publish(1);
  buffer.Publish(2);
  EXPECT_TRUE(buffer.Update());
  EXPECT_EQ(buffer.Front(), 2);
  EXPECT_FALSE(buffer.Update());  // nothing new: the front stays
  EXPECT_EQ(buffer.Front(), 2);
  buffer.Back() = 3;
  EXPECT_FALSE(buffer.Update());  // written but not published
  buffer.Publish();
  EXPECT_TRUE(buffer.Update());
  EXPECT_EQ(buffer.Front(), 3);
}

// A value whose every element must agree: a torn read would mix two publications.
struct Record {
  long sequence = 0;
  std::array<long, 32> copies{};
};

TEST(TripleBufferTest, ConcurrentReadsNeverTearAndNeverGoBack) {
  TripleBuffer<Record> buffer;
  constexpr long kCount = 200000;
  std::thread producer([&] {
    for (long i = 1; i <= kCount; ++i) {
      Record& r = buffer.Back();
      r.sequence = i;
      r.copies.fill(i);
      buffer.Publish();
    }
  });
  long last = 0, torn = 0, backwards = 0;
  while (last < kCount) {
    if (!buffer.Update()) continue;
    const Record& r = buffer.Front();
    for (long c : r.copies) torn += c != r.sequence;
    backwards += r.sequence < last;
    last = r.sequence;
  }
  producer.join();
  EXPECT_EQ(torn, 0);
  EXPECT_EQ(backwards, 0);
  EXPECT_EQ(last, kCount);
}

}  // namespace
}  // namespace cosmems
