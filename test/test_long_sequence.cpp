// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// A long run through one object, as on a robot: 20,000 frames of real and synthetic images
// and recorded segment sets, every length filter mode in turn. Resident memory must stay flat
// after warm-up, no output may be NaN/inf, and alpha must stay in its mode's range.
// Not run under AddressSanitizer (scripts/sanitizers.sh): its quarantine holds freed memory,
// so resident memory grows by design there.

#include "test_precomp.hpp"
#include "opencv2/lsd_advance/evaluation.hpp"

#include <fstream>

namespace opencv_test { namespace {

// Resident set size of this process in kB (Linux); -1 when unknown.
long residentKb()
{
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key)
    {
        if (key == "VmRSS:")
        {
            long kb = -1;
            status >> kb;
            return kb;
        }
        status.ignore(1 << 12, '\n');
    }
    return -1;
}

// Every `step`-th frame of a real sequence downscaled to 160 px wide, and the base segments of
// the frame at 400 px wide (what a caller of processSegments() would record).
void loadRealFrames(const char* set, int step, std::vector<Mat>& images, std::vector<std::vector<Vec4f> >& segmentSets)
{
    Ptr<LineSegmentDetector> lsd = createLineSegmentDetector(LSD_REFINE_NONE, 1.0);
    const std::vector<String> paths = loadSequence(dataFolder(set)).imagePaths;
    for (size_t k = 0; k < paths.size(); k += step)
    {
        const Mat img = imread(paths[k], IMREAD_GRAYSCALE);
        CV_Assert(!img.empty());
        Mat small, medium;
        resize(img, small, Size(), 160.0 / img.cols, 160.0 / img.cols, INTER_AREA);
        resize(img, medium, Size(), 400.0 / img.cols, 400.0 / img.cols, INTER_AREA);
        images.push_back(small);
        std::vector<Vec4f> segments;
        lsd->detect(medium, segments);
        segmentSets.push_back(segments);
    }
}

std::vector<Mat> syntheticFrames()
{
    const Size size(160, 120);
    Mat noise(size, CV_8UC1), lines(size, CV_8UC1, Scalar(30)), bright(size, CV_8UC3, Scalar::all(255));
    RNG rng(2026);
    rng.fill(noise, RNG::UNIFORM, 0, 256);
    for (int i = 0; i < 12; i++)
        line(lines, Point(rng.uniform(0, 160), rng.uniform(0, 120)), Point(rng.uniform(0, 160), rng.uniform(0, 120)),
             Scalar(rng.uniform(120, 256)), rng.uniform(1, 4));
    return { Mat(size, CV_8UC1, Scalar(0)), noise, lines, bright, Mat(1, 1, CV_8UC1, Scalar(9)) };
}

// The documented range of alpha per mode (LSDAdvance::LengthFilterMode).
bool alphaInRange(int mode, double alpha)
{
    if (mode == LSDAdvance::LENGTH_FILTER_NONE || mode == LSDAdvance::LENGTH_FILTER_ADAPTIVE)
        return alpha == 1.0;
    return alpha >= 0.8 && alpha <= 1.2;
}

TEST(LSDAdvance_LongSequence, twenty_thousand_frames_keep_memory_flat_and_outputs_finite)
{
    std::vector<Mat> images;
    std::vector<std::vector<Vec4f> > segmentSets;
    loadRealFrames("kitti_seq1", 2, images, segmentSets);
    loadRealFrames("euroc_v101_static", 4, images, segmentSets);
    ASSERT_EQ(50u, images.size());
    const std::vector<Mat> synthetic = syntheticFrames();
    segmentSets.push_back(std::vector<Vec4f>());

    const int modes[] = { LSDAdvance::LENGTH_FILTER_NONE, LSDAdvance::LENGTH_FILTER_ADAPTIVE,
                          LSDAdvance::LENGTH_FILTER_INTERFRAME, LSDAdvance::LENGTH_FILTER_INTERFRAME_CONTINUOUS,
                          LSDAdvance::LENGTH_FILTER_COUNT_TRACKING };
    const int frames = 20000, framesPerMode = frames / 5, warmUp = 2000;
    // Memory may move by allocator noise, but not grow with the frames: 4 MB over 18,000 frames
    // is a leak of over 230 bytes per frame, less than one lost segment array.
    const long toleranceKb = 4096;

    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<Vec4f> lines;
    long warmKb = -1, peakKb = 0;
    int detectCalls = 0, segmentCalls = 0, alphaNotOne[5] = { 0 };
    double alphaMin = DBL_MAX, alphaMax = -DBL_MAX;
    const int64 start = getTickCount();
    for (int k = 0; k < frames; k++)
    {
        const int m = k / framesPerMode;
        if (k % framesPerMode == 0)
            detector->setLengthFilterMode(modes[m]);
        // Forwards through the real frames: a synthetic image every 10th call, a real image every
        // 5th, and recorded segment sets in between (cheaper: the run must fit in CI).
        Size bounds;
        if (k % 10 == 9)
        {
            const Mat& img = synthetic[(k / 10) % synthetic.size()];
            detector->detect(img, lines);
            bounds = img.size();
            detectCalls++;
        }
        else if (k % 5 != 0)
        {
            detector->processSegments(segmentSets[(k / 5) % segmentSets.size()], lines);
            bounds = Size(400, 256);  // the largest recorded frame
            segmentCalls++;
        }
        else
        {
            const Mat& img = images[(k / 5) % images.size()];
            detector->detect(img, lines);
            bounds = img.size();
            detectCalls++;
        }

        const LSDAdvanceStats s = detector->getLastStats();
        ASSERT_TRUE(alphaInRange(modes[m], s.alpha)) << "frame " << k << " mode " << modes[m] << " alpha " << s.alpha;
        ASSERT_TRUE(std::isfinite(s.minLength) && s.minLength >= 0) << "frame " << k;
        ASSERT_LE(s.outputSegments, s.baseSegments) << "frame " << k;
        ASSERT_EQ((int)lines.size(), s.outputSegments) << "frame " << k;
        for (const Vec4f& l : lines)
            for (int i = 0; i < 4; i++)
                ASSERT_TRUE(std::isfinite(l[i]) && l[i] > -10.f &&
                            l[i] < (i % 2 == 0 ? bounds.width : bounds.height) + 10.f)
                    << "frame " << k << ": " << l;
        alphaNotOne[m] += s.alpha != 1.0;
        alphaMin = std::min(alphaMin, s.alpha);
        alphaMax = std::max(alphaMax, s.alpha);

        if (k + 1 == warmUp)
            warmKb = residentKb();
        if (k + 1 >= warmUp)
            peakKb = std::max(peakKb, residentKb());
    }
    const double seconds = (double)(getTickCount() - start) / getTickFrequency();
    const long endKb = residentKb();
    std::cout << format("%d frames (%d detect, %d processSegments) in %.1f s; resident memory after %d frames "
                        "%ld kB, peak after warm-up %ld kB, at the end %ld kB (growth %ld kB); alpha in "
                        "[%.3f, %.3f]; frames with alpha != 1 per mode: %d %d %d %d %d",
                        frames, detectCalls, segmentCalls, seconds, warmUp, warmKb, peakKb, endKb, endKb - warmKb,
                        alphaMin, alphaMax, alphaNotOne[0], alphaNotOne[1], alphaNotOne[2], alphaNotOne[3],
                        alphaNotOne[4])
              << std::endl;
    ASSERT_GT(warmKb, 0) << "no /proc/self/status";
    EXPECT_LE(endKb - warmKb, toleranceKb);
    EXPECT_LE(peakKb - warmKb, toleranceKb);
    // Every inter-frame mode acted: the range checks above were not vacuous.
    for (int m = 2; m < 5; m++)
        EXPECT_GT(alphaNotOne[m], 0) << "mode " << modes[m];
}

}} // namespace
