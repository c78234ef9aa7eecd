#!/usr/bin/env python3
# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
"""Writes the bindings of the standalone module `lsd_advance` with OpenCV's own generator
(modules/python/src2/gen2.py of the OpenCV source tree of the installed version), from the
module's public headers, exactly as OpenCV's build writes them in-tree.

The types of other modules that the headers use (cv::Algorithm, DMatch, line_descriptor::KeyLine,
EdgeDrawing::Params) are given to the generator by their declarations alone: their converters are
generated, their Python types are cv2's own (lsd_advance_module.cpp), so that what the module
returns goes straight into cv2 (a KeyLine into line_descriptor's BinaryDescriptor) and back.
Writes pyopencv_generated_*.h as gen2.py does, with those types moved from
pyopencv_generated_types.h to pyopencv_foreign_types.h.

Usage: gen_lsd_advance.py <src2 dir> <output dir> <OpenCV include dir (the one holding opencv2/)>
                          <with KeyLines: 1 or 0> <public header>...
"""

import os
import sys

src2, output, include, with_keylines = sys.argv[1:5]
headers = sys.argv[5:]
sys.path.insert(0, src2)
import gen2  # noqa: E402
import hdr_parser  # noqa: E402

# The declarations of other modules' types, by header: (generator's name, needed).
FOREIGN = {
    "core.hpp": [("class cv.Algorithm", True)],
    "core/types.hpp": [("class cv.DMatch", True)],
    "ximgproc/edge_drawing.hpp": [("struct cv.ximgproc.EdgeDrawing.Params", True)],
    "line_descriptor/descriptor.hpp": [("struct cv.line_descriptor.KeyLine", with_keylines == "1")],
}
foreign = {os.path.join(include, "opencv2", h): [name for name, needed in decls if needed]
           for h, decls in FOREIGN.items()}
foreign = {h: names for h, names in foreign.items() if names}


def uses_keylines(decl):
    return "KeyLine" in str(decl[1]) or any("KeyLine" in str(arg[0]) for arg in decl[3] if arg)


parse = hdr_parser.CppHeaderParser.parse


def parse_for_module(self, hname, wmode=True):
    decls = parse(self, hname, wmode)
    if hname in foreign:
        return [d for d in decls if d[0] in foreign[hname]]
    # Without line_descriptor the KeyLine API is not compiled (HAVE_OPENCV_LINE_DESCRIPTOR).
    return decls if with_keylines == "1" else [d for d in decls if not uses_keylines(d)]


hdr_parser.CppHeaderParser.parse = parse_for_module
# cv2.UMat is not this module's: no UMat variants of the functions.
parser_init = hdr_parser.CppHeaderParser.__init__
hdr_parser.CppHeaderParser.__init__ = \
    lambda self, **kw: parser_init(self, generate_umat_decls=False, generate_gpumat_decls=False)

gen2.PythonWrapperGenerator().gen(headers + list(foreign), output)

foreign_ids = {gen2.normalize_class_name(name.split(" ", 1)[1]) for names in foreign.values() for name in names}
types_path = os.path.join(output, "pyopencv_generated_types.h")
with open(types_path) as f:
    types = f.readlines()  # CVPY_TYPE(EXPORT_NAME, CLASS_ID, ...);


def is_foreign(line):
    return line.split("(", 1)[1].split(",")[1].strip() in foreign_ids


with open(types_path, "w") as f:
    f.writelines(line for line in types if not is_foreign(line))
with open(os.path.join(output, "pyopencv_foreign_types.h"), "w") as f:
    f.writelines(line for line in types if is_foreign(line))
