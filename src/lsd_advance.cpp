// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LSDAdvance: its parameters (the tables of parameters.hpp), its sequence state, and the order of
// the stages (stages.hpp), whose outputs it keeps for getLastStageOutputs() and getLastSources().

#include "precomp.hpp"
#include "parameters.hpp"
#include "segment_merging.hpp"

namespace cv {
namespace ximgproc {

namespace {

double elapsedMs(int64 since)
{
    return (double)(getTickCount() - since) * 1000.0 / getTickFrequency();
}

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
        baseDetector->detectOnMask(gray, onMask, frame.incoming);
        runStages(elapsedMs(start), &gray, onMask, lines);
    }

    void processSegments(InputArray segments, OutputArray lines, Size imageSize, InputArray mask) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        CV_CheckGE(imageSize.width, 0, "LSDAdvance::processSegments: imageSize is empty or positive");
        CV_CheckGE(imageSize.height, 0, "LSDAdvance::processSegments: imageSize is empty or positive");
        if (imageSize.empty())
            imageSize = mask.size();  // the mask's image, or none
        const Mat onMask = lsda::toMask(mask, imageSize, "LSDAdvance::processSegments");
        lsda::toImageSegments(segments, "LSDAdvance::processSegments: segments", frame.incoming);
        if (!onMask.empty())
            lsda::cutAtMask(onMask, frame.incoming, frame.pieces);
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
        if (base.needed())
            Mat(frame.base).copyTo(base);
        if (filtered.needed())
            Mat(frame.filtered).copyTo(filtered);
        if (merged.needed())
            Mat(frame.merged).copyTo(merged);
        if (groupLabels.needed())
        {
            std::vector<int> labels;
            if (frame.grouped)
                lsda::groupLabels(frame.groups, labels);
            Mat(labels).copyTo(groupLabels);
        }
    }

    void getLastSources(OutputArrayOfArrays sources) const CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        frame.provenance.sources(lastStats.outputSegments, sources);
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
        lsda::Parameters p = parameters;
        lsda::readParameters(fn, p);  // validates every value before changing p
        parameters = p;
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

    // Stages 1-3 in the configured order on the segments in frame.incoming, which become the
    // frame's base segments, then the clipping to the image gray, or to an image of imageSize
    // when there is no gray (processSegments; none when imageSize is empty), then the selection.
    // Stage 3 fuses nothing across the mask (empty: none).
    void runStages(double baseMs, const Mat* gray, const Mat& mask, OutputArray lines, Size imageSize = Size())
    {
        if (gray)
            imageSize = gray->size();
        // Only a call that got this far replaces the previous call's stage outputs.
        frame.base.swap(frame.incoming);
        LSDAdvanceStats stats;
        stats.baseSegments = (int)frame.base.size();
        stats.baseMs = baseMs;
        frame.provenance.start(frame.base.size());
        frame.knownResponses.clear();
        const int64 t = getTickCount();
        frame.lengthFilter.measure(frame.base, gray, lsda::LengthFilterParams(parameters.own), frame.knownResponses);
        stats.filterMs = elapsedMs(t);

        const bool filterFirst = parameters.own.stageOrder == FILTER_THEN_MERGE;
        if (filterFirst)
            filterStage(frame.base, gray, frame.filtered, stats);
        mergeStage(filterFirst ? frame.filtered : frame.base, mask, frame.merged, stats);
        if (!filterFirst)
            filterStage(frame.merged, gray, frame.filtered, stats);
        const std::vector<Vec4f>& last = filterFirst ? frame.merged : frame.filtered;

        if (!imageSize.empty())
        {
            lsda::clipToImage(last, imageSize, frame.clipped, frame.keptFrom);
            frame.provenance.followKept(frame.keptFrom, last.size());
            frame.knownResponses.followKept(last, frame.clipped, frame.keptFrom);
        }
        const std::vector<Vec4f>& unselected = imageSize.empty() ? last : frame.clipped;

        const int64 s = getTickCount();
        frame.selection.apply(unselected, gray, lsda::SelectionParams(parameters.own), imageSize, frame.knownResponses,
                              frame.selected, frame.responses, frame.keptFrom);
        frame.provenance.followKept(frame.keptFrom, unselected.size());
        stats.selectionMs = elapsedMs(s);
        stats.outputSegments = (int)frame.selected.size();
        stats.frameInSequence = framesInSequence;
        Mat(frame.selected).copyTo(lines);
        history.add(stats.filteredSegments);  // the frame counts only once its output is delivered
        framesInSequence++;
        lastStats = stats;
    }

    void filterStage(const std::vector<Vec4f>& in, const Mat* gray, std::vector<Vec4f>& kept, LSDAdvanceStats& stats)
    {
        const int64 t = getTickCount();
        frame.lengthFilter.apply(in, gray, history, frame.knownResponses, kept, frame.keptFrom, stats);
        frame.provenance.followKept(frame.keptFrom, in.size());
        frame.knownResponses.followKept(in, kept, frame.keptFrom);
        stats.filterMs += elapsedMs(t);
    }

    void mergeStage(const std::vector<Vec4f>& in, const Mat& mask, std::vector<Vec4f>& merged, LSDAdvanceStats& stats)
    {
        const lsda::MergingParams merging(parameters.own);
        frame.grouped = merging.mergeStrategy != MERGE_NONE;  // with MERGE_NONE, stages 2 and 3 are skipped
        if (!frame.grouped)
        {
            merged = in;
            stats.mergedSegments = (int)in.size();
            return;
        }
        int64 t = getTickCount();
        lsda::groupSegments(in, lsda::GroupingParams(parameters.own), frame.groups, frame.grouping);
        stats.mergeGroups = lsda::mergeGroupCount(frame.groups);
        stats.groupingMs = elapsedMs(t);
        t = getTickCount();
        lsda::mergeGroups(in, frame.groups, merging, merged, frame.mergedInto, frame.merging, mask);
        frame.provenance.followMerged(frame.mergedInto);
        frame.knownResponses.followMerged(in, merged, frame.mergedInto);
        stats.mergedSegments = (int)merged.size();
        stats.mergingMs = elapsedMs(t);
    }

    lsda::Parameters parameters;
    Ptr<lsda::BaseSegmentDetector> baseDetector;  // built on first use after a base parameter changes
    // The last call's stage outputs (a stage that is off copies its input), and the buffers of the
    // stages, kept from frame to frame so that a sequence does not allocate.
    struct Frame
    {
        std::vector<Vec4f> incoming;  // segments of the current call until its stages run
        std::vector<Vec4f> pieces;    // a buffer of the cut at the mask
        std::vector<Vec4f> base, filtered, merged, clipped, selected;
        std::vector<float> responses;  // of the selected lines, with an image
        bool grouped = false;         // groups partition stage 2's input
        lsda::SegmentGroups groups;
        std::vector<int> keptFrom, mergedInto;
        lsda::SegmentProvenance provenance;
        lsda::KnownResponses knownResponses;
        lsda::LengthFilter lengthFilter;
        lsda::GroupingWorkspace grouping;
        lsda::MergeWorkspace merging;
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
