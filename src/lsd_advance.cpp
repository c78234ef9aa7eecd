// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LSDAdvance: its parameters (the tables of parameters.hpp), its sequence state, and the order of
// the stages (stages.hpp), whose outputs it keeps for getLastStageOutputs() and getLastSources().

#include "precomp.hpp"
#include "parameters.hpp"

namespace cv {
namespace ximgproc {

namespace {

class LSDAdvanceImpl CV_FINAL : public LSDAdvance
{
public:
    explicit LSDAdvanceImpl(const lsda::Parameters& p) : parameters(p) {}

    void detect(InputArray image, OutputArray lines, InputArray mask) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        const int64 start = getTickCount();
        const Mat gray = lsda::toGray8U(image);
        const Mat onMask = lsda::toMask(mask, gray.size(), "LSDAdvance::detect");
        if (!baseDetector)
            baseDetector = lsda::createBaseDetector(parameters.own.baseDetector, parameters.lsd, parameters.fld,
                                                    parameters.edLines);
        baseDetector->detectReadingMask(gray, onMask, frame.incoming);
        runStages(lsda::elapsedMs(start), &gray, onMask, lines);
    }

    void processSegments(InputArray segments, OutputArray lines, Size imageSize, InputArray mask) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        CV_Check(imageSize, imageSize.width >= 0 && imageSize.height >= 0,
                 "LSDAdvance::processSegments: imageSize is empty or positive");
        if (imageSize.empty())
            imageSize = mask.size();  // the mask's image, or none
        const Mat onMask = lsda::toMask(mask, imageSize, "LSDAdvance::processSegments");
        lsda::toImageSegments(segments, "LSDAdvance::processSegments: segments", frame.incoming);
        runStages(0.0, nullptr, onMask, lines, imageSize);
    }

    void drawSegments(InputOutputArray image, InputArray lines) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        lsda::drawSegments(image, lines);
    }

    void reset() CV_OVERRIDE
    {
        history = lsda::KeptCounts();
        framesInSequence = 0;
    }

    LSDAdvanceStats getLastStats() const CV_OVERRIDE { return lastStats; }

    void getLastResponses(OutputArray responses) const CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        Mat(frame.responses).copyTo(responses);
    }

    void getLastStageOutputs(OutputArray base, OutputArray filtered, OutputArray groupLabels,
                             OutputArray merged) const CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        // Only the outputs asked for (noArray() for the others).
        for (const auto& out : { std::make_pair(&frame.base, &base), std::make_pair(&frame.filtered, &filtered),
                                 std::make_pair(&frame.merged, &merged) })
            if (out.second->needed())
                Mat(*out.first).copyTo(*out.second);
        if (groupLabels.needed())
        {
            std::vector<int> labels;
            frame.merge.labels(labels);
            Mat(labels).copyTo(groupLabels);
        }
    }

    void getLastSources(OutputArrayOfArrays sources) const CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        frame.trace.sources(lastStats.outputSegments, sources);
    }

    Params getParams() const CV_OVERRIDE { return parameters.own; }
    void setParams(const Params& p) CV_OVERRIDE { set(parameters.own, p, p.baseDetector != parameters.own.baseDetector); }
    LSDParams getLSDParams() const CV_OVERRIDE { return parameters.lsd; }
    void setLSDParams(const LSDParams& p) CV_OVERRIDE { set(parameters.lsd, p, true); }
    FLDParams getFLDParams() const CV_OVERRIDE { return parameters.fld; }
    void setFLDParams(const FLDParams& p) CV_OVERRIDE { set(parameters.fld, p, true); }
    EdgeDrawing::Params getEDLinesParams() const CV_OVERRIDE { return parameters.edLines; }
    void setEDLinesParams(const EdgeDrawing::Params& p) CV_OVERRIDE { set(parameters.edLines, p, true); }

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
        lsda::readParameters(fn, parameters);  // validates every value before changing any
        baseDetector.release();
        reset();
    }

    String getDefaultName() const CV_OVERRIDE { return "LSDAdvance"; }

private:
    // Every setter: all fields validated before any changes; a new sequence.
    template <class S>
    void set(S& current, const S& p, bool baseChanges)
    {
        lsda::validate(p);
        if (baseChanges)
            baseDetector.release();
        current = p;
        reset();
    }

    // Stages 1-3 in the configured order on frame.incoming cut at the mask (empty: none), the base
    // segments; then the clipping to gray's size or imageSize (processSegments; none when empty) and
    // the selection. Stage 3 fuses nothing across the mask. The trace follows every stage once.
    void runStages(double baseMs, const Mat* gray, const Mat& mask, OutputArray lines, Size imageSize = Size())
    {
        if (gray)
            imageSize = gray->size();
        if (!mask.empty())
            lsda::cutAtMask(mask, frame.incoming, frame.pieces);
        // Only a call that got this far replaces the previous call's stage outputs.
        frame.base.swap(frame.incoming);
        LSDAdvanceStats stats;
        stats.baseSegments = (int)frame.base.size();
        stats.baseMs = baseMs;
        frame.trace.start(frame.base);
        frame.lengthFilter.measure(frame.base, gray, lsda::LengthFilterParams(parameters.own), frame.trace.responses,
                                   stats);
        const bool filterFirst = parameters.own.stageOrder == FILTER_THEN_MERGE;
        if (filterFirst)
            filterStage(frame.base, gray, frame.filtered, stats);
        const std::vector<Vec4f>& toMerge = filterFirst ? frame.filtered : frame.base;
        frame.merge.apply(toMerge, lsda::GroupingParams(parameters.own), lsda::MergingParams(parameters.own), mask,
                          frame.merged, stats);
        frame.trace.followMerged(toMerge, frame.merged, frame.merge.mergedInto());
        if (!filterFirst)
            filterStage(frame.merged, gray, frame.filtered, stats);
        const std::vector<Vec4f>& last = filterFirst ? frame.merged : frame.filtered;

        if (!imageSize.empty())
        {
            lsda::clipToImage(last, imageSize, frame.clipped, frame.keptFrom);
            frame.trace.followKept(last, frame.clipped, frame.keptFrom);
        }
        const std::vector<Vec4f>& unselected = imageSize.empty() ? last : frame.clipped;
        const int64 s = getTickCount();
        frame.selection.apply(unselected, gray, lsda::SelectionParams(parameters.own), imageSize, frame.trace.responses,
                              frame.selected, frame.responses, frame.keptFrom);
        frame.trace.followSelected(frame.keptFrom, unselected.size());
        stats.selectionMs = lsda::elapsedMs(s);
        stats.outputSegments = (int)frame.selected.size();
        stats.frameInSequence = framesInSequence;
        Mat(frame.selected).copyTo(lines);
        history.add(stats.filteredSegments);  // the frame counts only once its output is delivered
        framesInSequence++;
        lastStats = stats;
    }

    void filterStage(const std::vector<Vec4f>& in, const Mat* gray, std::vector<Vec4f>& kept, LSDAdvanceStats& stats)
    {
        frame.lengthFilter.apply(in, gray, history, frame.trace.responses, kept, frame.keptFrom, stats);
        frame.trace.followKept(in, kept, frame.keptFrom);
    }

    lsda::Parameters parameters;
    Ptr<lsda::BaseSegmentDetector> baseDetector;  // built on first use after a base parameter changes
    // The last call's stage outputs (a stage that is off copies its input) and the stages' buffers,
    // kept from frame to frame so that a sequence does not allocate.
    struct Frame
    {
        std::vector<Vec4f> incoming;  // segments of the current call until its stages run
        std::vector<Vec4f> pieces;    // a buffer of the cut at the mask
        std::vector<Vec4f> base, filtered, merged, clipped, selected;
        std::vector<float> responses;  // of the selected lines, with an image
        std::vector<int> keptFrom;
        lsda::StageTrace trace;
        lsda::LengthFilter lengthFilter;
        lsda::MergeStage merge;
        lsda::LineSelection selection;
    } frame;
    lsda::KeptCounts history;  // the sequence state
    int framesInSequence = 0;
    LSDAdvanceStats lastStats;
};

} // namespace

Ptr<LSDAdvance> createLSDAdvance(LSDAdvance::Preset preset)
{
    return makePtr<LSDAdvanceImpl>(lsda::presetParameters(preset));
}

}} // namespace cv::ximgproc
