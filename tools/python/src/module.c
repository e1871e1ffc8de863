/* module.c - the extension module ssda._ssda: the exception class, version,
   numpy, and one init per feature file (add a feature: its bind_*.c and a
   line in feature_inits). */
#include "ssdapy.h"

#ifndef SSDAPY_KERNEL
#define SSDAPY_KERNEL "unknown"
#endif

static int (*const feature_inits[])(PyObject *) = {
    ssdapy_init_match,
    ssdapy_init_track,
    ssdapy_init_grad,
    ssdapy_init_pitch,
    ssdapy_init_stream,
    ssdapy_init_ncc,
    ssdapy_init_shape,  /* before symreg: FD_DTYPE */
    ssdapy_init_symreg,
    ssdapy_init_seg,
    ssdapy_init_flow,
    ssdapy_init_reg,
};

static const char error_doc[] =
    "An error the ssda library returned. Attributes: code (the library's negative\n"
    "error code, ssda.ERR_*), message (ssda_strerror(code)), function (the call).";

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT, "ssda._ssda",
    "The ssda C library (exact fixed-point SSDA matching) for Python: see the\n"
    "ssda package and docs/python.md.",
    -1, NULL, NULL, NULL, NULL, NULL};

static int add_constants(PyObject *m)
{
    static const struct {
        const char *name;
        long value;
    } ints[] = {
        {"ERR_NULL", SSDA_ERR_NULL},       {"ERR_ARG", SSDA_ERR_ARG},
        {"ERR_SIZE", SSDA_ERR_SIZE},       {"ERR_FORMAT", SSDA_ERR_FORMAT},
        {"ERR_STRIDE", SSDA_ERR_STRIDE},   {"ERR_OVERFLOW", SSDA_ERR_OVERFLOW},
        {"ERR_BUFFER", SSDA_ERR_BUFFER},   {"ERR_IO", SSDA_ERR_IO},
        {"ERR_STATE", SSDA_ERR_STATE},     {"ERR_UNSUPPORTED", SSDA_ERR_UNSUPPORTED},
        {"VERSION_MAJOR", SSDA_VERSION_MAJOR}, {"VERSION_MINOR", SSDA_VERSION_MINOR},
        {"VERSION_PATCH", SSDA_VERSION_PATCH},
    };
    size_t i;
    for (i = 0; i < sizeof ints / sizeof ints[0]; i++) {
        if (PyModule_AddIntConstant(m, ints[i].name, ints[i].value) != 0) {
            return -1;
        }
    }
    if (PyModule_AddObject(m, "__version__",
                           PyUnicode_FromFormat("%d.%d.%d", SSDA_VERSION_MAJOR,
                                                SSDA_VERSION_MINOR, SSDA_VERSION_PATCH)) != 0 ||
        PyModule_AddStringConstant(m, "KERNEL", SSDAPY_KERNEL) != 0) {
        return -1;
    }
    return 0;
}

static PyObject *py_strerror(PyObject *self, PyObject *arg)
{
    long long code;
    (void)self;
    if (ssdapy_int(arg, "code", INT32_MIN, INT32_MAX, &code) != 0) {
        return NULL;
    }
    return PyUnicode_FromString(ssda_strerror((int)code));
}

static PyObject *py_copies(PyObject *self, PyObject *unused)
{
    (void)self;
    (void)unused;
    return PyLong_FromUnsignedLongLong(ssdapy.copies);
}

static PyMethodDef module_methods[] = {
    {"_copies", py_copies, METH_NOARGS,
     "_copies($module, /)\n--\n\n"
     "How many array arguments were copied so far because their layout allowed\n"
     "no view (for the tests)."},
    {"strerror", py_strerror, METH_O,
     "strerror($module, code, /)\n--\n\n"
     "The library's short English name of an error code (ssda_strerror)."},
    {NULL, NULL, 0, NULL}};

PyMODINIT_FUNC PyInit__ssda(void)
{
    PyObject *m, *np;
    size_t i;
    np = PyImport_ImportModule("numpy");
    if (np == NULL) {
        return NULL;
    }
    ssdapy.np_empty = PyObject_GetAttrString(np, "empty");
    ssdapy.np_dtype = PyObject_GetAttrString(np, "dtype");
    ssdapy.np_frombuffer = PyObject_GetAttrString(np, "frombuffer");
    Py_DECREF(np);
    if (ssdapy.np_empty == NULL || ssdapy.np_dtype == NULL || ssdapy.np_frombuffer == NULL) {
        return NULL;
    }
    m = PyModule_Create(&module_def);
    if (m == NULL) {
        return NULL;
    }
    ssdapy.error = PyErr_NewExceptionWithDoc("ssda.Error", error_doc, NULL, NULL);
    if (ssdapy.error == NULL) {
        goto fail;
    }
    Py_INCREF(ssdapy.error);
    if (PyModule_AddObject(m, "Error", ssdapy.error) != 0 || add_constants(m) != 0 ||
        PyModule_AddFunctions(m, module_methods) != 0) {
        goto fail;
    }
    for (i = 0; i < sizeof feature_inits / sizeof feature_inits[0]; i++) {
        if (feature_inits[i](m) != 0) {
            goto fail;
        }
    }
    return m;
fail:
    Py_DECREF(m);
    return NULL;
}
