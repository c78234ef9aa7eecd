// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_KEYLINES_HPP
#define OPENCV_LSD_ADVANCE_KEYLINES_HPP

#include "opencv2/core.hpp"
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
#include "opencv2/line_descriptor.hpp"

namespace cv {
namespace ximgproc {

//! @addtogroup lsd_advance
//! @{

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
8-connected digital line between the endpoints, `octave` 0, `class_id` the index of the segment,
and `response` = lineLength / max(width, height), in [0, sqrt(2)]: the longer the line, the
higher, so it ranks lines by the length that makes them stable to track and distinctive to
describe.
*/
CV_EXPORTS void linesToKeyLines(InputArray lines, Size imageSize, std::vector<line_descriptor::KeyLine>& keylines);

/** @brief Converts KeyLines back to segments.

@param keylines KeyLines of any octave.
@param lines Output N x 1 CV_32FC4 (std::vector<cv::Vec4f> works), in the same order:
(x1, y1, x2, y2) = (startPointX, startPointY, endPointX, endPointY), pixels. The octave copies
are ignored: the full-resolution endpoints are used whatever the octave. */
CV_EXPORTS void keyLinesToLines(const std::vector<line_descriptor::KeyLine>& keylines, OutputArray lines);

//! @} lsd_advance

}} // namespace cv::ximgproc

#endif // HAVE_OPENCV_LINE_DESCRIPTOR
#endif
