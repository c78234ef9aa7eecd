# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""LSDAdvance line segment detector for Python (standalone build).

The bindings are those OpenCV's generator makes in-tree, from the same headers: what an OpenCV
built with the module has as cv2.ximgproc.NAME is lsd_advance.NAME here (cv2.ximgproc.line_evaluation
is lsd_advance.line_evaluation), with the same arguments, numpy conventions and errors (cv2.error).
Code written for one runs on the other::

    import cv2
    try:
        import lsd_advance as lsda   # standalone build
    except ImportError:
        lsda = cv2.ximgproc          # OpenCV built with the module
    detector = lsda.createLSDAdvance()
    lines = detector.detect(cv2.imread("building.jpg"))  # N x 1 x 4 float32, or None
    keylines = detector.detectKeyLines(gray)             # cv2.line_descriptor.KeyLine, for LBD

The types of other modules are cv2's: LSDAdvance is a cv2.Algorithm, KeyLines are
cv2.line_descriptor.KeyLine, getEDLinesParams() returns a cv2.ximgproc.EdgeDrawing.Params.
"""

from ._lsd_advance import *  # noqa: F401,F403
from ._lsd_advance import error, line_evaluation  # noqa: F401
