// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Under ThreadSanitizer (scripts/sanitizers.sh) the tests run cv::parallel_for_ on std::threads
// compiled with the tests. OpenCV's own pool (TBB on Debian) is not instrumented: ThreadSanitizer
// would not see how its workers synchronise and would report the module's hand-over of data to
// them as races, or hide real ones behind suppressions wide enough to silence those reports.

#if defined(__SANITIZE_THREAD__)
#define LSDA_TEST_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define LSDA_TEST_TSAN 1
#endif
#endif

#ifdef LSDA_TEST_TSAN

#include "test_precomp.hpp"
#include "opencv2/core/parallel/parallel_backend.hpp"

#include <atomic>
#include <thread>

namespace opencv_test { namespace {

// Each parallel_for starts its threads, which take the tasks one by one, and joins them: no state
// is shared between loops, so loops from several threads at once (separate detectors) are safe.
class InstrumentedThreads CV_FINAL : public cv::parallel::ParallelForAPI
{
public:
    void parallel_for(int tasks, FN_parallel_for_body_cb_t body, void* data) CV_OVERRIDE
    {
        std::atomic<int> next(0);
        const auto work = [&](int index) {
            threadIndex() = index;
            for (int t = next++; t < tasks; t = next++)
                body(t, t + 1, data);
            threadIndex() = 0;
        };
        std::vector<std::thread> workers;
        for (int i = 1; i < std::min(threads.load(), tasks); i++)
            workers.emplace_back(work, i);
        work(0);
        for (std::thread& w : workers)
            w.join();
    }
    int getThreadNum() const CV_OVERRIDE { return threadIndex(); }
    int getNumThreads() const CV_OVERRIDE { return threads; }
    int setNumThreads(int n) CV_OVERRIDE
    {
        const int previous = threads;
        threads = n > 0 ? n : (int)std::max(1u, std::thread::hardware_concurrency());
        return previous;
    }
    const char* getName() const CV_OVERRIDE { return "std::thread (ThreadSanitizer)"; }

private:
    static int& threadIndex()
    {
        static thread_local int index = 0;
        return index;
    }
    std::atomic<int> threads{ (int)std::max(1u, std::thread::hardware_concurrency()) };
};

// Before main(), as setParallelForBackend requires: no other thread exists yet.
const bool installed = [] {
    cv::parallel::setParallelForBackend(std::make_shared<InstrumentedThreads>());
    return true;
}();

}} // namespace

#endif
