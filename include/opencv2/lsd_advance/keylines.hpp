// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_KEYLINES_HPP
#define OPENCV_LSD_ADVANCE_KEYLINES_HPP

#include "opencv2/core.hpp"
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
#include "opencv2/line_descriptor.hpp"
#endif

namespace cv {
namespace ximgproc {

//! @addtogroup lsd_advance
//! @{

/** @brief Computes the response of line segments on the image they were detected in: how much
evidence of an edge they carry, for ranking lines (KeyLine::response of LSDAdvance::detect) and for
stage 1's strong segments (LSDAdvance::Params::keepStrongSegments).

@param image 8-bit gray, BGR or BGRA image, not empty (colour is converted to gray as
LSDAdvance::detect converts it).
@param lines Segments, N x 1 or 1 x N CV_32FC4 (std::vector<cv::Vec4f>), (x1, y1, x2, y2) in
pixels, finite, oriented as LSD orients them (brighter side on the left).
@param responses Output N x 1 CV_32FC1 (std::vector<float> works), in the order of lines:
@f$v \cdot (l / \max(W, H)) \cdot (\bar c / 255)^2@f$, with l the length in pixels, @f$\bar c@f$
the mean gray-level step across the segment (at the centre of each unit step along it, the
bilinear gray level 1 px to its left minus 1 px to its right, coordinates clamped into the image,
negative steps counting 0), and v = 1 for a segment inside the image, 0.1 for one the image border
cuts (an endpoint within 2 px of the first or last pixel centre of a row or column, or beyond).
In [0, sqrt(2)]: cv::line_descriptor::LSDDetector's response (l / max(W, H)) for a line of full
contrast inside the image, less for weaker ones, 0 for a segment whose left is not brighter.

Ranked by response, a line budget keeps long lines of high contrast first, short lines of high
contrast before long faint ones, and lines the border cuts last: the lines LBD matches again, and
correctly, in the next view (doc/matching.md). Throws cv::Exception on an empty image, another
image type, or another layout of lines.
*/
CV_EXPORTS_W void computeLineResponses(InputArray image, InputArray lines, OutputArray responses);

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

/** @brief Converts segments to KeyLines of octave 0, field by field as
cv::line_descriptor::LSDDetector does, for the LBD descriptor (@cite LBD) and its matcher.

@param lines Segments, N x 1 or 1 x N CV_32FC4 (std::vector<cv::Vec4f>), (x1, y1, x2, y2) in
pixels, finite.
@param imageSize Size of the image they were detected in, both sides at least 1 px.
@param keylines Output, one KeyLine per segment in the same order. Each coordinate is first clamped
as LSDDetector clamps it: below 0 it becomes 0, at or beyond the width (height) it becomes
width - 1 (height - 1); then `startPoint*` and
`sPointInOctave*` are the first endpoint, `endPoint*` and `ePointInOctave*` the second, `pt` the
midpoint, `lineLength` the length in pixels, `angle` = atan2(dy, dx) in radians in (-pi, pi],
`size` = dx * dy (LSDDetector's definition, signed), `numOfPixels` the number of pixels of the
8-connected digital line between the endpoints rounded to pixels, at least 1 (LSDDetector counts 0
for a line along the last column or row whose endpoints round to just outside the image; here its
endpoints are then moved onto the image's last pixels), `octave` 0, `class_id` the index of the segment
(0..N-1, contiguous: LBD needs it; keepStrongestKeyLines() keeps it so),
and `response` = lineLength / max(width, height), in [0, sqrt(2)], as LSDDetector sets it (the
length alone: these are lines without their image; LSDAdvance::detect(image, keylines) sets
computeLineResponses()'s instead).
*/
CV_EXPORTS_W void linesToKeyLines(InputArray lines, Size imageSize,
                                  CV_OUT std::vector<line_descriptor::KeyLine>& keylines);

/** @brief Keeps a front end's budget of KeyLines: the strongest first, numbered anew.

@param keylines KeyLines (of LSDAdvance::detect(image, keylines), linesToKeyLines() or any
detector), whatever their order and class_id.
@param maxLines The budget: the number of KeyLines kept, 0 for all (then only sorted).
@param kept Output: the maxLines KeyLines of highest `response` (all when fewer), by decreasing
response (equal responses in their order in keylines), otherwise unchanged but for `class_id`,
which is their index 0..N-1: the numbering LBD (BinaryDescriptor::compute) and its matcher expect
of a KeyLine vector. May be keylines itself.
Throws cv::Exception on a negative maxLines.
@note This is the strongest-first budget. The KeyLines of a detector in
LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS are in the order of that budget already: a smaller budget
is their first N (setMaxLines() on the detector gives it directly).
*/
CV_EXPORTS_W void keepStrongestKeyLines(const std::vector<line_descriptor::KeyLine>& keylines, int maxLines,
                                        CV_OUT std::vector<line_descriptor::KeyLine>& kept);

/** @brief Computes the binary LBD descriptors (@cite LBD) of KeyLines: those of
cv::line_descriptor::BinaryDescriptor::compute with its default parameters, byte for byte, in a
fraction of its time (doc/matching.md).

@param image The image the KeyLines were detected in: 8-bit gray, BGR or BGRA, not empty (colour
is converted to gray as BinaryDescriptor converts it).
@param keylines KeyLines of octave 0 (LSDAdvance::detect(image, keylines), linesToKeyLines(),
cv::line_descriptor::LSDDetector or BinaryDescriptor::detect with one octave), each with:
`sPointInOctave*` / `ePointInOctave*` equal to `startPoint*` / `endPoint*`, two distinct endpoints
within the image and one pixel around it (x in [-1, W], y in [-1, H]), a finite `angle` (radians,
the direction of the line: LBD measures the gradient along it and across it) and `numOfPixels`
in [1, 32767] (the length of the support region in samples, 1 px apart). `class_id`, `response`,
`size` and `lineLength` are not read: each KeyLine is described on its own (BinaryDescriptor
needs distinct `class_id` values, and describes only one KeyLine of each).
@param descriptors Output N x 32 CV_8U, row i the 256-bit descriptor of keylines[i] (0 x 32 for
no KeyLine), for cv::line_descriptor::BinaryDescriptorMatcher or any NORM_HAMMING matcher.

The 63-row support region of each line is sampled as BinaryDescriptor samples it (9 bands of 7
rows, coordinates rounded to the nearest pixel and clamped into the image), on the gradient of
the image after a 5 x 5 Gaussian of sigma 1, computed only where some region reaches; the lines
are described in parallel (cv::parallel_for_), with the same output for any number of threads.
A thread's buffers are kept for its next call: a sequence of frames of one size allocates
nothing but the output once warm. Safe to call from several threads at once.

Throws cv::Exception on an empty image or another image type, and on a KeyLine of another octave
(StsNotImplemented: describe a multi-octave pyramid with BinaryDescriptor), with a coordinate or
angle that is not finite, outside the image, of zero length, or with numOfPixels out of range:
the message names the KeyLine's index.
In Python: computeLBD(image, keylines) -> descriptors.
*/
CV_EXPORTS_W void computeLBD(InputArray image, const std::vector<line_descriptor::KeyLine>& keylines,
                             OutputArray descriptors);

/** @brief Converts KeyLines back to segments.

@param keylines KeyLines of any octave.
@param lines Output N x 1 CV_32FC4 (std::vector<cv::Vec4f> works), in the same order:
(x1, y1, x2, y2) = (startPointX, startPointY, endPointX, endPointY), pixels. The octave copies
are ignored: the full-resolution endpoints are used whatever the octave. */
CV_EXPORTS_W void keyLinesToLines(const std::vector<line_descriptor::KeyLine>& keylines, OutputArray lines);
#endif // HAVE_OPENCV_LINE_DESCRIPTOR

//! @} lsd_advance

}} // namespace cv::ximgproc

#endif
