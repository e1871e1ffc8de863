/* bind_flow.c - seed 003: ssda.composite (ssda/composite.h, composite
   template matching) and ssda.relax / ssda.relax_median (ssda/relax.h,
   cleaning a vector field), the library calls of `ssda flow`. */
#include "ssdapy.h"
#include "ssda/composite.h"
#include "ssda/relax.h"

static PyObject *tp_dtype, *relax_dtype;
static PyTypeObject *composite_type;

static PyStructSequence_Field composite_fields[] = {
    {"templates", "(rows, cols) COMPOSITE_DTYPE records (ssda_composite_tp_t), written by "
                  "the library: var, dx, dy (Q24.8 px), rho_q30, x, y, status, origin"},
    {"cols", "templates per row"},
    {"rows", "template rows"},
    {"count", "cols * rows"},
    {"ok", "templates matched (status COMPOSITE_OK)"},
    {"origin", "index (row * cols + col) of the origin template"},
    {"mean_rho_q30", "mean rho of the matched templates, Q2.30 (0 if none)"},
    {"mean_rho", "mean_rho_q30 / 2**30"},
    {"pixel_ops", "the searches' and the variances' work"},
    {NULL, NULL}};

static const ssdapy_name_t metrics[] = {
    {"rho", SSDA_NCC_RHO}, {"abs", SSDA_NCC_ABS}, {NULL, 0}};

static const ssdapy_field_t composite_cfg_fields[] = {
    {"tp", offsetof(ssda_composite_config_t, tp), 2, 0, 65535},
    {"step", offsetof(ssda_composite_config_t, step), 2, 0, 65535},
    {"roi_x", offsetof(ssda_composite_config_t, roi_x), 2, 0, 65535},
    {"roi_y", offsetof(ssda_composite_config_t, roi_y), 2, 0, 65535},
    {"roi_w", offsetof(ssda_composite_config_t, roi_w), 2, 0, 65535},
    {"roi_h", offsetof(ssda_composite_config_t, roi_h), 2, 0, 65535},
    {"radius_q8", offsetof(ssda_composite_config_t, radius_q8), 2, 0, 65535},
    {"min_radius", offsetof(ssda_composite_config_t, min_radius), 2, 0, 65535},
    {"min_std_q8", offsetof(ssda_composite_config_t, min_std_q8), 2, 0, 65535},
    {NULL, 0, 0, 0, 0}};

static const ssdapy_field_t relax_cfg_fields[] = {
    {"iterations", offsetof(ssda_relax_config_t, iterations), 2, 0, 65535},
    {"len_step_q8", offsetof(ssda_relax_config_t, len_step_q8), 2, 0, 65535},
    {NULL, 0, 0, 0, 0}};

static const ssdapy_field_t median_cfg_fields[] = {
    {"threshold_q8", offsetof(ssda_relax_median_config_t, threshold_q8), 2, 0, 65535},
    {"eps_q8", offsetof(ssda_relax_median_config_t, eps_q8), 2, 0, 65535},
    {NULL, 0, 0, 0, 0}};

/* ---- composite ---- */

static int composite_options(PyObject *kw, ssda_composite_config_t *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    if (ssdapy_fields(kw, cfg, composite_cfg_fields) != 0 ||
        ssdapy_flag(kw, "subpixel", &cfg->flags, SSDA_COMPOSITE_SUBPIXEL) != 0) {
        return -1;
    }
    if (ssdapy_kw_enum(kw, "metric", metrics, &cfg->metric) != 0) {
        return -1;
    }
    return 0;
}

static PyObject *composite_object(PyObject *templates, const ssda_composite_result_t *r)
{
    PyObject *o = PyStructSequence_New(composite_type);
    if (o == NULL) {
        return NULL;
    }
    Py_INCREF(templates);
    PyStructSequence_SET_ITEM(o, 0, templates);
    PyStructSequence_SET_ITEM(o, 1, PyLong_FromUnsignedLong(r->cols));
    PyStructSequence_SET_ITEM(o, 2, PyLong_FromUnsignedLong(r->rows));
    PyStructSequence_SET_ITEM(o, 3, PyLong_FromUnsignedLong(r->count));
    PyStructSequence_SET_ITEM(o, 4, PyLong_FromUnsignedLong(r->ok));
    PyStructSequence_SET_ITEM(o, 5, PyLong_FromUnsignedLong(r->origin));
    PyStructSequence_SET_ITEM(o, 6, PyLong_FromLong(r->mean_rho_q30));
    PyStructSequence_SET_ITEM(o, 7, PyFloat_FromDouble(r->mean_rho_q30 / 1073741824.0));
    PyStructSequence_SET_ITEM(o, 8, PyLong_FromUnsignedLongLong(r->pixel_ops));
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

/* The template grid of the region cfg names in a w x h REF (the library
   checks the region; an empty grid gets one row so the array exists). */
static void grid_shape(const ssda_composite_config_t *cfg, uint16_t w, uint16_t h,
                       Py_ssize_t shape[2])
{
    const size_t tp = cfg->tp != 0u ? cfg->tp : SSDA_COMPOSITE_DEFAULT_TP;
    const size_t step = cfg->step != 0u ? cfg->step : SSDA_COMPOSITE_DEFAULT_STEP;
    const size_t rw = cfg->roi_w != 0u ? cfg->roi_w : (cfg->roi_x < w ? (size_t)w - cfg->roi_x : (size_t)0u);
    const size_t rh = cfg->roi_h != 0u ? cfg->roi_h : (cfg->roi_y < h ? (size_t)h - cfg->roi_y : (size_t)0u);
    shape[0] = (Py_ssize_t)SSDA_COMPOSITE_DIM(rh, tp, step);
    shape[1] = (Py_ssize_t)SSDA_COMPOSITE_DIM(rw, tp, step);
}

static PyObject *py_composite(PyObject *self, PyObject *args, PyObject *kw)
{
    static uint64_t no_work;
    uint32_t side;
    PyObject *a[2], *kwc = NULL, *arr = NULL, *out = NULL;
    ssdapy_image_t ref, next;
    ssda_composite_config_t cfg;
    ssda_composite_result_t res;
    Py_ssize_t shape[2];
    ssda_composite_tp_t *tp;
    void *work = NULL;
    int e;
    (void)self;
    if (ssdapy_args(args, "composite", 2, 2, a) != 0 || ssdapy_image_get(a[0], "ref", &ref) != 0) {
        return NULL;
    }
    if (ssdapy_image_get(a[1], "next", &next) != 0) {
        ssdapy_image_release(&ref);
        return NULL;
    }
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || composite_options(kwc, &cfg) != 0 ||
        ssdapy_kw_done(kwc, "composite") != 0) {
        goto done;
    }
    grid_shape(&cfg, ref.view.width, ref.view.height, shape);
    if ((arr = ssdapy_np_empty(2, shape, tp_dtype)) == NULL ||
        (tp = ssdapy_np_data(arr)) == NULL) {
        goto done;
    }
    side = cfg.tp != 0u ? cfg.tp : SSDA_COMPOSITE_DEFAULT_TP;
    if (side > 256u || side > next.view.width || side > next.view.height) {
        cfg.work = &no_work; /* the library names the size or argument error first */
        cfg.work_size = 0;
    } else {
        cfg.work_size = SSDA_COMPOSITE_WORK_SIZE(next.view.width, side);
        if ((work = PyMem_Malloc(cfg.work_size)) == NULL) {
            PyErr_NoMemory(); /* PyMem_Malloc: 8-byte aligned or more */
            goto done;
        }
        cfg.work = work;
    }
    SSDAPY_NOGIL(e = ssda_composite_match(&ref.view, &next.view, &cfg, tp,
                                          (size_t)(shape[0] * shape[1]), &res));
    out = e == SSDA_OK ? composite_object(arr, &res) : ssdapy_error(e, "ssda_composite_match");
done:
    PyMem_Free(work);
    Py_XDECREF(arr);
    Py_XDECREF(kwc);
    ssdapy_image_release(&ref);
    ssdapy_image_release(&next);
    return out;
}

/* ---- relax ---- */

/* One node as the library reads it: dx, dy and status at one stride. */
typedef struct {
    int32_t dx, dy;
    uint8_t status;
} node_t;

/* A 2-D array of one dtype (format char f, item size n) of rows x cols
   (rows < 0: any, set here), read through its strides. */
typedef struct {
    Py_buffer b;
    int have;
} strided_t;

static int strided_get(PyObject *o, const char *what, char f, Py_ssize_t n, Py_ssize_t *rows,
                       Py_ssize_t *cols, strided_t *s)
{
    const char *fmt;
    s->have = 0;
    if (PyObject_GetBuffer(o, &s->b, PyBUF_RECORDS_RO) != 0) {
        PyErr_Format(PyExc_TypeError, "%s must be a 2-D array", what);
        return -1;
    }
    s->have = 1;
    fmt = s->b.format != NULL ? s->b.format : "B";
    if (*fmt == '<' || *fmt == '=' || *fmt == '@') {
        fmt++;
    }
    if (s->b.itemsize != n || (fmt[0] != f && !(f == 'i' && fmt[0] == 'l' && n == 4)) ||
        fmt[1] != '\0') {
        PyErr_Format(PyExc_TypeError, "%s must be %s (got format '%s')", what,
                     f == 'i' ? "int32" : "uint8", s->b.format != NULL ? s->b.format : "B");
        return -1;
    }
    if (s->b.ndim != 2) {
        PyErr_Format(PyExc_ValueError, "%s must be 2-D (rows, cols), not %d-D", what,
                     s->b.ndim);
        return -1;
    }
    if (*rows < 0) {
        *rows = s->b.shape[0];
        *cols = s->b.shape[1];
    } else if (s->b.shape[0] != *rows || s->b.shape[1] != *cols) {
        PyErr_Format(PyExc_ValueError, "%s must have dx's shape (%zd, %zd)", what, *rows, *cols);
        return -1;
    }
    return 0;
}

static void strided_release(strided_t *s)
{
    if (s->have) {
        PyBuffer_Release(&s->b);
        s->have = 0;
    }
}

static const char *strided_at(const strided_t *s, Py_ssize_t r, Py_ssize_t c)
{
    return (const char *)s->b.buf + r * s->b.strides[0] + c * s->b.strides[1];
}

/* The field (dx, dy[, status]) of the call, interleaved into *nodes
   (PyMem), and the grid over it. Returns 0 or -1 with an exception. */
static int field_get(PyObject *const *a, Py_ssize_t na, unsigned frac_bits, node_t **nodes,
                     ssda_relax_grid_t *g, Py_ssize_t shape[2])
{
    strided_t s[3];
    Py_ssize_t r, c;
    int rc = -1, i;
    shape[0] = shape[1] = -1;
    memset(s, 0, sizeof s);
    *nodes = NULL;
    if (strided_get(a[0], "dx", 'i', 4, &shape[0], &shape[1], &s[0]) != 0 ||
        strided_get(a[1], "dy", 'i', 4, &shape[0], &shape[1], &s[1]) != 0 ||
        (na > 2 && a[2] != Py_None &&
         strided_get(a[2], "status", 'B', 1, &shape[0], &shape[1], &s[2]) != 0)) {
        goto done;
    }
    if (shape[0] < 1 || shape[1] < 1 || shape[0] > 65535 || shape[1] > 65535) {
        PyErr_Format(PyExc_ValueError, "the grid must be 1..65535 rows and columns, not %zd x %zd",
                     shape[0], shape[1]);
        goto done;
    }
    if ((*nodes = PyMem_Malloc((size_t)(shape[0] * shape[1]) * sizeof **nodes)) == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    for (r = 0; r < shape[0]; r++) {
        for (c = 0; c < shape[1]; c++) {
            node_t *n = &(*nodes)[r * shape[1] + c];
            memcpy(&n->dx, strided_at(&s[0], r, c), 4);
            memcpy(&n->dy, strided_at(&s[1], r, c), 4);
            n->status = s[2].have ? *(const uint8_t *)strided_at(&s[2], r, c) : 0u;
        }
    }
    g->dx = &(*nodes)[0].dx;
    g->dy = &(*nodes)[0].dy;
    g->status = s[2].have ? &(*nodes)[0].status : NULL;
    g->stride = sizeof **nodes;
    g->cols = (uint16_t)shape[1];
    g->rows = (uint16_t)shape[0];
    g->frac_bits = (uint8_t)frac_bits;
    rc = 0;
done:
    for (i = 0; i < 3; i++) {
        strided_release(&s[i]);
    }
    return rc;
}

/* (dx, dy[, status]) and frac_bits: the grid, its nodes, the output array. */
static int relax_inputs(PyObject *args, PyObject *kwc, const char *func, node_t **nodes,
                        ssda_relax_grid_t *g, PyObject **arr, ssda_relax_vector_t **out)
{
    PyObject *a[3] = {NULL, NULL, NULL}, *v;
    unsigned long long fb = 0;
    Py_ssize_t shape[2];
    if (ssdapy_args(args, func, 2, 3, a) != 0) {
        return -1;
    }
    if ((v = ssdapy_kw_take(kwc, "frac_bits")) != NULL) {
        int rc = ssdapy_uint(v, "frac_bits", 0, 8, &fb);
        Py_DECREF(v);
        if (rc != 0) {
            return -1;
        }
    }
    if (field_get(a, a[2] != NULL ? 3 : 2, (unsigned)fb, nodes, g, shape) != 0) {
        return -1;
    }
    if ((*arr = ssdapy_np_empty(2, shape, relax_dtype)) == NULL ||
        (*out = ssdapy_np_data(*arr)) == NULL) {
        return -1;
    }
    return 0;
}

static PyObject *py_relax(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *kwc, *arr = NULL, *out = NULL;
    node_t *nodes = NULL;
    ssda_relax_grid_t g;
    ssda_relax_config_t cfg;
    ssda_relax_vector_t *vec;
    int e;
    (void)self;
    memset(&cfg, 0, sizeof cfg);
    if ((kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (ssdapy_fields(kwc, &cfg, relax_cfg_fields) != 0 ||
        ssdapy_flag(kwc, "keep", &cfg.flags, SSDA_RELAX_KEEP) != 0 ||
        relax_inputs(args, kwc, "relax", &nodes, &g, &arr, &vec) != 0 ||
        ssdapy_kw_done(kwc, "relax") != 0) {
        goto done;
    }
    cfg.work_size = SSDA_RELAX_WORK_SIZE(g.cols, g.rows);
    if ((cfg.work = PyMem_Malloc(cfg.work_size)) == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    SSDAPY_NOGIL(e = ssda_relax_labels(&g, &cfg, vec, (size_t)g.cols * g.rows));
    if (e == SSDA_OK) {
        Py_INCREF(arr);
        out = arr;
    } else {
        ssdapy_error(e, "ssda_relax_labels");
    }
done:
    PyMem_Free(cfg.work);
    PyMem_Free(nodes);
    Py_XDECREF(arr);
    Py_DECREF(kwc);
    return out;
}

static PyObject *py_relax_median(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *kwc, *arr = NULL, *out = NULL;
    node_t *nodes = NULL;
    ssda_relax_grid_t g;
    ssda_relax_median_config_t cfg;
    ssda_relax_vector_t *vec;
    int e;
    (void)self;
    memset(&cfg, 0, sizeof cfg);
    if ((kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (ssdapy_fields(kwc, &cfg, median_cfg_fields) != 0 ||
        relax_inputs(args, kwc, "relax_median", &nodes, &g, &arr, &vec) != 0 ||
        ssdapy_kw_done(kwc, "relax_median") != 0) {
        goto done;
    }
    SSDAPY_NOGIL(e = ssda_relax_median(&g, &cfg, vec, (size_t)g.cols * g.rows));
    if (e == SSDA_OK) {
        Py_INCREF(arr);
        out = arr;
    } else {
        ssdapy_error(e, "ssda_relax_median");
    }
done:
    PyMem_Free(nodes);
    Py_XDECREF(arr);
    Py_DECREF(kwc);
    return out;
}

static PyMethodDef methods[] = {
    {"composite", (PyCFunction)(void (*)(void))py_composite, METH_VARARGS | METH_KEYWORDS,
     "composite(ref, next, /, *, tp=20, step=5, roi_x=0, roi_y=0, roi_w=0, roi_h=0, "
     "radius_q8=64, min_radius=3, min_std_q8=0, metric='rho', subpixel=False)\n--\n\n"
     "Composite template matching (seed 003; ssda_composite_match, ssda/composite.h):\n"
     "templates of tp x tp px every step px in the region (roi_*; 0 = to REF's edge)\n"
     "of ref, ranked by standard deviation; the origin (largest) is searched over\n"
     "all of next by the exact correlation coefficient, every other template in a\n"
     "circle around the origin's match plus its offset from the origin, of radius\n"
     "radius_q8 / 256 times that offset's length (at least min_radius px).\n"
     "ref and next: 2-D uint8 or uint16 arrays of one dtype. Returns a\n"
     "CompositeResult; templates is a (rows, cols) COMPOSITE_DTYPE array the\n"
     "library writes (dx, dy Q24.8 px, motion ref -> next). metric: 'rho' or\n"
     "'abs'; subpixel: parabolic refinement. The GIL is released."},
    {"relax", (PyCFunction)(void (*)(void))py_relax, METH_VARARGS | METH_KEYWORDS,
     "relax(dx, dy, status=None, /, *, frac_bits=0, iterations=50, len_step_q8=0, "
     "keep=False)\n--\n\n"
     "Relaxation labelling of a vector field (seed 003 section 4; ssda_relax_labels,\n"
     "ssda/relax.h). dx, dy: 2-D int32 arrays (rows, cols) of any strides, in\n"
     "Q(frac_bits) px (0 for track vectors, 8 for composite templates); status:\n"
     "2-D uint8 of the same shape, valid where 0 (None: all valid). For example\n"
     "relax(t['dx'], t['dy'], t['status'], frac_bits=8) with t = composite(...).templates.\n"
     "Returns a (rows, cols) RELAX_DTYPE array: dx_q8, dy_q8 (Q24.8 px), p_q15, cls,\n"
     "flags (RELAX_VALID, RELAX_CHANGED). len_step_q8 0: automatic; keep: vectors\n"
     "whose most likely class is their own stay unchanged. The binding packs the\n"
     "field into one buffer (the library reads dx, dy and status at one stride)\n"
     "and allocates the work buffer; the GIL is released."},
    {"relax_median", (PyCFunction)(void (*)(void))py_relax_median,
     METH_VARARGS | METH_KEYWORDS,
     "relax_median(dx, dy, status=None, /, *, frac_bits=0, threshold_q8=512, "
     "eps_q8=26)\n--\n\n"
     "Normalised median test with replacement (Westerweel & Scarano 2005;\n"
     "ssda_relax_median): arguments and result as relax; threshold_q8 and eps_q8\n"
     "in Q8.8 (0: the paper's 2.0 and 0.1 px)."},
    {NULL, NULL, 0, NULL}};

static int add_dtypes(PyObject *m)
{
    static const char *const tnames[] = {"var", "dx", "dy", "rho_q30", "x", "y", "status",
                                         "origin"};
    static const char *const tformats[] = {"u8", "i4", "i4", "i4", "u2", "u2", "u1", "u1"};
    static const size_t toffsets[] = {
        offsetof(ssda_composite_tp_t, var),     offsetof(ssda_composite_tp_t, dx),
        offsetof(ssda_composite_tp_t, dy),      offsetof(ssda_composite_tp_t, rho_q30),
        offsetof(ssda_composite_tp_t, x),       offsetof(ssda_composite_tp_t, y),
        offsetof(ssda_composite_tp_t, status),  offsetof(ssda_composite_tp_t, origin)};
    static const char *const rnames[] = {"dx_q8", "dy_q8", "p_q15", "cls", "flags"};
    static const char *const rformats[] = {"i4", "i4", "u2", "u1", "u1"};
    static const size_t roffsets[] = {
        offsetof(ssda_relax_vector_t, dx_q8), offsetof(ssda_relax_vector_t, dy_q8),
        offsetof(ssda_relax_vector_t, p_q15), offsetof(ssda_relax_vector_t, cls),
        offsetof(ssda_relax_vector_t, flags)};
    tp_dtype = ssdapy_np_struct_dtype(8, tnames, tformats, toffsets, sizeof(ssda_composite_tp_t));
    relax_dtype = ssdapy_np_struct_dtype(5, rnames, rformats, roffsets,
                                         sizeof(ssda_relax_vector_t));
    if (tp_dtype == NULL || relax_dtype == NULL) {
        return -1;
    }
    Py_INCREF(tp_dtype);
    Py_INCREF(relax_dtype);
    return PyModule_AddObject(m, "COMPOSITE_DTYPE", tp_dtype) != 0 ||
                   PyModule_AddObject(m, "RELAX_DTYPE", relax_dtype) != 0
               ? -1
               : 0;
}

int ssdapy_init_flow(PyObject *m)
{
    composite_type = ssdapy_struct_type(m, "ssda.CompositeResult",
                                        "Result of composite (ssda_composite_result_t and the "
                                        "templates).",
                                        composite_fields, 9);
    if (composite_type == NULL || add_dtypes(m) != 0 ||
        PyModule_AddIntConstant(m, "COMPOSITE_OK", SSDA_COMPOSITE_OK) != 0 ||
        PyModule_AddIntConstant(m, "COMPOSITE_FLAT", SSDA_COMPOSITE_FLAT) != 0 ||
        PyModule_AddIntConstant(m, "COMPOSITE_EDGE", SSDA_COMPOSITE_EDGE) != 0 ||
        PyModule_AddIntConstant(m, "RELAX_VALID", SSDA_RELAX_VALID) != 0 ||
        PyModule_AddIntConstant(m, "RELAX_CHANGED", SSDA_RELAX_CHANGED) != 0 ||
        PyModule_AddIntConstant(m, "RELAX_CLASSES", SSDA_RELAX_CLASSES) != 0) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
