// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// computeLineResponses: length times squared contrast, polarity, ranking by evidence rather than
// span; and stage 1's strong segments (setKeepStrongSegments).

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// 300 x 200: bright (200) left of x = 150, dark (50) right of it, a sharp vertical step.
Mat stepImage()
{
    Mat img(200, 300, CV_8UC1, Scalar(50));
    img(Rect(0, 0, 150, 200)).setTo(200);
    return img;
}

std::vector<float> responsesOf(const Mat& img, const std::vector<Vec4f>& lines)
{
    std::vector<float> r;
    computeLineResponses(img, lines, r);
    return r;
}

TEST(LSDAdvance_LineResponse, is_length_over_the_longer_side_times_the_squared_contrast_of_the_brighter_left)
{
    const Mat img = stepImage();
    // On the step, pointing up (y decreasing): its left is the bright side. 1 px either side of
    // x = 149.5 the gray levels are 200 and 50 exactly.
    const Vec4f up(149.5f, 160, 149.5f, 40), down(149.5f, 40, 149.5f, 160);
    const std::vector<float> r = responsesOf(img, { up, down, Vec4f(20, 20, 120, 20) });
    ASSERT_EQ(3u, r.size());
    EXPECT_NEAR(120.0 / 300.0 * (150.0 / 255) * (150.0 / 255), r[0], 1e-6);
    EXPECT_EQ(0.f, r[1]);  // its left is the dark side: no evidence for this orientation
    EXPECT_EQ(0.f, r[2]);  // flat region
    // A full-contrast line has LSDDetector's response, length over the longer side.
    Mat full(100, 100, CV_8UC1, Scalar(0));
    full(Rect(0, 0, 50, 100)).setTo(255);
    EXPECT_NEAR(80.0 / 100.0, responsesOf(full, { Vec4f(49.5f, 90, 49.5f, 10) })[0], 1e-6);
}

TEST(LSDAdvance_LineResponse, ranks_a_short_line_on_its_edge_above_a_longer_one_half_off_it)
{
    // The step covers rows 0..99 only; below it the image is flat.
    Mat img = stepImage();
    img(Rect(0, 100, 300, 100)).setTo(50);
    const Vec4f onEdge(149.5f, 90, 149.5f, 30);     // 60 px, all on the step
    const Vec4f halfOff(149.5f, 180, 149.5f, 20);   // 160 px, 80 of them on the step
    const std::vector<float> r = responsesOf(img, { onEdge, halfOff });
    // Contrast 150 over 60 px against about 75 over 160 px: 60 > 160 / 4. Of the 160 samples of
    // halfOff (y = 179.5 .. 20.5), 79 lie on the step, and the one at y = 99.5 sees half of it
    // (bilinear between rows 99 and 100).
    EXPECT_NEAR(60.0 / 300.0 * std::pow(150.0 / 255, 2), r[0], 1e-6);
    EXPECT_NEAR(160.0 / 300.0 * std::pow((79 * 150.0 + 75) / 160 / 255, 2), r[1], 1e-6);
    EXPECT_GT(r[0], r[1]);
}

TEST(LSDAdvance_LineResponse, is_a_tenth_for_a_segment_the_image_border_cuts)
{
    const Mat img = stepImage();  // 300 x 200, the step at x = 149.5 on every row
    const double inside = std::pow(150.0 / 255, 2) / 300.0;  // per pixel of length
    // Endpoints at y = 2 and y = 197 are 2 px from the first and last rows: still inside; at
    // y = 1.9 or 197.1, or beyond the image, the border cuts the segment.
    const std::vector<float> r = responsesOf(img, { Vec4f(149.5f, 197, 149.5f, 2), Vec4f(149.5f, 197.1f, 149.5f, 2),
                                                    Vec4f(149.5f, 197, 149.5f, 1.9f), Vec4f(149.5f, 230, 149.5f, -30) });
    EXPECT_NEAR(195.0 * inside, r[0], 1e-6);
    EXPECT_NEAR(0.1 * 195.1 * inside, r[1], 1e-6);
    EXPECT_NEAR(0.1 * 195.1 * inside, r[2], 1e-6);
    EXPECT_NEAR(0.1 * 260.0 * inside, r[3], 1e-6);
    // The same along x: a horizontal step, a segment from x = 2 to x = 297 and one to x = 298.
    Mat rows(200, 300, CV_8UC1, Scalar(50));
    rows(Rect(0, 0, 300, 100)).setTo(200);  // bright above y = 99.5: a segment pointing +x has it on its left
    const std::vector<float> h = responsesOf(rows, { Vec4f(2, 99.5f, 297, 99.5f), Vec4f(2, 99.5f, 298, 99.5f) });
    EXPECT_NEAR(295.0 * inside, h[0], 1e-6);
    EXPECT_NEAR(0.1 * 296.0 * inside, h[1], 1e-6);
}

TEST(LSDAdvance_LineResponse, colour_images_give_the_gray_responses_and_bad_input_throws)
{
    const Mat img = stepImage();
    const std::vector<Vec4f> lines = { Vec4f(149.5f, 160, 149.5f, 40), Vec4f(100, 10, 200, 190) };
    Mat bgr, bgra;
    cvtColor(img, bgr, COLOR_GRAY2BGR);
    cvtColor(img, bgra, COLOR_GRAY2BGRA);
    EXPECT_EQ(responsesOf(img, lines), responsesOf(bgr, lines));
    EXPECT_EQ(responsesOf(img, lines), responsesOf(bgra, lines));
    // Segments partly or wholly outside the image are sampled at the clamped border.
    const std::vector<float> outside = responsesOf(img, { Vec4f(-50, -50, -10, -50), Vec4f(149.5f, 260, 149.5f, -60) });
    EXPECT_EQ(0.f, outside[0]);
    EXPECT_NEAR(0.1 * 320.0 / 300.0 * std::pow(150.0 / 255, 2), outside[1], 1e-6);
    EXPECT_TRUE(responsesOf(img, std::vector<Vec4f>()).empty());

    std::vector<float> r;
    EXPECT_THROW(computeLineResponses(Mat(), lines, r), cv::Exception);
    EXPECT_THROW(computeLineResponses(Mat(10, 10, CV_32FC1, Scalar(0)), lines, r), cv::Exception);
    EXPECT_THROW(computeLineResponses(img, Mat(2, 4, CV_32FC1, Scalar(0)), r), cv::Exception);
    EXPECT_THROW(computeLineResponses(img, std::vector<Vec4f>{ Vec4f(0, 0, NAN, 5) }, r), cv::Exception);
}

// Faint blocks on a mid-gray image, long edges of low contrast (140 against 120), and short
// bright bars (250, 24 x 8 px), short edges of high contrast: the case where a length filter drops
// the lines a matcher finds again.
Mat faintLongStrongShort()
{
    Mat img(400, 600, CV_8UC1, Scalar(120));
    for (int k = 0; k < 4; k++)
        img(Rect(40 + 140 * k, 40, 100, 300)).setTo(140);
    RNG rng(3);
    for (int k = 0; k < 40; k++)
        img(Rect(rng.uniform(10, 570), rng.uniform(10, 380), 24, 8)).setTo(250);
    return img;
}

// Stage 1's output of the last call (before the clipping to the image).
std::vector<Vec4f> filteredOf(const LSDAdvance& detector)
{
    std::vector<Vec4f> base, filtered, merged;
    std::vector<int> labels;
    detector.getLastStageOutputs(base, filtered, labels, merged);
    return filtered;
}

TEST(LSDAdvance_LineResponse, stage1_keeps_short_strong_segments_only_when_asked)
{
    const Mat img = faintLongStrongShort();
    Ptr<LSDAdvance> lengthOnly = createLSDAdvance(), strong = createLSDAdvance();
    // Off by default (and in the paper's and the fastest preset), on in the sequence preset.
    ASSERT_FALSE(lengthOnly->getKeepStrongSegments());
    EXPECT_FALSE(createLSDAdvance(LSDAdvance::PRESET_PAPER)->getKeepStrongSegments());
    EXPECT_FALSE(createLSDAdvance(LSDAdvance::PRESET_FASTEST)->getKeepStrongSegments());
    EXPECT_TRUE(createLSDAdvance(LSDAdvance::PRESET_SEQUENCE)->getKeepStrongSegments());
    strong->setKeepStrongSegments(true);
    std::vector<Vec4f> lines;
    strong->detect(img, lines);
    lengthOnly->detect(img, lines);
    const std::vector<Vec4f> withStrong = filteredOf(*strong), longOnly = filteredOf(*lengthOnly);
    const LSDAdvanceStats s = strong->getLastStats(), l = lengthOnly->getLastStats();
    EXPECT_EQ(0.0, l.minResponse);
    ASSERT_GT(s.minResponse, 0.0);
    EXPECT_EQ(l.minLength, s.minLength);

    // Length only: nothing shorter than the threshold.
    for (const Vec4f& line : longOnly)
        EXPECT_GE(lsda::segmentLength(line), l.minLength);
    // With strong segments: the same long ones, plus short ones whose response reaches minResponse.
    const std::vector<float> responses = responsesOf(img, withStrong);
    int shortStrong = 0;
    for (size_t i = 0; i < withStrong.size(); i++)
        if (lsda::segmentLength(withStrong[i]) < s.minLength)
        {
            shortStrong++;
            EXPECT_GE(responses[i], s.minResponse);
        }
    EXPECT_GT(shortStrong, 20);
    EXPECT_EQ(longOnly.size() + shortStrong, withStrong.size());

    // The parameter is saved and loaded.
    FileStorage out(".yml", FileStorage::WRITE | FileStorage::MEMORY);
    strong->write(out);
    const std::string text = out.releaseAndGetString();
    FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
    Ptr<LSDAdvance> loaded = createLSDAdvance();
    loaded->read(in.root());
    EXPECT_TRUE(loaded->getKeepStrongSegments());
}

}} // namespace
