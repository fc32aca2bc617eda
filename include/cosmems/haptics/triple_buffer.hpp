#pragma once

#include <atomic>
#include <cstdint>

namespace cosmems {

/// The newest value from one producer thread to one consumer thread, wait-free on both sides:
/// three slots, one owned by each side and one in the middle, swapped through one atomic byte.
/// A slot changes owner only through that atomic (acquire/release), so no value is ever read
/// while it is written and nothing tears. The servo loop publishes device states and loop
/// figures this way; the simulation publishes its local model to the servo loop.
template <class T>
class TripleBuffer {
 public:
  TripleBuffer() = default;
  explicit TripleBuffer(const T& initial) {
    for (Slot& s : slots_) s.value = initial;
  }
  TripleBuffer(const TripleBuffer&) = delete;
  TripleBuffer& operator=(const TripleBuffer&) = delete;

  /// Producer: the slot to fill; Publish() hands it to the consumer.
  T& Back() { return slots_[back_].value; }
  void Publish() {
    back_ = middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel) &
            kIndex;
  }
  /// Producer: copies `value` in and publishes it.
  void Publish(const T& value) {
    Back() = value;
    Publish();
  }

  /// Consumer: takes the newest published value if there is one; true when Front() changed.
  bool Update() {
    if ((middle_.load(std::memory_order_relaxed) & kFresh) == 0) return false;
    front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
    return true;
  }
  /// Consumer: the value taken by the last Update().
  const T& Front() const { return slots_[front_].value; }

 private:
  static constexpr std::uint8_t kIndex = 3;
  static constexpr std::uint8_t kFresh = 4;
  // Each slot on its own cache line: the two threads never write the same line.
  struct alignas(64) Slot {
    T value{};
  };
  Slot slots_[3];
  std::atomic<std::uint8_t> middle_{1};
  std::uint8_t back_ = 0;   // producer's
  std::uint8_t front_ = 2;  // consumer's
};

}  // namespace cosmems
