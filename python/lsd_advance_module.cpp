// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The standalone Python module lsd_advance: the bindings OpenCV's own generator writes from the
// public headers (gen_lsd_advance.py), with cv2's conversions (cv2_convert.cpp of the same OpenCV
// source tree), so that they behave as OpenCV's build makes them in-tree. What is
// cv2.ximgproc.NAME in-tree is lsd_advance.NAME here, cv2.ximgproc.line_evaluation.NAME is
// lsd_advance.line_evaluation.NAME. The types of other modules are cv2's (what is returned goes
// straight into cv2, and back), as are its error type and its base class cv2.Algorithm.

#define PY_ARRAY_UNIQUE_SYMBOL opencv_ARRAY_API

// As OpenCV's cv2.cpp: the generated code leaves the trailing fields of its tables to zero. Of the
// types of other modules only the converters are used, and cv2's headers define more helpers
// than this module needs.
#ifdef __GNUC__
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
#endif

#include "cv2.hpp"
#include "opencv2/opencv_modules.hpp"
#include "pyopencv_generated_include.h"
#include "cv2_util.hpp"
#include "cv2_numpy.hpp"
#include "cv2_convert.hpp"

#include <string>

using namespace cv;

typedef std::vector<int> vector_int;
typedef std::vector<uchar> vector_uchar;
typedef std::vector<DMatch> vector_DMatch;
typedef std::vector<Mat> vector_Mat;

struct ConstDef
{
    const char* name;
    long long val;
};


#include "pyopencv_generated_enums.h"
// The generated code declares every type with OpenCV's macro for types created at run time.
#define CVPY_TYPE(EXPORT_NAME, CLASS_ID, STORAGE, SNAME, _1, _2, SCOPE) \
    CVPY_TYPE_DECLARE_DYNAMIC(EXPORT_NAME, CLASS_ID, STORAGE, SNAME, SCOPE)
#include "pyopencv_generated_types.h"
#include "pyopencv_foreign_types.h"
#undef CVPY_TYPE
// What OpenCV's build includes from the modules' misc/python folders.
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
#include "pyopencv_LSDDetector.hpp"
#endif
#include "pyopencv_ximgproc.hpp"
#include "pyopencv_lsd_advance.hpp"
#include "pyopencv_generated_types_content.h"
#include "pyopencv_generated_funcs.h"
#include "pyopencv_generated_modules_content.h"

namespace {

// The module or type at the dotted path below root ("" is root); a new reference, or NULL with
// the Python error set.
PyObject* attributeAt(PyObject* root, const std::string& path)
{
    Py_INCREF(root);
    PyObject* at = root;
    for (size_t begin = 0; at && begin < path.size();)
    {
        const size_t end = std::min(path.find('.', begin), path.size());
        PyObject* next = PyObject_GetAttrString(at, path.substr(begin, end - begin).c_str());
        Py_DECREF(at);
        at = next;
        begin = end + 1;
    }
    return at;
}

// Where the names of an OpenCV scope (".ximgproc", ".ximgproc.line_evaluation",
// ".ximgproc.LSDAdvance") go in module m: cv::ximgproc is m itself, a namespace below it a
// submodule (made when missing), a class its type. A new reference, or NULL with the error set.
PyObject* scopeIn(PyObject* m, const std::string& scope)
{
    const std::string top = ".ximgproc";
    if (scope.compare(0, top.size(), top) != 0)
        return PyErr_Format(PyExc_ImportError, "lsd_advance: no place for names of cv%s", scope.c_str());
    Py_INCREF(m);
    PyObject* at = m;
    for (size_t begin = top.size() + 1; at && begin <= scope.size();)
    {
        const size_t end = std::min(scope.find('.', begin), scope.size());
        const std::string name = scope.substr(begin, end - begin);
        PyObject* next = PyObject_GetAttrString(at, name.c_str());
        if (!next && PyModule_Check(at))
        {
            PyErr_Clear();
            next = PyModule_New((std::string(PyModule_GetName(at)) + "." + name).c_str());
            if (next && PyObject_SetAttrString(at, name.c_str(), next) < 0)
                Py_CLEAR(next);
        }
        Py_DECREF(at);
        at = next;
        begin = end + 1;
    }
    return at;
}

bool setAttribute(PyObject* scope, const char* name, PyObject* value)
{
    const bool ok = value && PyObject_SetAttrString(scope, name, value) == 0;
    Py_XDECREF(value);
    return ok;
}

// The functions and constants of one OpenCV namespace; only cv::ximgproc and the namespaces below
// it have any (the others are those of the foreign types).
bool addNamespace(PyObject* m, const std::string& scope, PyMethodDef* methods, ConstDef* consts)
{
    if (!methods->ml_name && !consts->name)
        return true;
    PyObject* at = scopeIn(m, scope);
    bool ok = at != NULL;
    for (PyMethodDef* f = methods; ok && f->ml_name; ++f)
        ok = setAttribute(at, f->ml_name, PyCFunction_NewEx(f, NULL, NULL));
    for (ConstDef* c = consts; ok && c->name; ++c)
        ok = setAttribute(at, c->name, PyLong_FromLongLong(c->val));
    Py_XDECREF(at);
    return ok;
}

// OpenCV's CVPY_TYPE_INIT_DYNAMIC registers each type it makes with this.
bool registerNewType(PyObject* m, const char* name, PyObject* type, const std::string& scope)
{
    PyObject* at = scopeIn(m, scope);
    Py_INCREF(type);
    const bool ok = at && setAttribute(at, name, type);
    Py_XDECREF(at);
    return ok;
}

PyModuleDef moduleDefinition = { PyModuleDef_HEAD_INIT, "lsd_advance._lsd_advance",
                                 "LSDAdvance for Python: see the package lsd_advance.", -1, NULL,
                                 NULL, NULL, NULL, NULL };

PyObject* initModule()
{
    PyObject* cv2 = PyImport_ImportModule("cv2");
    if (!cv2)
        return NULL;
    opencv_error = PyObject_GetAttrString(cv2, "error");
    PyObject* m = opencv_error ? PyModule_Create(&moduleDefinition) : NULL;
    if (!m)
        return NULL;
    Py_INCREF(opencv_error);
    if (PyModule_AddObject(m, "error", opencv_error) < 0)
        return NULL;
#define CVPY_MODULE(NAMESTR, NAME) \
    if (!addNamespace(m, NAMESTR, methods_##NAME, consts_##NAME)) \
        return NULL;
#include "pyopencv_generated_modules.h"
#undef CVPY_MODULE
    // cv2's own types first: the module's derive from cv2.Algorithm.
#define CVPY_TYPE(EXPORT_NAME, CLASS_ID, _1, _2, BASE, CONSTRUCTOR, SCOPE) \
    pyopencv_##CLASS_ID##_TypePtr = attributeAt(cv2, std::string(SCOPE "." #EXPORT_NAME).substr(1)); \
    if (!pyopencv_##CLASS_ID##_TypePtr) \
        return NULL;
#include "pyopencv_foreign_types.h"
#undef CVPY_TYPE
    PyObject* pyopencv_NoBase_TypePtr = NULL;
#define CVPY_TYPE(EXPORT_NAME, CLASS_ID, _1, _2, BASE, CONSTRUCTOR, SCOPE) \
    CVPY_TYPE_INIT_DYNAMIC(EXPORT_NAME, CLASS_ID, return NULL, BASE, CONSTRUCTOR, SCOPE)
#include "pyopencv_generated_types.h"
#undef CVPY_TYPE
    return m;
}

} // namespace

PyMODINIT_FUNC PyInit__lsd_advance();
PyMODINIT_FUNC PyInit__lsd_advance()
{
    import_array();  // numpy's C API, as cv2 imports it
    return initModule();
}
