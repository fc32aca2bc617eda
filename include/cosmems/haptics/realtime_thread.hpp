#pragma once

#include <string>

namespace cosmems {

/// What MakeThisThreadRealtime() obtained. Without CAP_SYS_NICE (or an rtprio limit) Linux
/// refuses SCHED_FIFO; the loop then runs on the normal scheduler and says so.
struct RealtimeSetup {
  bool fifo = false;           ///< the thread runs SCHED_FIFO at the requested priority
  bool memory_locked = false;  ///< mlockall succeeded: no page faults in the loop
  std::string note;            ///< why not, when either failed

  bool realtime() const { return fifo && memory_locked; }
};

/// Locks the process's memory and moves the calling thread to SCHED_FIFO at `priority` (80 by
/// default: above ordinary work, below the kernel's own per-CPU threads at 99).
RealtimeSetup MakeThisThreadRealtime(int priority = 80);

}  // namespace cosmems
