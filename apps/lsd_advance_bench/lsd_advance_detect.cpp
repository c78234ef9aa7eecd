// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Detects line segments in an image, each image of a folder or each frame of a video with one
// of the methods of line_methods.hpp (LSDAdvance's variants: methods/<name>.yml), optionally writes them (<stem>.txt, x1 y1 x2 y2 per row)
// and drawn on the image (<stem>.png), and prints segments per image, the share of long
// segments and the time of the detection. For LSDAdvance it also draws what each stage did
// (--draw=filter,groups,merge), like the figures of the paper, from getLastStageOutputs() and
// getLastSources(). --write-params writes an LSDAdvance method as a method file, to start a new
// variant from.

#include "command_line.hpp"
#include "line_methods.hpp"

#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/lsd_advance/evaluation.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

using namespace cv;

namespace {

//--- input

// File name without folder and extension.
std::string stemOf(const std::string& path)
{
    const size_t slash = path.find_last_of("/\\");
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return name.substr(0, name.rfind('.'));
}

// The gray images to detect on, one after the other: an image file, the images of a folder
// in name order, or the frames of a video. A file of a folder that cannot be read as an image
// is reported on stderr and skipped; with a progress label, "[label] k/n" counts the files on
// one stderr line.
class FrameSource
{
public:
    //! Throws std::runtime_error when the input does not exist, cannot be read or holds no image.
    explicit FrameSource(const String& input, const std::string& progressLabel = std::string())
        : progressLabel_(progressLabel)
    {
        // Finds sample names such as building.jpg; keeps what it cannot find (video URLs, patterns).
        const String path = samples::findFileOrKeep(input, true);
        const bool exists = utils::fs::exists(path);
        if (utils::fs::isDirectory(path))
            paths_ = ximgproc::line_evaluation::loadSequence(path).imagePaths;  // name order; throws when there is none
        else if (exists && haveImageReader(path))
        {
            paths_.push_back(path);
            singleImage_ = true;
        }
        // A file named as an image (OpenCV would write one under this name) is not tried as a
        // video: the video backends would only add their own messages to the app's error.
        else if (exists && haveImageWriter(path))
            throw std::runtime_error("cannot read " + path + " as an image");
        // Streams and image-sequence patterns do not exist as files; anything else missing is
        // reported here rather than by the video backends' warnings.
        else if (!exists && path.find("://") == String::npos && path.find('%') == String::npos)
            throw std::runtime_error("no such image, folder or video: " + path);
        else
        {
            // The backends that cannot open the file log why; the app's error says it once.
            const utils::logging::LogLevel logLevel =
                utils::logging::setLogLevel(utils::logging::LOG_LEVEL_FATAL);
            const bool opened = video_.open(path);
            utils::logging::setLogLevel(logLevel);
            if (!opened)
                throw std::runtime_error("cannot read " + path + " as an image or a video");
        }
    }

    //! Number of images, 0 when a video does not tell.
    size_t count() const
    {
        return video_.isOpened() ? (size_t)std::max(0.0, video_.get(CAP_PROP_FRAME_COUNT)) : paths_.size();
    }

    //! The next image as CV_8UC1 and the stem of its output files; false after the last one.
    //! Throws std::runtime_error when no image at all could be read.
    bool next(Mat& gray, std::string& stem)
    {
        if (video_.isOpened())
        {
            Mat frame;
            if (!video_.read(frame) || frame.empty())
                return finish();
            if (frame.channels() == 1)
                gray = frame;
            else
                cvtColor(frame, gray, frame.channels() == 4 ? COLOR_BGRA2GRAY : COLOR_BGR2GRAY);
            stem = format("frame_%06d", frameIndex_++);
            showProgress((size_t)frameIndex_);
            return true;
        }
        while (nextPath_ < paths_.size())
        {
            const String& path = paths_[nextPath_++];
            showProgress(nextPath_);
            gray = readGrayImage(path);
            if (!gray.empty())
            {
                stem = stemOf(path);
                read_++;
                return true;
            }
            if (singleImage_)
                throw std::runtime_error("cannot read " + path + " as an image");
            skipped_.push_back(path);
            if (progressShown_)
                std::cerr << "\n";
            progressShown_ = false;
            reportSkipped(path);
        }
        return finish();
    }

    //! The files of a folder skipped so far as unreadable.
    const std::vector<std::string>& skipped() const { return skipped_; }

private:
    void showProgress(size_t done)
    {
        if (progressLabel_.empty() || singleImage_)
            return;
        std::cerr << "\r[" << progressLabel_ << "] " << done;
        if (count() > 0)
            std::cerr << "/" << count();
        std::cerr << std::flush;
        progressShown_ = true;
    }

    // Ends the progress line; false, for next().
    bool finish()
    {
        if (progressShown_)
            std::cerr << "\n";
        progressShown_ = false;
        if (read_ == 0 && frameIndex_ == 0 && !skipped_.empty())
            throw std::runtime_error(format("none of the %zu image files could be read", skipped_.size()));
        return false;
    }

    std::string progressLabel_;
    std::vector<String> paths_;
    bool singleImage_ = false;
    size_t nextPath_ = 0, read_ = 0;
    std::vector<std::string> skipped_;
    bool progressShown_ = false;
    VideoCapture video_;
    int frameIndex_ = 0;
};

//--- drawings of the stages

const Scalar kGrey(150, 150, 150), kKept(80, 220, 80), kDropped(60, 60, 235), kFused(230, 200, 40),
    kPieceA(40, 170, 255), kPieceB(200, 80, 255);

// A key of a drawing's caption: a short stroke of the colour, then the text.
struct LegendItem
{
    Scalar colour;
    std::string text;
};

// What --draw asks for.
struct Drawings
{
    bool lines = false, filter = false, groups = false, merge = false;

    bool any() const { return lines || filter || groups || merge; }
    bool ofStages() const { return filter || groups || merge; }
};

Drawings parseDrawings(const std::string& list)
{
    Drawings d;
    std::stringstream ss(list);
    std::string kind;
    while (std::getline(ss, kind, ','))
    {
        if (kind == "lines")
            d.lines = true;
        else if (kind == "filter")
            d.filter = true;
        else if (kind == "groups")
            d.groups = true;
        else if (kind == "merge")
            d.merge = true;
        else if (kind == "stages")
            d.filter = d.groups = d.merge = true;
        else if (!kind.empty())
            throw std::runtime_error("unknown drawing '" + kind + "'; known: lines, filter, groups, merge, stages");
    }
    return d;
}

// The image, or a region of it enlarged to about 900 px wide (--zoom), darkened so that
// coloured segments stand out on any content; segments are given in image coordinates.
class StageCanvas
{
public:
    StageCanvas(const Mat& gray, const Rect& region)
        : region_(region), scale_(std::max(1, cvRound(900.0 / region.width)))
    {
        Mat dim;
        gray(region).convertTo(dim, -1, 0.4, 10);
        resize(dim, dim, Size(), scale_, scale_, INTER_LINEAR);
        cvtColor(dim, image, COLOR_GRAY2BGR);
        stroke = std::max(1, cvRound(std::min(image.cols, image.rows) / 900.0));
        whole_ = region.size() == gray.size();
    }
    //! A copy is a separate drawing on the same background (Mat alone would share the pixels).
    StageCanvas(const StageCanvas& other)
        : image(other.image.clone()), stroke(other.stroke), region_(other.region_), scale_(other.scale_),
          whole_(other.whole_)
    {}
    StageCanvas& operator=(const StageCanvas&) = delete;

    Mat image;       //!< BGR
    int stroke = 1;  //!< width of a thin line, px

    void segment(const Vec4f& s, const Scalar& colour, int thickness) { segmentOn(image, s, colour, thickness); }
    //! The same on another image of the canvas' size (a layer blended later).
    void segmentOn(Mat& target, const Vec4f& s, const Scalar& colour, int thickness) const
    {
        line(target, at(s[0], s[1]), at(s[2], s[3]), colour, thickness, LINE_AA);
    }
    void endpoints(const Vec4f& s, const Scalar& colour)
    {
        circle(image, at(s[0], s[1]), stroke + 1, colour, FILLED, LINE_AA);
        circle(image, at(s[2], s[3]), stroke + 1, colour, FILLED, LINE_AA);
    }
    //! For the title: which part of the image is shown.
    std::string shownPart() const
    {
        return whole_ ? std::string() : format(" [region %d,%d %dx%d, %dx]", region_.x, region_.y, region_.width,
                                               region_.height, scale_);
    }

private:
    // Pixel i of the image covers [i - 0.5, i + 0.5), as pixel centres are integers.
    Point2f at(float x, float y) const
    {
        return Point2f((float)((x - region_.x + 0.5) * scale_ - 0.5), (float)((y - region_.y + 0.5) * scale_ - 0.5));
    }

    Rect region_;
    int scale_;
    bool whole_ = true;
};

// --zoom=x,y,w,h (pixels, width and height >= 1); an empty rectangle when not given.
Rect parseZoom(const std::string& zoom)
{
    Rect r;
    char tail = 0;
    if (!zoom.empty() && (std::sscanf(zoom.c_str(), "%d,%d,%d,%d%c", &r.x, &r.y, &r.width, &r.height, &tail) != 4 ||
                          r.width < 1 || r.height < 1))
        throw std::runtime_error("--zoom must be x,y,width,height in pixels, width and height >= 1, got '" + zoom + "'");
    return r;
}

// The zoom rectangle within the image; the whole image without --zoom.
Rect zoomRegion(const Rect& zoom, const Size& imageSize)
{
    const Rect whole(Point(), imageSize);
    if (zoom.empty())
        return whole;
    if ((zoom & whole).area() == 0)
        throw std::runtime_error(format("--zoom=%d,%d,%d,%d does not overlap the %dx%d image", zoom.x, zoom.y,
                                        zoom.width, zoom.height, imageSize.width, imageSize.height));
    return zoom & whole;
}

// The drawing with a black band above it: a title, then the legend, wrapped to the width.
Mat withCaption(const Mat& picture, const std::string& title, const std::vector<LegendItem>& legend)
{
    const int font = FONT_HERSHEY_SIMPLEX;
    const double scale = std::min(1.2, std::max(0.42, picture.cols / 1500.0));
    const int weight = scale > 0.8 ? 2 : 1;
    int baseline = 0;
    const int textHeight = getTextSize("Ag", font, scale, weight, &baseline).height;
    const int rowHeight = textHeight + baseline + 8, margin = 8, keyLength = 3 * textHeight;

    // Lay out first: rows of (x, item), the title alone on the first row.
    std::vector<std::vector<std::pair<int, const LegendItem*> > > rows(1);
    int x = margin;
    for (const LegendItem& item : legend)
    {
        const int width = keyLength + 6 + getTextSize(item.text, font, scale, weight, &baseline).width;
        if (rows.size() == 1 || (x + width > picture.cols - margin && !rows.back().empty()))
        {
            rows.push_back({});
            x = margin;
        }
        rows.back().push_back(std::make_pair(x, &item));
        x += width + 3 * margin;
    }
    Mat out(picture.rows + (int)rows.size() * rowHeight + margin, picture.cols, CV_8UC3, Scalar::all(0));
    picture.copyTo(out(Rect(0, out.rows - picture.rows, picture.cols, picture.rows)));
    const Scalar white(255, 255, 255);
    putText(out, title, Point(margin, margin + textHeight), font, scale, white, weight, LINE_AA);
    for (size_t r = 1; r < rows.size(); r++)
    {
        const int y = margin + (int)r * rowHeight + textHeight;
        for (const auto& placed : rows[r])
        {
            line(out, Point(placed.first, y - textHeight / 2), Point(placed.first + keyLength, y - textHeight / 2),
                 placed.second->colour, std::max(2, weight + 1), LINE_AA);
            putText(out, placed.second->text, Point(placed.first + keyLength + 6, y), font, scale, white, weight, LINE_AA);
        }
    }
    return out;
}

// Distinct colour number k: hues spaced by the golden angle, bright and saturated.
Scalar groupColour(int k)
{
    const double hue = std::fmod(k * 0.618033988749895, 1.0) * 180.0;
    Mat hsv(1, 1, CV_8UC3, Scalar(hue, k % 3 == 1 ? 170 : 255, 255)), bgr;
    cvtColor(hsv, bgr, COLOR_HSV2BGR);
    const Vec3b c = bgr.at<Vec3b>(0, 0);
    return Scalar(c[0], c[1], c[2]);
}

// The outputs of the stages of the last detect(), the lines it returned with the base segments
// each was made from, and how the stages were run.
struct Stages
{
    std::vector<Vec4f> base, filtered, merged, lines;
    std::vector<int> labels;
    std::vector<std::vector<int> > sources;
    ximgproc::LSDAdvanceStats stats;
    bool filterFirst = false, filterOn = false, mergeOn = false;

    Stages(const ximgproc::LSDAdvance& detector, const std::vector<Vec4f>& returned) : lines(returned)
    {
        detector.getLastStageOutputs(base, filtered, labels, merged);
        detector.getLastSources(sources);
        stats = detector.getLastStats();
        filterFirst = detector.getStageOrder() == ximgproc::LSDAdvance::FILTER_THEN_MERGE;
        filterOn = detector.getLengthFilterMode() != ximgproc::LSDAdvance::LENGTH_FILTER_NONE;
        mergeOn = detector.getMergeStrategy() != ximgproc::LSDAdvance::MERGE_NONE;
    }
    const std::vector<Vec4f>& filterInput() const { return filterFirst ? base : merged; }
    const std::vector<Vec4f>& groupingInput() const { return filterFirst ? filtered : base; }
};

// (a) Stage 1: the segments it kept and those it dropped.
Mat drawFilter(StageCanvas canvas, const Stages& st)
{
    const int w = canvas.stroke;
    const std::vector<Vec4f>& input = st.filterInput();
    // The filter keeps segments in their order, so kept ones are a subsequence of the input.
    size_t k = 0;
    for (const Vec4f& s : input)
        if (k < st.filtered.size() && s == st.filtered[k])
            k++;
        else
            canvas.segment(s, kDropped, w);
    for (const Vec4f& s : st.filtered)
        canvas.segment(s, kKept, w + 1);
    const int dropped = (int)(input.size() - st.filtered.size());
    // Short segments stay when strong (setKeepStrongSegments): then the response threshold is shown too.
    const bool strong = st.stats.minResponse > 0;
    const std::string title = format("Stage 1, length filter on the %s segments: min length %.1f px%s (alpha %.2f)%s%s",
                                     st.filterFirst ? "base" : "merged", st.stats.minLength,
                                     strong ? format(" or min response %.4f", st.stats.minResponse).c_str() : "",
                                     st.stats.alpha, st.filterOn ? "" : " - filter off", canvas.shownPart().c_str());
    return withCaption(canvas.image, title,
                       { { kKept, format("kept: %zu", st.filtered.size()) },
                         { kDropped, format(strong ? "dropped (shorter and weaker): %d" : "dropped (shorter): %d", dropped) } });
}

// (b) Stage 2: each group of two or more segments in its own colour, segments alone in grey.
Mat drawGroups(StageCanvas canvas, const Stages& st)
{
    const int w = canvas.stroke;
    const std::vector<Vec4f>& input = st.groupingInput();
    int alone = 0, grouped = 0;
    for (size_t i = 0; i < input.size(); i++)
        if (st.labels.empty() || st.labels[i] < 0)
        {
            canvas.segment(input[i], kGrey, w);
            alone++;
        }
    for (size_t i = 0; i < st.labels.size(); i++)
        if (st.labels[i] >= 0)
        {
            canvas.segment(input[i], groupColour(st.labels[i]), w + 1);
            grouped++;
        }
    const std::string title = format("Stage 2, grouping of the %s segments by angle and endpoints%s%s",
                                     st.filterFirst ? "filtered" : "base", st.mergeOn ? "" : " - merging off",
                                     canvas.shownPart().c_str());
    return withCaption(canvas.image, title, { { groupColour(0), format("%d groups of 2+ segments (one colour each): %d segments",
                                                                 st.stats.mergeGroups, grouped) },
                                        { kGrey, format("alone: %d", alone) } });
}

// (c) Stage 3: every returned line fused from several base segments (getLastSources()) as a wide
// band with those pieces drawn thin on top in alternating colours; lines of one segment in grey.
Mat drawMerge(StageCanvas canvas, const Stages& st)
{
    const int w = canvas.stroke;
    int fused = 0, pieces = 0, unchanged = 0;
    for (size_t j = 0; j < st.lines.size(); j++)
        if (st.sources[j].size() == 1)
        {
            canvas.segment(st.lines[j], kGrey, w);
            unchanged++;
        }
    Mat bands = canvas.image.clone();
    for (size_t j = 0; j < st.lines.size(); j++)
        if (st.sources[j].size() > 1)
        {
            canvas.segmentOn(bands, st.lines[j], kFused, 4 * w + 3);
            fused++;
        }
    addWeighted(bands, 0.6, canvas.image, 0.4, 0, canvas.image);
    for (const std::vector<int>& from : st.sources)
        if (from.size() > 1)
            for (int i : from)
            {
                const Scalar& c = pieces % 2 ? kPieceB : kPieceA;
                canvas.segment(st.base[i], c, w);
                canvas.endpoints(st.base[i], c);
                pieces++;
            }
    const std::string title = format("Stage 3, merging: %zu segments in, %zu out, %zu returned%s%s",
                                     st.groupingInput().size(), st.merged.size(), st.lines.size(),
                                     st.mergeOn ? "" : " - merging off", canvas.shownPart().c_str());
    return withCaption(canvas.image, title, { { kFused, format("fused lines: %d", fused) },
                                        { kPieceA, format("base segments they were fused from (orange and pink in turn): %d", pieces) },
                                        { kGrey, format("lines of one segment: %d", unchanged) } });
}

void writeImage(const std::string& path, const Mat& image)
{
    if (!imwrite(path, image))
        throw std::runtime_error("cannot write " + path);
}

struct Summary
{
    size_t images = 0;
    double segments = 0, longSegments = 0;
    std::vector<double> ms;

    void add(const std::vector<Vec4f>& lines, double detectMs, double longLength)
    {
        images++;
        segments += (double)lines.size();
        longSegments += ximgproc::line_evaluation::longSegmentShare(lines, longLength) * (double)lines.size();
        ms.push_back(detectMs);
    }

    void print(const std::string& method, double longLength, size_t skipped) const
    {
        std::printf("method:            %s\n", method.c_str());
        if (skipped > 0)
            std::printf("images:            %zu (%zu unreadable file(s) skipped)\n", images, skipped);
        else
            std::printf("images:            %zu\n", images);
        std::printf("segments / image:  %.1f\n", segments / (double)images);
        std::printf("long share:        %.3f (>= %g px, over all segments)\n",
                    segments > 0 ? longSegments / segments : 0.0, longLength);
        std::printf("ms / image:        %.2f mean, %.2f median (detection only)\n", mean(ms)[0], median(ms));
    }
};

int run(const AppOptions& args)
{
    const String input = args.text("input");
    const String output = args.text("output");
    const bool sequence = args.has("sequence"), writeTxt = !args.has("no-segments");
    const Drawings draw = parseDrawings(args.has("draw") ? args.text("draw") : std::string());
    const std::string extension = args.oneOf("ext", { "png", "jpg" });
    const Rect zoom = parseZoom(args.text("zoom"));
    const double longLength = args.number("long", 0, kUnbounded, true);
    if (draw.any() && output.empty())
        throw std::runtime_error("--draw needs --output=<folder>");

    const String paramsOut = args.text("write-params");
    checkOutputFolder("write-params", paramsOut);
    const FileStorage params = openParamsFile(args.text("params"));
    const LineMethod method = makeLineMethod(args.text("method"), params.isOpened() ? params.root() : FileNode());
    if (!paramsOut.empty())
    {
        if (!method.lsdAdvance)
            throw std::runtime_error("--write-params needs an LSDAdvance method, not " + method.name);
        writeLineMethod(paramsOut, method);
        std::printf("wrote the parameters of %s to %s\n", method.name.c_str(), paramsOut.c_str());
        return 0;
    }
    if (input.empty())
        throw std::runtime_error("--input is required: an image, a folder of images or a video");
    if (draw.ofStages() && !method.lsdAdvance)
        throw std::runtime_error("--draw=filter, groups or merge needs an LSDAdvance method, not " + method.name);
    FrameSource source(input, "detect");
    if (!output.empty() && !utils::fs::createDirectories(output))
        throw std::runtime_error("cannot create the output folder " + output);

    const Ptr<ximgproc::LSDAdvance> drawer = ximgproc::createLSDAdvance();
    Summary summary;
    Mat gray;
    std::string stem;
    method.reset();
    while (source.next(gray, stem))
    {
        // Unrelated images must not steer the inter-frame factor of the next one.
        if (!sequence)
            method.reset();
        std::vector<Vec4f> lines;
        TickMeter tm;
        tm.start();
        method.detect(gray, lines);
        tm.stop();
        summary.add(lines, tm.getTimeMilli(), longLength);

        if (!output.empty() && writeTxt)
            ximgproc::line_evaluation::writeSegments(utils::fs::join(output, stem + ".txt"), lines);
        if (draw.lines)
        {
            Mat canvas = gray.clone();
            drawer->drawSegments(canvas, lines);
            writeImage(utils::fs::join(output, stem + "." + extension), canvas);
        }
        if (draw.ofStages())
        {
            const Stages stages(*method.lsdAdvance, lines);
            const StageCanvas canvas(gray, zoomRegion(zoom, gray.size()));
            if (draw.filter)
                writeImage(utils::fs::join(output, stem + "_filter." + extension), drawFilter(canvas, stages));
            if (draw.groups)
                writeImage(utils::fs::join(output, stem + "_groups." + extension), drawGroups(canvas, stages));
            if (draw.merge)
                writeImage(utils::fs::join(output, stem + "_merge." + extension), drawMerge(canvas, stages));
        }
    }
    if (summary.images == 0)
        throw std::runtime_error("no frame in " + input);

    summary.print(method.name, longLength, source.skipped().size());
    if (!output.empty())
    {
        if (writeTxt)
            std::printf("wrote %zu segment file(s)%s to %s\n", summary.images, draw.any() ? " and drawings" : "",
                        output.c_str());
        else
            std::printf("wrote the drawings of %zu image(s) to %s\n", summary.images, output.c_str());
    }
    return source.skipped().empty() ? 0 : kExitSkipped;
}

} // namespace

int main(int argc, char** argv)
{
    const String keys =
        "{help h   |            | print this help }"
        "{input i  |            | an image, a folder of images (png, jpg, jpeg, ppm, pgm, bmp) or a video; required "
                                 "unless --write-params is given }"
        "{output o |            | folder for <stem>.txt (x1 y1 x2 y2 per segment, pixel centres); created if missing }"
        "{method m | lsdadvance | one of: " + lineMethodList() + " }"
        "{sequence |            | the images of a folder (in name order) or a video are consecutive frames: "
                                 "LSDAdvance's inter-frame factor is on; otherwise every image is independent }"
        "{draw     |            | also write drawings (needs --output), a comma-separated list: lines (<stem>.png, the "
                                 "segments on the image); for LSDAdvance methods filter "
                                 "(<stem>_filter.png: kept and dropped by the length filter), groups (<stem>_groups.png: "
                                 "the merge groups in colours), merge (<stem>_merge.png: fused segments and their pieces); "
                                 "stages = filter,groups,merge }"
        "{ext      | png        | file type of the drawings: png or jpg }"
        "{zoom     |            | the filter, groups and merge drawings show only this region x,y,width,height (px, "
                                 "width and height >= 1, overlapping the image) of the image, enlarged to about 900 px wide }"
        "{no-segments |         | with --output, write only the drawings, not <stem>.txt }"
        "{params p |            | YAML/XML of LSDAdvance parameters saved with write(), for the lsdadvance method }"
        "{write-params |        | write the parameters of the LSDAdvance method (with --params) to this file as a "
                                 "method file, methods/<name>.yml, and exit }"
        "{long     | 60         | length in pixels from which a segment counts as long, > 0 }";
    const String about = "Detects line segments with LSDAdvance (or another method) and writes them to text files. "
                         "Exit status: 0, 1 on an error, 2 when unreadable files of a folder were skipped.";
    return runApp(argc, argv, keys, about, { "sequence", "no-segments" }, run);
}
