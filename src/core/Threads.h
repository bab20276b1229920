#pragma once
// Work spread over threads, shared by the raster engine (render/), the attractor algorithms
// (ifs/) and the benchmarks: plain std::thread, joined before returning.

#include <cmath>
#include <thread>
#include <vector>

namespace awb {

// Clears the upper halves of the AVX registers (vzeroupper) on a CPU that has them. Our code is
// compiled for x86-64's SSE; while those halves are dirty -- after code that used 256-bit AVX
// without clearing them, as something in a Qt program's start-up does -- every call into
// libm's AVX/FMA routines (sin, cos, atan2, pow: the flame variations) pays a state transition
// and SSE instructions a false dependency: 10 times the cost of a sinusoidal flame on this
// machine's Xeon (0.63 s against 0.06 s for a million samples; issue 45). The workers clear
// them before their loops.
inline void clearUpperVectorState()
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    static const bool avx = __builtin_cpu_supports("avx");
    if (avx)
        asm volatile("vzeroupper");
#endif
}

// Runs fn(t) for t = 0 .. threads - 1, t = 0 on the caller's thread, and joins the others.
template <typename Fn>
void onThreads(int threads, Fn fn)
{
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back([&fn, t] {
            clearUpperVectorState();
            fn(t);
        });
    clearUpperVectorState();
    fn(0);
    for (auto &th : pool)
        th.join();
}

// The tasks of a walk of the N-ary address tree of `depth` levels on `threads` threads: the
// words of its first levels, as few levels as give at least `perThread` words per thread (one
// empty word, the whole tree, for one thread).
inline std::vector<std::vector<int>> splitTasks(int N, int depth, int threads, int perThread)
{
    int split = 0;
    while (split < depth && std::pow(double(N), split) < double(perThread) * threads && threads > 1)
        ++split;
    std::vector<std::vector<int>> tasks(1);
    for (int s = 0; s < split; ++s) {
        std::vector<std::vector<int>> next;
        for (const auto &t : tasks)
            for (int i = 0; i < N; ++i) {
                auto u = t;
                u.push_back(i);
                next.push_back(u);
            }
        tasks.swap(next);
    }
    return tasks;
}

} // namespace awb
