// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LSDAdvance: its parameters (the tables of parameters.hpp), presets, sequence state, the order
// of the stages and what they leave for getLastStageOutputs() and getLastSources(). The stages
// themselves are in length_filter.cpp, segment_grouping.cpp, segment_merging.cpp and
// image_clipping.cpp.

#include "precomp.hpp"
#include "parameters.hpp"
#include "segment_merging.hpp"

namespace cv {
namespace ximgproc {

namespace {

// Larger coordinates are not image coordinates; bounding them keeps the grouping grid's cells
// within 32 bits.
constexpr double kMaxCoordinate = 1e7;

double elapsedMs(int64 since)
{
    return (double)(getTickCount() - since) * 1000.0 / getTickFrequency();
}

// The preset's parameters: the defaults (the tables of parameters.hpp), then what the preset
// changes. The most accurate configuration is the defaults; the fastest is the default base at
// OpenCV LSD's scale 0.8 (the fastest measured set-up whose F stays above LSD's, doc/performance.md).
lsda::Parameters presetParameters(int preset)
{
    lsda::Parameters p;
    switch (preset)
    {
    case LSDAdvance::PRESET_MOST_ACCURATE:
        break;
    case LSDAdvance::PRESET_FASTEST:
        p.lsd.scale = 0.8;
        break;
    case LSDAdvance::PRESET_PAPER:
        // OpenCV's LSD with its own set-up (createLineSegmentDetector's defaults), the paper's base.
        p.own.baseDetector = LSDAdvance::BASE_LSD;
        p.lsd.refine = LSD_REFINE_STD;
        p.lsd.scale = 0.8;
        p.own.lengthFilterMode = LSDAdvance::LENGTH_FILTER_INTERFRAME;
        p.own.lengthThresholdRule = LSDAdvance::LENGTH_THRESHOLD_PAPER;
        p.own.stageOrder = LSDAdvance::FILTER_THEN_MERGE;
        p.own.mergeStrategy = LSDAdvance::MERGE_BASELINES;
        p.own.proximityRatio = 0.1;
        break;
    case LSDAdvance::PRESET_SEQUENCE:
        p.own.lengthFilterMode = LSDAdvance::LENGTH_FILTER_COUNT_TRACKING;
        // A front end keeps its N best lines: short strong ones give it more correct LBD matches
        // at an equal line budget (doc/matching.md).
        p.own.keepStrongSegments = true;
        break;
    default:
        CV_Error_(Error::StsOutOfRange, ("createLSDAdvance: preset must be %s, got %d",
                                         lsda::Range::enumOf(lsda::kPresets).describe().c_str(), preset));
    }
    return p;
}

// Replaces, for each base segment, the index of the segment of the last stage it is part of by
// that of the next stage: `into` maps the last stage's segments to the next's (-1: dropped).
void followStage(std::vector<int>& partOf, const std::vector<int>& into)
{
    for (int& k : partOf)
        k = k < 0 ? -1 : into[k];
}

// The same for a stage that keeps a subsequence: keptFrom[j] is the index of its j-th segment
// in its input of inputSize segments.
void followKept(std::vector<int>& partOf, const std::vector<int>& keptFrom, int inputSize, std::vector<int>& into)
{
    into.assign(inputSize, -1);
    for (size_t j = 0; j < keptFrom.size(); j++)
        into[keptFrom[j]] = (int)j;
    followStage(partOf, into);
}

class LSDAdvanceImpl CV_FINAL : public LSDAdvance
{
public:
    explicit LSDAdvanceImpl(const lsda::Parameters& p) : parameters(p) {}
    // Not copyable: frame holds pointers into itself.
    LSDAdvanceImpl(const LSDAdvanceImpl&) = delete;
    LSDAdvanceImpl& operator=(const LSDAdvanceImpl&) = delete;

    void detect(InputArray image, OutputArray lines) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        const int64 start = getTickCount();
        const Mat gray = lsda::toGray8U(image);
        if (!baseSegments)
            baseSegments = lsda::createBaseDetector(parameters.own.baseDetector, parameters.lsd, parameters.fld,
                                                    parameters.edLines);
        // LSD's resize throws on an image that scales to no pixel; such an image has no segment.
        const double scale = parameters.lsd.scale;
        if (parameters.own.baseDetector != BASE_LSD ||
            (saturate_cast<int>(gray.cols * scale) > 0 && saturate_cast<int>(gray.rows * scale) > 0))
            baseSegments->detect(gray, frame.incoming);
        else
            frame.incoming.clear();
        runStages(elapsedMs(start), &gray, lines);
    }

    void processSegments(InputArray segments, OutputArray lines, Size imageSize) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        CV_CheckGE(imageSize.width, 0, "LSDAdvance::processSegments: imageSize is empty or positive");
        CV_CheckGE(imageSize.height, 0, "LSDAdvance::processSegments: imageSize is empty or positive");
        lsda::toSegments(segments, "LSDAdvance::processSegments: segments", frame.incoming);
        if (!checkRange(Mat(frame.incoming), true, nullptr, -kMaxCoordinate, kMaxCoordinate))
            CV_Error_(Error::StsOutOfRange,
                      ("LSDAdvance::processSegments: segment coordinates must be finite and within "
                       "[-%g, %g) px", kMaxCoordinate, kMaxCoordinate));
        runStages(0.0, nullptr, lines, imageSize);
    }

    void drawSegments(InputOutputArray image, InputArray lines) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3))
            CV_Error_(Error::StsBadArg, ("LSDAdvance::drawSegments: image must be a non-empty CV_8UC1 or CV_8UC3 "
                                         "image, got %s %dx%d", typeToString(image.type()).c_str(), image.cols(),
                                         image.rows()));
        const std::vector<Vec4f> segments = lsda::toSegments(lines, "LSDAdvance::drawSegments: lines");
        if (image.channels() == 1)
            cvtColor(image, image, COLOR_GRAY2BGR);
        Mat canvas = image.getMat();
        for (const Vec4f& s : segments)
            line(canvas, Point2f(s[0], s[1]), Point2f(s[2], s[3]), Scalar(0, 0, 255), 1);
    }

    void reset() CV_OVERRIDE
    {
        framesSeen = 0;
        keptCounts[0] = keptCounts[1] = 0;
    }

    LSDAdvanceStats getLastStats() const CV_OVERRIDE { return lastStats; }

    void getLastStageOutputs(OutputArray base, OutputArray filtered, OutputArray groupLabels,
                             OutputArray merged) const CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        const std::vector<Vec4f> none;
        Mat(frame.base).copyTo(base);
        Mat(frame.filtered ? *frame.filtered : none).copyTo(filtered);
        Mat(frame.merged ? *frame.merged : none).copyTo(merged);
        std::vector<int> labels;
        if (frame.grouped)
        {
            // Numbered only when they hold two or more segments, as LSDAdvanceStats::mergeGroups counts them.
            const lsda::SegmentGroups& groups = frame.groups;
            labels.assign(groups.members.size(), -1);
            int next = 0;
            for (int g = 0; g < groups.count(); g++)
            {
                if (groups.offsets[g + 1] - groups.offsets[g] < 2)
                    continue;
                for (int k = groups.offsets[g]; k < groups.offsets[g + 1]; k++)
                    labels[groups.members[k]] = next;
                next++;
            }
        }
        Mat(labels).copyTo(groupLabels);
    }

    void getLastSources(OutputArrayOfArrays sources) const CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        const size_t lineCount = frame.lines ? frame.lines->size() : 0;
        std::vector<int> count(lineCount, 0);
        for (int line : frame.lineOf)
            if (line >= 0)
                count[line]++;
        sources.create((int)lineCount, 1, CV_32S);
        std::vector<Mat> lists(lineCount);
        for (size_t j = 0; j < lists.size(); j++)
        {
            sources.create(count[j], 1, CV_32S, (int)j);
            lists[j] = sources.getMat((int)j);
            count[j] = 0;
        }
        for (size_t i = 0; i < frame.lineOf.size(); i++)
        {
            const int j = frame.lineOf[i];
            if (j >= 0)
                lists[j].at<int>(count[j]++) = (int)i;
        }
    }

    Params getParams() const CV_OVERRIDE { return parameters.own; }
    void setParams(const Params& p) CV_OVERRIDE
    {
        lsda::validate(p);
        if (p.baseDetector != parameters.own.baseDetector)
            baseSegments.release();
        parameters.own = p;
        reset();
    }
    LSDParams getLSDParams() const CV_OVERRIDE { return parameters.lsd; }
    void setLSDParams(const LSDParams& p) CV_OVERRIDE { setBase(parameters.lsd, p); }
    FLDParams getFLDParams() const CV_OVERRIDE { return parameters.fld; }
    void setFLDParams(const FLDParams& p) CV_OVERRIDE { setBase(parameters.fld, p); }
    EdgeDrawing::Params getEDLinesParams() const CV_OVERRIDE { return parameters.edLines; }
    void setEDLinesParams(const EdgeDrawing::Params& p) CV_OVERRIDE { setBase(parameters.edLines, p); }

    // A getter and a setter per row of the table; the setter validates through setParams().
#define LSDA_ACCESSORS(type, field, Accessor, value, range, legacyKey) \
    void set##Accessor(type v) CV_OVERRIDE                                  \
    {                                                                       \
        Params p = parameters.own;                                          \
        p.field = v;                                                        \
        setParams(p);                                                       \
    }                                                                       \
    type get##Accessor() const CV_OVERRIDE { return parameters.own.field; }
    LSDA_PARAMS(LSDA_ACCESSORS)
#undef LSDA_ACCESSORS

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeFormat(fs);
        lsda::writeParameters(fs, parameters);
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        lsda::Parameters p = parameters;
        lsda::readParameters(fn, p);  // validates every value before changing p
        parameters = p;
        baseSegments.release();
        reset();
    }

    String getDefaultName() const CV_OVERRIDE { return "LSDAdvance"; }

private:
    template <class S>
    void setBase(S& current, const S& p)
    {
        lsda::validate(p);
        current = p;
        baseSegments.release();
        reset();
    }

    // Stages 1-3 in the configured order on the segments in frame.incoming, which become the
    // frame's base segments, then the clipping to the image gray, or to an image of imageSize
    // when there is no gray (processSegments; none when imageSize is empty); fills lastStats and
    // what getLastStageOutputs() and getLastSources() return. Without gray, stage 1 has no
    // responses and keeps long segments only.
    void runStages(double baseMs, const Mat* gray, OutputArray lines, Size imageSize = Size())
    {
        if (gray)
            imageSize = gray->size();
        // Only a call that got this far replaces the previous call's stage outputs.
        frame.base.swap(frame.incoming);
        const std::vector<Vec4f>& base = frame.base;
        const Params& own = parameters.own;
        LSDAdvanceStats stats;
        stats.baseSegments = (int)base.size();
        stats.baseMs = baseMs;
        frame.lineOf.resize(base.size());
        for (size_t i = 0; i < base.size(); i++)
            frame.lineOf[i] = (int)i;

        // The threshold always comes from the base segments: after merging, the lengths are
        // no longer those of one detector's output. Every rule is proportional to alpha.
        const int64 t = getTickCount();
        const bool filtering = own.lengthFilterMode != LENGTH_FILTER_NONE;
        const double unitMinLength =
            filtering ? own.lengthThresholdScale * lsda::adaptiveMinLength(base, 1.0, own.lengthThresholdRule) : 0.0;
        // The responses of the base segments give the threshold of the strong ones, as their
        // lengths give the length threshold; computed only when strong segments are kept.
        const Mat* strongFrom = filtering && own.keepStrongSegments ? gray : nullptr;
        frame.baseResponses.clear();
        if (strongFrom)
            lsda::lineResponses(*strongFrom, base, frame.baseResponses);
        const double unitMinResponse =
            strongFrom ? own.lengthThresholdScale *
                             lsda::adaptiveMinResponse(frame.baseResponses, 1.0, own.lengthThresholdRule)
                       : 0.0;
        stats.filterMs = elapsedMs(t);

        if (own.stageOrder == FILTER_THEN_MERGE)
        {
            frame.filtered = &filterStage(base, frame.baseResponses, unitMinLength, unitMinResponse, stats, frame.work);
            frame.merged = &mergeStage(*frame.filtered, stats, frame.out);
        }
        else
        {
            frame.merged = &mergeStage(base, stats, frame.work);
            // Fused segments have responses of their own; unmerged input keeps the base's.
            const std::vector<float>* responses = &frame.baseResponses;
            if (strongFrom && frame.merged != &base)
            {
                const int64 tr = getTickCount();
                lsda::lineResponses(*strongFrom, *frame.merged, frame.mergedResponses);
                responses = &frame.mergedResponses;
                stats.filterMs += elapsedMs(tr);
            }
            frame.filtered = &filterStage(*frame.merged, *responses, unitMinLength, unitMinResponse, stats, frame.out);
        }
        frame.lines = own.stageOrder == FILTER_THEN_MERGE ? frame.merged : frame.filtered;
        if (!imageSize.empty())
        {
            lsda::clipToImage(*frame.lines, imageSize, frame.clipped, frame.keptFrom);
            followKept(frame.lineOf, frame.keptFrom, (int)frame.lines->size(), frame.into);
            frame.lines = &frame.clipped;
        }
        stats.outputSegments = (int)frame.lines->size();
        Mat(*frame.lines).copyTo(lines);
        // The frame counts only once its output is delivered.
        keptCounts[1] = keptCounts[0];
        keptCounts[0] = stats.filteredSegments;
        framesSeen = std::min(framesSeen + 1, 2);
        lastStats = stats;
    }

    // alpha of this frame; the kept counts of the two previous frames are keptCounts.
    double frameAlpha(const std::vector<Vec4f>& in, const std::vector<float>& responses, double unitMinLength,
                      double unitMinResponse) const
    {
        if (framesSeen < 2)
            return 1.0;
        switch (parameters.own.lengthFilterMode)
        {
        case LENGTH_FILTER_INTERFRAME:
            return lsda::interFrameAlpha(keptCounts[0], keptCounts[1]);
        case LENGTH_FILTER_INTERFRAME_CONTINUOUS:
            return lsda::continuousInterFrameAlpha(keptCounts[0], keptCounts[1]);
        case LENGTH_FILTER_COUNT_TRACKING:
            return lsda::countTrackingAlpha(lsda::countLongOrStrong(in, responses, unitMinLength, unitMinResponse),
                                            keptCounts[0], keptCounts[1]);
        default:
            return 1.0;
        }
    }

    // Returns the stage's output: kept, or in itself when the filter is off (no copy). responses
    // are those of in, or empty when short segments are never kept for their response.
    const std::vector<Vec4f>& filterStage(const std::vector<Vec4f>& in, const std::vector<float>& responses,
                                          double unitMinLength, double unitMinResponse, LSDAdvanceStats& stats,
                                          std::vector<Vec4f>& kept)
    {
        const int64 t = getTickCount();
        const std::vector<Vec4f>* out = &in;
        if (parameters.own.lengthFilterMode != LENGTH_FILTER_NONE)
        {
            stats.alpha = frameAlpha(in, responses, unitMinLength, unitMinResponse);
            stats.minLength = stats.alpha * unitMinLength;
            stats.minResponse = responses.empty() ? 0.0 : stats.alpha * unitMinResponse;
            lsda::keepLongOrStrong(in, responses, stats.minLength, stats.minResponse, kept, &frame.keptFrom);
            followKept(frame.lineOf, frame.keptFrom, (int)in.size(), frame.into);
            out = &kept;
        }
        stats.filteredSegments = (int)out->size();
        stats.filterMs += elapsedMs(t);
        return *out;
    }

    // Returns the stage's output: merged, or in itself when merging is off (no copy).
    const std::vector<Vec4f>& mergeStage(const std::vector<Vec4f>& in, LSDAdvanceStats& stats,
                                         std::vector<Vec4f>& merged)
    {
        const Params& own = parameters.own;
        frame.grouped = own.mergeStrategy != MERGE_NONE;
        if (!frame.grouped)
        {
            stats.mergedSegments = (int)in.size();
            return in;
        }
        int64 t = getTickCount();
        lsda::SegmentGroups& groups = frame.groups;
        lsda::groupSegments(in, own, groups, frame.grouping);
        for (int g = 0; g < groups.count(); g++)
            stats.mergeGroups += groups.offsets[g + 1] - groups.offsets[g] > 1;
        stats.groupingMs = elapsedMs(t);

        t = getTickCount();
        lsda::mergeGroups(in, groups, own, merged, frame.into, frame.merging);
        followStage(frame.lineOf, frame.into);
        stats.mergedSegments = (int)merged.size();
        stats.mergingMs = elapsedMs(t);
        return merged;
    }

    lsda::Parameters parameters;
    Ptr<lsda::BaseSegmentDetector> baseSegments;  // built on first use after a base parameter changes
    // Buffers of the stages, kept from frame to frame so that a sequence does not allocate. They
    // also hold the last call's stage outputs (getLastStageOutputs): a stage that is off passes
    // its input on, so filtered and merged point into base, work or out.
    struct FrameWorkspace
    {
        std::vector<Vec4f> incoming;  // segments of the current call until its stages run
        std::vector<Vec4f> base, work, out, clipped;
        std::vector<float> baseResponses, mergedResponses;  // stage 1's responses (empty when unused)
        const std::vector<Vec4f>* filtered = nullptr;  // stage 1's output (nullptr before the first call)
        const std::vector<Vec4f>* merged = nullptr;    // stage 3's output
        const std::vector<Vec4f>* lines = nullptr;     // the returned lines
        bool grouped = false;                          // groups partition stage 2's input
        std::vector<int> lineOf;                       // the returned line each base segment is part of (-1: none)
        std::vector<int> keptFrom, into;               // how a stage's segments map to the next's
        lsda::SegmentGroups groups;
        lsda::GroupingWorkspace grouping;
        lsda::MergeWorkspace merging;
    } frame;
    int framesSeen = 0;
    int keptCounts[2] = { 0, 0 };  // kept by stage 1 in frames k-1 and k-2
    LSDAdvanceStats lastStats;
};

} // namespace

Ptr<LSDAdvance> createLSDAdvance(LSDAdvance::Preset preset)
{
    return makePtr<LSDAdvanceImpl>(presetParameters(preset));
}

}} // namespace cv::ximgproc
