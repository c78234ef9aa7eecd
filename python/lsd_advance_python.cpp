// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Python bindings of the standalone build (pybind11), for use with the distribution's cv2:
// the same names, arguments and numpy conventions as the bindings OpenCV's generator makes
// in-tree (cv2.ximgproc.createLSDAdvance, ...), so that code runs unchanged on both.
// numpy <-> cv::Mat follows cv2's own rules (modules/python/src2/cv2_convert.cpp of 4.6).

#include <opencv2/lsd_advance.hpp>

#include "parameters.hpp"  // the parameter tables (src/)

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace pybind11::literals;
using namespace cv;
using namespace cv::ximgproc;
using namespace cv::ximgproc::line_evaluation;

namespace {

// ------------------------------------------------------------------------------------------
// Errors: cv::Exception -> cv2.error (or lsd_advance.error without cv2), with cv2's attributes.

PyObject* g_errorType = nullptr;  // owned for the life of the interpreter

void raiseOpenCVError(const cv::Exception& e)
{
    py::object error = py::reinterpret_borrow<py::object>(g_errorType)(e.what());
    error.attr("code") = e.code;
    error.attr("err") = e.err;
    error.attr("func") = e.func;
    error.attr("file") = e.file;
    error.attr("line") = e.line;
    error.attr("msg") = e.msg;
    PyErr_SetObject(g_errorType, error.ptr());
}

py::module_ importCv2(const char* what)
{
    try
    {
        return py::module_::import("cv2");
    }
    catch (py::error_already_set&)
    {
        throw py::import_error(std::string(what) + " needs cv2 (Debian: apt-get install python3-opencv)");
    }
}

// ------------------------------------------------------------------------------------------
// numpy -> cv::Mat, as cv2 converts an InputArray / OutputArray argument.

// cv::Mat's largest number of dimensions (CV_MAX_DIM of the C API, as cv2 uses it).
constexpr int kMaxDims = 32;

// A Mat viewing a numpy array's data; `owner` keeps that data alive while the Mat is used.
struct ArrayArg
{
    Mat mat;
    py::object owner;
};

// cv2's depth of a dtype; int64/uint64 are cast to int32 as cv2 does; -1 if unsupported.
int depthOf(const py::dtype& dt, bool& castToInt32)
{
    const char kind = dt.kind();
    const ssize_t size = dt.itemsize();
    castToInt32 = false;
    if (kind == 'u' && size == 1) return CV_8U;
    if (kind == 'i' && size == 1) return CV_8S;
    if (kind == 'u' && size == 2) return CV_16U;
    if (kind == 'i' && size == 2) return CV_16S;
    if (kind == 'i' && size == 4) return CV_32S;
    if (kind == 'f' && size == 4) return CV_32F;
    if (kind == 'f' && size == 8) return CV_64F;
    if ((kind == 'i' || kind == 'u') && size == 8)
    {
        castToInt32 = true;
        return CV_32S;
    }
    return -1;
}

bool isLittleEndian()
{
    const uint16_t one = 1;
    return *reinterpret_cast<const uint8_t*>(&one) == 1;
}

// output: the array receives the result in place when its layout allows (cv2's OutputArray).
ArrayArg toMat(const py::handle& o, const char* name, bool output = false)
{
    ArrayArg arg;
    if (o.is_none())
        return arg;  // an empty Mat, as cv2 passes None
    if (!output && (py::isinstance<py::int_>(o) || py::isinstance<py::float_>(o)))
    {
        double value[4] = { o.cast<double>(), 0., 0., 0. };  // cv2's Scalar-like 4 x 1
        arg.mat = Mat(4, 1, CV_64F, value).clone();
        return arg;
    }
    if (!output && py::isinstance<py::tuple>(o))
    {
        std::vector<double> values;
        for (const py::handle item : o)
        {
            if (!py::isinstance<py::int_>(item) && !py::isinstance<py::float_>(item))
                throw py::type_error(std::string(name) + " is not a numerical tuple");
            values.push_back(item.cast<double>());
        }
        arg.mat = Mat((int)values.size(), 1, CV_64F, values.data()).clone();
        return arg;
    }
    if (!py::isinstance<py::array>(o))
        throw py::type_error(std::string(name) + " is not a numpy array, neither a scalar");

    py::array array = py::reinterpret_borrow<py::array>(o);
    if (output && !array.writeable())
        throw py::value_error(std::string("the output array ") + name + " is read-only");
    bool castToInt32 = false;
    int depth = depthOf(array.dtype(), castToInt32);
    if (depth < 0)
        throw py::type_error(std::string(name) + ": numpy data type " + py::str(array.dtype()).cast<std::string>() +
                             " is not supported (uint8, int8, uint16, int16, int32, float32, float64; "
                             "int64 and uint64 are converted to int32)");
    const char byteorder = array.dtype().byteorder();
    const bool nativeOrder = byteorder == '=' || byteorder == '|' || (byteorder == '<') == isLittleEndian();
    int ndims = (int)array.ndim();
    if (ndims >= kMaxDims)
        throw py::value_error(std::string(name) + " has too many dimensions (" + std::to_string(ndims) + ")");
    for (int i = 0; i < ndims; i++)
        if (array.shape(i) > (ssize_t)INT_MAX)
            throw py::value_error(std::string(name) + " is too large for cv::Mat");

    size_t elemSize = CV_ELEM_SIZE1(depth);
    bool needCopy = castToInt32 || !nativeOrder;
    for (int i = ndims - 1; i >= 0 && !needCopy; i--)
        if ((i == ndims - 1 && array.shape(i) > 1 && (size_t)array.strides(i) != elemSize) ||
            (i < ndims - 1 && array.shape(i) > 1 && array.strides(i) < array.strides(i + 1)))
            needCopy = true;
    const bool multiChannel = ndims == 3 && array.shape(2) <= CV_CN_MAX;
    int type = depth;
    if (multiChannel)
    {
        const int channels = (int)array.shape(2);
        ndims--;
        type = CV_MAKETYPE(depth, std::max(channels, 1));
        if (array.strides(ndims - 1) != (ssize_t)elemSize * array.shape(ndims))
            needCopy = true;
        elemSize = CV_ELEM_SIZE(type);
    }
    if (array.size() == 0)
    {
        arg.mat = Mat();
        return arg;
    }
    if (needCopy)
    {
        if (output)
            throw py::type_error(std::string("Layout of the output array ") + name + " is incompatible with cv::Mat");
        py::module_ numpy = py::module_::import("numpy");
        if (castToInt32)
            array = numpy.attr("ascontiguousarray")(array, "dtype"_a = numpy.attr("int32"));
        else
            array = numpy.attr("ascontiguousarray")(array, "dtype"_a = array.dtype().attr("newbyteorder")("="));
    }

    int size[kMaxDims + 1] = {};
    size_t step[kMaxDims + 1] = {};
    // Strides of dimensions of size 1 are arbitrary in numpy: normalize them (as cv2 does).
    size_t defaultStep = elemSize;
    for (int i = ndims - 1; i >= 0; --i)
    {
        size[i] = (int)array.shape(i);
        if (size[i] > 1)
        {
            step[i] = (size_t)array.strides(i);
            defaultStep = step[i] * size[i];
        }
        else
        {
            step[i] = defaultStep;
            defaultStep *= size[i];
        }
    }
    if (ndims == 0)
    {
        size[0] = 1;
        step[0] = elemSize;
        ndims = 1;
    }
    arg.mat = Mat(ndims, size, type, const_cast<void*>(array.data()), step);
    arg.owner = array;
    return arg;
}

// ------------------------------------------------------------------------------------------
// cv::Mat -> numpy, as cv2 returns it: None when empty, channels as the last dimension.

py::dtype dtypeOf(int depth)
{
    switch (depth)
    {
    case CV_8U: return py::dtype::of<uint8_t>();
    case CV_8S: return py::dtype::of<int8_t>();
    case CV_16U: return py::dtype::of<uint16_t>();
    case CV_16S: return py::dtype::of<int16_t>();
    case CV_32S: return py::dtype::of<int32_t>();
    case CV_32F: return py::dtype::of<float>();
    case CV_64F: return py::dtype::of<double>();
    default: return py::dtype("float16");
    }
}

py::object toNumpy(const Mat& m)
{
    if (!m.data)
        return py::none();
    Mat* kept = new Mat(m);
    py::capsule owner(kept, [](void* p) { delete static_cast<Mat*>(p); });
    std::vector<ssize_t> shape, strides;
    for (int i = 0; i < m.dims; i++)
    {
        shape.push_back(m.size[i]);
        strides.push_back((ssize_t)m.step[i]);
    }
    if (m.channels() > 1)
    {
        shape.push_back(m.channels());
        strides.push_back((ssize_t)m.elemSize1());
    }
    return py::array(dtypeOf(m.depth()), shape, strides, kept->data, owner);
}

// std::vector<Vec4f> as cv2 returns it: N x 4 float32.
py::object toNumpy(const std::vector<Vec4f>& segments)
{
    Mat rows((int)segments.size(), 4, CV_32F);
    if (!segments.empty())
        Mat(segments).reshape(1, (int)segments.size()).copyTo(rows);
    return py::array(py::dtype::of<float>(), { (ssize_t)segments.size(), (ssize_t)4 },
                     { (ssize_t)(4 * sizeof(float)), (ssize_t)sizeof(float) }, rows.data,
                     py::capsule(new Mat(rows), [](void* p) { delete static_cast<Mat*>(p); }));
}

// What cv2 returns for an output argument: the array given, when the result was written into it,
// or a new array (None when empty).
py::object returnedOutput(const py::object& given, const ArrayArg& output)
{
    if (output.owner && output.mat.data == static_cast<const uchar*>(py::array(output.owner).data()))
        return given;
    return toNumpy(output.mat);
}

// Calls f(input, output) without the GIL, with cv2's handling of an optional output array:
// filled in place (and returned) when its shape and type already fit, replaced otherwise.
template <typename F>
py::object callWithOutput(const ArrayArg& input, const py::object& out, const char* outName, F f)
{
    ArrayArg output = toMat(out, outName, true);
    {
        py::gil_scoped_release noGil;
        f(input.mat, output.mat);
    }
    return returnedOutput(out, output);
}

// ------------------------------------------------------------------------------------------
// Python objects of cv2 (KeyLine, DMatch, FileStorage, FileNode) read and made attribute by
// attribute: this module cannot share cv2's C++ objects, only their Python interface.

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
using line_descriptor::KeyLine;

py::list toPythonKeyLines(const std::vector<KeyLine>& keylines)
{
    const py::object keyLineType = importCv2("KeyLines").attr("line_descriptor").attr("KeyLine");
    py::list out;
    for (const KeyLine& k : keylines)
    {
        py::object o = keyLineType();
        o.attr("angle") = k.angle;
        o.attr("class_id") = k.class_id;
        o.attr("octave") = k.octave;
        o.attr("pt") = py::make_tuple(k.pt.x, k.pt.y);
        o.attr("response") = k.response;
        o.attr("size") = k.size;
        o.attr("startPointX") = k.startPointX;
        o.attr("startPointY") = k.startPointY;
        o.attr("endPointX") = k.endPointX;
        o.attr("endPointY") = k.endPointY;
        o.attr("sPointInOctaveX") = k.sPointInOctaveX;
        o.attr("sPointInOctaveY") = k.sPointInOctaveY;
        o.attr("ePointInOctaveX") = k.ePointInOctaveX;
        o.attr("ePointInOctaveY") = k.ePointInOctaveY;
        o.attr("lineLength") = k.lineLength;
        o.attr("numOfPixels") = k.numOfPixels;
        out.append(o);
    }
    return out;
}

std::vector<KeyLine> fromPythonKeyLines(const py::iterable& keylines)
{
    std::vector<KeyLine> out;
    for (const py::handle o : keylines)
    {
        KeyLine k;
        k.startPointX = o.attr("startPointX").cast<float>();
        k.startPointY = o.attr("startPointY").cast<float>();
        k.endPointX = o.attr("endPointX").cast<float>();
        k.endPointY = o.attr("endPointY").cast<float>();
        out.push_back(k);
    }
    return out;
}
#endif

std::vector<DMatch> fromPythonMatches(const py::iterable& matches)
{
    std::vector<DMatch> out;
    for (const py::handle o : matches)
        out.push_back(DMatch(o.attr("queryIdx").cast<int>(), o.attr("trainIdx").cast<int>(),
                             o.attr("imgIdx").cast<int>(), o.attr("distance").cast<float>()));
    return out;
}

Size toSize(const std::array<int, 2>& wh)
{
    return Size(wh[0], wh[1]);
}

Vec4f toVec4f(const std::array<float, 4>& v)
{
    return Vec4f(v[0], v[1], v[2], v[3]);
}

// Copies a cv2.FileNode (maps, sequences, numbers, strings) into fs.
void copyFileNode(const py::handle& node, const std::string& key, FileStorage& fs)
{
    const bool isMap = node.attr("isMap")().cast<bool>(), isSeq = node.attr("isSeq")().cast<bool>();
    if (isMap || isSeq)
    {
        fs.startWriteStruct(key, isMap ? FileNode::MAP : FileNode::SEQ);
        if (isMap)
            for (const py::handle name : node.attr("keys")())
                copyFileNode(node.attr("getNode")(name), name.cast<std::string>(), fs);
        else
            for (int i = 0, n = node.attr("size")().cast<int>(); i < n; i++)
                copyFileNode(node.attr("at")(i), std::string(), fs);
        fs.endWriteStruct();
    }
    else if (node.attr("isInt")().cast<bool>())
        fs.write(key, (int)node.attr("real")().cast<double>());
    else if (node.attr("isReal")().cast<bool>())
        fs.write(key, node.attr("real")().cast<double>());
    else if (node.attr("isString")().cast<bool>())
        fs.write(key, node.attr("string")().cast<std::string>());
    else if (!node.attr("empty")().cast<bool>() && !node.attr("isNone")().cast<bool>())
        throw py::value_error("read: unsupported FileNode type under '" + key + "'");
}

// Copies a C++ FileNode into a cv2.FileStorage opened for writing.
void copyFileNode(const FileNode& node, const std::string& key, const py::object& fs, const py::module_& cv2)
{
    if (node.isMap() || node.isSeq())
    {
        fs.attr("startWriteStruct")(key, cv2.attr(node.isMap() ? "FileNode_MAP" : "FileNode_SEQ"));
        for (const FileNode& child : node)
            copyFileNode(child, node.isMap() ? child.name() : std::string(), fs, cv2);
        fs.attr("endWriteStruct")();
    }
    else if (node.isInt())
        fs.attr("write")(key, (int)node);
    else if (node.isReal())
        fs.attr("write")(key, (double)node);
    else if (node.isString())
        fs.attr("write")(key, (std::string)node);
}

// EdgeDrawing::Params as cv2.ximgproc.EdgeDrawing.Params, field by field (the table's rows).
py::object toPythonEdLinesParams(const EdgeDrawing::Params& p)
{
    py::object o = importCv2("getEDLinesParams").attr("ximgproc").attr("EdgeDrawing").attr("Params")();
#define LSDA_TO_PYTHON(type, field, range, legacyKey) o.attr(#field) = p.field;
    LSDA_EDLINES_PARAMS(LSDA_TO_PYTHON)
#undef LSDA_TO_PYTHON
    return o;
}

EdgeDrawing::Params fromPythonEdLinesParams(const py::handle& o)
{
    EdgeDrawing::Params p;
#define LSDA_FROM_PYTHON(type, field, range, legacyKey) p.field = o.attr(#field).cast<type>();
    LSDA_EDLINES_PARAMS(LSDA_FROM_PYTHON)
#undef LSDA_FROM_PYTHON
    return p;
}

std::string statsRepr(const LSDAdvanceStats& s)
{
    return format("LSDAdvanceStats(baseSegments=%d, mergedSegments=%d, filteredSegments=%d, mergeGroups=%d, "
                  "outputSegments=%d, minLength=%g, minResponse=%g, alpha=%g, baseMs=%g, filterMs=%g, groupingMs=%g, "
                  "mergingMs=%g)",
                  s.baseSegments, s.mergedSegments, s.filteredSegments, s.mergeGroups, s.outputSegments,
                  s.minLength, s.minResponse, s.alpha, s.baseMs, s.filterMs, s.groupingMs, s.mergingMs);
}

} // namespace

PYBIND11_MODULE(_lsd_advance, m)
{
    m.doc() = "LSDAdvance line segment detector (standalone build): the API of cv2.ximgproc's in-tree bindings.";

    try
    {
        g_errorType = py::object(py::module_::import("cv2").attr("error")).release().ptr();
    }
    catch (py::error_already_set&)
    {
        g_errorType = PyErr_NewExceptionWithDoc("lsd_advance.error", "OpenCV error (cv::Exception); cv2 is absent",
                                                PyExc_RuntimeError, nullptr);
    }
    m.attr("error") = py::reinterpret_borrow<py::object>(g_errorType);
    py::register_exception_translator([](std::exception_ptr p) {
        try
        {
            if (p)
                std::rethrow_exception(p);
        }
        catch (const cv::Exception& e)
        {
            raiseOpenCVError(e);
        }
    });

    py::class_<LSDAdvanceStats>(m, "LSDAdvanceStats", "Statistics of the last detect() or processSegments() call.")
        .def(py::init<>())
        .def_readwrite("baseSegments", &LSDAdvanceStats::baseSegments)
        .def_readwrite("mergedSegments", &LSDAdvanceStats::mergedSegments)
        .def_readwrite("filteredSegments", &LSDAdvanceStats::filteredSegments)
        .def_readwrite("mergeGroups", &LSDAdvanceStats::mergeGroups)
        .def_readwrite("outputSegments", &LSDAdvanceStats::outputSegments)
        .def_readwrite("minLength", &LSDAdvanceStats::minLength)
        .def_readwrite("minResponse", &LSDAdvanceStats::minResponse)
        .def_readwrite("alpha", &LSDAdvanceStats::alpha)
        .def_readwrite("baseMs", &LSDAdvanceStats::baseMs)
        .def_readwrite("filterMs", &LSDAdvanceStats::filterMs)
        .def_readwrite("groupingMs", &LSDAdvanceStats::groupingMs)
        .def_readwrite("mergingMs", &LSDAdvanceStats::mergingMs)
        .def("__repr__", &statsRepr);

    py::class_<LSDAdvance, std::shared_ptr<LSDAdvance>> detector(m, "LSDAdvance",
                                                                  "Line segment detector; create it with createLSDAdvance().");
    // The parameter structs, nested in the class as cv2 nests them (cv2.ximgproc.LSDAdvance.Params).
    py::class_<LSDAdvance::Params> ownParams(detector, "Params", "LSDAdvance's own parameters.");
    ownParams.def(py::init<>());
#define LSDA_FIELD(type, field, Accessor, value, range, legacyKey) ownParams.def_readwrite(#field, &LSDAdvance::Params::field);
    LSDA_PARAMS(LSDA_FIELD)
#undef LSDA_FIELD
    py::class_<LSDAdvance::LSDParams> lsdParams(detector, "LSDParams", "The LSD algorithm's parameters (BASE_LSD).");
    lsdParams.def(py::init<>());
#define LSDA_FIELD(type, field, value, range, legacyKey) lsdParams.def_readwrite(#field, &LSDAdvance::LSDParams::field);
    LSDA_LSD_PARAMS(LSDA_FIELD)
#undef LSDA_FIELD
    py::class_<LSDAdvance::FLDParams> fldParams(detector, "FLDParams", "FastLineDetector's parameters (BASE_FLD).");
    fldParams.def(py::init<>());
#define LSDA_FIELD(type, field, value, range, legacyKey) fldParams.def_readwrite(#field, &LSDAdvance::FLDParams::field);
    LSDA_FLD_PARAMS(LSDA_FIELD)
#undef LSDA_FIELD
    // A getter and a setter per parameter, as the in-tree bindings have them.
#define LSDA_ACCESSORS(type, field, Accessor, value, range, legacyKey)                                     \
    detector.def("get" #Accessor, &LSDAdvance::get##Accessor);                                             \
    detector.def("set" #Accessor, &LSDAdvance::set##Accessor, py::arg(#field));
    LSDA_PARAMS(LSDA_ACCESSORS)
#undef LSDA_ACCESSORS

    detector
        .def(
            "detect",
            [](LSDAdvance& self, const py::object& image, const py::object& lines) {
                const ArrayArg in = toMat(image, "image");
                return callWithOutput(in, lines, "lines", [&self](const Mat& i, Mat& o) { self.detect(i, o); });
            },
            "image"_a, "lines"_a = py::none(),
            "detect(image[, lines]) -> lines\n\nDetects line segments in an 8-bit gray, BGR or BGRA image. Returns "
            "an N x 1 x 4 float32 array (x1, y1, x2, y2), or None when there is no segment.")
        .def(
            "processSegments",
            [](LSDAdvance& self, const py::object& segments, const py::object& lines, const std::array<int, 2>& imageSize) {
                const ArrayArg in = toMat(segments, "segments");
                const Size size = toSize(imageSize);
                return callWithOutput(in, lines, "lines",
                                      [&self, size](const Mat& i, Mat& o) { self.processSegments(i, o, size); });
            },
            "segments"_a, "lines"_a = py::none(), "imageSize"_a = std::array<int, 2>{ { 0, 0 } },
            "processSegments(segments[, lines[, imageSize]]) -> lines\n\nRuns stages 1-3 on segments (N x 1 x 4 "
            "float32) of any detector; clips them to an image of imageSize (width, height) when given.")
        .def(
            "drawSegments",
            [](LSDAdvance& self, const py::object& image, const py::object& lines) {
                ArrayArg canvas = toMat(image, "image", true);
                const ArrayArg segments = toMat(lines, "lines");
                self.drawSegments(canvas.mat, segments.mat);
                return returnedOutput(image, canvas);
            },
            "image"_a, "lines"_a,
            "drawSegments(image, lines) -> image\n\nDraws the segments in red on an 8-bit gray (made BGR) or BGR image.")
        .def(
            "getLastSources",
            [](const LSDAdvance& self) {
                std::vector<Mat> sources;
                self.getLastSources(sources);
                py::tuple result(sources.size());
                for (size_t j = 0; j < sources.size(); j++)
                    result[j] = toNumpy(sources[j]);
                return result;
            },
            "getLastSources() -> sources\n\nFor each line of the last call, the indices (N x 1 int32) of the base "
            "segments it was made from.")
        .def("getParams", &LSDAdvance::getParams)
        .def("setParams", &LSDAdvance::setParams, "params"_a)
        .def("getLSDParams", &LSDAdvance::getLSDParams)
        .def("setLSDParams", &LSDAdvance::setLSDParams, "params"_a)
        .def("getFLDParams", &LSDAdvance::getFLDParams)
        .def("setFLDParams", &LSDAdvance::setFLDParams, "params"_a)
        .def("getEDLinesParams", [](const LSDAdvance& self) { return toPythonEdLinesParams(self.getEDLinesParams()); },
             "getEDLinesParams() -> params\n\nThe parameters of BASE_EDLINES, as a cv2.ximgproc.EdgeDrawing.Params.")
        .def(
            "setEDLinesParams",
            [](LSDAdvance& self, const py::object& p) { self.setEDLinesParams(fromPythonEdLinesParams(p)); }, "params"_a,
            "setEDLinesParams(params) -> None\n\nSets the parameters of BASE_EDLINES from a "
            "cv2.ximgproc.EdgeDrawing.Params.")
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
        .def(
            "detectKeyLines",
            [](LSDAdvance& self, const py::object& image) {
                const ArrayArg in = toMat(image, "image");
                std::vector<KeyLine> keylines;
                {
                    py::gil_scoped_release noGil;
                    self.detect(in.mat, keylines);
                }
                return toPythonKeyLines(keylines);
            },
            "image"_a,
            "detectKeyLines(image) -> keylines\n\nC++ LSDAdvance::detect(image, keylines): detect() as a list of "
            "cv2.line_descriptor.KeyLine for BinaryDescriptor.compute and BinaryDescriptorMatcher.")
#endif
        .def("reset", &LSDAdvance::reset, "Forgets the sequence: the next detect() is the first frame.")
        .def("getLastStats", &LSDAdvance::getLastStats)
        .def(
            "getLastStageOutputs",
            [](const LSDAdvance& self, const py::object& baseSegments, const py::object& filteredSegments,
               const py::object& groupLabels, const py::object& mergedSegments) {
                const py::object given[4] = { baseSegments, filteredSegments, groupLabels, mergedSegments };
                const char* names[4] = { "baseSegments", "filteredSegments", "groupLabels", "mergedSegments" };
                ArrayArg outputs[4];
                for (int i = 0; i < 4; i++)
                    outputs[i] = toMat(given[i], names[i], true);
                {
                    py::gil_scoped_release noGil;
                    self.getLastStageOutputs(outputs[0].mat, outputs[1].mat, outputs[2].mat, outputs[3].mat);
                }
                py::tuple result(4);
                for (int i = 0; i < 4; i++)
                    result[i] = returnedOutput(given[i], outputs[i]);
                return result;
            },
            "baseSegments"_a = py::none(), "filteredSegments"_a = py::none(), "groupLabels"_a = py::none(),
            "mergedSegments"_a = py::none(),
            "getLastStageOutputs([, baseSegments[, filteredSegments[, groupLabels[, mergedSegments]]]]) -> "
            "baseSegments, filteredSegments, groupLabels, mergedSegments\n\nThe segments after each stage of the "
            "last detect() or processSegments() (N x 1 x 4 float32; groupLabels N x 1 int32), None when empty.")
        .def("getDefaultName", &LSDAdvance::getDefaultName)
        .def("empty", &LSDAdvance::empty)
        .def("clear", &LSDAdvance::clear)
        .def("save", &LSDAdvance::save, "filename"_a,
             "save(filename) -> None\n\nWrites the parameters to a FileStorage file (.yml, .xml, .json) under a "
             "node named getDefaultName().")
        .def(
            "write",
            [](const LSDAdvance& self, const py::object& fs, const std::string& name) {
                FileStorage memory(".yml", FileStorage::WRITE | FileStorage::MEMORY);
                if (name.empty())
                    self.write(memory);
                else
                {
                    memory << name << "{";
                    self.write(memory);
                    memory << "}";
                }
                FileStorage written(memory.releaseAndGetString(), FileStorage::READ | FileStorage::MEMORY);
                const py::module_ cv2 = importCv2("write");
                for (const FileNode& node : written.root())
                    copyFileNode(node, node.name(), fs, cv2);
            },
            "fs"_a, "name"_a = std::string(),
            "write(fs[, name]) -> None\n\nWrites the parameters into a cv2.FileStorage opened for writing "
            "(under a map called name when given).")
        .def(
            "read",
            [](LSDAdvance& self, const py::object& fn) {
                // The node is copied under one key, so that read() gets a node of the same kind.
                FileStorage memory(".yml", FileStorage::WRITE | FileStorage::MEMORY);
                copyFileNode(fn, "node", memory);
                FileStorage copied(memory.releaseAndGetString(), FileStorage::READ | FileStorage::MEMORY);
                self.read(copied["node"]);
            },
            "fn"_a,
            "read(fn) -> None\n\nReads the parameters from a cv2.FileNode, e.g. "
            "cv2.FileStorage(path, cv2.FILE_STORAGE_READ).getNode('LSDAdvance') for a file written by save().");

    m.def(
        "createLSDAdvance",
        [](int preset) { return std::shared_ptr<LSDAdvance>(createLSDAdvance((LSDAdvance::Preset)preset)); },
        "preset"_a = (int)LSDAdvance::PRESET_MOST_ACCURATE, "createLSDAdvance([, preset]) -> retval");

    // Constants named as OpenCV 4.6's generator names them (cv2.ximgproc.LSDAdvance_...): the names of
    // the enumerated parameters of the table, and the presets.
    for (const lsda::Field<LSDAdvance::Params>& f : lsda::fieldsOf<LSDAdvance::Params>())
        if (f.range.kind == lsda::Range::ENUM)
            for (int k = 0; k < f.range.count; k++)
                m.attr(("LSDAdvance_" + std::string(f.range.names[k])).c_str()) = k;
    for (int k = 0; k < LSDA_COUNT_OF(lsda::kPresets); k++)
        m.attr(("LSDAdvance_" + std::string(lsda::kPresets[k])).c_str()) = k;

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    m.def(
        "linesToKeyLines",
        [](const py::object& lines, const std::array<int, 2>& imageSize) {
            const ArrayArg in = toMat(lines, "lines");
            std::vector<KeyLine> keylines;
            {
                py::gil_scoped_release noGil;
                linesToKeyLines(in.mat, toSize(imageSize), keylines);
            }
            return toPythonKeyLines(keylines);
        },
        "lines"_a, "imageSize"_a,
        "linesToKeyLines(lines, imageSize) -> keylines\n\nSegments (N x 1 x 4 float32) to a list of "
        "cv2.line_descriptor.KeyLine of octave 0, as LSDDetector fills them. imageSize is (width, height) "
        "like cv2's Size, i.e. (img.shape[1], img.shape[0]).");
    m.def(
        "keyLinesToLines",
        [](const py::iterable& keylines) {
            Mat lines;
            keyLinesToLines(fromPythonKeyLines(keylines), lines);
            return toNumpy(lines);
        },
        "keylines"_a,
        "keyLinesToLines(keylines) -> lines\n\nKeyLines back to segments (startPoint, endPoint), N x 1 x 4 float32.");
#endif
    m.def(
        "computeLineResponses",
        [](const py::object& image, const py::object& lines) {
            const ArrayArg img = toMat(image, "image");
            const ArrayArg segments = toMat(lines, "lines");
            Mat responses;
            computeLineResponses(img.mat, segments.mat, responses);
            return toNumpy(responses);
        },
        "image"_a, "lines"_a,
        "computeLineResponses(image, lines) -> responses\n\nResponse of each segment (N x 1 float32): "
        "length / max(width, height) times the squared mean contrast across it / 255.");

    // Evaluation (opencv2/lsd_advance/evaluation.hpp), as cv2.ximgproc.line_evaluation has it in-tree.
    py::module_ ev = m.def_submodule("line_evaluation", "Evaluation of line segments and line matches "
                                                          "(cv::ximgproc::line_evaluation).");
    ev.attr("EPIPOLAR_CONSISTENT") = (int)EPIPOLAR_CONSISTENT;
    ev.attr("EPIPOLAR_INCONSISTENT") = (int)EPIPOLAR_INCONSISTENT;
    ev.attr("EPIPOLAR_UNDECIDABLE") = (int)EPIPOLAR_UNDECIDABLE;
    py::class_<StructuralMatchParams>(ev, "StructuralMatchParams")
        .def(py::init<>())
        .def_readwrite("maxDistance", &StructuralMatchParams::maxDistance)
        .def_readwrite("maxAngle", &StructuralMatchParams::maxAngle)
        .def_readwrite("minCoverage", &StructuralMatchParams::minCoverage)
        .def_readwrite("offset", &StructuralMatchParams::offset);
    py::class_<StructuralScore>(ev, "StructuralScore")
        .def(py::init<>())
        .def_readwrite("precision", &StructuralScore::precision)
        .def_readwrite("recall", &StructuralScore::recall)
        .def_readwrite("matchedLength", &StructuralScore::matchedLength)
        .def_readwrite("detectedLength", &StructuralScore::detectedLength)
        .def_readwrite("coveredLength", &StructuralScore::coveredLength)
        .def_readwrite("groundTruthLength", &StructuralScore::groundTruthLength)
        .def_readwrite("found", &StructuralScore::found)
        .def_readwrite("groundTruthCount", &StructuralScore::groundTruthCount);
    py::class_<HomographyMatchScore>(ev, "HomographyMatchScore")
        .def(py::init<>())
        .def_readwrite("matches", &HomographyMatchScore::matches)
        .def_readwrite("correct", &HomographyMatchScore::correct)
        .def_readwrite("precision", &HomographyMatchScore::precision)
        .def_readwrite("repeatability", &HomographyMatchScore::repeatability)
        .def_readwrite("localisationError", &HomographyMatchScore::localisationError)
        .def_readwrite("repeated", &HomographyMatchScore::repeated)
        .def_readwrite("visible", &HomographyMatchScore::visible);
    py::class_<EpipolarMatchScore>(ev, "EpipolarMatchScore")
        .def(py::init<>())
        .def_readwrite("matches", &EpipolarMatchScore::matches)
        .def_readwrite("consistent", &EpipolarMatchScore::consistent)
        .def_readwrite("inconsistent", &EpipolarMatchScore::inconsistent)
        .def_readwrite("undecidable", &EpipolarMatchScore::undecidable)
        .def_readwrite("precision", &EpipolarMatchScore::precision);
    py::class_<SequenceData>(ev, "SequenceData")
        .def(py::init<>())
        .def_readwrite("imagePaths", &SequenceData::imagePaths)
        .def_property_readonly("P0", [](const SequenceData& s) { return toNumpy(s.P0); })
        .def_property_readonly("P1", [](const SequenceData& s) { return toNumpy(s.P1); })
        .def_property_readonly("poses", [](const SequenceData& s) {
            py::list poses;
            for (const Mat& p : s.poses)
                poses.append(toNumpy(p));
            return poses;
        });

    ev.def(
        "evaluateStructural",
        [](const py::object& detections, const py::object& groundTruth, const StructuralMatchParams& params) {
            return evaluateStructural(toMat(detections, "detections").mat, toMat(groundTruth, "groundTruth").mat,
                                      params);
        },
        "detections"_a, "groundTruth"_a, "params"_a = StructuralMatchParams());
    ev.def("fScore", &fScore, "averagePrecision"_a, "averageRecall"_a);
    ev.def(
        "longSegmentShare",
        [](const py::object& lines, double minLength) { return longSegmentShare(toMat(lines, "lines").mat, minLength); },
        "lines"_a, "minLength"_a = 60.0);
    ev.def(
        "readSegments", [](const std::string& path) { return toNumpy(readSegments(path)); }, "path"_a);
    ev.def(
        "writeSegments",
        [](const std::string& path, const py::object& lines) { writeSegments(path, toMat(lines, "lines").mat); },
        "path"_a, "lines"_a);
    ev.def("loadSequence", &loadSequence, "folder"_a);
    ev.def(
        "correspondUnderHomography",
        [](const std::array<float, 4>& a, const std::array<float, 4>& b, const py::object& H, double maxDistance) {
            return correspondUnderHomography(toVec4f(a), toVec4f(b), toMat(H, "H").mat, maxDistance);
        },
        "a"_a, "b"_a, "H"_a, "maxDistance"_a = 3.0);
    ev.def(
        "evaluateHomographyMatches",
        [](const py::object& segments1, const py::object& segments2, const py::iterable& matches, const py::object& H,
           const std::array<int, 2>& imageSize1, const std::array<int, 2>& imageSize2, double maxDistance) {
            return evaluateHomographyMatches(toMat(segments1, "segments1").mat, toMat(segments2, "segments2").mat,
                                             fromPythonMatches(matches), toMat(H, "H").mat, toSize(imageSize1),
                                             toSize(imageSize2), maxDistance);
        },
        "segments1"_a, "segments2"_a, "matches"_a, "H"_a, "imageSize1"_a, "imageSize2"_a, "maxDistance"_a = 3.0);
    ev.def(
        "checkEpipolar",
        [](const std::array<float, 4>& a, const std::array<float, 4>& b, const py::object& F, double tolerance,
           double minAngle) { return checkEpipolar(toVec4f(a), toVec4f(b), toMat(F, "F").mat, tolerance, minAngle); },
        "a"_a, "b"_a, "F"_a, "tolerance"_a = 2.0, "minAngle"_a = 5.0);
    ev.def(
        "fundamentalFromPoses",
        [](const py::object& P, const py::object& pose1, const py::object& pose2) {
            return toNumpy(fundamentalFromPoses(toMat(P, "P").mat, toMat(pose1, "pose1").mat, toMat(pose2, "pose2").mat));
        },
        "P"_a, "pose1"_a, "pose2"_a);
    ev.def(
        "evaluateEpipolarMatches",
        [](const py::object& segments1, const py::object& segments2, const py::iterable& matches, const py::object& F,
           double tolerance, double minAngle) {
            return evaluateEpipolarMatches(toMat(segments1, "segments1").mat, toMat(segments2, "segments2").mat,
                                           fromPythonMatches(matches), toMat(F, "F").mat, tolerance, minAngle);
        },
        "segments1"_a, "segments2"_a, "matches"_a, "F"_a, "tolerance"_a = 2.0, "minAngle"_a = 5.0);
    ev.def(
        "readHomography", [](const std::string& path) { return toNumpy(readHomography(path)); }, "path"_a);
}
