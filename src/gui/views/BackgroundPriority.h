#pragma once
// The analyses (Hausdorff series, regularity bounds, charts) run on threads of their own beside
// the pictures' workers, often started when a gesture ends, just when the view builds its full
// picture. On two cores they took the CPU from it: the last picture of a 3D drag came later than
// 300 ms after the release. Their threads call lowerThisThreadPriority() first: nice 10 (on Linux
// a thread's own attribute), so that the scheduler gives the pictures the cores when both want
// them and the analyses everything else. (QThread::LowPriority does nothing on Linux: the
// default policy has a single priority.)

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace awb {

inline void lowerThisThreadPriority()
{
#ifdef SYS_gettid
    (void)setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), 10);
#endif
}

} // namespace awb
