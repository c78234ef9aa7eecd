// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Accuracy and sequence behaviour on the real evaluation data (doc/data.md), whose folder
// is given by LSD_ADVANCE_DATA_DIR. Without it the tests are skipped, except under CI=true,
// where they fail.

#include "test_precomp.hpp"
#include "opencv2/lsd_advance/evaluation.hpp"
#include "opencv2/ximgproc.hpp"

namespace opencv_test { namespace {

typedef std::function<void(const Mat&, std::vector<Vec4f>&)> Detect;

// Structural F over the images (AP and AR are means over images).
double structuralF(const Detect& detect, const std::vector<LabelledImage>& images, const std::vector<Mat>& grays)
{
    double ap = 0, ar = 0;
    std::vector<Vec4f> lines;
    for (size_t k = 0; k < images.size(); k++)
    {
        detect(grays[k], lines);
        const StructuralScore s = evaluateStructural(lines, images[k].groundTruth);
        ap += s.precision;
        ar += s.recall;
    }
    return fScore(ap / images.size(), ar / images.size());
}

TEST(LSDAdvance_RealData, yorkurban_F_beats_LSD_FLD_and_EDLines_on_images_not_used_for_tuning)
{
    // The defaults were chosen on the even images of list.txt (doc/parameter_sweep.md): score the odd ones.
    const std::vector<LabelledImage> all = loadYorkUrban(dataFolder("yorkurban"));
    std::vector<LabelledImage> images;
    std::vector<Mat> grays;
    for (size_t k = 1; k < all.size(); k += 2)
    {
        images.push_back(all[k]);
        grays.push_back(imread(all[k].imagePath, IMREAD_GRAYSCALE));
        ASSERT_FALSE(grays.back().empty());
    }
    ASSERT_EQ(25u, images.size());

    Ptr<LineSegmentDetector> lsd = createLineSegmentDetector();
    Ptr<FastLineDetector> fld = createFastLineDetector();
    Ptr<FastLineDetector> fldMerge = createFastLineDetector(10, 1.414213562f, 50, 50, 3, true);
    Ptr<EdgeDrawing> ed = createEdgeDrawing();
    Ptr<LSDAdvance> ours = createLSDAdvance();
    const double fLsd = structuralF([&](const Mat& g, std::vector<Vec4f>& l) { lsd->detect(g, l); }, images, grays);
    const double fFld = structuralF([&](const Mat& g, std::vector<Vec4f>& l) { fld->detect(g, l); }, images, grays);
    const double fFldMerge = structuralF([&](const Mat& g, std::vector<Vec4f>& l) { fldMerge->detect(g, l); }, images, grays);
    const double fEd = structuralF([&](const Mat& g, std::vector<Vec4f>& l) { ed->detectEdges(g); ed->detectLines(l); },
                                   images, grays);
    const double fOurs = structuralF([&](const Mat& g, std::vector<Vec4f>& l) { ours->reset(); ours->detect(g, l); },
                                     images, grays);
    std::cout << format("structural F on 25 held-out YorkUrban images: LSD %.3f, FLD %.3f, FLD+merge %.3f, "
                        "EDLines %.3f, LSDAdvance %.3f", fLsd, fFld, fFldMerge, fEd, fOurs) << std::endl;
    EXPECT_GT(fOurs, fLsd);
    EXPECT_GT(fOurs, fFld);
    EXPECT_GT(fOurs, fFldMerge);
    EXPECT_GT(fOurs, fEd);
}

struct SequenceCounts
{
    std::vector<double> counts, longShares;
};

SequenceCounts runSequence(const Detect& detect, const std::vector<Mat>& frames)
{
    SequenceCounts out;
    std::vector<Vec4f> lines;
    for (const Mat& f : frames)
    {
        detect(f, lines);
        out.counts.push_back((double)lines.size());
        out.longShares.push_back(longSegmentShare(lines, 60.0));
    }
    return out;
}

std::vector<Mat> loadFrames(const char* set)
{
    std::vector<Mat> frames;
    for (const String& path : loadSequence(dataFolder(set)).imagePaths)
    {
        frames.push_back(imread(path, IMREAD_GRAYSCALE));
        CV_Assert(!frames.back().empty());
    }
    return frames;
}

TEST(LSDAdvance_RealData, kitti_gives_fewer_segments_with_a_larger_long_share_than_LSD)
{
    const std::vector<Mat> frames = loadFrames("kitti_seq1");
    ASSERT_EQ(51u, frames.size());
    Ptr<LineSegmentDetector> lsd = createLineSegmentDetector();
    Ptr<LSDAdvance> ours = createLSDAdvance();
    const SequenceCounts base = runSequence([&](const Mat& g, std::vector<Vec4f>& l) { lsd->detect(g, l); }, frames);
    const SequenceCounts adv = runSequence([&](const Mat& g, std::vector<Vec4f>& l) { ours->detect(g, l); }, frames);
    const double lsdCount = mean(base.counts)[0], ourCount = mean(adv.counts)[0];
    const double lsdShare = mean(base.longShares)[0], ourShare = mean(adv.longShares)[0];
    std::cout << format("KITTI, 51 frames: segments / frame LSD %.1f, LSDAdvance %.1f; long share LSD %.3f, "
                        "LSDAdvance %.3f", lsdCount, ourCount, lsdShare, ourShare) << std::endl;
    EXPECT_LT(ourCount, lsdCount);
    EXPECT_GT(ourShare, lsdShare);
}

TEST(LSDAdvance_RealData, euroc_still_camera_count_tracking_steadies_the_segment_count)
{
    const std::vector<Mat> frames = loadFrames("euroc_v101_static");
    ASSERT_EQ(95u, frames.size());
    const auto countStd = [&](int mode) {
        Ptr<LSDAdvance> d = createLSDAdvanceWith(mode);
        const SequenceCounts s = runSequence([&](const Mat& g, std::vector<Vec4f>& l) { d->detect(g, l); }, frames);
        Scalar m, sd;
        meanStdDev(s.counts, m, sd);
        return sd[0];
    };
    const double without = countStd(LSDAdvance::LENGTH_FILTER_ADAPTIVE);
    const double printedRule = countStd(LSDAdvance::LENGTH_FILTER_INTERFRAME);
    const double tracking = countStd(LSDAdvance::LENGTH_FILTER_COUNT_TRACKING);
    std::cout << format("EuRoC still camera, std of the segment count over 95 frames: alpha = 1 %.2f, paper's "
                        "inter-frame rule %.2f, count tracking %.2f", without, printedRule, tracking) << std::endl;
    EXPECT_LT(tracking, without);
    // The paper's rule does not steady the count (measured, reported): it must at least not be
    // the steadiest of the three, or the documentation of the modes is wrong.
    EXPECT_GE(printedRule, tracking);
}

}} // namespace
