// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LSDAdvance: parameters and their validation, persistence, sequence state, and the order of
// the stages. The stages themselves are in length_filter.cpp, segment_grouping.cpp and
// segment_merging.cpp.

#include "precomp.hpp"
#include "opencv2/ximgproc/edge_drawing.hpp"  // EdgeDrawing::GradientOperator

namespace cv {
namespace ximgproc {

namespace {

// Larger coordinates are not image coordinates; bounding them keeps the grouping grid's cells
// within 32 bits.
constexpr double kMaxCoordinate = 1e7;

// The valid range of a parameter; the bounds are excluded where loOpen / hiOpen.
struct ParamRange
{
    const char* name;
    double lo;
    bool loOpen;
    double hi;
    bool hiOpen;
    const char* unit;
};

constexpr ParamRange kLsdScale = { "lsdScale", 0, true, 1, false, "" };
constexpr ParamRange kLsdSigmaScale = { "lsdSigmaScale", 0, true, 100, false, "" };
constexpr ParamRange kLsdQuant = { "lsdQuant", 0, false, 255, false, "" };
constexpr ParamRange kLsdAngleTolerance = { "lsdAngleTolerance", 0, true, 180, true, " deg" };
constexpr ParamRange kLsdLogEps = { "lsdLogEps", -1000, false, 1000, false, "" };
constexpr ParamRange kLsdDensityThreshold = { "lsdDensityThreshold", 0, false, 1, true, "" };
constexpr ParamRange kLsdNumBins = { "lsdNumBins", 1, false, 65536, false, "" };
constexpr ParamRange kFldLengthThreshold = { "fldLengthThreshold", 1, false, 100000, false, " px" };
constexpr ParamRange kFldDistanceThreshold = { "fldDistanceThreshold", 0, true, 100, false, " px" };
constexpr ParamRange kFldCannyThreshold1 = { "fldCannyThreshold1", 0, true, 100000, false, "" };
constexpr ParamRange kFldCannyThreshold2 = { "fldCannyThreshold2", 0, true, 100000, false, "" };
constexpr ParamRange kEdGradientThreshold = { "edGradientThreshold", 1, false, 10000, false, "" };
constexpr ParamRange kEdAnchorThreshold = { "edAnchorThreshold", 0, false, 10000, false, "" };
constexpr ParamRange kEdScanInterval = { "edScanInterval", 1, false, 100, false, "" };
constexpr ParamRange kEdMinPathLength = { "edMinPathLength", 2, false, 100000, false, " px" };
constexpr ParamRange kEdSigma = { "edSigma", 0, false, 100, false, "" };
constexpr ParamRange kEdMinLineLength = { "edMinLineLength (or -1: from the image size)", 9, false, 100000, false, " px" };
constexpr ParamRange kEdLineFitErrorThreshold = { "edLineFitErrorThreshold", 0, true, 100, false, " px" };
constexpr ParamRange kEdMaxDistanceBetweenTwoLines = { "edMaxDistanceBetweenTwoLines", 0, true, 1000, false, " px" };
constexpr ParamRange kEdMaxErrorThreshold = { "edMaxErrorThreshold", 0, true, 100, false, " px" };
constexpr ParamRange kAngleBinWidth = { "angleBinWidth", 1, false, 90, false, " deg" };
constexpr ParamRange kEndpointDistance = { "endpointDistance", 0.1, false, 200, false, " px" };
constexpr ParamRange kBaselineRatio = { "baselineRatio", 0, true, 1, false, "" };
constexpr ParamRange kDirectionWeight = { "directionWeight", 0, false, 1, false, "" };
constexpr ParamRange kProximityWeight = { "proximityWeight", 0, false, 1, false, "" };
constexpr ParamRange kLengthWeight = { "lengthWeight", 0, false, 1, false, "" };
constexpr ParamRange kProximityRatio = { "proximityRatio", 0, true, 10, false, "" };
constexpr ParamRange kMergeThreshold = { "mergeThreshold", 0, false, 1, false, "" };
constexpr ParamRange kMaxPerpendicularOffset = { "maxPerpendicularOffset", 0, false, 100, false, " px" };
constexpr ParamRange kLengthThresholdScale = { "lengthThresholdScale", 0, true, 10, false, "" };

// Validates value against its range (finite, inside the bounds) and stores it.
template <typename T>
void assign(T& field, T value, const ParamRange& r)
{
    const double v = (double)value;
    const bool ok = std::isfinite(v) && (r.loOpen ? v > r.lo : v >= r.lo) &&
                    (r.hiOpen ? v < r.hi : v <= r.hi);
    if (!ok)
        CV_Error_(Error::StsOutOfRange,
                  ("LSDAdvance: %s must be a finite number in %c%g, %g%c%s, got %.10g", r.name,
                   r.loOpen ? '(' : '[', r.lo, r.hi, r.hiOpen ? ')' : ']', r.unit, v));
    field = value;
}

// Validates an enumerated value (first..last) and stores it.
void assignEnum(int& field, int value, const char* name, int first, int last, const char* names)
{
    if (value < first || value > last)
        CV_Error_(Error::StsOutOfRange,
                  ("LSDAdvance: %s must be one of %s (%d..%d), got %d", name, names, first, last, value));
    field = value;
}

double elapsedMs(int64 since)
{
    return (double)(getTickCount() - since) * 1000.0 / getTickFrequency();
}

class LSDAdvanceImpl CV_FINAL : public LSDAdvance
{
public:
    LSDAdvanceImpl() {}
    // Not copyable: frame holds pointers into itself.
    LSDAdvanceImpl(const LSDAdvanceImpl&) = delete;
    LSDAdvanceImpl& operator=(const LSDAdvanceImpl&) = delete;

    void detect(InputArray image, OutputArray lines) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        const int64 start = getTickCount();
        const Mat gray = lsda::toGray8U(image);
        if (!baseSegments)
            baseSegments = lsda::createBaseDetector((lsda::BaseKind)baseDetector, lsd, fld, ed);
        // LSD's resize throws on an image that scales to no pixel; such an image has no segment.
        if (baseDetector != BASE_LSD ||
            (saturate_cast<int>(gray.cols * lsd.scale) > 0 && saturate_cast<int>(gray.rows * lsd.scale) > 0))
            baseSegments->detect(gray, frame.incoming);
        else
            frame.incoming.clear();
        runStages(elapsedMs(start), lines);
    }

    void processSegments(InputArray segments, OutputArray lines) CV_OVERRIDE
    {
        CV_INSTRUMENT_REGION();
        lsda::toSegments(segments, "LSDAdvance::processSegments: segments", frame.incoming);
        if (!checkRange(Mat(frame.incoming), true, nullptr, -kMaxCoordinate, kMaxCoordinate))
            CV_Error_(Error::StsOutOfRange,
                      ("LSDAdvance::processSegments: segment coordinates must be finite and within "
                       "[-%g, %g) px", kMaxCoordinate, kMaxCoordinate));
        runStages(0.0, lines);
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

    void setLsdRefine(int v) CV_OVERRIDE
    {
        assignEnum(lsd.refine, v, "lsdRefine", LSD_REFINE_NONE, LSD_REFINE_ADV,
                   "LSD_REFINE_NONE, LSD_REFINE_STD, LSD_REFINE_ADV");
        baseDetectorChanged();
    }
    int getLsdRefine() const CV_OVERRIDE { return lsd.refine; }
    void setLsdScale(double v) CV_OVERRIDE { assign(lsd.scale, v, kLsdScale); baseDetectorChanged(); }
    double getLsdScale() const CV_OVERRIDE { return lsd.scale; }
    void setLsdSigmaScale(double v) CV_OVERRIDE { assign(lsd.sigmaScale, v, kLsdSigmaScale); baseDetectorChanged(); }
    double getLsdSigmaScale() const CV_OVERRIDE { return lsd.sigmaScale; }
    void setLsdQuant(double v) CV_OVERRIDE { assign(lsd.quant, v, kLsdQuant); baseDetectorChanged(); }
    double getLsdQuant() const CV_OVERRIDE { return lsd.quant; }
    void setLsdAngleTolerance(double v) CV_OVERRIDE { assign(lsd.angleTolerance, v, kLsdAngleTolerance); baseDetectorChanged(); }
    double getLsdAngleTolerance() const CV_OVERRIDE { return lsd.angleTolerance; }
    void setLsdLogEps(double v) CV_OVERRIDE { assign(lsd.logEps, v, kLsdLogEps); baseDetectorChanged(); }
    double getLsdLogEps() const CV_OVERRIDE { return lsd.logEps; }
    void setLsdDensityThreshold(double v) CV_OVERRIDE { assign(lsd.densityThreshold, v, kLsdDensityThreshold); baseDetectorChanged(); }
    double getLsdDensityThreshold() const CV_OVERRIDE { return lsd.densityThreshold; }
    void setLsdNumBins(int v) CV_OVERRIDE { assign(lsd.numBins, v, kLsdNumBins); baseDetectorChanged(); }
    int getLsdNumBins() const CV_OVERRIDE { return lsd.numBins; }

    void setBaseDetector(int v) CV_OVERRIDE
    {
        assignEnum(baseDetector, v, "baseDetector", BASE_LSD, BASE_FAST_LSD,
                   "BASE_LSD, BASE_FLD, BASE_EDLINES, BASE_FAST_LSD");
        baseDetectorChanged();
    }
    int getBaseDetector() const CV_OVERRIDE { return baseDetector; }

    void setFldLengthThreshold(int v) CV_OVERRIDE { assign(fld.lengthThreshold, v, kFldLengthThreshold); baseDetectorChanged(); }
    int getFldLengthThreshold() const CV_OVERRIDE { return fld.lengthThreshold; }
    void setFldDistanceThreshold(double v) CV_OVERRIDE { assign(fld.distanceThreshold, v, kFldDistanceThreshold); baseDetectorChanged(); }
    double getFldDistanceThreshold() const CV_OVERRIDE { return fld.distanceThreshold; }
    void setFldCannyThreshold1(double v) CV_OVERRIDE { assign(fld.cannyThreshold1, v, kFldCannyThreshold1); baseDetectorChanged(); }
    double getFldCannyThreshold1() const CV_OVERRIDE { return fld.cannyThreshold1; }
    void setFldCannyThreshold2(double v) CV_OVERRIDE { assign(fld.cannyThreshold2, v, kFldCannyThreshold2); baseDetectorChanged(); }
    double getFldCannyThreshold2() const CV_OVERRIDE { return fld.cannyThreshold2; }
    void setFldCannyApertureSize(int v) CV_OVERRIDE
    {
        if (v != 3 && v != 5 && v != 7)
            CV_Error_(Error::StsOutOfRange, ("LSDAdvance: fldCannyApertureSize must be 3, 5 or 7, got %d", v));
        fld.cannyApertureSize = v;
        baseDetectorChanged();
    }
    int getFldCannyApertureSize() const CV_OVERRIDE { return fld.cannyApertureSize; }
    void setFldDoMerge(bool v) CV_OVERRIDE { fld.doMerge = v; baseDetectorChanged(); }
    bool getFldDoMerge() const CV_OVERRIDE { return fld.doMerge; }

    void setEdGradientOperator(int v) CV_OVERRIDE
    {
        assignEnum(ed.gradientOperator, v, "edGradientOperator", EdgeDrawing::PREWITT,
                   EdgeDrawing::LSD, "PREWITT, SOBEL, SCHARR, LSD of EdgeDrawing::GradientOperator");
        baseDetectorChanged();
    }
    int getEdGradientOperator() const CV_OVERRIDE { return ed.gradientOperator; }
    void setEdGradientThreshold(int v) CV_OVERRIDE { assign(ed.gradientThreshold, v, kEdGradientThreshold); baseDetectorChanged(); }
    int getEdGradientThreshold() const CV_OVERRIDE { return ed.gradientThreshold; }
    void setEdAnchorThreshold(int v) CV_OVERRIDE { assign(ed.anchorThreshold, v, kEdAnchorThreshold); baseDetectorChanged(); }
    int getEdAnchorThreshold() const CV_OVERRIDE { return ed.anchorThreshold; }
    void setEdScanInterval(int v) CV_OVERRIDE { assign(ed.scanInterval, v, kEdScanInterval); baseDetectorChanged(); }
    int getEdScanInterval() const CV_OVERRIDE { return ed.scanInterval; }
    void setEdMinPathLength(int v) CV_OVERRIDE { assign(ed.minPathLength, v, kEdMinPathLength); baseDetectorChanged(); }
    int getEdMinPathLength() const CV_OVERRIDE { return ed.minPathLength; }
    void setEdSigma(double v) CV_OVERRIDE { assign(ed.sigma, v, kEdSigma); baseDetectorChanged(); }
    double getEdSigma() const CV_OVERRIDE { return ed.sigma; }
    void setEdNfaValidation(bool v) CV_OVERRIDE { ed.nfaValidation = v; baseDetectorChanged(); }
    bool getEdNfaValidation() const CV_OVERRIDE { return ed.nfaValidation; }
    void setEdMinLineLength(int v) CV_OVERRIDE
    {
        if (v != -1)
            assign(ed.minLineLength, v, kEdMinLineLength);
        ed.minLineLength = v;
        baseDetectorChanged();
    }
    int getEdMinLineLength() const CV_OVERRIDE { return ed.minLineLength; }
    void setEdLineFitErrorThreshold(double v) CV_OVERRIDE { assign(ed.lineFitErrorThreshold, v, kEdLineFitErrorThreshold); baseDetectorChanged(); }
    double getEdLineFitErrorThreshold() const CV_OVERRIDE { return ed.lineFitErrorThreshold; }
    void setEdMaxDistanceBetweenTwoLines(double v) CV_OVERRIDE
    {
        assign(ed.maxDistanceBetweenTwoLines, v, kEdMaxDistanceBetweenTwoLines);
        baseDetectorChanged();
    }
    double getEdMaxDistanceBetweenTwoLines() const CV_OVERRIDE { return ed.maxDistanceBetweenTwoLines; }
    void setEdMaxErrorThreshold(double v) CV_OVERRIDE { assign(ed.maxErrorThreshold, v, kEdMaxErrorThreshold); baseDetectorChanged(); }
    double getEdMaxErrorThreshold() const CV_OVERRIDE { return ed.maxErrorThreshold; }

    void setLengthFilterMode(int v) CV_OVERRIDE
    {
        assignEnum(lengthFilterMode, v, "lengthFilterMode", LENGTH_FILTER_NONE, LENGTH_FILTER_COUNT_TRACKING,
                   "LENGTH_FILTER_NONE, LENGTH_FILTER_ADAPTIVE, LENGTH_FILTER_INTERFRAME, "
                   "LENGTH_FILTER_INTERFRAME_CONTINUOUS, LENGTH_FILTER_COUNT_TRACKING");
        reset();
    }
    int getLengthFilterMode() const CV_OVERRIDE { return lengthFilterMode; }

    void setLengthThreshold(int v) CV_OVERRIDE
    {
        int rule;
        assignEnum(rule, v, "lengthThreshold", LENGTH_THRESHOLD_PAPER, LENGTH_THRESHOLD_CAPPED,
                   "LENGTH_THRESHOLD_PAPER, LENGTH_THRESHOLD_CAPPED");
        lengthThreshold = (lsda::LengthThreshold)rule;
        reset();
    }
    int getLengthThreshold() const CV_OVERRIDE { return (int)lengthThreshold; }
    void setLengthThresholdScale(double v) CV_OVERRIDE { assign(lengthThresholdScale, v, kLengthThresholdScale); reset(); }
    double getLengthThresholdScale() const CV_OVERRIDE { return lengthThresholdScale; }

    void setMergeStrategy(int v) CV_OVERRIDE
    {
        int strategy;
        assignEnum(strategy, v, "mergeStrategy", MERGE_NONE, MERGE_LONGEST_FIRST,
                   "MERGE_NONE, MERGE_BASELINES, MERGE_LONGEST_FIRST");
        merging.strategy = (lsda::MergeStrategy)strategy;
        reset();
    }
    int getMergeStrategy() const CV_OVERRIDE { return (int)merging.strategy; }
    void setStageOrder(int v) CV_OVERRIDE
    {
        assignEnum(stageOrder, v, "stageOrder", FILTER_THEN_MERGE, MERGE_THEN_FILTER,
                   "FILTER_THEN_MERGE, MERGE_THEN_FILTER");
        reset();
    }
    int getStageOrder() const CV_OVERRIDE { return stageOrder; }

    void setAngleBinWidth(double v) CV_OVERRIDE { assign(grouping.angleBinWidth, v, kAngleBinWidth); reset(); }
    double getAngleBinWidth() const CV_OVERRIDE { return grouping.angleBinWidth; }
    void setAngleBinning(int v) CV_OVERRIDE
    {
        int binning;
        assignEnum(binning, v, "angleBinning", ANGLE_BINS_STRICT, ANGLE_BINS_NEIGHBOURS,
                   "ANGLE_BINS_STRICT, ANGLE_BINS_NEIGHBOURS");
        grouping.neighbourBins = binning == ANGLE_BINS_NEIGHBOURS;
        reset();
    }
    int getAngleBinning() const CV_OVERRIDE
    {
        return grouping.neighbourBins ? ANGLE_BINS_NEIGHBOURS : ANGLE_BINS_STRICT;
    }
    void setEndpointDistance(double v) CV_OVERRIDE { assign(grouping.endpointDistance, v, kEndpointDistance); reset(); }
    double getEndpointDistance() const CV_OVERRIDE { return grouping.endpointDistance; }

    void setBaselineRatio(double v) CV_OVERRIDE { assign(merging.baselineRatio, v, kBaselineRatio); reset(); }
    double getBaselineRatio() const CV_OVERRIDE { return merging.baselineRatio; }
    void setDirectionWeight(double v) CV_OVERRIDE { assign(merging.directionWeight, v, kDirectionWeight); reset(); }
    double getDirectionWeight() const CV_OVERRIDE { return merging.directionWeight; }
    void setProximityWeight(double v) CV_OVERRIDE { assign(merging.proximityWeight, v, kProximityWeight); reset(); }
    double getProximityWeight() const CV_OVERRIDE { return merging.proximityWeight; }
    void setLengthWeight(double v) CV_OVERRIDE { assign(merging.lengthWeight, v, kLengthWeight); reset(); }
    double getLengthWeight() const CV_OVERRIDE { return merging.lengthWeight; }
    void setProximityRatio(double v) CV_OVERRIDE { assign(merging.proximityRatio, v, kProximityRatio); reset(); }
    double getProximityRatio() const CV_OVERRIDE { return merging.proximityRatio; }
    void setMergeThreshold(double v) CV_OVERRIDE { assign(merging.mergeThreshold, v, kMergeThreshold); reset(); }
    double getMergeThreshold() const CV_OVERRIDE { return merging.mergeThreshold; }
    void setMaxPerpendicularOffset(double v) CV_OVERRIDE { assign(merging.maxPerpendicularOffset, v, kMaxPerpendicularOffset); reset(); }
    double getMaxPerpendicularOffset() const CV_OVERRIDE { return merging.maxPerpendicularOffset; }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeFormat(fs);
        for (const IntParam& p : intParams())
            fs << p.name << (this->*p.get)();
        for (const RealParam& p : realParams())
            fs << p.name << (this->*p.get)();
        for (const BoolParam& p : boolParams())
            fs << p.name << (int)(this->*p.get)();
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        // Validity does not depend on other parameters: checking every value on a scratch object
        // first means a bad file throws before this object changes.
        LSDAdvanceImpl scratch;
        scratch.apply(fn);
        apply(fn);
    }

    String getDefaultName() const CV_OVERRIDE { return "LSDAdvance"; }

private:
    void apply(const FileNode& fn)
    {
        for (const IntParam& p : intParams())
        {
            const FileNode node = fn[p.name];
            if (node.empty())
                continue;
            if (!node.isInt())
                CV_Error_(Error::StsParseError,
                          ("LSDAdvance::read: %s must be an integer", p.name));
            (this->*p.set)((int)node);
        }
        for (const RealParam& p : realParams())
        {
            const FileNode node = fn[p.name];
            if (node.empty())
                continue;
            if (!node.isReal() && !node.isInt())
                CV_Error_(Error::StsParseError, ("LSDAdvance::read: %s must be a number", p.name));
            (this->*p.set)((double)node);
        }
        for (const BoolParam& p : boolParams())
        {
            const FileNode node = fn[p.name];
            if (node.empty())
                continue;
            if (!node.isInt() || ((int)node != 0 && (int)node != 1))
                CV_Error_(Error::StsParseError, ("LSDAdvance::read: %s must be 0 or 1", p.name));
            (this->*p.set)((int)node != 0);
        }
    }

    struct IntParam
    {
        const char* name;
        int (LSDAdvanceImpl::*get)() const;
        void (LSDAdvanceImpl::*set)(int);
    };
    struct RealParam
    {
        const char* name;
        double (LSDAdvanceImpl::*get)() const;
        void (LSDAdvanceImpl::*set)(double);
    };
    struct BoolParam  // stored as the integer 0 or 1
    {
        const char* name;
        bool (LSDAdvanceImpl::*get)() const;
        void (LSDAdvanceImpl::*set)(bool);
    };

    // Stages 1-3 in the configured order on the segments in frame.incoming, which become the
    // frame's base segments; fills lastStats and the stage outputs of getLastStageOutputs.
    void runStages(double baseMs, OutputArray lines)
    {
        // Only a call that got this far replaces the previous call's stage outputs.
        frame.base.swap(frame.incoming);
        const std::vector<Vec4f>& base = frame.base;
        LSDAdvanceStats stats;
        stats.baseSegments = (int)base.size();
        stats.baseMs = baseMs;

        // The threshold always comes from the base segments: after merging, the lengths are
        // no longer those of one detector's output. Every rule is proportional to alpha.
        const int64 t = getTickCount();
        const double unitMinLength = lengthFilterMode == LENGTH_FILTER_NONE
                                         ? 0.0
                                         : lengthThresholdScale * lsda::adaptiveMinLength(base, 1.0, lengthThreshold);
        stats.filterMs = elapsedMs(t);

        if (stageOrder == FILTER_THEN_MERGE)
        {
            frame.filtered = &filterStage(base, unitMinLength, stats, frame.work);
            frame.merged = &mergeStage(*frame.filtered, stats, frame.out);
        }
        else
        {
            frame.merged = &mergeStage(base, stats, frame.work);
            frame.filtered = &filterStage(*frame.merged, unitMinLength, stats, frame.out);
        }
        const std::vector<Vec4f>& out = stageOrder == FILTER_THEN_MERGE ? *frame.merged : *frame.filtered;
        stats.outputSegments = (int)out.size();
        Mat(out).copyTo(lines);
        // The frame counts only once its output is delivered.
        keptCounts[1] = keptCounts[0];
        keptCounts[0] = stats.filteredSegments;
        framesSeen = std::min(framesSeen + 1, 2);
        lastStats = stats;
    }

    // alpha of this frame; the kept counts of the two previous frames are keptCounts.
    double frameAlpha(const std::vector<Vec4f>& in, double unitMinLength) const
    {
        if (framesSeen < 2)
            return 1.0;
        switch (lengthFilterMode)
        {
        case LENGTH_FILTER_INTERFRAME:
            return lsda::interFrameAlpha(keptCounts[0], keptCounts[1]);
        case LENGTH_FILTER_INTERFRAME_CONTINUOUS:
            return lsda::continuousInterFrameAlpha(keptCounts[0], keptCounts[1]);
        case LENGTH_FILTER_COUNT_TRACKING:
            return lsda::countTrackingAlpha(lsda::countAtLeast(in, unitMinLength), keptCounts[0], keptCounts[1]);
        default:
            return 1.0;
        }
    }

    // Returns the stage's output: kept, or in itself when the filter is off (no copy).
    const std::vector<Vec4f>& filterStage(const std::vector<Vec4f>& in, double unitMinLength,
                                          LSDAdvanceStats& stats, std::vector<Vec4f>& kept) const
    {
        const int64 t = getTickCount();
        const std::vector<Vec4f>* out = &in;
        if (lengthFilterMode != LENGTH_FILTER_NONE)
        {
            stats.alpha = frameAlpha(in, unitMinLength);
            stats.minLength = stats.alpha * unitMinLength;
            lsda::dropShortSegments(in, stats.minLength, kept);
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
        frame.grouped = merging.strategy != lsda::MergeStrategy::NONE;
        if (!frame.grouped)
        {
            stats.mergedSegments = (int)in.size();
            return in;
        }
        int64 t = getTickCount();
        lsda::SegmentGroups& groups = frame.groups;
        lsda::groupSegments(in, grouping, groups, frame.grouping);
        for (int g = 0; g < groups.count(); g++)
            stats.mergeGroups += groups.offsets[g + 1] - groups.offsets[g] > 1;
        stats.groupingMs = elapsedMs(t);

        t = getTickCount();
        lsda::mergeGroups(in, groups, merging, merged, frame.merging);
        stats.mergedSegments = (int)merged.size();
        stats.mergingMs = elapsedMs(t);
        return merged;
    }

    // The persisted parameters: one table drives write() and read().
    static const std::vector<IntParam>& intParams()
    {
        static const std::vector<IntParam> params = {
            { "lsdRefine", &LSDAdvanceImpl::getLsdRefine, &LSDAdvanceImpl::setLsdRefine },
            { "lsdNumBins", &LSDAdvanceImpl::getLsdNumBins, &LSDAdvanceImpl::setLsdNumBins },
            { "lengthFilterMode", &LSDAdvanceImpl::getLengthFilterMode, &LSDAdvanceImpl::setLengthFilterMode },
            { "angleBinning", &LSDAdvanceImpl::getAngleBinning, &LSDAdvanceImpl::setAngleBinning },
            { "lengthThreshold", &LSDAdvanceImpl::getLengthThreshold, &LSDAdvanceImpl::setLengthThreshold },
            { "mergeStrategy", &LSDAdvanceImpl::getMergeStrategy, &LSDAdvanceImpl::setMergeStrategy },
            { "stageOrder", &LSDAdvanceImpl::getStageOrder, &LSDAdvanceImpl::setStageOrder },
            { "baseDetector", &LSDAdvanceImpl::getBaseDetector, &LSDAdvanceImpl::setBaseDetector },
            { "fldLengthThreshold", &LSDAdvanceImpl::getFldLengthThreshold, &LSDAdvanceImpl::setFldLengthThreshold },
            { "fldCannyApertureSize", &LSDAdvanceImpl::getFldCannyApertureSize, &LSDAdvanceImpl::setFldCannyApertureSize },
            { "edGradientOperator", &LSDAdvanceImpl::getEdGradientOperator, &LSDAdvanceImpl::setEdGradientOperator },
            { "edGradientThreshold", &LSDAdvanceImpl::getEdGradientThreshold, &LSDAdvanceImpl::setEdGradientThreshold },
            { "edAnchorThreshold", &LSDAdvanceImpl::getEdAnchorThreshold, &LSDAdvanceImpl::setEdAnchorThreshold },
            { "edScanInterval", &LSDAdvanceImpl::getEdScanInterval, &LSDAdvanceImpl::setEdScanInterval },
            { "edMinPathLength", &LSDAdvanceImpl::getEdMinPathLength, &LSDAdvanceImpl::setEdMinPathLength },
            { "edMinLineLength", &LSDAdvanceImpl::getEdMinLineLength, &LSDAdvanceImpl::setEdMinLineLength },
        };
        return params;
    }
    static const std::vector<RealParam>& realParams()
    {
        static const std::vector<RealParam> params = {
            { "lsdScale", &LSDAdvanceImpl::getLsdScale, &LSDAdvanceImpl::setLsdScale },
            { "lsdSigmaScale", &LSDAdvanceImpl::getLsdSigmaScale, &LSDAdvanceImpl::setLsdSigmaScale },
            { "lsdQuant", &LSDAdvanceImpl::getLsdQuant, &LSDAdvanceImpl::setLsdQuant },
            { "lsdAngleTolerance", &LSDAdvanceImpl::getLsdAngleTolerance, &LSDAdvanceImpl::setLsdAngleTolerance },
            { "lsdLogEps", &LSDAdvanceImpl::getLsdLogEps, &LSDAdvanceImpl::setLsdLogEps },
            { "lsdDensityThreshold", &LSDAdvanceImpl::getLsdDensityThreshold, &LSDAdvanceImpl::setLsdDensityThreshold },
            { "angleBinWidth", &LSDAdvanceImpl::getAngleBinWidth, &LSDAdvanceImpl::setAngleBinWidth },
            { "endpointDistance", &LSDAdvanceImpl::getEndpointDistance, &LSDAdvanceImpl::setEndpointDistance },
            { "baselineRatio", &LSDAdvanceImpl::getBaselineRatio, &LSDAdvanceImpl::setBaselineRatio },
            { "directionWeight", &LSDAdvanceImpl::getDirectionWeight, &LSDAdvanceImpl::setDirectionWeight },
            { "proximityWeight", &LSDAdvanceImpl::getProximityWeight, &LSDAdvanceImpl::setProximityWeight },
            { "lengthWeight", &LSDAdvanceImpl::getLengthWeight, &LSDAdvanceImpl::setLengthWeight },
            { "proximityRatio", &LSDAdvanceImpl::getProximityRatio, &LSDAdvanceImpl::setProximityRatio },
            { "mergeThreshold", &LSDAdvanceImpl::getMergeThreshold, &LSDAdvanceImpl::setMergeThreshold },
            { "maxPerpendicularOffset", &LSDAdvanceImpl::getMaxPerpendicularOffset, &LSDAdvanceImpl::setMaxPerpendicularOffset },
            { "lengthThresholdScale", &LSDAdvanceImpl::getLengthThresholdScale, &LSDAdvanceImpl::setLengthThresholdScale },
            { "fldDistanceThreshold", &LSDAdvanceImpl::getFldDistanceThreshold, &LSDAdvanceImpl::setFldDistanceThreshold },
            { "fldCannyThreshold1", &LSDAdvanceImpl::getFldCannyThreshold1, &LSDAdvanceImpl::setFldCannyThreshold1 },
            { "fldCannyThreshold2", &LSDAdvanceImpl::getFldCannyThreshold2, &LSDAdvanceImpl::setFldCannyThreshold2 },
            { "edSigma", &LSDAdvanceImpl::getEdSigma, &LSDAdvanceImpl::setEdSigma },
            { "edLineFitErrorThreshold", &LSDAdvanceImpl::getEdLineFitErrorThreshold, &LSDAdvanceImpl::setEdLineFitErrorThreshold },
            { "edMaxDistanceBetweenTwoLines", &LSDAdvanceImpl::getEdMaxDistanceBetweenTwoLines, &LSDAdvanceImpl::setEdMaxDistanceBetweenTwoLines },
            { "edMaxErrorThreshold", &LSDAdvanceImpl::getEdMaxErrorThreshold, &LSDAdvanceImpl::setEdMaxErrorThreshold },
        };
        return params;
    }
    static const std::vector<BoolParam>& boolParams()
    {
        static const std::vector<BoolParam> params = {
            { "fldDoMerge", &LSDAdvanceImpl::getFldDoMerge, &LSDAdvanceImpl::setFldDoMerge },
            { "edNfaValidation", &LSDAdvanceImpl::getEdNfaValidation, &LSDAdvanceImpl::setEdNfaValidation },
        };
        return params;
    }

    void baseDetectorChanged()
    {
        baseSegments.release();
        reset();
    }

    lsda::LsdParams lsd;
    int lengthFilterMode = LENGTH_FILTER_INTERFRAME;
    int stageOrder = MERGE_THEN_FILTER;
    lsda::LengthThreshold lengthThreshold = lsda::LengthThreshold::CAPPED;
    double lengthThresholdScale = 1.0;
    lsda::GroupingParams grouping;
    lsda::MergeParams merging;

    int baseDetector = BASE_FAST_LSD;
    lsda::FldParams fld;
    lsda::EdParams ed;
    Ptr<lsda::BaseSegmentDetector> baseSegments;  // built on first use after a base parameter changes
    // Buffers of the stages, kept from frame to frame so that a sequence does not allocate. They
    // also hold the last call's stage outputs (getLastStageOutputs): a stage that is off passes
    // its input on, so filtered and merged point into base, work or out.
    struct FrameWorkspace
    {
        std::vector<Vec4f> incoming;  // segments of the current call until its stages run
        std::vector<Vec4f> base, work, out;
        const std::vector<Vec4f>* filtered = nullptr;  // stage 1's output (nullptr before the first call)
        const std::vector<Vec4f>* merged = nullptr;    // stage 3's output
        bool grouped = false;                          // groups partition stage 2's input
        lsda::SegmentGroups groups;
        lsda::GroupingWorkspace grouping;
        lsda::MergeWorkspace merging;
    } frame;
    int framesSeen = 0;
    int keptCounts[2] = { 0, 0 };  // kept by stage 1 in frames k-1 and k-2
    LSDAdvanceStats lastStats;
};

} // namespace

Ptr<LSDAdvance> createLSDAdvance(int lengthFilterMode, double endpointDistance, double mergeThreshold)
{
    Ptr<LSDAdvance> detector = makePtr<LSDAdvanceImpl>();
    detector->setLengthFilterMode(lengthFilterMode);
    detector->setEndpointDistance(endpointDistance);
    detector->setMergeThreshold(mergeThreshold);
    return detector;
}

}} // namespace cv::ximgproc
