#pragma once

#include <array>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "HD/hd.h"
#include "HD/hd_fake.h"

namespace cosmems::fake_hd {

using Vec3 = std::array<double, 3>;
using Clock = std::chrono::steady_clock;

/// The only device handle the fake hands out (one device, as the SDK numbers its first).
constexpr HHD kDevice = 0;
/// Scheduler handles start above 2^32, so storing one in 32 bits loses it.
constexpr HDSchedulerHandle kFirstOperation = 0x100000000UL;
constexpr std::size_t kMaxOperations = 32;  // beyond: HD_SCHEDULER_FULL
constexpr std::size_t kMaxErrors = 32;      // the stack drops its oldest entry beyond
constexpr std::size_t kForceLogTicks = 65536;

/// One scheduled callback.
struct Operation {
  HDSchedulerHandle handle = 0;
  HDSchedulerCallback callback = nullptr;
  void* user_data = nullptr;
  HDushort priority = 0;
  std::uint64_t order = 0;  // submission order: equal priorities run first come, first served
  bool synchronous = false;
  bool finished = false;  // synchronous: has run, its caller may return
};

/// The stylus as sampled at one tick, in the API's units (mm, mm/s).
struct Sample {
  Vec3 position_mm{};
  Vec3 velocity_mm_s{};
  HDint buttons = 0;
};

/// The default specs (the Omni's).
HDFakeSpecs DefaultSpecs();

struct InjectedError {
  HDerror code = HD_SUCCESS;
  HDulong tick = 0;
};

/// The whole simulated world: device, scheduler, errors and the hooks' settings. Every field is
/// guarded by Lock(); callbacks run without it.
struct World {
  World() : specs(DefaultSpecs()) {}

  // Set by hooks.
  HDFakeSpecs specs;
  HDFakeMotion motion = nullptr;
  void* motion_user = nullptr;
  Vec3 fixed_position_mm{};
  HDint buttons = 0;
  HDenum calibration = HD_CALIBRATION_OK;
  std::vector<InjectedError> injected;
  HDerror init_failure = HD_SUCCESS;
  int init_failures_left = 0;
  bool device_present = true;
  bool manual_ticks = false;

  // Device.
  bool initialized = false;
  HHD current = HD_INVALID_HANDLE;
  bool force_output = false;
  bool max_force_clamping = false;
  bool force_ramping = false;
  bool software_force_limit = true;
  bool one_frame_limit = true;
  Sample now, last;
  bool sampled = false;  // `now` holds a tick's sample (velocity needs two)
  int frame_depth = 0;
  bool frame_done_this_tick = false;
  Vec3 commanded_n{};  // set in the open frame
  Vec3 latched_n{};    // output by the motors
  Vec3 last_latched_n{};

  // Scheduler.
  bool started = false;
  bool stop_requested = false;
  HDulong rate_hz = 1000;
  std::uint64_t ticks = 0;  // ticks run; the running one is ticks - 1
  Clock::time_point tick_start{}, previous_tick_start{}, first_tick_start{};
  std::uint64_t timed_ticks = 0;  // ticks since hdStartScheduler
  std::vector<Operation> operations;
  HDSchedulerHandle next_handle = kFirstOperation;
  std::uint64_t next_order = 0;
  std::thread thread;

  // Errors and records.
  std::vector<HDErrorInfo> errors;
  std::vector<Vec3> force_log;
  std::vector<const char*> calls;
};

/// The world's lock and the world itself (valid only while the lock is held).
std::unique_lock<std::mutex> Lock();
World& TheWorld();
/// Signalled when an operation finishes or ends, or the scheduler stops.
std::condition_variable& Changed();
/// True on the thread running a tick (the scheduler thread, or hdFakeStep's caller).
bool& OnTickingThread();

/// Pushes an error on the stack, attributed to the current device.
void Raise(World& w, HDerror code);
void Record(World& w, const char* call);
/// True, and an HD_INVALID_OPERATION raised, when no device is initialised.
bool NoDevice(World& w);
/// Samples the stylus for the tick about to run (or at initialisation).
void SampleStylus(World& w, double time_s);
/// What the injected errors of a tick did to the link.
enum class Injected {
  kNone,
  kForceError,  ///< the device refused this tick's force: it outputs zero
  kLinkError,   ///< the link failed: the command never arrived, the motors keep the last force
};
/// Raises the errors injected for the running tick and says what they did.
Injected RaiseInjected(World& w);

/// Runs one scheduler tick on the calling thread. Takes the lock itself.
void RunTick();

}  // namespace cosmems::fake_hd
