// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "opencv2/ximgproc/edge_drawing.hpp"

namespace opencv_test { namespace {

// One real-valued parameter: how to set and get it, its default, values that must be
// accepted (range edges included) and values that must be rejected.
struct RealParameter
{
    const char* name;
    void (LSDAdvance::*set)(double);
    double (LSDAdvance::*get)() const;
    double defaultValue;
    std::vector<double> valid;
    std::vector<double> invalid;
};

struct IntParameter
{
    const char* name;
    void (LSDAdvance::*set)(int);
    int (LSDAdvance::*get)() const;
    int defaultValue;
    std::vector<int> valid;
    std::vector<int> invalid;
};

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

std::vector<RealParameter> realParameters()
{
    return {
        { "lsdScale", &LSDAdvance::setLsdScale, &LSDAdvance::getLsdScale, 1.0, { 1.0, 0.01, 0.5 }, { 0.0, -1, 1.01, kNaN, kInf } },
        { "lsdSigmaScale", &LSDAdvance::setLsdSigmaScale, &LSDAdvance::getLsdSigmaScale, 0.6, { 0.1, 100 }, { 0.0, -0.5, 101, kNaN, -kInf } },
        { "lsdQuant", &LSDAdvance::setLsdQuant, &LSDAdvance::getLsdQuant, 2.0, { 0.0, 255, 4 }, { -0.1, 256, kNaN } },
        { "lsdAngleTolerance", &LSDAdvance::setLsdAngleTolerance, &LSDAdvance::getLsdAngleTolerance, 22.5, { 1, 179.9 }, { 0, 180, -5, kNaN } },
        { "lsdLogEps", &LSDAdvance::setLsdLogEps, &LSDAdvance::getLsdLogEps, 0.0, { -1000, 1000, 2 }, { -1001, 1001, kNaN, kInf } },
        { "lsdDensityThreshold", &LSDAdvance::setLsdDensityThreshold, &LSDAdvance::getLsdDensityThreshold, 0.7, { 0.0, 0.99 }, { 1.0, -0.1, kNaN } },
        { "angleBinWidth", &LSDAdvance::setAngleBinWidth, &LSDAdvance::getAngleBinWidth, 10.0, { 1, 90, 7.5 }, { 0.99, 90.1, 0, kNaN } },
        { "endpointDistance", &LSDAdvance::setEndpointDistance, &LSDAdvance::getEndpointDistance, 10.0, { 0.1, 200, 3 }, { 0.0, 0.09, 201, -1, kNaN, kInf } },
        { "baselineRatio", &LSDAdvance::setBaselineRatio, &LSDAdvance::getBaselineRatio, 0.8, { 1.0, 0.01 }, { 0.0, 1.01, kNaN } },
        { "directionWeight", &LSDAdvance::setDirectionWeight, &LSDAdvance::getDirectionWeight, 0.4, { 0.0, 1.0 }, { -0.01, 1.01, kNaN } },
        { "proximityWeight", &LSDAdvance::setProximityWeight, &LSDAdvance::getProximityWeight, 0.35, { 0.0, 1.0 }, { -0.01, 1.01, kNaN } },
        { "lengthWeight", &LSDAdvance::setLengthWeight, &LSDAdvance::getLengthWeight, 0.2, { 0.0, 1.0 }, { -0.01, 1.01, kNaN } },
        { "proximityRatio", &LSDAdvance::setProximityRatio, &LSDAdvance::getProximityRatio, 1.0, { 0.001, 10 }, { 0.0, 10.5, kNaN } },
        { "mergeThreshold", &LSDAdvance::setMergeThreshold, &LSDAdvance::getMergeThreshold, 0.6, { 0.0, 1.0 }, { -0.1, 1.1, kNaN } },
        { "maxPerpendicularOffset", &LSDAdvance::setMaxPerpendicularOffset, &LSDAdvance::getMaxPerpendicularOffset, 1.5, { 0.0, 100 }, { -0.1, 101, kNaN, kInf } },
        { "lengthThresholdScale", &LSDAdvance::setLengthThresholdScale, &LSDAdvance::getLengthThresholdScale, 1.0, { 0.01, 10, 0.5 }, { 0.0, -1, 10.5, kNaN, kInf } },
        { "fldDistanceThreshold", &LSDAdvance::setFldDistanceThreshold, &LSDAdvance::getFldDistanceThreshold, 1.414213562, { 100, 0.5 }, { 0.0, -1, 100.5, kNaN } },
        { "fldCannyThreshold1", &LSDAdvance::setFldCannyThreshold1, &LSDAdvance::getFldCannyThreshold1, 50, { 100000, 0.5 }, { 0.0, -1, 100001, kInf } },
        { "fldCannyThreshold2", &LSDAdvance::setFldCannyThreshold2, &LSDAdvance::getFldCannyThreshold2, 50, { 100000, 0.5 }, { 0.0, -1, 100001, kNaN } },
        { "edSigma", &LSDAdvance::setEdSigma, &LSDAdvance::getEdSigma, 1.0, { 0.0, 100 }, { -0.1, 100.5, kNaN } },
        { "edLineFitErrorThreshold", &LSDAdvance::setEdLineFitErrorThreshold, &LSDAdvance::getEdLineFitErrorThreshold, 1.0, { 100, 0.5 }, { 0.0, 101, kNaN } },
        { "edMaxDistanceBetweenTwoLines", &LSDAdvance::setEdMaxDistanceBetweenTwoLines, &LSDAdvance::getEdMaxDistanceBetweenTwoLines, 6.0, { 1000, 0.5 }, { 0.0, 1001, kInf } },
        { "edMaxErrorThreshold", &LSDAdvance::setEdMaxErrorThreshold, &LSDAdvance::getEdMaxErrorThreshold, 1.3, { 100, 0.5 }, { 0.0, -2, 101, kNaN } },
    };
}

std::vector<IntParameter> intParameters()
{
    return {
        { "lsdRefine", &LSDAdvance::setLsdRefine, &LSDAdvance::getLsdRefine, LSD_REFINE_NONE,
          { LSD_REFINE_STD, LSD_REFINE_ADV }, { -1, 3 } },
        { "lsdNumBins", &LSDAdvance::setLsdNumBins, &LSDAdvance::getLsdNumBins, 1024, { 1, 65536 }, { 0, -5, 65537 } },
        { "lengthFilterMode", &LSDAdvance::setLengthFilterMode, &LSDAdvance::getLengthFilterMode,
          LSDAdvance::LENGTH_FILTER_INTERFRAME,
          { LSDAdvance::LENGTH_FILTER_NONE, LSDAdvance::LENGTH_FILTER_ADAPTIVE, LSDAdvance::LENGTH_FILTER_INTERFRAME_CONTINUOUS,
            LSDAdvance::LENGTH_FILTER_COUNT_TRACKING }, { -1, 5 } },
        { "angleBinning", &LSDAdvance::setAngleBinning, &LSDAdvance::getAngleBinning,
          LSDAdvance::ANGLE_BINS_NEIGHBOURS, { LSDAdvance::ANGLE_BINS_STRICT }, { -1, 2 } },
        { "lengthThreshold", &LSDAdvance::setLengthThreshold, &LSDAdvance::getLengthThreshold,
          LSDAdvance::LENGTH_THRESHOLD_CAPPED, { LSDAdvance::LENGTH_THRESHOLD_PAPER }, { -1, 2 } },
        { "mergeStrategy", &LSDAdvance::setMergeStrategy, &LSDAdvance::getMergeStrategy,
          LSDAdvance::MERGE_LONGEST_FIRST, { LSDAdvance::MERGE_NONE, LSDAdvance::MERGE_BASELINES }, { -1, 3 } },
        { "stageOrder", &LSDAdvance::setStageOrder, &LSDAdvance::getStageOrder,
          LSDAdvance::MERGE_THEN_FILTER, { LSDAdvance::FILTER_THEN_MERGE }, { -1, 2 } },
        { "baseDetector", &LSDAdvance::setBaseDetector, &LSDAdvance::getBaseDetector, LSDAdvance::BASE_FAST_LSD,
          { LSDAdvance::BASE_LSD, LSDAdvance::BASE_FLD, LSDAdvance::BASE_EDLINES }, { -1, 4 } },
        { "fldLengthThreshold", &LSDAdvance::setFldLengthThreshold, &LSDAdvance::getFldLengthThreshold, 10, { 1, 100000, 25 }, { 0, -3, 100001 } },
        { "fldCannyApertureSize", &LSDAdvance::setFldCannyApertureSize, &LSDAdvance::getFldCannyApertureSize, 3, { 7, 5 }, { 0, 1, 4, 9, -3 } },
        { "edGradientOperator", &LSDAdvance::setEdGradientOperator, &LSDAdvance::getEdGradientOperator, EdgeDrawing::PREWITT,
          { EdgeDrawing::SOBEL, EdgeDrawing::SCHARR, EdgeDrawing::LSD }, { -1, 4 } },
        { "edGradientThreshold", &LSDAdvance::setEdGradientThreshold, &LSDAdvance::getEdGradientThreshold, 20, { 1, 10000, 36 }, { 0, 10001 } },
        { "edAnchorThreshold", &LSDAdvance::setEdAnchorThreshold, &LSDAdvance::getEdAnchorThreshold, 0, { 10000, 4 }, { -1, 10001 } },
        { "edScanInterval", &LSDAdvance::setEdScanInterval, &LSDAdvance::getEdScanInterval, 1, { 100, 2 }, { 0, 101 } },
        { "edMinPathLength", &LSDAdvance::setEdMinPathLength, &LSDAdvance::getEdMinPathLength, 10, { 2, 100000, 15 }, { 1, 0, 100001 } },
        { "edMinLineLength", &LSDAdvance::setEdMinLineLength, &LSDAdvance::getEdMinLineLength, -1, { -1, 9, 100000, 20 }, { 8, 0, -2, 100001 } },
    };
}

struct BoolParameter
{
    const char* name;
    void (LSDAdvance::*set)(bool);
    bool (LSDAdvance::*get)() const;
    bool defaultValue;
};

std::vector<BoolParameter> boolParameters()
{
    return {
        { "fldDoMerge", &LSDAdvance::setFldDoMerge, &LSDAdvance::getFldDoMerge, false },
        { "edNfaValidation", &LSDAdvance::setEdNfaValidation, &LSDAdvance::getEdNfaValidation, true },
    };
}

// Expects the setter to throw an out-of-range cv::Exception that names the parameter.
template <typename T, typename Setter>
void expectRejected(const Ptr<LSDAdvance>& detector, Setter set, const char* name, T value)
{
    try
    {
        ((*detector).*set)(value);
        ADD_FAILURE() << name << " accepted " << value;
    }
    catch (const cv::Exception& e)
    {
        EXPECT_EQ(Error::StsOutOfRange, e.code);
        EXPECT_NE(std::string::npos, e.msg.find(name)) << e.msg;
    }
}

TEST(LSDAdvance_Parameters, defaults_are_the_documented_ones)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    for (const RealParameter& p : realParameters())
        EXPECT_EQ(p.defaultValue, ((*detector).*p.get)()) << p.name;
    for (const IntParameter& p : intParameters())
        EXPECT_EQ(p.defaultValue, ((*detector).*p.get)()) << p.name;
    for (const BoolParameter& p : boolParameters())
        EXPECT_EQ(p.defaultValue, ((*detector).*p.get)()) << p.name;
}

TEST(LSDAdvance_Parameters, setters_round_trip_valid_values)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    for (const RealParameter& p : realParameters())
        for (double v : p.valid)
        {
            ((*detector).*p.set)(v);
            EXPECT_EQ(v, ((*detector).*p.get)()) << p.name;
        }
    for (const IntParameter& p : intParameters())
        for (int v : p.valid)
        {
            ((*detector).*p.set)(v);
            EXPECT_EQ(v, ((*detector).*p.get)()) << p.name;
        }
    for (const BoolParameter& p : boolParameters())
        for (bool v : { !p.defaultValue, p.defaultValue })
        {
            ((*detector).*p.set)(v);
            EXPECT_EQ(v, ((*detector).*p.get)()) << p.name;
        }
}

TEST(LSDAdvance_Parameters, setters_reject_out_of_range_values_and_keep_the_old_one)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    for (const RealParameter& p : realParameters())
        for (double v : p.invalid)
        {
            SCOPED_TRACE(p.name);
            expectRejected(detector, p.set, p.name, v);
            EXPECT_EQ(p.defaultValue, ((*detector).*p.get)());
        }
    for (const IntParameter& p : intParameters())
        for (int v : p.invalid)
        {
            SCOPED_TRACE(p.name);
            expectRejected(detector, p.set, p.name, v);
            EXPECT_EQ(p.defaultValue, ((*detector).*p.get)());
        }
}

TEST(LSDAdvance_Parameters, factory_arguments_are_validated_and_applied)
{
    Ptr<LSDAdvance> detector = createLSDAdvance(LSDAdvance::LENGTH_FILTER_NONE, 4.0, 0.75);
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_NONE, detector->getLengthFilterMode());
    EXPECT_EQ(4.0, detector->getEndpointDistance());
    EXPECT_EQ(0.75, detector->getMergeThreshold());
    EXPECT_THROW(createLSDAdvance(LSDAdvance::LENGTH_FILTER_NONE, -1.0), cv::Exception);
    EXPECT_THROW(createLSDAdvance(7), cv::Exception);
}

// A detector with every parameter set to its second valid value.
Ptr<LSDAdvance> detectorWithNonDefaults()
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    for (const RealParameter& p : realParameters())
        ((*detector).*p.set)(p.valid[1]);
    for (const IntParameter& p : intParameters())
        ((*detector).*p.set)(p.valid.back());
    for (const BoolParameter& p : boolParameters())
        ((*detector).*p.set)(!p.defaultValue);
    return detector;
}

TEST(LSDAdvance_Parameters, write_read_round_trip_preserves_every_parameter)
{
    const Ptr<LSDAdvance> saved = detectorWithNonDefaults();
    FileStorage out("lsd_advance.yml", FileStorage::WRITE | FileStorage::MEMORY);
    saved->write(out);
    const String text = out.releaseAndGetString();

    Ptr<LSDAdvance> loaded = createLSDAdvance();
    FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
    loaded->read(in.root());
    for (const RealParameter& p : realParameters())
        EXPECT_EQ(((*saved).*p.get)(), ((*loaded).*p.get)()) << p.name;
    for (const IntParameter& p : intParameters())
        EXPECT_EQ(((*saved).*p.get)(), ((*loaded).*p.get)()) << p.name;
    for (const BoolParameter& p : boolParameters())
        EXPECT_EQ(((*saved).*p.get)(), ((*loaded).*p.get)()) << p.name;
    EXPECT_EQ(String("LSDAdvance"), loaded->getDefaultName());
}

TEST(LSDAdvance_Parameters, read_keeps_defaults_for_missing_keys_and_ignores_unknown_ones)
{
    const String text = "%YAML:1.0\n---\nmergeThreshold: 0.9\nfutureParameter: 3\n";
    Ptr<LSDAdvance> loaded = createLSDAdvance();
    FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
    loaded->read(in.root());
    EXPECT_EQ(0.9, loaded->getMergeThreshold());
    EXPECT_EQ(10.0, loaded->getEndpointDistance());
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_INTERFRAME, loaded->getLengthFilterMode());
}

TEST(LSDAdvance_Parameters, read_rejects_wrong_types_and_out_of_range_values)
{
    const char* bad[] = {
        "%YAML:1.0\n---\nmergeThreshold: \"high\"\n",
        "%YAML:1.0\n---\nlengthFilterMode: 1.5\n",
        "%YAML:1.0\n---\nendpointDistance: -3\n",
        "%YAML:1.0\n---\nlsdRefine: 9\n",
        "%YAML:1.0\n---\nedNfaValidation: 2\n",
        "%YAML:1.0\n---\nfldDoMerge: 0.5\n",
        "%YAML:1.0\n---\nbaseDetector: 4\n",
    };
    for (const char* text : bad)
    {
        SCOPED_TRACE(text);
        Ptr<LSDAdvance> loaded = createLSDAdvance();
        FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
        EXPECT_THROW(loaded->read(in.root()), cv::Exception);
    }
}

TEST(LSDAdvance_Parameters, a_rejected_file_leaves_every_parameter_unchanged)
{
    const String text = "%YAML:1.0\n---\nlsdScale: 0.5\nmergeThreshold: 0.9\nendpointDistance: -3\n";
    Ptr<LSDAdvance> detector = createLSDAdvance();
    FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
    EXPECT_THROW(detector->read(in.root()), cv::Exception);
    EXPECT_EQ(1.0, detector->getLsdScale());
    EXPECT_EQ(0.6, detector->getMergeThreshold());
    EXPECT_EQ(10.0, detector->getEndpointDistance());
}

TEST(LSDAdvance_Parameters, every_base_detector_parameter_changes_the_base_segments)
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    typedef std::function<void(LSDAdvance&)> Apply;
    // setUp is applied to the reference and to the changed detector, change to the latter only.
    struct Change { const char* name; Apply setUp; Apply change; };
    const Apply nothing = [](LSDAdvance&) {};
    const std::vector<Change> changes = {
        { "lsdRefine", nothing, [](LSDAdvance& d) { d.setLsdRefine(LSD_REFINE_STD); } },
        { "lsdScale", nothing, [](LSDAdvance& d) { d.setLsdScale(0.5); } },
        { "lsdSigmaScale", [](LSDAdvance& d) { d.setLsdScale(0.8); }, [](LSDAdvance& d) { d.setLsdSigmaScale(1.2); } },
        { "lsdQuant", nothing, [](LSDAdvance& d) { d.setLsdQuant(8.0); } },
        { "lsdAngleTolerance", nothing, [](LSDAdvance& d) { d.setLsdAngleTolerance(12.0); } },
        { "lsdLogEps", [](LSDAdvance& d) { d.setLsdRefine(LSD_REFINE_ADV); }, [](LSDAdvance& d) { d.setLsdLogEps(3.0); } },
        { "lsdDensityThreshold", [](LSDAdvance& d) { d.setLsdRefine(LSD_REFINE_STD); },
          [](LSDAdvance& d) { d.setLsdDensityThreshold(0.95); } },
        { "lsdNumBins", nothing, [](LSDAdvance& d) { d.setLsdNumBins(4); } },
    };
    for (const int base : { LSDAdvance::BASE_LSD, LSDAdvance::BASE_FAST_LSD })  // both take the lsd* parameters
        for (const Change& c : changes)
        {
            SCOPED_TRACE(cv::format("%s, base %d", c.name, base));
            Ptr<LSDAdvance> reference = createLSDAdvance(LSDAdvance::LENGTH_FILTER_NONE);
            Ptr<LSDAdvance> changed = createLSDAdvance(LSDAdvance::LENGTH_FILTER_NONE);
            for (LSDAdvance* d : { reference.get(), changed.get() })
            {
                d->setBaseDetector(base);
                d->setMergeStrategy(LSDAdvance::MERGE_NONE);
                c.setUp(*d);
            }
            c.change(*changed);
            std::vector<Vec4f> expected, lines;
            reference->detect(img, expected);
            changed->detect(img, lines);
            EXPECT_NE(expected, lines);
        }
}

TEST(LSDAdvance_Parameters, grouping_and_merging_parameters_change_the_output)
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    std::vector<Vec4f> expected, lines;
    createLSDAdvance()->detect(img, expected);

    struct Change { const char* name; std::function<void(LSDAdvance&)> apply; };
    const std::vector<Change> changes = {
        { "angleBinWidth", [](LSDAdvance& d) { d.setAngleBinWidth(3.0); } },
        { "angleBinning", [](LSDAdvance& d) { d.setAngleBinning(LSDAdvance::ANGLE_BINS_STRICT); } },
        { "endpointDistance", [](LSDAdvance& d) { d.setEndpointDistance(2.0); } },
        { "baselineRatio", [](LSDAdvance& d) { d.setMergeStrategy(LSDAdvance::MERGE_BASELINES); d.setBaselineRatio(0.3); } },
        { "mergeStrategy", [](LSDAdvance& d) { d.setMergeStrategy(LSDAdvance::MERGE_BASELINES); } },
        { "stageOrder", [](LSDAdvance& d) { d.setStageOrder(LSDAdvance::FILTER_THEN_MERGE); } },
        { "directionWeight", [](LSDAdvance& d) { d.setDirectionWeight(0.0); } },
        { "proximityWeight", [](LSDAdvance& d) { d.setProximityWeight(0.0); } },
        { "lengthWeight", [](LSDAdvance& d) { d.setLengthWeight(0.6); } },
        { "proximityRatio", [](LSDAdvance& d) { d.setProximityRatio(0.1); } },
        { "mergeThreshold", [](LSDAdvance& d) { d.setMergeThreshold(1.0); } },
        { "maxPerpendicularOffset", [](LSDAdvance& d) { d.setMaxPerpendicularOffset(4.0); } },
    };
    for (const Change& c : changes)
    {
        SCOPED_TRACE(c.name);
        Ptr<LSDAdvance> detector = createLSDAdvance();
        c.apply(*detector);
        detector->detect(img, lines);
        EXPECT_NE(expected, lines);
    }
}

TEST(LSDAdvance_Parameters, user_workflow_set_every_parameter_save_load_and_detect)
{
    // What the module issue asks of a user program: every setter, a FileStorage file, detect().
    Ptr<LSDAdvance> configured = createLSDAdvance();
    for (const RealParameter& p : realParameters())
        ((*configured).*p.set)(p.defaultValue);
    for (const IntParameter& p : intParameters())
        ((*configured).*p.set)(p.defaultValue);
    for (const BoolParameter& p : boolParameters())
        ((*configured).*p.set)(p.defaultValue);
    const String path = cv::tempfile(".yml");
    configured->save(path);  // the parameters under a node named getDefaultName()
    Ptr<LSDAdvance> loaded = createLSDAdvance(LSDAdvance::LENGTH_FILTER_NONE, 3.0, 0.9);
    {
        FileStorage fs(path, FileStorage::READ);
        ASSERT_TRUE(fs.isOpened());
        loaded->read(fs[loaded->getDefaultName()]);
    }
    std::remove(path.c_str());
    for (const RealParameter& p : realParameters())
        EXPECT_EQ(p.defaultValue, ((*loaded).*p.get)()) << p.name;
    for (const IntParameter& p : intParameters())
        EXPECT_EQ(p.defaultValue, ((*loaded).*p.get)()) << p.name;
    for (const BoolParameter& p : boolParameters())
        EXPECT_EQ(p.defaultValue, ((*loaded).*p.get)()) << p.name;

    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    std::vector<Vec4f> ours, lsd;
    loaded->detect(img, ours);
    createLineSegmentDetector()->detect(img, lsd);
    EXPECT_LT(ours.size(), lsd.size());
    EXPECT_GT(longSegmentShare(ours, 60.0), longSegmentShare(lsd, 60.0));
}

}} // namespace
