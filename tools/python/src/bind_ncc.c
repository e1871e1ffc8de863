/* bind_ncc.c - ssda.ncc_match, ssda.ncc_at (ssda/ncc.h): the exact
   correlation-coefficient search. */
#include "ssdapy.h"
#include "ssda/ncc.h"

static PyTypeObject *ncc_result_type;

static PyStructSequence_Field ncc_result_fields[] = {
    {"x", "best top-left column in the area, px"},
    {"y", "best top-left row in the area, px"},
    {"rho", "rho at (x, y) as a float: rho_q30 / 2**30"},
    {"rho_q30", "rho at (x, y), Q2.30, truncated toward zero (the library's value)"},
    {"flat_window", "True: the window's pixels are all equal (rho 0 everywhere)"},
    {"pixel_ops", "products summed, plus sliding-sum and bound work"},
    {"positions", "positions considered"},
    {"completed", "positions whose products were summed in full"},
    {"around_q30", "around=True: 3 x 3 int32 array of rho_q30 at (x + i - 1, y + j - 1) "
                   "as [j, i] (NCC_NONE outside the positions); else None"},
    {NULL, NULL}};

static const ssdapy_name_t metrics[] = {
    {"rho", SSDA_NCC_RHO}, {"abs", SSDA_NCC_ABS}, {NULL, 0}};

static PyObject *result_object(const ssda_ncc_result_t *r, int around)
{
    PyObject *o = PyStructSequence_New(ncc_result_type), *a = Py_None;
    if (o == NULL) {
        return NULL;
    }
    if (around) {
        const Py_ssize_t shape[2] = {3, 3};
        PyObject *dt = PyUnicode_FromString("int32");
        void *data;
        a = dt != NULL ? ssdapy_np_empty(2, shape, dt) : NULL;
        Py_XDECREF(dt);
        if (a == NULL || (data = ssdapy_np_data(a)) == NULL) {
            Py_XDECREF(a);
            Py_DECREF(o);
            return NULL;
        }
        memcpy(data, r->around_q30, sizeof r->around_q30);
    } else {
        Py_INCREF(a);
    }
    PyStructSequence_SET_ITEM(o, 0, PyLong_FromUnsignedLong(r->x));
    PyStructSequence_SET_ITEM(o, 1, PyLong_FromUnsignedLong(r->y));
    PyStructSequence_SET_ITEM(o, 2, PyFloat_FromDouble(r->rho_q30 / 1073741824.0));
    PyStructSequence_SET_ITEM(o, 3, PyLong_FromLong(r->rho_q30));
    PyStructSequence_SET_ITEM(o, 4, PyBool_FromLong((r->flags & SSDA_NCC_FLAT_WINDOW) != 0u));
    PyStructSequence_SET_ITEM(o, 5, PyLong_FromUnsignedLongLong(r->pixel_ops));
    PyStructSequence_SET_ITEM(o, 6, PyLong_FromUnsignedLong(r->positions));
    PyStructSequence_SET_ITEM(o, 7, PyLong_FromUnsignedLong(r->completed));
    PyStructSequence_SET_ITEM(o, 8, a);
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

/* Options: metric, full, predict=(x, y), radius (disk around predict),
   around. */
static int ncc_options(PyObject *kw, ssda_ncc_config_t *cfg)
{
    PyObject *v;
    unsigned long long radius;
    int b;
    size_t i;
    static const struct {
        const char *name;
        uint8_t bit;
    } flags[] = {{"full", SSDA_NCC_FULL}, {"around", SSDA_NCC_AROUND}};
    memset(cfg, 0, sizeof *cfg);
    if (ssdapy_kw_enum(kw, "metric", metrics, &cfg->metric) != 0) {
        return -1;
    }
    for (i = 0; i < sizeof flags / sizeof flags[0]; i++) {
        if ((v = ssdapy_kw_take(kw, flags[i].name)) != NULL) {
            b = PyObject_IsTrue(v);
            Py_DECREF(v);
            if (b < 0) {
                return -1;
            }
            cfg->flags = (uint8_t)(b ? cfg->flags | flags[i].bit : cfg->flags & ~flags[i].bit);
        }
    }
    if ((v = ssdapy_kw_take(kw, "radius")) != NULL) {
        int rc = ssdapy_uint(v, "radius", 0, 65535u, &radius);
        Py_DECREF(v);
        if (rc != 0) {
            return -1;
        }
        cfg->radius = (uint16_t)radius;
        cfg->flags |= SSDA_NCC_DISK | SSDA_NCC_PREDICT;
    }
    b = ssdapy_kw_xy(kw, "predict", &cfg->predict_x, &cfg->predict_y);
    if (b < 0) {
        return -1;
    }
    if (b > 0) {
        cfg->flags |= SSDA_NCC_PREDICT;
    }
    return 0;
}

/* (area, window[, x, y]) */
static int two_images(PyObject *args, const char *func, Py_ssize_t n, PyObject **a,
                      ssdapy_image_t *area, ssdapy_image_t *win)
{
    if (ssdapy_args(args, func, n, n, a) != 0 || ssdapy_image_get(a[0], "area", area) != 0) {
        return -1;
    }
    if (ssdapy_image_get(a[1], "window", win) != 0) {
        ssdapy_image_release(area);
        return -1;
    }
    return 0;
}

static PyObject *py_ncc_match(PyObject *self, PyObject *args, PyObject *kw)
{
    static uint64_t no_work; /* when the window is wider than the area: the
                                library names that error before the buffer's */
    PyObject *a[2], *kwc, *out = NULL;
    ssdapy_image_t area, win;
    ssda_ncc_config_t cfg;
    ssda_ncc_result_t res;
    void *work = NULL;
    int e;
    (void)self;
    if (two_images(args, "ncc_match", 2, a, &area, &win) != 0) {
        return NULL;
    }
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || ncc_options(kwc, &cfg) != 0 ||
        ssdapy_kw_done(kwc, "ncc_match") != 0) {
        goto done;
    }
    if (win.view.width > area.view.width) {
        cfg.work = &no_work;
        cfg.work_size = 0;
    } else {
        cfg.work_size = SSDA_NCC_WORK_SIZE(area.view.width, win.view.width, win.view.height);
        if ((work = PyMem_Malloc(cfg.work_size)) == NULL) { /* 8-byte aligned or more */
            PyErr_NoMemory();
            goto done;
        }
        cfg.work = work;
    }
    SSDAPY_NOGIL(e = ssda_ncc_match(&area.view, &win.view, &cfg, &res));
    out = e == SSDA_OK ? result_object(&res, (cfg.flags & SSDA_NCC_AROUND) != 0u)
                       : ssdapy_error(e, "ssda_ncc_match");
done:
    PyMem_Free(work);
    Py_XDECREF(kwc);
    ssdapy_image_release(&area);
    ssdapy_image_release(&win);
    return out;
}

static PyObject *py_ncc_at(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[4], *out = NULL;
    ssdapy_image_t area, win;
    unsigned long long x, y;
    int32_t rho = 0;
    int e;
    (void)self;
    if (kw != NULL && PyDict_Size(kw) != 0) {
        ssdapy_kw_done(kw, "ncc_at"); /* raises TypeError naming the keyword */
        return NULL;
    }
    if (two_images(args, "ncc_at", 4, a, &area, &win) != 0) {
        return NULL;
    }
    if (ssdapy_uint(a[2], "x", 0, 65535u, &x) == 0 && ssdapy_uint(a[3], "y", 0, 65535u, &y) == 0) {
        SSDAPY_NOGIL(e = ssda_ncc_at(&area.view, &win.view, (uint16_t)x, (uint16_t)y, &rho));
        out = e == SSDA_OK ? PyLong_FromLong(rho) : ssdapy_error(e, "ssda_ncc_at");
    }
    ssdapy_image_release(&area);
    ssdapy_image_release(&win);
    return out;
}

static PyMethodDef methods[] = {
    {"ncc_match", (PyCFunction)(void (*)(void))py_ncc_match, METH_VARARGS | METH_KEYWORDS,
     "ncc_match(area, window, /, *, metric='rho', full=False, predict=None, radius=None, "
     "around=False)\n--\n\n"
     "Where window correlates best with area: the largest zero-mean normalised\n"
     "cross-correlation rho (OpenCV's TM_CCOEFF_NORMED), exactly, in integers\n"
     "(ssda_ncc_match, ssda/ncc.h). Both are 2-D uint8 or uint16 arrays of one dtype;\n"
     "the window has at most 65536 pixels. Returns an NccResult (x, y, rho,\n"
     "rho_q30, flat_window, pixel_ops, positions, completed, around_q30); ties go\n"
     "to the smallest y, then x. metric: 'rho' or 'abs' (|rho|: inverted contrast\n"
     "matches); full: no early exit (same answer); predict=(x, y): evaluated\n"
     "first; radius: only positions within radius px of predict (a disk);\n"
     "around: also rho at the 8 neighbours of the best (a 3 x 3 array).\n"
     "The binding allocates the work buffer; the GIL is released."},
    {"ncc_at", (PyCFunction)(void (*)(void))py_ncc_at, METH_VARARGS | METH_KEYWORDS,
     "ncc_at(area, window, x, y, /)\n--\n\n"
     "rho_q30 (Q2.30, int) of window placed with its top-left at (x, y) of area\n"
     "(ssda_ncc_at); 0 where the placement or the window is flat."},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_ncc(PyObject *m)
{
    ncc_result_type = ssdapy_struct_type(m, "ssda.NccResult",
                                         "Outcome of one correlation search "
                                         "(ssda_ncc_result_t).",
                                         ncc_result_fields, 9);
    if (ncc_result_type == NULL || PyModule_AddIntConstant(m, "NCC_ONE_Q30", SSDA_NCC_ONE_Q30) != 0 ||
        PyModule_AddIntConstant(m, "NCC_NONE", SSDA_NCC_NONE) != 0 ||
        PyModule_AddIntConstant(m, "NCC_MAX_PIXELS", SSDA_NCC_MAX_PIXELS) != 0) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
