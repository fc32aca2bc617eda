#include "cosmems/haptics/realtime_thread.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace cosmems {

RealtimeSetup MakeThisThreadRealtime(int priority) {
  RealtimeSetup setup;
  // Current and future pages stay resident: a page fault in the loop costs a deadline. Under a
  // finite memlock limit MCL_FUTURE would make later allocations fail once it is reached, so
  // memory is locked only when the limit cannot be hit.
  rlimit limit{};
  const bool unlimited = getrlimit(RLIMIT_MEMLOCK, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY;
  if (!unlimited && geteuid() != 0) {
    setup.note = "mlockall: skipped under a finite RLIMIT_MEMLOCK";
  } else {
    setup.memory_locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
    if (!setup.memory_locked) setup.note = std::string("mlockall: ") + std::strerror(errno);
  }
  sched_param param{};
  param.sched_priority = priority;
  const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
  setup.fifo = error == 0;
  if (!setup.fifo) {
    if (!setup.note.empty()) setup.note += "; ";
    setup.note += std::string("SCHED_FIFO: ") + std::strerror(error) +
                  " (needs CAP_SYS_NICE or an rtprio limit); running on the normal scheduler";
  }
  return setup;
}

}  // namespace cosmems
