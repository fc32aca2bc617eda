// The servo scheduler of the fake HD API: operations, ticks and the scheduler thread.
#include <time.h>

#include <algorithm>
#include <cerrno>

#include "fake_world.hpp"

namespace cosmems::fake_hd {
namespace {

std::vector<Operation>::iterator Find(World& w, HDSchedulerHandle handle) {
  return std::find_if(w.operations.begin(), w.operations.end(),
                      [handle](const Operation& op) { return op.handle == handle; });
}

void End(World& w, std::vector<Operation>::iterator op) {
  w.operations.erase(op);
  Changed().notify_all();
}

HDSchedulerHandle Submit(World& w, HDSchedulerCallback callback, void* user_data, HDushort priority,
                         bool synchronous) {
  Operation op;
  op.handle = w.next_handle++;
  op.callback = callback;
  op.user_data = user_data;
  op.priority = priority;
  op.order = w.next_order++;
  op.synchronous = synchronous;
  w.operations.push_back(op);
  return op.handle;
}

void BeginTick(World& w) {
  const Clock::time_point now = Clock::now();
  w.previous_tick_start = w.tick_start;
  w.tick_start = now;
  if (w.timed_ticks == 0) w.first_tick_start = now;
  ++w.timed_ticks;
  const double time_s = static_cast<double>(w.ticks) / static_cast<double>(w.rate_hz);
  ++w.ticks;
  w.last_latched_n = w.latched_n;
  SampleStylus(w, time_s);
  w.frame_done_this_tick = false;
}

void EndTick(World& w) {
  RaiseInjected(w);  // errors meant for this tick that no frame has raised
  if (w.force_log.size() < kForceLogTicks) w.force_log.push_back(w.latched_n);
}

void Advance(timespec& t, long nanoseconds) {
  t.tv_nsec += nanoseconds;
  while (t.tv_nsec >= 1000000000L) {
    t.tv_nsec -= 1000000000L;
    ++t.tv_sec;
  }
}

bool Before(const timespec& a, const timespec& b) {
  return a.tv_sec != b.tv_sec ? a.tv_sec < b.tv_sec : a.tv_nsec < b.tv_nsec;
}

// The scheduler thread: one tick per period, paced by absolute deadlines so that the time a
// tick takes does not accumulate into drift.
void Serve() {
  timespec deadline{};
  clock_gettime(CLOCK_MONOTONIC, &deadline);
  for (;;) {
    HDulong rate = 0;
    {
      auto lock = Lock();
      if (TheWorld().stop_requested) return;
      rate = TheWorld().rate_hz;
    }
    RunTick();
    const long period_ns = static_cast<long>(1000000000UL / rate);
    Advance(deadline, period_ns);
    // After an overrun of a whole period (a preempted thread), start the schedule again from
    // now rather than catch up with a burst of ticks.
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    timespec late = deadline;
    Advance(late, period_ns);
    if (Before(late, now)) deadline = now;
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) == EINTR) {
    }
  }
}

}  // namespace

void RunTick() {
  std::vector<Operation> due;
  {
    auto lock = Lock();
    World& w = TheWorld();
    BeginTick(w);
    due = w.operations;
  }
  std::sort(due.begin(), due.end(), [](const Operation& a, const Operation& b) {
    return a.priority != b.priority ? a.priority > b.priority : a.order < b.order;
  });
  OnTickingThread() = true;
  for (const Operation& op : due) {
    {
      auto lock = Lock();
      World& w = TheWorld();
      const auto it = Find(w, op.handle);
      if (it == w.operations.end() || it->finished) continue;  // unscheduled earlier this tick
    }
    const HDCallbackCode code = op.callback(op.user_data);
    auto lock = Lock();
    World& w = TheWorld();
    const auto it = Find(w, op.handle);
    if (it == w.operations.end()) continue;  // it unscheduled itself
    if (it->synchronous) {
      it->finished = true;
      Changed().notify_all();
    } else if (code == HD_CALLBACK_DONE) {
      End(w, it);
    }
  }
  OnTickingThread() = false;
  auto lock = Lock();
  EndTick(TheWorld());
}

extern "C" {

void hdStartScheduler(void) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdStartScheduler");
  if (w.started) return;
  w.started = true;
  w.stop_requested = false;
  w.force_output = true;  // starting the scheduler turns the motors on
  w.timed_ticks = 0;
  if (!w.manual_ticks) w.thread = std::thread(Serve);
}

// Joins the scheduler thread before it reports the scheduler stopped, so that a synchronous
// call woken by the stop never runs its callback alongside a last tick.
void hdStopScheduler(void) {
  std::thread serving;
  {
    auto lock = Lock();
    World& w = TheWorld();
    Record(w, "hdStopScheduler");
    if (OnTickingThread()) {  // the scheduler cannot wait for itself
      Raise(w, HD_INVALID_OPERATION);
      return;
    }
    if (!w.started) return;
    w.stop_requested = true;
    serving = std::move(w.thread);
  }
  if (serving.joinable()) serving.join();
  auto lock = Lock();
  World& w = TheWorld();
  w.started = false;
  w.latched_n = Vec3{};  // no servo loop, no force
  Changed().notify_all();
}

// PCI and parallel-port devices run at 500, 1000 or 2000 Hz; the fake accepts those.
void hdSetSchedulerRate(HDulong nRate) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdSetSchedulerRate");
  if (nRate != 500 && nRate != 1000 && nRate != 2000) {
    Raise(w, HD_INVALID_VALUE);
    return;
  }
  w.rate_hz = nRate;
}

HDSchedulerHandle hdScheduleAsynchronous(HDSchedulerCallback pCallback, void* pUserData,
                                         HDushort nPriority) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdScheduleAsynchronous");
  if (pCallback == nullptr) {
    Raise(w, HD_INVALID_VALUE);
    return 0;
  }
  if (w.operations.size() >= kMaxOperations) {
    Raise(w, HD_SCHEDULER_FULL);
    return 0;
  }
  return Submit(w, pCallback, pUserData, nPriority, false);
}

// Runs inline when no scheduler thread could run it (stopped, manual ticks) or when called from
// the scheduler itself; otherwise waits for the tick that runs it.
void hdScheduleSynchronous(HDSchedulerCallback pCallback, void* pUserData, HDushort nPriority) {
  auto lock = Lock();
  World& w = TheWorld();
  if (pCallback == nullptr) {
    Raise(w, HD_INVALID_VALUE);
    return;
  }
  if (!w.started || w.manual_ticks || OnTickingThread()) {
    lock.unlock();
    pCallback(pUserData);
    return;
  }
  const HDSchedulerHandle handle = Submit(w, pCallback, pUserData, nPriority, true);
  Changed().wait(lock, [&] { return Find(w, handle)->finished || !w.started; });
  const auto op = Find(w, handle);
  const bool ran = op->finished;
  w.operations.erase(op);
  if (!ran) {  // the scheduler stopped first
    lock.unlock();
    pCallback(pUserData);
  }
}

void hdUnschedule(HDSchedulerHandle hHandle) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdUnschedule");
  const auto op = Find(w, hHandle);
  if (op == w.operations.end() || op->synchronous) {
    Raise(w, HD_INVALID_OPERATION);
    return;
  }
  End(w, op);
}

// True while the operation is scheduled. HD_WAIT_INFINITE first waits for it to end, as long
// as a scheduler thread is running it.
HDboolean hdWaitForCompletion(HDSchedulerHandle hHandle, HDWaitCode param) {
  auto lock = Lock();
  World& w = TheWorld();
  auto active = [&] { return Find(w, hHandle) != w.operations.end(); };
  if (param == HD_WAIT_INFINITE && !OnTickingThread()) {
    Changed().wait(lock, [&] { return !active() || !w.started || w.manual_ticks; });
  }
  return active() ? HD_TRUE : HD_FALSE;
}

HDdouble hdGetSchedulerTimeStamp(void) {
  auto lock = Lock();
  const World& w = TheWorld();
  if (w.timed_ticks == 0) return 0.0;
  return std::chrono::duration<double>(Clock::now() - w.tick_start).count();
}

}  // extern "C"

}  // namespace cosmems::fake_hd
