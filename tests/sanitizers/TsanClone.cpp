// ThreadSanitizer builds only (AWB_TSAN, linked into every executable that may start a
// process): QProcess starts its children through glibc's clone() (Qt's forkfd), and the clone()
// interceptor of the ThreadSanitizer runtime (LLVM 14, and 16 as well) aborts in the child
// before it can exec ("CHECK failed: tsan_rtl.cpp:234 ((!thr->slot)) != (0)", in ForkAfter).
// The runtime defines clone as a weak symbol; this strong one calls glibc's directly. The child
// runs only Qt's own, uninstrumented, code from the clone to its exec, so no race can hide
// there; the parent's threads stay checked.
#include <dlfcn.h>
#include <sys/types.h>

#include <cstdarg>

extern "C" int clone(int (*fn)(void *), void *stack, int flags, void *arg, ...)
{
    va_list ap;
    va_start(ap, arg);
    pid_t *parentTid = va_arg(ap, pid_t *);
    void *tls = va_arg(ap, void *);
    pid_t *childTid = va_arg(ap, pid_t *);
    va_end(ap);
    using Clone = int (*)(int (*)(void *), void *, int, void *, ...);
    static const auto glibcClone = reinterpret_cast<Clone>(dlsym(RTLD_NEXT, "clone"));
    return glibcClone(fn, stack, flags, arg, parentTid, tls, childTid);
}
