// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Aliased edges: shapes drawn without anti-aliasing, as in drawings, screenshots and the frames of
// simulators, have staircase edges whose 2x2 gradients swing past LSD's angle tolerance. The
// pre-smoothing at scale 1 (LSDParams::fullScaleSigma), which both LSD bases apply with the same
// Gaussian (FullScaleSmoothing), finds more of them; at 0 the bases read the image as the LSD
// algorithm does. By default (LSDParams::fullScaleSmoothing SMOOTH_ALIASED_IMAGES) only images
// whose edges are mostly steps of one pixel are smoothed (hasAliasedEdges): a photograph is read as
// it is. Also: a view of a larger image gives the lines of its copy at every scale (the Gaussians
// reflect the view's border instead of reading around it).

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Whether a line runs along an edge: both its endpoints within `distance` px of the edge's line,
// its direction within 3 degrees, and its projection on the edge covering `share` of it.
bool runsAlong(const Vec4f& line, const Vec4f& edge, double distance = 1.5, double share = 0.6)
{
    const Point2d a(edge[0], edge[1]), d(edge[2] - edge[0], edge[3] - edge[1]);
    const double length = std::sqrt(d.dot(d));
    const Point2d u = d * (1.0 / length), n(-u.y, u.x);
    const Point2d p(line[0], line[1]), q(line[2], line[3]);
    if (std::abs((p - a).dot(n)) > distance || std::abs((q - a).dot(n)) > distance)
        return false;
    double angle = std::abs(undirectedAngle(line) - undirectedAngle(edge));
    angle = std::min(angle, 180.0 - angle);
    if (angle > 3.0)
        return false;
    const double s = (p - a).dot(u), t = (q - a).dot(u);
    const double covered = std::min(length, std::max(s, t)) - std::max(0.0, std::min(s, t));
    return covered >= share * length;
}

int edgesFound(const std::vector<Vec4f>& lines, const std::vector<Vec4f>& edges)
{
    int found = 0;
    for (const Vec4f& e : edges)
        found += std::any_of(lines.begin(), lines.end(), [&](const Vec4f& l) { return runsAlong(l, e); });
    return found;
}

// The edge from a to b moved by `offset` px to its left (y down) and shortened by `trim` px at both ends.
Vec4f edgeOf(Point2f a, Point2f b, double offset, double trim)
{
    const Point2d d(b.x - a.x, b.y - a.y);
    const Point2d u = d * (1.0 / std::sqrt(d.dot(d))), n(u.y, -u.x);
    const Point2d p = Point2d(a) + n * offset + u * trim, q = Point2d(b) + n * offset - u * trim;
    return Vec4f((float)p.x, (float)p.y, (float)q.x, (float)q.y);
}

// Issue 21's case, the rotated rectangles of OpenCV's LSD test (lines 3 px wide, LINE_8): the
// inner and outer edges of each side (8 edges), away from the corners. cv::line takes integer
// points: the sides run between the corners rounded, as drawn (the corners as computed lie up to
// 0.7 px off, which put a correct line 1.5 px from a side's edge).
std::vector<Vec4f> rectangleEdges(const RotatedRect& r)
{
    Point2f v[4];
    r.points(v);
    std::vector<Vec4f> edges;
    for (int i = 0; i < 4; i++)
        for (const double offset : { -1.5, 1.5 })
            edges.push_back(edgeOf(Point(v[i]), Point(v[(i + 1) % 4]), offset, 3.0));
    return edges;
}

Mat rectangleImage(Size size, const RotatedRect& r)
{
    Mat image = Mat::zeros(size, CV_8UC1);
    Point2f v[4];
    r.points(v);
    for (int i = 0; i < 4; i++)
        line(image, v[i], v[(i + 1) % 4], Scalar(255), 3);
    return image;
}

// OpenCV's draws of a rotated rectangle at an image size (test_lsd.cpp, test_fld.cpp).
RotatedRect randomRectangle(RNG& rng, Size size)
{
    const Point centre(rng.uniform(size.width / 4, size.width * 3 / 4), rng.uniform(size.height / 4, size.height * 3 / 4));
    const Size sides(rng.uniform(size.width / 8, size.width / 6), rng.uniform(size.height / 8, size.height / 6));
    const float angle = rng.uniform(0.f, 360.f);
    return RotatedRect(centre, sides, angle);
}

std::vector<Vec4f> detectWith(Ptr<LSDAdvance> detector, const Mat& image)
{
    std::vector<Vec4f> lines;
    detector->detect(image, lines);
    return lines;
}

Ptr<LSDAdvance> withFullScaleSigma(double sigma, int images = LSDAdvance::LSDParams().fullScaleSmoothing)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    LSDAdvance::LSDParams p = detector->getLSDParams();
    p.fullScaleSigma = sigma;
    p.fullScaleSmoothing = images;
    detector->setLSDParams(p);
    return detector;
}

bool aliased(const Mat& gray)
{
    std::vector<int64> counts;
    return lsda::hasAliasedEdges(gray, counts);
}

// The issue's own example: OpenCV's LSD finds 8 lines, the defaults found none.
TEST(LSDAdvance_AliasedEdges, the_issues_rectangle_gives_its_eight_edges)
{
    const RotatedRect r(Point(367, 274), Size(80, 66), 216.784f);
    const Mat image = rectangleImage(Size(640, 480), r);
    std::vector<Vec4f> lsd;
    createLineSegmentDetector()->detect(image, lsd);
    EXPECT_EQ(8u, lsd.size());
    const std::vector<Vec4f> lines = detectWith(createLSDAdvance(), image);
    EXPECT_EQ(8, edgesFound(lines, rectangleEdges(r)));
    EXPECT_GE(lines.size(), lsd.size());
}

// Issue 21's target: in each of OpenCV's 20 random rectangles at 640 x 480 and at 320 x 240, the
// defaults find at least as many of the edges as OpenCV's LSD (createLineSegmentDetector(), at
// scale 0.8). The side of a rectangle some degrees off an axis reaches the base as its staircase's
// runs, which the merging stage fuses along the line through them.
TEST(LSDAdvance_AliasedEdges, the_defaults_find_the_edges_LSD_finds_in_every_rotated_rectangle)
{
    for (const Size size : { Size(640, 480), Size(320, 240) })
    {
        RNG rng(0x134679);
        int epochs = 0, lsdFound = 0, found = 0;
        for (int epoch = 0; epoch < 20; epoch++)
        {
            const RotatedRect r = randomRectangle(rng, size);
            const Mat image = rectangleImage(size, r);
            std::vector<Vec4f> lsd;
            createLineSegmentDetector()->detect(image, lsd);
            const std::vector<Vec4f> sides = rectangleEdges(r);
            const int byLsd = edgesFound(lsd, sides), byDefaults = edgesFound(detectWith(createLSDAdvance(), image), sides);
            EXPECT_GE(byDefaults, byLsd) << size << ", epoch " << epoch << ", angle " << r.angle;
            epochs += byDefaults >= byLsd;
            lsdFound += byLsd;
            found += byDefaults;
        }
        std::cout << "[ INFO ] " << size << ": the defaults find at least LSD's edges in " << epochs
                  << " of 20 rectangles; of their 160 edges LSD finds " << lsdFound << ", the defaults " << found << std::endl;
    }
}

// The same rectangles, pooled: the pre-smoothing finds more of their edges than the image read
// as it is (the counts are in the test's output).
TEST(LSDAdvance_AliasedEdges, the_pre_smoothing_finds_more_edges_of_the_rotated_rectangles)
{
    int edges = 0, lsdFound = 0, smoothedFound = 0, exactFound = 0;
    for (const Size size : { Size(640, 480), Size(320, 240) })
    {
        RNG rng(0x134679);
        for (int epoch = 0; epoch < 20; epoch++)
        {
            const RotatedRect r = randomRectangle(rng, size);
            const Mat image = rectangleImage(size, r);
            std::vector<Vec4f> lsd;
            createLineSegmentDetector()->detect(image, lsd);
            const std::vector<Vec4f> lines = detectWith(createLSDAdvance(), image);
            const std::vector<Vec4f> sides = rectangleEdges(r);
            edges += (int)sides.size();
            lsdFound += edgesFound(lsd, sides);
            smoothedFound += edgesFound(lines, sides);
            exactFound += edgesFound(detectWith(withFullScaleSigma(0.0), image), sides);
        }
    }
    std::cout << "[ INFO ] of " << edges << " rectangle edges: OpenCV's LSD finds " << lsdFound << ", the defaults "
              << smoothedFound << ", fullScaleSigma 0 " << exactFound << std::endl;
    EXPECT_GT(smoothedFound, 2 * exactFound);
}

// A scene drawn without anti-aliasing: a filled rotated square, or a line of some width, at a
// contrast over the background, with Gaussian noise; the edges it must give.
struct AliasedScene
{
    Mat image;
    std::vector<Vec4f> edges;
};

// Gaussian noise of sigma `noise` gray levels, saturated.
void addNoise(Mat& image, double noise, RNG& rng)
{
    if (noise <= 0)
        return;
    Mat n(image.size(), CV_16SC1), sum;
    rng.fill(n, RNG::NORMAL, 0, noise);
    cv::add(image, n, sum, noArray(), CV_16S);
    sum.convertTo(image, CV_8U);
}

AliasedScene filledSquare(Size size, double angle, int background, int contrast, double noise, RNG& rng)
{
    AliasedScene s;
    s.image = Mat(size, CV_8UC1, Scalar(background));
    const RotatedRect r(Point2f(size.width * 0.5f, size.height * 0.5f), Size2f(size.height * 0.5f, size.height * 0.5f), (float)angle);
    Point2f v[4];
    r.points(v);
    std::vector<Point> corners;
    for (const Point2f& p : v)
        corners.push_back(Point(cvRound(p.x), cvRound(p.y)));
    fillPoly(s.image, std::vector<std::vector<Point> >{ corners }, Scalar(background + contrast), LINE_8);
    for (int i = 0; i < 4; i++)
        s.edges.push_back(edgeOf(corners[i], corners[(i + 1) % 4], 0.0, 3.0));
    addNoise(s.image, noise, rng);
    return s;
}

AliasedScene drawnLine(Size size, double angle, int width, int background, int contrast, double noise, RNG& rng)
{
    AliasedScene s;
    s.image = Mat(size, CV_8UC1, Scalar(background));
    const double a = angle * CV_PI / 180.0, half = 0.4 * size.height;
    const Point2f c(size.width * 0.5f, size.height * 0.5f);
    const Point2f d((float)(half * std::cos(a)), (float)(half * std::sin(a)));
    line(s.image, c - d, c + d, Scalar(background + contrast), width, LINE_8);
    // Its two edges (width / 2 either side); a line 1 or 2 px wide has its edges within 1.5 px of its centre.
    const double offset = width >= 3 ? width / 2.0 : 0.0;
    s.edges.push_back(edgeOf(c - d, c + d, offset, 3.0));
    if (offset > 0)
        s.edges.push_back(edgeOf(c - d, c + d, -offset, 3.0));
    addNoise(s.image, noise, rng);
    return s;
}

const double kAngles[] = { 4, 11, 18, 26.5, 33, 41, 48, 56, 63.5, 71, 79, 86 };

// Every scene, at several angles, widths, contrasts and noise levels.
void forEachScene(const std::function<void(const AliasedScene&)>& visit)
{
    RNG rng(21);
    for (const double angle : kAngles)
        for (const int contrast : { 40, 120, 200 })
            for (const double noise : { 0.0, 3.0 })
            {
                visit(filledSquare(Size(640, 480), angle, 30, contrast, noise, rng));
                for (const int width : { 1, 2, 3, 5 })
                    visit(drawnLine(Size(640, 480), angle, width, 30, contrast, noise, rng));
            }
}

// The edges of every scene that a detector misses.
int missedEdges(const std::function<Ptr<LSDAdvance>()>& create, int& edges)
{
    int missed = 0;
    edges = 0;
    forEachScene([&](const AliasedScene& s) {
        edges += (int)s.edges.size();
        missed += (int)s.edges.size() - edgesFound(detectWith(create(), s.image), s.edges);
    });
    return missed;
}

// The pre-smoothing of the defaults misses fewer of those edges than the LSD algorithm's reading.
TEST(LSDAdvance_AliasedEdges, the_pre_smoothing_misses_fewer_edges_of_shapes_drawn_without_anti_aliasing)
{
    int edges = 0;
    const int smoothed = missedEdges([] { return createLSDAdvance(); }, edges);
    const int exact = missedEdges([] { return withFullScaleSigma(0.0); }, edges);
    std::cout << "[ INFO ] of " << edges << " edges, the defaults miss " << smoothed << ", fullScaleSigma 0 misses "
              << exact << std::endl;
    EXPECT_LT(smoothed, exact);
}

// BASE_LSD is OpenCV's LSD on FullScaleSmoothing's image (BASE_FAST_LSD, its oracle test:
// LSDAdvance_FastLsdOracle.reproduces_OpenCV_LSD_both_ways/pre_smoothing).
TEST(LSDAdvance_AliasedEdges, BASE_LSD_reads_the_smoothed_image)
{
    LSDAdvance::LSDParams p;
    ASSERT_GT(p.fullScaleSigma, 0);
    p.fullScaleSmoothing = LSDAdvance::SMOOTH_EVERY_IMAGE;
    const Mat image = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(image.empty());
    std::vector<Vec4f> base, direct, unsmoothed;
    lsda::createBaseDetector(LSDAdvance::BASE_LSD, p, LSDAdvance::FLDParams(), EdgeDrawing::Params())->detect(image, base);
    lsda::FullScaleSmoothing smoothing(p.fullScaleSigma, p.fullScaleSmoothing);
    createLineSegmentDetector(LSD_REFINE_NONE, 1.0)->detect(smoothing.apply(image), direct);
    createLineSegmentDetector(LSD_REFINE_NONE, 1.0)->detect(image, unsmoothed);
    ASSERT_FALSE(base.empty());
    EXPECT_EQ(direct, base);
    EXPECT_NE(unsmoothed, base);
}

// The smoothing is a Gaussian: within one gray level of cv::GaussianBlur's over LSD's support, on
// noise and on an image, for views too (their border reflected, not read around).
TEST(LSDAdvance_AliasedEdges, the_smoothing_is_OpenCVs_Gaussian_to_one_gray_level)
{
    Mat noise(97, 131, CV_8UC1);
    RNG(3).fill(noise, RNG::UNIFORM, 0, 256);
    const Mat building = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(building.empty());
    const Mat view = building(Rect(41, 17, 203, 151));
    for (const double sigma : { 0.3, 0.5, 1.0, 2.5 })
        for (const Mat& image : { noise, building, view })
        {
            SCOPED_TRACE(cv::format("sigma %g, %dx%d", sigma, image.cols, image.rows));
            const int half = (int)std::ceil(sigma * std::sqrt(2.0 * 3.0 * std::log(10.0)));
            Mat expected;
            GaussianBlur(image.clone(), expected, Size(2 * half + 1, 2 * half + 1), sigma, sigma, BORDER_REFLECT_101);
            lsda::FullScaleSmoothing smoothing(sigma, LSDAdvance::SMOOTH_EVERY_IMAGE);
            ASSERT_FALSE(smoothing.isIdentity());
            const Mat& smoothed = smoothing.apply(image);
            ASSERT_EQ(image.size(), smoothed.size());
            EXPECT_LE(cvtest::norm(smoothed, expected, NORM_INF), 1);
        }
    // Tiny images: the reflection of a border 1 or 2 px from the other.
    for (const Size size : { Size(1, 1), Size(2, 1), Size(1, 3), Size(2, 2), Size(3, 2) })
    {
        Mat tiny(size, CV_8UC1);
        RNG(5).fill(tiny, RNG::UNIFORM, 0, 256);
        Mat expected;
        GaussianBlur(tiny, expected, Size(5, 5), 0.5, 0.5, BORDER_REFLECT_101);
        lsda::FullScaleSmoothing smoothing(0.5, LSDAdvance::SMOOTH_EVERY_IMAGE);
        EXPECT_LE(cvtest::norm(smoothing.apply(tiny), expected, NORM_INF), 1) << size;
    }
}

TEST(LSDAdvance_AliasedEdges, a_sigma_of_0_reads_the_image_as_it_is)
{
    EXPECT_TRUE(lsda::FullScaleSmoothing(0.0, LSDAdvance::SMOOTH_EVERY_IMAGE).isIdentity());
    const Mat image = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(image.empty());
    LSDAdvance::LSDParams p;
    p.fullScaleSigma = 0;
    std::vector<Vec4f> withoutSmoothing, opencv;
    p.seedGradientRatio = 1;
    p.seedAlignedNeighbours = 0;
    p.tileHeight = 0;
    lsda::createBaseDetector(LSDAdvance::BASE_LSD, p, LSDAdvance::FLDParams(), EdgeDrawing::Params())->detect(image, withoutSmoothing);
    createLineSegmentDetector(LSD_REFINE_NONE, 1.0)->detect(image, opencv);
    EXPECT_EQ(opencv, withoutSmoothing);
}

// A view of a larger image gives the lines of its copy, at scale 1 with and without the
// pre-smoothing and below scale 1 (LSD's Gaussian), on both LSD bases.
TEST(LSDAdvance_AliasedEdges, a_view_gives_the_lines_of_its_copy_at_every_scale)
{
    const Mat building = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(building.empty());
    const Mat view = building(Rect(57, 43, 301, 233));
    for (const int base : { (int)LSDAdvance::BASE_FAST_LSD, (int)LSDAdvance::BASE_LSD })
        for (const double scale : { 1.0, 0.8, 0.5 })
            for (const double sigma : { 0.0, 0.5 })
            {
                SCOPED_TRACE(cv::format("base %d, scale %g, fullScaleSigma %g", base, scale, sigma));
                LSDAdvance::LSDParams p;
                p.scale = scale;
                p.fullScaleSigma = sigma;
                p.fullScaleSmoothing = LSDAdvance::SMOOTH_EVERY_IMAGE;  // a photograph's view
                Ptr<lsda::BaseSegmentDetector> d = lsda::createBaseDetector(base, p, LSDAdvance::FLDParams(), EdgeDrawing::Params());
                std::vector<Vec4f> ofView, ofCopy;
                d->detect(view, ofView);
                d->detect(view.clone(), ofCopy);
                ASSERT_FALSE(ofCopy.empty());
                EXPECT_EQ(ofCopy, ofView);
            }
}

Mat grayImage(const char* name)
{
    const Mat image = imread(samples::findFile(name), IMREAD_GRAYSCALE);
    CV_Assert(!image.empty());
    return image;
}

// What hasAliasedEdges takes for aliased: images drawn without anti-aliasing (OpenCV's rotated
// rectangles, the scenes above with and without noise, OpenCV's logo) and a photograph enlarged
// without interpolation; not a photograph (OpenCV's, every YorkUrban image, KITTI frames), nor the
// same enlargement interpolated, nor white noise, a constant image or one too small for an edge.
TEST(LSDAdvance_AliasedEdges, drawn_images_have_aliased_edges_and_photographs_do_not)
{
    for (const Size size : { Size(640, 480), Size(320, 240) })
    {
        RNG rng(0x134679);
        for (int epoch = 0; epoch < 20; epoch++)
            EXPECT_TRUE(aliased(rectangleImage(size, randomRectangle(rng, size)))) << size << ", epoch " << epoch;
    }
    int scenes = 0;
    forEachScene([&](const AliasedScene& s) {
        EXPECT_TRUE(aliased(s.image)) << "scene " << scenes;
        scenes++;
    });
    EXPECT_TRUE(aliased(grayImage("opencv-logo.png")));
    const Mat building = grayImage("building.jpg");
    Mat enlarged;
    resize(building, enlarged, Size(), 2, 2, INTER_NEAREST);
    EXPECT_TRUE(aliased(enlarged));

    resize(building, enlarged, Size(), 2, 2, INTER_LINEAR);
    EXPECT_FALSE(aliased(enlarged));
    for (const char* name : { "building.jpg", "graf1.png", "messi5.jpg", "baboon.jpg", "fruits.jpg" })
        EXPECT_FALSE(aliased(grayImage(name))) << name;
    std::vector<std::string> photographs;
    glob(utils::fs::join(dataFolder("yorkurban"), "images/*.jpg"), photographs);
    EXPECT_EQ(51u, photographs.size());
    for (int frame = 0; frame <= 50; frame += 10)
        photographs.push_back(utils::fs::join(dataFolder("kitti_seq1"), cv::format("image_l/%06d.png", frame)));
    for (const std::string& path : photographs)
    {
        const Mat photograph = imread(path, IMREAD_GRAYSCALE);
        ASSERT_FALSE(photograph.empty()) << path;
        EXPECT_FALSE(aliased(photograph)) << path;
    }
    Mat noise(240, 320, CV_8UC1);
    RNG(7).fill(noise, RNG::UNIFORM, 0, 256);
    EXPECT_FALSE(aliased(noise));
    EXPECT_FALSE(aliased(Mat(240, 320, CV_8UC1, Scalar(90))));
    EXPECT_FALSE(aliased(Mat(3, 3, CV_8UC1, Scalar(90))));
    Mat tiny = (Mat_<uchar>(1, 4) << 10, 10, 200, 200);
    EXPECT_TRUE(aliased(tiny));
    EXPECT_TRUE(aliased(tiny.t()));
}

// By default (SMOOTH_ALIASED_IMAGES) a photograph gives the lines of fullScaleSigma 0, which
// SMOOTH_EVERY_IMAGE changes, and an aliased image those of SMOOTH_EVERY_IMAGE, which fullScaleSigma
// 0 changes; on both LSD bases.
TEST(LSDAdvance_AliasedEdges, only_aliased_images_are_smoothed_by_default)
{
    ASSERT_EQ(LSDAdvance::SMOOTH_ALIASED_IMAGES, LSDAdvance::LSDParams().fullScaleSmoothing);
    RNG rng(5);
    const Mat photograph = grayImage("building.jpg");
    Mat drawn = rectangleImage(Size(640, 480), RotatedRect(Point(300, 220), Size(160, 120), 23.f));
    addNoise(drawn, 3.0, rng);
    for (const int base : { (int)LSDAdvance::BASE_FAST_LSD, (int)LSDAdvance::BASE_LSD })
    {
        SCOPED_TRACE(base == LSDAdvance::BASE_LSD ? "BASE_LSD" : "BASE_FAST_LSD");
        const auto linesOf = [&](Ptr<LSDAdvance> detector, const Mat& image) {
            detector->setBaseDetector(base);
            return detectWith(detector, image);
        };
        const std::vector<Vec4f> photographLines = linesOf(createLSDAdvance(), photograph);
        EXPECT_EQ(linesOf(withFullScaleSigma(0.0), photograph), photographLines);
        EXPECT_NE(linesOf(withFullScaleSigma(0.5, LSDAdvance::SMOOTH_EVERY_IMAGE), photograph), photographLines);
        const std::vector<Vec4f> drawnLines = linesOf(createLSDAdvance(), drawn);
        EXPECT_EQ(linesOf(withFullScaleSigma(0.5, LSDAdvance::SMOOTH_EVERY_IMAGE), drawn), drawnLines);
        EXPECT_NE(linesOf(withFullScaleSigma(0.0), drawn), drawnLines);
    }
}

// The test of aliasing counts in stripes of rows in parallel: the lines of an aliased image (and so
// the test's outcome) are the same for any number of threads.
TEST(LSDAdvance_AliasedEdges, the_lines_of_an_aliased_image_do_not_depend_on_the_number_of_threads)
{
    const Mat drawn = rectangleImage(Size(640, 480), RotatedRect(Point(300, 220), Size(160, 120), 23.f));
    const int threads = getNumThreads();
    std::vector<Vec4f> reference;
    for (const int n : { 1, 2, 3, 8 })
    {
        setNumThreads(n);
        const std::vector<Vec4f> lines = detectWith(createLSDAdvance(), drawn);
        if (n == 1)
            reference = lines;
        ASSERT_EQ(reference.size(), lines.size()) << n << " threads";
        EXPECT_EQ(0, memcmp(reference.data(), lines.data(), lines.size() * sizeof(Vec4f))) << n << " threads";
    }
    setNumThreads(threads);
    EXPECT_EQ(8, edgesFound(reference, rectangleEdges(RotatedRect(Point(300, 220), Size(160, 120), 23.f))));
}

}} // namespace
