// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The layout of an OpenCV after opencv#29349 (test only): imgproc without LineSegmentDetector.
// The real header is read with the names of its LSD declarations changed, so that no
// LineSegmentDetector, createLineSegmentDetector or LSD_REFINE_* is left in cv.

#define LineSegmentDetector LineSegmentDetector_not_in_imgproc
#define createLineSegmentDetector createLineSegmentDetector_not_in_imgproc
#define LineSegmentDetectorModes LineSegmentDetectorModes_not_in_imgproc
#define LSD_REFINE_NONE LSD_REFINE_NONE_not_in_imgproc
#define LSD_REFINE_STD LSD_REFINE_STD_not_in_imgproc
#define LSD_REFINE_ADV LSD_REFINE_ADV_not_in_imgproc
#include_next <opencv2/imgproc.hpp>
#undef LineSegmentDetector
#undef createLineSegmentDetector
#undef LineSegmentDetectorModes
#undef LSD_REFINE_NONE
#undef LSD_REFINE_STD
#undef LSD_REFINE_ADV
