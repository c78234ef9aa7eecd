# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""LSDAdvance line segment detector for Python (standalone build, pybind11).

The names, arguments and numpy conventions are those of the in-tree bindings
(cv2.ximgproc.createLSDAdvance, cv2.ximgproc.LSDAdvance_LENGTH_FILTER_INTERFRAME, ...), so code
written for one runs on the other::

    import cv2, lsd_advance
    detector = lsd_advance.createLSDAdvance()
    lines = detector.detect(cv2.imread("building.jpg"))  # N x 1 x 4 float32, or None

OpenCV errors are raised as cv2.error (lsd_advance.error is cv2.error when cv2 is importable,
otherwise a RuntimeError subclass), with cv2's attributes code, err, func, file, line and msg.

Beyond cv2.ximgproc: detectKeyLines(), linesToKeyLines() and keyLinesToLines() give and take
cv2.line_descriptor.KeyLine objects for OpenCV's LBD descriptor and matcher.
"""

from ._lsd_advance import *  # noqa: F401,F403
from ._lsd_advance import error  # noqa: F401
