#pragma once

namespace abalike
{

/// Lowers the calling thread's CPU priority as far as it goes: SCHED_IDLE (it runs only when no other thread of
/// the machine wants the CPU), else nice 19. Linux keeps both per thread. Returns false when neither was allowed.
bool lowerThisThreadsPriority();

} // namespace abalike
