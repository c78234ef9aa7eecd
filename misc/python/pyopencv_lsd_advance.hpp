// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The names OpenCV's Python binding generator gives the types of the module's headers in the code
// it writes (as ximgproc does for EdgeDrawing::Params): included by OpenCV's build in-tree and by
// python/lsd_advance_module.cpp in the standalone build.
#ifdef HAVE_OPENCV_LSD_ADVANCE
typedef cv::ximgproc::LSDAdvance::Params LSDAdvance_Params;
typedef cv::ximgproc::LSDAdvance::LSDParams LSDAdvance_LSDParams;
typedef cv::ximgproc::LSDAdvance::FLDParams LSDAdvance_FLDParams;
typedef cv::ximgproc::LSDAdvance::Preset LSDAdvance_Preset;
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
typedef std::vector<cv::line_descriptor::KeyLine> vector_line_descriptor_KeyLine;
#endif
#endif
