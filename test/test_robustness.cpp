// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Determinism (bit-exact across runs, thread counts and replays), concurrency of separate
// instances, and degenerate segment geometry given to processSegments().

#include "test_precomp.hpp"
#include "opencv2/lsd_advance/evaluation.hpp"

#include <chrono>
#include <cstring>
#include <thread>

namespace opencv_test { namespace {

const int kAllModes[] = { LSDAdvance::LENGTH_FILTER_NONE, LSDAdvance::LENGTH_FILTER_ADAPTIVE,
                          LSDAdvance::LENGTH_FILTER_INTERFRAME, LSDAdvance::LENGTH_FILTER_INTERFRAME_CONTINUOUS,
                          LSDAdvance::LENGTH_FILTER_COUNT_TRACKING };

// Frames 0, 5, 10, ... of a real sequence, half size.
std::vector<Mat> realFrames(const char* set, int count)
{
    const std::vector<String> paths = loadSequence(dataFolder(set)).imagePaths;
    std::vector<Mat> frames;
    for (int k = 0; k < count && k * 5 < (int)paths.size(); k++)
    {
        const Mat img = imread(paths[k * 5], IMREAD_GRAYSCALE);
        CV_Assert(!img.empty());
        Mat half;
        resize(img, half, Size(), 0.5, 0.5, INTER_AREA);
        frames.push_back(half);
    }
    return frames;
}

// Real frames of a moving and of a still camera, then synthetic ones, so that the kept
// counts change and every inter-frame rule acts.
std::vector<Mat> mixedFrames()
{
    std::vector<Mat> frames = realFrames("kitti_seq1", 5);
    const std::vector<Mat> still = realFrames("euroc_v101_static", 3);
    frames.insert(frames.end(), still.begin(), still.end());
    Mat noise(120, 160, CV_8UC1);
    RNG(7).fill(noise, RNG::UNIFORM, 0, 256);
    frames.push_back(noise);
    frames.push_back(Mat(120, 160, CV_8UC1, Scalar(0)));
    frames.push_back(frames[0]);
    return frames;
}

// Everything a frame returns: the lines and the statistics that are not times.
struct FrameOutput
{
    std::vector<Vec4f> lines;
    double alpha, minLength;
    int base, filtered, merged, groups;
};

bool bitIdentical(const FrameOutput& a, const FrameOutput& b)
{
    return a.lines.size() == b.lines.size() &&
           (a.lines.empty() || std::memcmp(a.lines.data(), b.lines.data(), a.lines.size() * sizeof(Vec4f)) == 0) &&
           std::memcmp(&a.alpha, &b.alpha, sizeof(double)) == 0 &&
           std::memcmp(&a.minLength, &b.minLength, sizeof(double)) == 0 && a.base == b.base &&
           a.filtered == b.filtered && a.merged == b.merged && a.groups == b.groups;
}

FrameOutput outputOf(const LSDAdvance& detector, const std::vector<Vec4f>& lines)
{
    const LSDAdvanceStats s = detector.getLastStats();
    FrameOutput out = { lines, s.alpha, s.minLength, s.baseSegments, s.filteredSegments, s.mergedSegments, s.mergeGroups };
    return out;
}

// Runs the frames through the detector: detect() on each, and processSegments() on the lines
// of the previous frame in between, so that both entry points take part in the sequence.
std::vector<FrameOutput> runSequence(LSDAdvance& detector, const std::vector<Mat>& frames)
{
    std::vector<FrameOutput> outputs;
    std::vector<Vec4f> lines;
    for (const Mat& frame : frames)
    {
        if (!lines.empty())
        {
            const std::vector<Vec4f> previous = lines;
            detector.processSegments(previous, lines);
            outputs.push_back(outputOf(detector, lines));
        }
        detector.detect(frame, lines);
        outputs.push_back(outputOf(detector, lines));
    }
    return outputs;
}

void expectBitIdentical(const std::vector<FrameOutput>& expected, const std::vector<FrameOutput>& actual)
{
    ASSERT_EQ(expected.size(), actual.size());
    for (size_t k = 0; k < expected.size(); k++)
        EXPECT_TRUE(bitIdentical(expected[k], actual[k])) << "call " << k;
}

// The sequence must exercise the mode: some frame of an inter-frame mode uses alpha != 1.
void expectModeActs(int mode, const std::vector<FrameOutput>& outputs)
{
    if (mode == LSDAdvance::LENGTH_FILTER_NONE || mode == LSDAdvance::LENGTH_FILTER_ADAPTIVE)
        return;
    int changed = 0;
    for (const FrameOutput& o : outputs)
        changed += o.alpha != 1.0;
    EXPECT_GT(changed, 0) << "mode " << mode;
}

TEST(LSDAdvance_Determinism, two_runs_are_bit_identical_for_every_mode)
{
    const std::vector<Mat> frames = mixedFrames();
    for (int mode : kAllModes)
    {
        SCOPED_TRACE(mode);
        const std::vector<FrameOutput> first = runSequence(*createLSDAdvanceWith(mode), frames);
        expectModeActs(mode, first);
        expectBitIdentical(first, runSequence(*createLSDAdvanceWith(mode), frames));
    }
}

// Thread counts set explicitly, so that the threads differ on any runner (OpenCV's default, all
// cores, is one thread on a one-core runner).
TEST(LSDAdvance_Determinism, every_thread_count_is_bit_identical_for_every_mode)
{
    expectParallelForRunsTasksAtOnce();
    const std::vector<Mat> frames = mixedFrames();
    for (int mode : kAllModes)
    {
        SCOPED_TRACE(mode);
        std::vector<FrameOutput> single;
        for (int n : threadCountsToCompare())
        {
            SCOPED_TRACE(cv::format("%d threads", n));
            const ThreadCount threads(n);
            const std::vector<FrameOutput> outputs = runSequence(*createLSDAdvanceWith(mode), frames);
            if (n == 1)
                single = outputs;
            else
                expectBitIdentical(single, outputs);
        }
    }
}

TEST(LSDAdvance_Determinism, replay_after_reset_is_bit_identical_for_every_mode)
{
    const std::vector<Mat> frames = mixedFrames();
    for (int mode : kAllModes)
    {
        SCOPED_TRACE(mode);
        Ptr<LSDAdvance> detector = createLSDAdvanceWith(mode);
        const std::vector<FrameOutput> first = runSequence(*detector, frames);
        detector->reset();
        expectBitIdentical(first, runSequence(*detector, frames));
    }
}

TEST(LSDAdvance_Determinism, replay_without_reset_differs_for_interframe_modes)
{
    // The counter-check of the replay test: without reset() the replay continues the sequence,
    // so its first frames use the previous frames' counts.
    const std::vector<Mat> frames = mixedFrames();
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_COUNT_TRACKING);
    const std::vector<FrameOutput> first = runSequence(*detector, frames);
    const std::vector<FrameOutput> second = runSequence(*detector, frames);
    EXPECT_NE(first[0].alpha, second[0].alpha);
}

TEST(LSDAdvance_Concurrency, separate_instances_on_separate_threads_match_serial_runs)
{
    const std::vector<Mat> frames = mixedFrames();
    const int tasks = 5;
    // Task t runs mode kAllModes[t] on the frames rotated by t.
    auto framesOf = [&](int t) {
        std::vector<Mat> rotated(frames.begin() + t, frames.end());
        rotated.insert(rotated.end(), frames.begin(), frames.begin() + t);
        return rotated;
    };
    std::vector<std::vector<FrameOutput> > serial(tasks), parallel(tasks);
    for (int t = 0; t < tasks; t++)
        serial[t] = runSequence(*createLSDAdvanceWith(kAllModes[t]), framesOf(t));

    std::vector<std::thread> threads;
    std::vector<std::string> errors(tasks);
    for (int t = 0; t < tasks; t++)
        threads.emplace_back([&, t] {
            try
            {
                const std::vector<Mat> mine = framesOf(t);
                Ptr<LSDAdvance> detector = createLSDAdvanceWith(kAllModes[t]);
                // Three passes, so that the threads overlap in time.
                for (int pass = 0; pass < 3; pass++)
                {
                    detector->reset();
                    parallel[t] = runSequence(*detector, mine);
                }
            }
            catch (const std::exception& e)
            {
                errors[t] = e.what();
            }
        });
    for (std::thread& th : threads)
        th.join();
    for (int t = 0; t < tasks; t++)
    {
        SCOPED_TRACE(t);
        EXPECT_EQ("", errors[t]);
        expectBitIdentical(serial[t], parallel[t]);
    }
}

//--- degenerate geometry through processSegments()

// Axis-aligned bounding box of the segments' endpoints.
Rect2f boundsOf(const std::vector<Vec4f>& segments)
{
    float x0 = FLT_MAX, y0 = FLT_MAX, x1 = -FLT_MAX, y1 = -FLT_MAX;
    for (const Vec4f& s : segments)
    {
        x0 = std::min(x0, std::min(s[0], s[2]));
        x1 = std::max(x1, std::max(s[0], s[2]));
        y0 = std::min(y0, std::min(s[1], s[3]));
        y1 = std::max(y1, std::max(s[1], s[3]));
    }
    return Rect2f(x0, y0, x1 - x0, y1 - y0);
}

// The output is finite, no larger than the input, and inside the input's bounding box grown by
// `margin` (fused segments span the projections of their pieces on a line within the
// perpendicular gate of each piece).
void expectSaneOutput(const std::vector<Vec4f>& input, const std::vector<Vec4f>& output, float margin)
{
    ASSERT_LE(output.size(), input.size());
    const Rect2f box = boundsOf(input);
    for (const Vec4f& l : output)
        for (int i = 0; i < 4; i++)
        {
            ASSERT_TRUE(std::isfinite(l[i])) << l;
            const float lo = i % 2 == 0 ? box.x : box.y;
            const float hi = i % 2 == 0 ? box.x + box.width : box.y + box.height;
            ASSERT_GE(l[i], lo - margin) << l;
            ASSERT_LE(l[i], hi + margin) << l;
        }
}

// Runs processSegments with each merge strategy and stage order; returns the outputs.
std::vector<std::vector<Vec4f> > processWithEveryStrategy(const std::vector<Vec4f>& segments,
                                                          double mergeThreshold = LSDAdvance::Params().mergeThreshold)
{
    std::vector<std::vector<Vec4f> > outputs;
    for (int strategy : { LSDAdvance::MERGE_NONE, LSDAdvance::MERGE_BASELINES, LSDAdvance::MERGE_LONGEST_FIRST })
        for (int order : { LSDAdvance::FILTER_THEN_MERGE, LSDAdvance::MERGE_THEN_FILTER })
        {
            Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_ADAPTIVE, LSDAdvance::Params().endpointDistance, mergeThreshold);
            detector->setMergeStrategy(strategy);
            detector->setStageOrder(order);
            std::vector<Vec4f> lines;
            detector->processSegments(segments, lines);
            expectSaneOutput(segments, lines, (float)detector->getMaxPerpendicularOffset());
            outputs.push_back(lines);
        }
    return outputs;
}

double secondsSince(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(LSDAdvance_DegenerateGeometry, zero_length_segments)
{
    // Points scattered, 2000 of them at one spot (one grid cell), among real segments.
    std::vector<Vec4f> segments;
    RNG rng(11);
    for (int i = 0; i < 500; i++)
    {
        const float x = rng.uniform(0.f, 640.f), y = rng.uniform(0.f, 480.f);
        segments.push_back(Vec4f(x, y, x, y));
    }
    for (int i = 0; i < 2000; i++)
        segments.push_back(Vec4f(100, 100, 100, 100));
    for (int i = 0; i < 50; i++)
        segments.push_back(segmentAt(rng.uniform(0, 600), rng.uniform(0, 440), rng.uniform(0, 360), 30));
    const auto t0 = std::chrono::steady_clock::now();
    processWithEveryStrategy(segments);
    // With a threshold that lets points fuse (direction 0, proximity 1, length 1 score 0.55).
    processWithEveryStrategy(segments, 0.5);
    std::cout << format("2550 segments, 2000 zero-length at one point: %.2f s for 12 runs", secondsSince(t0))
              << std::endl;
    // Without the length filter (which drops points), the 2000 coincident points fuse into one.
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_NONE, LSDAdvance::Params().endpointDistance, 0.5);
    std::vector<Vec4f> lines;
    detector->processSegments(segments, lines);
    int atTheSpot = 0;
    for (const Vec4f& l : lines)
        atTheSpot += l == Vec4f(100, 100, 100, 100);
    EXPECT_EQ(1, atTheSpot);
}

TEST(LSDAdvance_DegenerateGeometry, sub_pixel_segments)
{
    std::vector<Vec4f> segments;
    RNG rng(12);
    for (int i = 0; i < 3000; i++)
        segments.push_back(segmentAt(rng.uniform(0., 200.), rng.uniform(0., 200.), rng.uniform(0., 360.),
                                     rng.uniform(1e-4, 0.9)));
    processWithEveryStrategy(segments);
}

TEST(LSDAdvance_DegenerateGeometry, identical_duplicates_fuse_into_one_with_longest_first)
{
    const Vec4f s(10.25f, 20.5f, 210.75f, 95.125f);
    const std::vector<Vec4f> segments(1000, s);
    const std::vector<std::vector<Vec4f> > outputs = processWithEveryStrategy(segments);
    // Order: (NONE, BASELINES, LONGEST_FIRST) x (FILTER_THEN_MERGE, MERGE_THEN_FILTER).
    EXPECT_EQ(1000u, outputs[0].size());
    EXPECT_EQ(1000u, outputs[2].size()) << "baselines never fuse with each other";
    for (int k : { 4, 5 })
    {
        ASSERT_EQ(1u, outputs[k].size());
        for (int i = 0; i < 4; i++)
            EXPECT_NEAR(s[i], outputs[k][0][i], 1e-3);
    }
}

TEST(LSDAdvance_DegenerateGeometry, segments_on_the_image_border_stay_on_it)
{
    // Collinear pieces along the four borders of a 640 x 480 image, gaps of 2 px.
    std::vector<Vec4f> segments;
    for (float x = 0; x + 20 <= 639; x += 22)
    {
        segments.push_back(Vec4f(x, 0, x + 20, 0));
        segments.push_back(Vec4f(x + 20, 479, x, 479));
    }
    for (float y = 0; y + 20 <= 479; y += 22)
    {
        segments.push_back(Vec4f(0, y + 20, 0, y));
        segments.push_back(Vec4f(639, y, 639, y + 20));
    }
    const std::vector<std::vector<Vec4f> > outputs = processWithEveryStrategy(segments);
    for (const std::vector<Vec4f>& lines : outputs)
        for (const Vec4f& l : lines)
        {
            EXPECT_TRUE((l[0] == l[2] && (l[0] == 0 || l[0] == 639)) || (l[1] == l[3] && (l[1] == 0 || l[1] == 479))) << l;
            for (int i = 0; i < 4; i++)
                EXPECT_GE(l[i], 0.f) << l;
            EXPECT_LE(std::max(l[0], l[2]), 639.f) << l;
            EXPECT_LE(std::max(l[1], l[3]), 479.f) << l;
        }
    // Each border comes out as one segment.
    EXPECT_EQ(4u, outputs.back().size());
}

TEST(LSDAdvance_DegenerateGeometry, border_frame_image_gives_lines_inside_the_image)
{
    Mat img(240, 320, CV_8UC1, Scalar(255));
    rectangle(img, Rect(0, 0, 320, 240), Scalar(0), 1);
    std::vector<Vec4f> lines;
    createLSDAdvance()->detect(img, lines);
    ASSERT_FALSE(lines.empty());
    for (const Vec4f& l : lines)
        for (int i = 0; i < 4; i++)
        {
            ASSERT_TRUE(std::isfinite(l[i]));
            EXPECT_GE(l[i], -1.5f) << l;
            EXPECT_LE(l[i], (i % 2 == 0 ? 319 : 239) + 1.5f) << l;
        }
}

TEST(LSDAdvance_DegenerateGeometry, all_segments_in_one_angle_bin)
{
    // 3000 horizontal segments of random length and position: one bin, and one big group
    // through their endpoints.
    std::vector<Vec4f> segments;
    RNG rng(13);
    for (int i = 0; i < 3000; i++)
    {
        const float x = rng.uniform(0.f, 600.f), y = rng.uniform(0.f, 480.f);
        segments.push_back(Vec4f(x, y, x + rng.uniform(1.f, 40.f), y));
    }
    for (const Vec4f& s : segments)
        ASSERT_EQ(0, lsda::angleBin(s, 10.0));
    const auto t0 = std::chrono::steady_clock::now();
    processWithEveryStrategy(segments);
    std::cout << format("3000 segments in one angle bin: %.2f s for 6 runs", secondsSince(t0)) << std::endl;
}

// n collinear fragments of `piece` px separated by 1 px gaps along y = 100.25, the first one
// `firstLength` px long: one group of n connected fragments.
std::vector<Vec4f> fragmentedLine(int n, float piece, float firstLength)
{
    std::vector<Vec4f> segments;
    float x = 0;
    for (int i = 0; i < n; i++)
    {
        const float length = i == 0 ? firstLength : piece;
        segments.push_back(Vec4f(x, 100.25f, x + length, 100.25f));
        x += length + 1;
    }
    return segments;
}

TEST(LSDAdvance_DegenerateGeometry, one_huge_group_of_connected_fragments_becomes_one_segment)
{
    const int n = 3000;
    const std::vector<Vec4f> segments = fragmentedLine(n, 3, 3);
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, lsda::GroupingParams(), groups);
    ASSERT_EQ(1, groups.count());

    for (int strategy : { LSDAdvance::MERGE_LONGEST_FIRST, LSDAdvance::MERGE_BASELINES })
    {
        SCOPED_TRACE(strategy);
        // With baselines, a long first piece is the only baseline and grows piece by piece.
        const std::vector<Vec4f> input = strategy == LSDAdvance::MERGE_BASELINES ? fragmentedLine(n, 3, 50) : segments;
        Ptr<LSDAdvance> detector = createLSDAdvance();
        detector->setMergeStrategy(strategy);
        std::vector<Vec4f> lines;
        const auto t0 = std::chrono::steady_clock::now();
        detector->processSegments(input, lines);
        std::cout << format("one group of %d fragments, strategy %d: %.2f s", n, strategy, secondsSince(t0))
                  << std::endl;
        expectSaneOutput(input, lines, 1e-3f);
        ASSERT_EQ(1u, lines.size());
        EXPECT_NEAR(0, std::min(lines[0][0], lines[0][2]), 1e-2);
        EXPECT_NEAR(input.back()[2], std::max(lines[0][0], lines[0][2]), 1e-2);
        EXPECT_NEAR(100.25, lines[0][1], 1e-3);
        EXPECT_NEAR(100.25, lines[0][3], 1e-3);
    }
}

TEST(LSDAdvance_DegenerateGeometry, segments_at_the_coordinate_bounds)
{
    // processSegments accepts coordinates of magnitude below 1e7 px: the grouping grid at its
    // finest cell (0.1 px) must not overflow, and fusion must stay finite.
    const float m = 9999990.f;
    std::vector<Vec4f> segments = {
        Vec4f(-m, -m, -m + 50, -m), Vec4f(-m + 52, -m, -m + 100, -m),
        Vec4f(m, m, m - 64, m), Vec4f(m - 66, m, m - 128, m),
        Vec4f(-m, m, m, -m), Vec4f(0, 0, m, m),
    };
    for (double distance : { 0.1, 10.0, 200.0 })
    {
        SCOPED_TRACE(distance);
        Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_ADAPTIVE, distance);
        std::vector<Vec4f> lines;
        ASSERT_NO_THROW(detector->processSegments(segments, lines));
        expectSaneOutput(segments, lines, 2.0f);
    }
}

}} // namespace
