#pragma once
// Work spread over threads, shared by the raster engine (render/), the attractor algorithms
// (ifs/) and the benchmarks: plain std::thread, joined before returning.

#include <cmath>
#include <thread>
#include <vector>

namespace awb {

// Runs fn(t) for t = 0 .. threads - 1, t = 0 on the caller's thread, and joins the others.
template <typename Fn>
void onThreads(int threads, Fn fn)
{
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(fn, t);
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
