// The fake HD scheduler: priorities, DONE/CONTINUE, synchronous calls, handles and rates.
#include <thread>

#include "fake_hd_fixture.hpp"

namespace cosmems {
namespace {

// Appends its id each time it runs; returns DONE once it has run `runs` times (0: never).
struct Probe {
  std::vector<int>* order = nullptr;
  int id = 0;
  int runs = 0;
  int ran = 0;
};

HDCallbackCode HDCALLBACK RunProbe(void* user) {
  auto* p = static_cast<Probe*>(user);
  p->order->push_back(p->id);
  ++p->ran;
  return p->runs != 0 && p->ran >= p->runs ? HD_CALLBACK_DONE : HD_CALLBACK_CONTINUE;
}

class FakeSchedulerTest : public FakeHdTest {
 protected:
  void StartManual() {
    hdFakeSetManualTicks(HD_TRUE);
    hdStartScheduler();
  }
  std::vector<int> order_;
};

TEST_F(FakeSchedulerTest, RunsHigherPrioritiesFirstAndEqualOnesInSubmissionOrder) {
  Probe low{&order_, 1}, high{&order_, 2}, high_later{&order_, 3}, top{&order_, 4};
  hdScheduleAsynchronous(RunProbe, &low, 10);
  hdScheduleAsynchronous(RunProbe, &high, 1000);
  hdScheduleAsynchronous(RunProbe, &high_later, 1000);
  hdScheduleAsynchronous(RunProbe, &top, HD_MAX_SCHEDULER_PRIORITY);
  StartManual();
  EXPECT_EQ(hdFakeStep(2), 2u);
  EXPECT_EQ(order_, (std::vector<int>{4, 2, 3, 1, 4, 2, 3, 1}));
}

TEST_F(FakeSchedulerTest, DoneRemovesTheOperationAndContinueKeepsIt) {
  Probe once_then_done{&order_, 1, 3}, forever{&order_, 2};
  const HDSchedulerHandle finite = hdScheduleAsynchronous(RunProbe, &once_then_done, 5);
  const HDSchedulerHandle endless = hdScheduleAsynchronous(RunProbe, &forever, 5);
  StartManual();
  hdFakeStep(2);
  EXPECT_TRUE(hdWaitForCompletion(finite, HD_WAIT_CHECK_STATUS));
  hdFakeStep(3);
  EXPECT_EQ(once_then_done.ran, 3);
  EXPECT_EQ(forever.ran, 5);
  EXPECT_FALSE(hdWaitForCompletion(finite, HD_WAIT_CHECK_STATUS));
  EXPECT_TRUE(hdWaitForCompletion(endless, HD_WAIT_CHECK_STATUS));
  // Unscheduling an operation that has ended is an error; an active one is not.
  hdUnschedule(finite);
  EXPECT_EQ(PopErrors(), std::vector<HDerror>{HD_INVALID_OPERATION});
  hdUnschedule(endless);
  EXPECT_TRUE(PopErrors().empty());
  hdFakeStep(1);
  EXPECT_EQ(forever.ran, 5);
}

TEST_F(FakeSchedulerTest, SynchronousCallRunsInlineWhileTheSchedulerIsStopped) {
  Probe probe{&order_, 1};
  hdScheduleSynchronous(RunProbe, &probe, HD_DEFAULT_SCHEDULER_PRIORITY);
  EXPECT_EQ(probe.ran, 1);
}

struct Nested {
  std::vector<int> order;
  Probe inner{&order, 2};
};

HDCallbackCode HDCALLBACK ScheduleNested(void* user) {
  auto* n = static_cast<Nested*>(user);
  hdScheduleSynchronous(RunProbe, &n->inner, HD_MIN_SCHEDULER_PRIORITY);
  n->order.push_back(1);  // after the inner one: it ran inline, whatever its priority
  return HD_CALLBACK_DONE;
}

TEST_F(FakeSchedulerTest, SynchronousCallFromTheSchedulerRunsInline) {
  Nested nested;
  hdScheduleAsynchronous(ScheduleNested, &nested, HD_MAX_SCHEDULER_PRIORITY);
  StartManual();
  hdFakeStep(1);
  EXPECT_EQ(nested.order, (std::vector<int>{2, 1}));
}

HDCallbackCode HDCALLBACK NoteThread(void* user) {
  *static_cast<std::thread::id*>(user) = std::this_thread::get_id();
  return HD_CALLBACK_DONE;
}

TEST_F(FakeSchedulerTest, SynchronousCallWaitsForTheSchedulerThread) {
  hdStartScheduler();
  std::thread::id ran_on;
  hdScheduleSynchronous(NoteThread, &ran_on, HD_DEFAULT_SCHEDULER_PRIORITY);
  EXPECT_NE(ran_on, std::thread::id());           // it has run when the call returns ...
  EXPECT_NE(ran_on, std::this_thread::get_id());  // ... on the scheduler's thread
  hdStopScheduler();
  EXPECT_TRUE(PopErrors().empty());
}

TEST_F(FakeSchedulerTest, HandlesNeedAllSixtyFourBits) {
  Probe probe{&order_, 1};
  const HDSchedulerHandle handle = hdScheduleAsynchronous(RunProbe, &probe, 5);
  EXPECT_GE(handle, 0x100000000UL);
  // What code storing the handle in an HDCallbackCode (32 bits) would unschedule: nothing.
  const auto truncated = static_cast<HDCallbackCode>(handle);
  hdUnschedule(truncated);
  EXPECT_EQ(PopErrors(), std::vector<HDerror>{HD_INVALID_OPERATION});
  EXPECT_TRUE(hdWaitForCompletion(handle, HD_WAIT_CHECK_STATUS));
}

TEST_F(FakeSchedulerTest, AcceptsOnlyTheSupportedRates) {
  for (const HDulong rate : {500UL, 1000UL, 2000UL}) {
    hdSetSchedulerRate(rate);
    EXPECT_TRUE(PopErrors().empty()) << rate;
  }
  for (const HDulong rate : {0UL, 999UL, 1600UL, 4000UL}) {
    hdSetSchedulerRate(rate);
    EXPECT_EQ(PopErrors(), std::vector<HDerror>{HD_INVALID_VALUE}) << rate;
  }
}

struct RateReading {
  HDint instantaneous = 0;
  HDdouble average = 0.0;
  HDdouble stamp = -1.0;
};

HDCallbackCode HDCALLBACK ReadRates(void* user) {
  auto* r = static_cast<RateReading*>(user);
  hdGetIntegerv(HD_INSTANTANEOUS_UPDATE_RATE, &r->instantaneous);
  hdGetDoublev(HD_UPDATE_RATE, &r->average);
  r->stamp = hdGetSchedulerTimeStamp();
  return HD_CALLBACK_CONTINUE;
}

TEST_F(FakeSchedulerTest, ManualTicksReportTheNominalRate) {
  hdInitDevice(HD_DEFAULT_DEVICE);
  hdSetSchedulerRate(2000);
  RateReading reading;
  hdScheduleAsynchronous(ReadRates, &reading, HD_DEFAULT_SCHEDULER_PRIORITY);
  StartManual();
  hdFakeStep(3);
  EXPECT_EQ(reading.instantaneous, 2000);
  EXPECT_EQ(reading.average, 2000.0);
  EXPECT_GE(reading.stamp, 0.0);  // seconds since the tick began: no bound on the machine's speed
  EXPECT_EQ(hdFakeTickCount(), 3u);
}

TEST_F(FakeSchedulerTest, ThreadedTicksMeasureTheirRate) {
  hdInitDevice(HD_DEFAULT_DEVICE);
  RateReading reading;
  const HDSchedulerHandle handle =
      hdScheduleAsynchronous(ReadRates, &reading, HD_DEFAULT_SCHEDULER_PRIORITY);
  hdStartScheduler();
  while (hdFakeTickCount() < 5) std::this_thread::yield();
  hdStopScheduler();
  hdUnschedule(handle);
  // Measured from the wall clock: positive and finite, but how close to 1 kHz depends on the
  // machine, which benchmarks measure, not tests.
  EXPECT_GT(reading.instantaneous, 0);
  EXPECT_GT(reading.average, 0.0);
  EXPECT_TRUE(PopErrors().empty());
}

}  // namespace
}  // namespace cosmems
