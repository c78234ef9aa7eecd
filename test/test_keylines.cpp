// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// KeyLine output: the fields LSDDetector fills, and LBD describing and matching them.

#include "test_precomp.hpp"

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

namespace opencv_test { namespace {

using line_descriptor::KeyLine;

Mat buildingGray()
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    CV_Assert(!img.empty());
    return img;
}

void expectSameKeyLine(const KeyLine& expected, const KeyLine& actual, size_t i)
{
    SCOPED_TRACE(cv::format("keyline %zu", i));
    EXPECT_EQ(expected.startPointX, actual.startPointX);
    EXPECT_EQ(expected.startPointY, actual.startPointY);
    EXPECT_EQ(expected.endPointX, actual.endPointX);
    EXPECT_EQ(expected.endPointY, actual.endPointY);
    EXPECT_EQ(expected.sPointInOctaveX, actual.sPointInOctaveX);
    EXPECT_EQ(expected.sPointInOctaveY, actual.sPointInOctaveY);
    EXPECT_EQ(expected.ePointInOctaveX, actual.ePointInOctaveX);
    EXPECT_EQ(expected.ePointInOctaveY, actual.ePointInOctaveY);
    EXPECT_FLOAT_EQ(expected.lineLength, actual.lineLength);
    EXPECT_EQ(expected.numOfPixels, actual.numOfPixels);
    EXPECT_NEAR(expected.angle, actual.angle, 1e-6);
    EXPECT_EQ(expected.class_id, actual.class_id);
    EXPECT_EQ(expected.octave, actual.octave);
    EXPECT_FLOAT_EQ(expected.size, actual.size);
    EXPECT_FLOAT_EQ(expected.response, actual.response);
    EXPECT_FLOAT_EQ(expected.pt.x, actual.pt.x);
    EXPECT_FLOAT_EQ(expected.pt.y, actual.pt.y);
}

TEST(LSDAdvance_KeyLines, fields_agree_with_LSDDetector_on_the_same_segments)
{
    const Mat gray = buildingGray();
    std::vector<KeyLine> reference;
    line_descriptor::LSDDetector::createLSDDetector()->detect(gray, reference, 2, 1);
    ASSERT_GT(reference.size(), 100u);

    // LSDDetector's own LSD set-up (its LSDParam defaults, LSD_REFINE_ADV), so that both
    // conversions start from the same segments.
    std::vector<Vec4f> segments;
    createLineSegmentDetector(LSD_REFINE_ADV, 0.8, 0.6, 2.0, 22.5, 0, 0.7, 1024)->detect(gray, segments);
    std::vector<KeyLine> keylines;
    linesToKeyLines(segments, gray.size(), keylines);

    ASSERT_EQ(reference.size(), keylines.size());
    for (size_t i = 0; i < keylines.size(); i++)
        expectSameKeyLine(reference[i], keylines[i], i);
}

TEST(LSDAdvance_KeyLines, detect_overload_returns_the_segments_of_detect_as_keylines)
{
    const Mat gray = buildingGray();
    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<KeyLine> keylines;
    detector->detect(gray, keylines);
    detector->reset();
    std::vector<Vec4f> segments;
    detector->detect(gray, segments);
    ASSERT_FALSE(segments.empty());
    ASSERT_EQ(segments.size(), keylines.size());

    // linesToKeyLines' fields, with computeLineResponses' response.
    std::vector<KeyLine> expected;
    linesToKeyLines(segments, gray.size(), expected);
    std::vector<float> responses;
    computeLineResponses(gray, segments, responses);
    for (size_t i = 0; i < keylines.size(); i++)
    {
        expected[i].response = responses[i];
        expectSameKeyLine(expected[i], keylines[i], i);
    }
    // A colour image gives the same KeyLines as its gray version.
    Mat colour;
    cvtColor(gray, colour, COLOR_GRAY2BGR);
    std::vector<KeyLine> fromColour;
    detector->reset();
    detector->detect(colour, fromColour);
    ASSERT_EQ(keylines.size(), fromColour.size());
    for (size_t i = 0; i < keylines.size(); i++)
        EXPECT_EQ(keylines[i].response, fromColour[i].response);
}

TEST(LSDAdvance_KeyLines, response_ranks_by_length_and_endpoints_are_clamped_into_the_image)
{
    const Size size(200, 100);
    const std::vector<Vec4f> segments = { Vec4f(10, 10, 50, 10), Vec4f(-20, 50, 250, 50), Vec4f(30, 90, 30, 60) };
    std::vector<KeyLine> keylines;
    linesToKeyLines(segments, size, keylines);
    ASSERT_EQ(3u, keylines.size());

    // The second segment crosses both vertical borders: clamped to x in [0, 199].
    EXPECT_EQ(0.f, keylines[1].startPointX);
    EXPECT_EQ(199.f, keylines[1].endPointX);
    EXPECT_FLOAT_EQ(199.f, keylines[1].lineLength);
    EXPECT_EQ(200, keylines[1].numOfPixels);
    EXPECT_FLOAT_EQ(199.f / 200.f, keylines[1].response);
    EXPECT_FLOAT_EQ(40.f / 200.f, keylines[0].response);
    EXPECT_FLOAT_EQ(30.f / 200.f, keylines[2].response);
    // The third one points up: angle -pi/2, size dx * dy = 0.
    EXPECT_NEAR(-CV_PI / 2, keylines[2].angle, 1e-6);
    EXPECT_EQ(0.f, keylines[2].size);
    for (size_t i = 0; i < keylines.size(); i++)
    {
        EXPECT_EQ((int)i, keylines[i].class_id);
        EXPECT_EQ(0, keylines[i].octave);
    }

    std::vector<Vec4f> back;
    keyLinesToLines(keylines, back);
    ASSERT_EQ(3u, back.size());
    EXPECT_EQ(segments[0], back[0]);
    EXPECT_EQ(Vec4f(0, 50, 199, 50), back[1]);
    EXPECT_EQ(segments[2], back[2]);
}

TEST(LSDAdvance_KeyLines, a_line_along_the_last_column_or_row_counts_its_pixels)
{
    // x = 199.5 rounds (to even) to 200, just outside: LSDDetector's count of the clipped line is 0.
    const Size size(200, 100);
    const std::vector<Vec4f> segments = { Vec4f(199.5f, 10, 199.5f, 50), Vec4f(20, 99.5f, 60, 99.5f),
                                          Vec4f(199.5f, 99.5f, 199.5f, 99.5f) };
    ASSERT_EQ(0, LineIterator(size, Point2f(199.5f, 10), Point2f(199.5f, 50)).count);
    std::vector<KeyLine> keylines;
    linesToKeyLines(segments, size, keylines);
    ASSERT_EQ(3u, keylines.size());
    EXPECT_EQ(41, keylines[0].numOfPixels);  // the pixels of column 199 from row 10 to row 50
    EXPECT_EQ(41, keylines[1].numOfPixels);
    EXPECT_EQ(1, keylines[2].numOfPixels);
    EXPECT_EQ(199.5f, keylines[0].startPointX);  // the endpoints themselves are kept
}

TEST(LSDAdvance_KeyLines, conversion_rejects_bad_input)
{
    std::vector<KeyLine> keylines;
    const std::vector<Vec4f> nan = { Vec4f(0, 0, std::numeric_limits<float>::quiet_NaN(), 1) };
    EXPECT_THROW(linesToKeyLines(nan, Size(10, 10), keylines), cv::Exception);
    EXPECT_THROW(linesToKeyLines(std::vector<Vec4f>(1, Vec4f(0, 0, 1, 1)), Size(0, 10), keylines), cv::Exception);
    EXPECT_THROW(linesToKeyLines(Mat::zeros(3, 4, CV_32F), Size(10, 10), keylines), cv::Exception);
    linesToKeyLines(std::vector<Vec4f>(), Size(10, 10), keylines);
    EXPECT_TRUE(keylines.empty());
}

TEST(LSDAdvance_KeyLines, every_keyline_gets_an_LBD_descriptor_and_matches_itself)
{
    const Mat gray = buildingGray();
    std::vector<KeyLine> keylines;
    createLSDAdvance()->detect(gray, keylines);
    ASSERT_GT(keylines.size(), 50u);
    const size_t count = keylines.size();

    Mat descriptors;
    line_descriptor::BinaryDescriptor::createBinaryDescriptor()->compute(gray, keylines, descriptors);
    ASSERT_EQ(count, keylines.size());
    ASSERT_EQ((int)count, descriptors.rows);
    EXPECT_EQ(32, descriptors.cols);
    EXPECT_EQ(CV_8UC1, descriptors.type());

    // Every descriptor finds one at Hamming distance 0 in the same set (itself or an identical one).
    std::vector<DMatch> matches;
    line_descriptor::BinaryDescriptorMatcher::createBinaryDescriptorMatcher()->match(descriptors, descriptors, matches);
    ASSERT_EQ(count, matches.size());
    int identical = 0;
    for (const DMatch& m : matches)
    {
        EXPECT_EQ(0.f, m.distance);
        identical += m.queryIdx == m.trainIdx;
    }
    EXPECT_GT(identical, (int)count * 9 / 10);
}

TEST(LSDAdvance_KeyLines, detect_after_the_budget_and_minimum_gives_contiguous_class_ids_strongest_first)
{
    const Mat gray = buildingGray();
    Ptr<LSDAdvance> detector = createLSDAdvance();
    detector->setMaxLines(40);
    detector->setMinLineLength(30);
    std::vector<KeyLine> keylines;
    detector->detect(gray, keylines);
    ASSERT_EQ(40u, keylines.size());
    std::vector<float> responses;
    detector->getLastResponses(responses);
    for (size_t i = 0; i < keylines.size(); i++)
    {
        EXPECT_EQ((int)i, keylines[i].class_id);
        EXPECT_EQ(responses[i], keylines[i].response);
        EXPECT_GE(keylines[i].lineLength, 30.f);
        if (i > 0)
        {
            EXPECT_GE(keylines[i - 1].response, keylines[i].response);
        }
    }
    // LBD describes each of them.
    Mat descriptors;
    line_descriptor::BinaryDescriptor::createBinaryDescriptor()->compute(gray, keylines, descriptors);
    EXPECT_EQ(40, descriptors.rows);
}

TEST(LSDAdvance_KeyLines, keepStrongestKeyLines_cuts_to_the_budget_and_numbers_them_anew)
{
    const Mat gray = buildingGray();
    std::vector<KeyLine> detected;
    line_descriptor::LSDDetector::createLSDDetector()->detect(gray, detected, 2, 1);  // another detector's order
    ASSERT_GT(detected.size(), 100u);
    std::vector<KeyLine> kept;
    keepStrongestKeyLines(detected, 50, kept);
    ASSERT_EQ(50u, kept.size());
    std::vector<float> responses;
    for (const KeyLine& k : detected)
        responses.push_back(k.response);
    std::sort(responses.begin(), responses.end(), std::greater<float>());
    for (size_t i = 0; i < kept.size(); i++)
    {
        EXPECT_EQ((int)i, kept[i].class_id);
        EXPECT_EQ(responses[i], kept[i].response);
        // Otherwise the KeyLine it was.
        const auto same = std::find_if(detected.begin(), detected.end(), [&](const KeyLine& k) {
            return k.startPointX == kept[i].startPointX && k.startPointY == kept[i].startPointY &&
                   k.endPointX == kept[i].endPointX && k.endPointY == kept[i].endPointY && k.response == kept[i].response;
        });
        ASSERT_TRUE(same != detected.end());
        KeyLine renumbered = *same;
        renumbered.class_id = (int)i;
        expectSameKeyLine(renumbered, kept[i], i);
    }
    Mat descriptors;
    line_descriptor::BinaryDescriptor::createBinaryDescriptor()->compute(gray, kept, descriptors);
    EXPECT_EQ(50, descriptors.rows);

    // In place, 0 = all (sorted only), a budget above the count, a bad budget.
    std::vector<KeyLine> all = detected;
    keepStrongestKeyLines(all, 0, all);
    ASSERT_EQ(detected.size(), all.size());
    for (size_t i = 0; i < all.size(); i++)
    {
        EXPECT_EQ((int)i, all[i].class_id);
        EXPECT_EQ(responses[i], all[i].response);
    }
    keepStrongestKeyLines(detected, (int)detected.size() + 5, kept);
    EXPECT_EQ(detected.size(), kept.size());
    EXPECT_THROW(keepStrongestKeyLines(detected, -1, kept), cv::Exception);
    keepStrongestKeyLines(std::vector<KeyLine>(), 10, kept);
    EXPECT_TRUE(kept.empty());
}

}} // namespace

#endif
