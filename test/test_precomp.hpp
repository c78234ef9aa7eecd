// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_TEST_PRECOMP_HPP
#define OPENCV_LSD_ADVANCE_TEST_PRECOMP_HPP

#include "opencv2/ts.hpp"
#include "opencv2/lsd_advance.hpp"
#include "opencv2/imgproc.hpp"
#include "opencv2/imgcodecs.hpp"
#include "opencv2/core/utils/filesystem.hpp"
#include "../src/stages.hpp"
#include "opencv_lsd_oracle.hpp"

#include <chrono>
#include <functional>
#include <mutex>
#include <numeric>
#include <set>
#include <thread>

namespace opencv_test {
using namespace cv::ximgproc;
using namespace cv::ximgproc::line_evaluation;

//! The number of threads of cv::parallel_for_ for the scope of the object, the previous one restored
//! when it ends (a failed ASSERT included). The count is set whatever the cores: OpenCV's pool
//! runs that many threads on a one-core machine too, so that a test over several counts proves
//! its point on any runner (threadCountsToCompare).
class ThreadCount
{
public:
    explicit ThreadCount(int threads) : previous(getNumThreads()) { set(threads); }
    ~ThreadCount() { setNumThreads(previous); }
    void set(int threads)
    {
        setNumThreads(threads);
        CV_Assert(getNumThreads() == threads);
    }

private:
    ThreadCount(const ThreadCount&) = delete;
    ThreadCount& operator=(const ThreadCount&) = delete;
    const int previous;
};

//! The thread counts a test of "the same output for any number of threads" compares: 1 first (the
//! reference), then counts that split the tasks differently, more than the cores of any runner.
inline std::vector<int> threadCountsToCompare()
{
    return { 1, 2, 3, 8 };
}

//! Expects cv::parallel_for_ to run tasks on several threads at once with two threads: without
//! that, a comparison of thread counts splits the work differently but never races.
inline void expectParallelForRunsTasksAtOnce()
{
    const ThreadCount two(2);
    std::mutex lock;
    std::set<std::thread::id> threads;
    parallel_for_(Range(0, 64), [&](const Range& tasks) {
        for (int t = tasks.start; t < tasks.end; t++)
        {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            std::lock_guard<std::mutex> hold(lock);
            threads.insert(std::this_thread::get_id());
        }
    }, 64);
    EXPECT_GT(threads.size(), 1u) << "cv::parallel_for_ ran every task on one thread: this runner cannot show "
                                     "that the output does not depend on the threads";
}

//! Undirected angle of a segment in degrees, in [0, 180).
inline double undirectedAngle(const Vec4f& s)
{
    double a = std::atan2((double)s[3] - s[1], (double)s[2] - s[0]) * 180.0 / CV_PI;
    return a < 0 ? a + 180.0 : (a >= 180.0 ? a - 180.0 : a);
}

//! Segments sorted by their coordinates: the set of lines, to compare outputs whose order differs
//! (detect() orders by response, processSegments() by length).
inline std::vector<Vec4f> asSet(std::vector<Vec4f> lines)
{
    std::sort(lines.begin(), lines.end(), [](const Vec4f& a, const Vec4f& b) {
        return std::lexicographical_compare(a.val, a.val + 4, b.val, b.val + 4);
    });
    return lines;
}

//! The LSD algorithm itself in LSDParams: the image read as it is at scale 1, every pixel seeds a
//! region, no tiles, the direction updated after every pixel that joins (what OpenCV's LSD does
//! with the same refine and scale).
inline LSDAdvance::LSDParams exactLsdParams(int refine, double scale)
{
    LSDAdvance::LSDParams p;
    p.refine = refine;
    p.scale = scale;
    p.fullScaleSigma = 0;
    p.seedGradientRatio = 1.0;
    p.seedAlignedNeighbours = 0;
    p.tileHeight = 0;
    p.regionGrowth = LSDAdvance::GROWTH_PER_PIXEL;
    return p;
}

//! A segment of the given length starting at (x, y) with the given directed angle (degrees).
inline Vec4f segmentAt(double x, double y, double angleDeg, double length)
{
    const double a = angleDeg * CV_PI / 180.0;
    return Vec4f((float)x, (float)y, (float)(x + length * std::cos(a)), (float)(y + length * std::sin(a)));
}

//! A detector at the defaults but for the length filter mode, the endpoint distance and the merge
//! threshold.
inline Ptr<LSDAdvance> createLSDAdvanceWith(int lengthFilterMode,
                                            double endpointDistance = LSDAdvance::Params().endpointDistance,
                                            double mergeThreshold = LSDAdvance::Params().mergeThreshold)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    LSDAdvance::Params p = detector->getParams();
    p.lengthFilterMode = lengthFilterMode;
    p.endpointDistance = endpointDistance;
    p.mergeThreshold = mergeThreshold;
    detector->setParams(p);
    return detector;
}

//! OpenCV's LSD with the LSD parameters of a detector: its stage 0.
inline Ptr<LineSegmentDetector> baseLsdOf(const LSDAdvance& detector)
{
    const LSDAdvance::LSDParams p = detector.getLSDParams();
    return createLineSegmentDetector(p.refine, p.scale, p.sigmaScale, p.quant, p.angleTolerance, p.logEps,
                                     p.densityThreshold, p.numBins);
}

//! Folder `set` of the evaluation data (LSD_ADVANCE_DATA_DIR). When it is missing the test is
//! skipped, except under CI=true, where it fails.
inline std::string dataFolder(const char* set)
{
    const char* root = getenv("LSD_ADVANCE_DATA_DIR");
    const char* ci = getenv("CI");
    const std::string folder = root ? utils::fs::join(root, set) : std::string();
    if (folder.empty() || !utils::fs::isDirectory(folder))
    {
        if (ci && std::string(ci) == "true")
            CV_Error_(Error::StsError, ("CI=true and the evaluation data %s is not in LSD_ADVANCE_DATA_DIR ('%s'; "
                                        "doc/data.md)", set, root ? root : ""));
        throw SkipTestException(std::string("needs the evaluation data ") + set +
                                ": LSD_ADVANCE_DATA_DIR is not set or does not hold it (doc/data.md)");
    }
    return folder;
}

} // namespace opencv_test

#endif
