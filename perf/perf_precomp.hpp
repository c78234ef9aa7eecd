// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_PERF_PRECOMP_HPP
#define OPENCV_LSD_ADVANCE_PERF_PRECOMP_HPP

#include "opencv2/ts.hpp"
#include "opencv2/lsd_advance.hpp"
#include "opencv2/imgproc.hpp"
#include "opencv2/imgcodecs.hpp"

#include "opencv2/core/utils/filesystem.hpp"

#include <functional>
#include <string>

namespace opencv_test {

//! An image of the evaluation data (LSD_ADVANCE_DATA_DIR): skipped without it, except under
//! CI=true, where it fails.
inline Mat evaluationImage(const std::string& relativePath)
{
    const char* root = getenv("LSD_ADVANCE_DATA_DIR");
    const char* ci = getenv("CI");
    const std::string path = root ? utils::fs::join(root, relativePath) : std::string();
    if (path.empty() || !utils::fs::exists(path))
    {
        if (ci && std::string(ci) == "true")
            CV_Error_(Error::StsError, ("CI=true and the evaluation image %s is not in LSD_ADVANCE_DATA_DIR ('%s'; "
                                        "doc/data.md)", relativePath.c_str(), root ? root : ""));
        throw SkipTestException("needs the evaluation image " + relativePath +
                                ": LSD_ADVANCE_DATA_DIR is not set or does not hold it (doc/data.md)");
    }
    return imread(path, IMREAD_GRAYSCALE);
}

} // namespace opencv_test

#endif
