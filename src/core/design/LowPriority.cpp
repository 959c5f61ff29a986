#include "design/LowPriority.hpp"

#if defined(__linux__)
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace abalike
{

bool lowerThisThreadsPriority()
{
#if defined(__linux__)
    sched_param param{};
    param.sched_priority = 0;
    if (sched_setscheduler(0, SCHED_IDLE, &param) == 0) // pid 0: the calling thread
        return true;
    return setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19) == 0;
#else
    return false;
#endif
}

} // namespace abalike
