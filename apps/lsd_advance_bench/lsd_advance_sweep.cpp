// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Chooses LSDAdvance's open thresholds by measurement: a grid over the base detector set-up,
// the length threshold rule, the merge strategy, the stage order, endpointDistance,
// mergeThreshold, proximityRatio and maxPerpendicularOffset, scored with the structural F on one half of YorkUrban (even or odd
// images), then the best setting and the defaults checked on the other half.
// Base segments are detected once per image and set-up; LSDAdvance::processSegments runs the
// other stages, so the whole grid takes a few minutes.

#include "command_line.hpp"

#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/lsd_advance.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

using namespace cv;
using namespace cv::ximgproc;
using namespace cv::ximgproc::line_evaluation;

namespace {

struct BaseSetup
{
    const char* name;
    int refine;
    double scale;
};

const BaseSetup kBases[] = { { "LSD default (STD, 0.8)", LSD_REFINE_STD, 0.8 },
                             { "LSD NONE, 1.0", LSD_REFINE_NONE, 1.0 } };

struct Setting
{
    int base, threshold, strategy, order;
    double endpointDistance, mergeThreshold, proximityRatio, maxOffset;
};

struct Score
{
    double ap = 0, ar = 0, f = 0, segments = 0;
};

// base[b][k]: segments of set-up b on image k.
typedef std::vector<std::vector<std::vector<Vec4f> > > BaseSegments;

Ptr<LSDAdvance> detectorFor(const Setting& s)
{
    Ptr<LSDAdvance> d = createLSDAdvance();
    d->setEndpointDistance(s.endpointDistance);
    d->setMergeThreshold(s.mergeThreshold);
    d->setLengthThresholdRule(s.threshold);
    d->setMergeStrategy(s.strategy);
    d->setStageOrder(s.order);
    d->setProximityRatio(s.proximityRatio);
    d->setMaxPerpendicularOffset(s.maxOffset);
    return d;
}

Score evaluate(const Ptr<LSDAdvance>& detector, const std::vector<std::vector<Vec4f> >& base,
               const std::vector<LabelledImage>& images, const std::vector<int>& subset)
{
    Score score;
    std::vector<Vec4f> lines;
    for (int k : subset)
    {
        detector->processSegments(base[k], lines);
        const StructuralScore s = evaluateStructural(lines, images[k].groundTruth);
        score.ap += s.precision;
        score.ar += s.recall;
        score.segments += (double)lines.size();
    }
    score.ap /= subset.size();
    score.ar /= subset.size();
    score.segments /= subset.size();
    score.f = fScore(score.ap, score.ar);
    return score;
}

const char* strategyName(int s)
{
    return s == LSDAdvance::MERGE_BASELINES ? "baselines" : s == LSDAdvance::MERGE_LONGEST_FIRST ? "longest first" : "none";
}

const char* thresholdName(int t)
{
    return t == LSDAdvance::LENGTH_THRESHOLD_PAPER ? "paper" : "capped";
}

const char* orderName(int o)
{
    return o == LSDAdvance::FILTER_THEN_MERGE ? "filter, merge" : "merge, filter";
}

void printRow(const Setting& s, const Score& tune, const Score* check)
{
    std::printf("| %s | %s | %s | %s | %g | %g | %g | %g | %.3f | %.3f | %.3f | %.0f |", kBases[s.base].name,
                thresholdName(s.threshold), strategyName(s.strategy), orderName(s.order), s.endpointDistance,
                s.mergeThreshold, s.proximityRatio, s.maxOffset, tune.ap, tune.ar, tune.f, tune.segments);
    if (check)
        std::printf(" %.3f | %.3f | %.3f |", check->ap, check->ar, check->f);
    std::printf("\n");
}

int run(const AppOptions& args)
{
    const String data = args.text("data");
    const bool tuneEven = args.oneOf("tune", { "even", "odd" }) == "even";
    const int top = args.integer("top", 1);
    if (!utils::fs::isDirectory(data))
        throw std::runtime_error("--data=" + data + ": no such folder");
    setNumThreads(1);

    const std::vector<LabelledImage> images = loadYorkUrban(data);
    // The halves by index in list.txt, without the images OpenCV cannot read.
    std::vector<int> tuneSet, checkSet;
    size_t skipped = 0;
    BaseSegments base(sizeof(kBases) / sizeof(kBases[0]), std::vector<std::vector<Vec4f> >(images.size()));
    for (size_t k = 0; k < images.size(); k++)
    {
        std::cerr << "\r[sweep] base segments " << k + 1 << "/" << images.size() << std::flush;
        const Mat gray = readGrayImage(images[k].imagePath);
        if (gray.empty())
        {
            std::cerr << "\n";
            reportSkipped(images[k].imagePath);
            skipped++;
            continue;
        }
        ((k % 2 == 0) == tuneEven ? tuneSet : checkSet).push_back((int)k);
        for (size_t b = 0; b < base.size(); b++)
            createLineSegmentDetector(kBases[b].refine, kBases[b].scale)->detect(gray, base[b][k]);
    }
    std::cerr << "\n";
    if (tuneSet.empty() || checkSet.empty())
        throw std::runtime_error("the sweep needs readable images in both halves of " + data);

    std::vector<std::pair<Score, Setting> > results;
    for (int b = 0; b < (int)base.size(); b++)
        for (int threshold : { (int)LSDAdvance::LENGTH_THRESHOLD_PAPER, (int)LSDAdvance::LENGTH_THRESHOLD_CAPPED })
        for (int strategy : { (int)LSDAdvance::MERGE_BASELINES, (int)LSDAdvance::MERGE_LONGEST_FIRST })
            for (int order : { (int)LSDAdvance::FILTER_THEN_MERGE, (int)LSDAdvance::MERGE_THEN_FILTER })
                for (double distance : { 5.0, 10.0, 15.0 })
                    for (double mergeThreshold : { 0.5, 0.6, 0.7 })
                        for (double ratio : { 0.1, 0.4, 1.0, 2.0 })
                            for (double offset : { 1.0, 1.5, 2.0 })
                            {
                                const Setting s = { b, threshold, strategy, order, distance, mergeThreshold, ratio, offset };
                                results.push_back(std::make_pair(evaluate(detectorFor(s), base[b], images, tuneSet), s));
                                std::cerr << "\r[sweep] setting " << results.size() << std::flush;
                            }
    std::cerr << "\n";
    std::stable_sort(results.begin(), results.end(), [](const std::pair<Score, Setting>& a, const std::pair<Score, Setting>& b) {
        return a.first.f > b.first.f;
    });

    std::printf("Grid of %zu settings, tuned on the %s images (%zu), checked on the others (%zu); length filter "
                "with alpha = 1 (LENGTH_FILTER_ADAPTIVE), angle bins 10 deg with neighbours, weights 0.4/0.35/0.2.\n\n",
                results.size(), tuneEven ? "even" : "odd", tuneSet.size(), checkSet.size());
    std::printf("| base | length threshold | merge | order | endpointDistance | mergeThreshold | proximityRatio | maxPerpendicularOffset "
                "| AP (tune) | AR (tune) | F (tune) | segments | AP (check) | AR (check) | F (check) |\n");
    std::printf("|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < std::min(top, (int)results.size()); i++)
    {
        const Setting& s = results[i].second;
        const Score check = evaluate(detectorFor(s), base[s.base], images, checkSet);
        printRow(s, results[i].first, &check);
    }

    // The best setting on OpenCV's own LSD set-up, for users who need LSD's cost.
    for (const auto& r : results)
        if (r.second.base == 0)
        {
            std::printf("\nBest setting on %s:\n\n", kBases[0].name);
            const Score check = evaluate(detectorFor(r.second), base[0], images, checkSet);
            printRow(r.second, r.first, &check);
            break;
        }

    // The defaults, the paper's configuration and the base detectors alone, on both halves.
    std::printf("\nReferences on both halves (tune / check):\n\n");
    // The paper's preset, each image on its own (alpha = 1), on OpenCV's default LSD set-up (its base).
    Ptr<LSDAdvance> paper = createLSDAdvance(LSDAdvance::PRESET_PAPER);
    paper->setLengthFilterMode(LSDAdvance::LENGTH_FILTER_ADAPTIVE);
    Ptr<LSDAdvance> defaults = createLSDAdvance();
    const int defaultBase = defaults->getLSDParams().refine == LSD_REFINE_NONE ? 1 : 0;
    std::printf("- the defaults (%s base): F %.3f / %.3f\n", kBases[defaultBase].name,
                evaluate(defaults, base[defaultBase], images, tuneSet).f,
                evaluate(defaults, base[defaultBase], images, checkSet).f);
    const Score paperTune = evaluate(paper, base[0], images, tuneSet);
    const Score paperCheck = evaluate(paper, base[0], images, checkSet);
    std::printf("- paper's stages on OpenCV's default LSD: F %.3f / %.3f\n", paperTune.f, paperCheck.f);
    for (size_t b = 0; b < base.size(); b++)
    {
        Ptr<LSDAdvance> none = createLSDAdvance();
        none->setLengthFilterMode(LSDAdvance::LENGTH_FILTER_NONE);
        none->setMergeStrategy(LSDAdvance::MERGE_NONE);
        std::printf("- %s alone: F %.3f / %.3f\n", kBases[b].name, evaluate(none, base[b], images, tuneSet).f,
                    evaluate(none, base[b], images, checkSet).f);
    }
    if (skipped > 0)
        std::printf("\n%zu unreadable image(s) skipped\n", skipped);
    return skipped == 0 ? 0 : kExitSkipped;
}

} // namespace

int main(int argc, char** argv)
{
    const String keys =
        "{help h |        | print this help }"
        "{data   | <none> | YorkUrban folder (images/, gt/, list.txt) }"
        "{tune   | even   | half to tune on: even or odd images of list.txt; the other half checks }"
        "{top    | 15     | rows of the sorted grid to print, >= 1 }";
    const String about = "Parameter sweep of LSDAdvance on YorkUrban, e.g. lsd_advance_sweep --data=<YorkUrban folder>. "
                         "Exit status: 0, 1 on an error, 2 when unreadable images were left out.";
    return runApp(argc, argv, keys, about, {}, run);
}
