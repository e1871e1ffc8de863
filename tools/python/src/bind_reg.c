/* bind_reg.c - seed 002: ssda.poly_init / poly_eval / poly_fit
   (ssda/poly.h: polynomial maps fitted to control points) and ssda.shade
   (ssda/shade.h: the seed's shading function of several images, removed),
   library calls of `ssda register`. */
#include "ssdapy.h"
#include "ssda/poly.h"
#include "ssda/register.h"
#include "ssda/shade.h"
#include "ssda/warp.h"

static PyObject *poly_dtype, *point_dtype;
static PyTypeObject *fit_type, *shade_type;

static PyStructSequence_Field fit_fields[] = {
    {"poly", "the map: a POLY_DTYPE record (ssda_poly_t's layout, written by the library)"},
    {"residual_q8", "(n,) uint32: each pair's residual under the final map, px Q24.8"},
    {"used", "(n,) bool: the pairs of the final fit"},
    {"rms_q8", "RMS residual of the pairs used, px Q24.8"},
    {"max_q8", "largest residual of a pair used"},
    {"cond", "conditioning estimate of the normal matrix"},
    {"n_used", "pairs in the final fit"},
    {"rejected", "pairs dropped as outliers"},
    {"refinements", "iterative-refinement steps"},
    {"within_bound", "every used pair's leave-one-out statistic within max_residual_q8"},
    {"max_leverage_q15", "largest leverage of a used pair, Q1.15 (32768 = 1)"},
    {"weak", "the map is weakly determined (fewer than 2 pairs per term or a leverage > 0.8)"},
    {NULL, NULL}};

static PyStructSequence_Field shade_fields[] = {
    {"corrected", "the images corrected, same shape and dtype as given"},
    {"k_q8", "(3, 3) int32: K[p, q], Q8 grey; p the x term (1, cos, sin), q the y term"},
    {"centre_x", "shading centre, px"},
    {"centre_y", NULL},
    {"centre_q8", "S at the centre, Q8 grey"},
    {"images", "images in the estimate"},
    {NULL, NULL}};

static const ssdapy_name_t centres[] = {
    {"max", SSDA_SHADE_CENTRE_MAX}, {"min", SSDA_SHADE_CENTRE_MIN}, {NULL, 0}};

/* A one-record POLY_DTYPE array and its C struct. */
static PyObject *poly_new(ssda_poly_t **p)
{
    const Py_ssize_t shape[1] = {1};
    PyObject *a = ssdapy_np_empty(1, shape, poly_dtype);
    if (a == NULL || (*p = ssdapy_np_data(a)) == NULL) {
        Py_XDECREF(a);
        return NULL;
    }
    memset(*p, 0, sizeof **p);
    return a;
}

/* A POLY_DTYPE record (or a one-record array) into *p. */
static int poly_get(PyObject *o, ssda_poly_t *p)
{
    Py_buffer b;
    Py_ssize_t n;
    PyObject *arr = o;
    int rc;
    if (PyObject_HasAttrString(o, "dtype") && !PyObject_HasAttrString(o, "__len__")) {
        arr = PyObject_CallMethod(o, "reshape", "i", 1); /* a numpy.void record */
        if (arr == NULL) {
            return -1;
        }
    } else {
        Py_INCREF(arr);
    }
    rc = ssdapy_records(arr, "poly", poly_dtype, &b, &n);
    Py_DECREF(arr);
    if (rc != 0) {
        return -1;
    }
    if (n != 1) {
        PyBuffer_Release(&b);
        PyErr_SetString(PyExc_ValueError, "poly must be one POLY_DTYPE record");
        return -1;
    }
    memcpy(p, b.buf, sizeof *p);
    PyBuffer_Release(&b);
    return 0;
}

static PyObject *py_poly_init(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc, *v, *arr = NULL;
    unsigned long long order = 2;
    uint16_t w, h;
    ssda_poly_t *p;
    int e;
    (void)self;
    if (ssdapy_args(args, "poly_init", 1, 1, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if ((v = ssdapy_kw_take(kwc, "order")) != NULL) {
        e = ssdapy_uint(v, "order", 0, 255, &order);
        Py_DECREF(v);
        if (e != 0) {
            goto done;
        }
    }
    if (ssdapy_kw_done(kwc, "poly_init") != 0 || ssdapy_size2(a[0], "size", 0, 65535, &w, &h) != 0 ||
        (arr = poly_new(&p)) == NULL) {
        goto done;
    }
    if ((e = ssda_poly_init(p, w, h, (uint8_t)order)) != SSDA_OK) {
        Py_CLEAR(arr);
        ssdapy_error(e, "ssda_poly_init");
    }
done:
    Py_DECREF(kwc);
    return arr;
}

static PyObject *py_poly_eval(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[3];
    ssda_poly_t p;
    long long x, y;
    int32_t u, v;
    int e;
    (void)self;
    if (kw != NULL && PyDict_Size(kw) != 0) {
        ssdapy_kw_done(kw, "poly_eval");
        return NULL;
    }
    if (ssdapy_args(args, "poly_eval", 3, 3, a) != 0 || poly_get(a[0], &p) != 0 ||
        ssdapy_int(a[1], "x", INT32_MIN, INT32_MAX, &x) != 0 ||
        ssdapy_int(a[2], "y", INT32_MIN, INT32_MAX, &y) != 0) {
        return NULL;
    }
    if ((e = ssda_poly_eval(&p, (int32_t)x, (int32_t)y, &u, &v)) != SSDA_OK) {
        return ssdapy_error(e, "ssda_poly_eval");
    }
    return Py_BuildValue("(ii)", (int)u, (int)v);
}

/* pairs: (n, 4) int32 array, rows ref_x ref_y mov_x mov_y (Q8), C order. */
static int pairs_get(PyObject *o, Py_buffer *b, Py_ssize_t *n)
{
    const char *f;
    if (PyObject_GetBuffer(o, b, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_ND) != 0) {
        PyErr_Clear();
        PyErr_SetString(PyExc_TypeError, "pairs must be a C-contiguous (n, 4) int32 array");
        return -1;
    }
    f = b->format != NULL ? b->format : "B";
    f += (*f == '<' || *f == '=' || *f == '@') ? 1 : 0;
    if (b->itemsize != 4 || (f[0] != 'i' && f[0] != 'l') || f[1] != '\0') {
        PyBuffer_Release(b);
        PyErr_Format(PyExc_TypeError, "pairs must be int32, not format '%s'", f);
        return -1;
    }
    if (b->ndim != 2 || b->shape[1] != 4 || b->shape[0] > 65535) {
        PyBuffer_Release(b);
        PyErr_SetString(PyExc_ValueError, "pairs must be (n, 4), n <= 65535: ref_x, ref_y, "
                                          "mov_x, mov_y in Q8 px");
        return -1;
    }
    *n = b->shape[0];
    return 0;
}

static PyObject *fit_object(PyObject *poly, PyObject *res, PyObject *used,
                            const ssda_poly_fit_result_t *r)
{
    PyObject *o = PyStructSequence_New(fit_type), *ub;
    if (o == NULL) {
        return NULL;
    }
    ub = PyObject_CallMethod(used, "astype", "s", "bool");
    Py_INCREF(poly);
    Py_INCREF(res);
    PyStructSequence_SET_ITEM(o, 0, poly);
    PyStructSequence_SET_ITEM(o, 1, res);
    PyStructSequence_SET_ITEM(o, 2, ub);
    PyStructSequence_SET_ITEM(o, 3, PyLong_FromUnsignedLong(r->rms_q8));
    PyStructSequence_SET_ITEM(o, 4, PyLong_FromUnsignedLong(r->max_q8));
    PyStructSequence_SET_ITEM(o, 5, PyLong_FromUnsignedLong(r->cond));
    PyStructSequence_SET_ITEM(o, 6, PyLong_FromUnsignedLong(r->used));
    PyStructSequence_SET_ITEM(o, 7, PyLong_FromUnsignedLong(r->rejected));
    PyStructSequence_SET_ITEM(o, 8, PyLong_FromUnsignedLong(r->refinements));
    PyStructSequence_SET_ITEM(o, 9, PyBool_FromLong(r->within_bound));
    PyStructSequence_SET_ITEM(o, 10, PyLong_FromUnsignedLong(r->max_leverage_q15));
    PyStructSequence_SET_ITEM(o, 11, PyBool_FromLong(r->weak));
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}


static PyObject *py_poly_fit(PyObject *self, PyObject *args, PyObject *kw)
{
    static const ssdapy_field_t f[] = {
        {"order", offsetof(ssda_poly_fit_config_t, order), 1, 0, 255},
        {"max_residual_q8", offsetof(ssda_poly_fit_config_t, max_residual_q8), 4, 0,
         0xFFFFFFFFll},
        {NULL, 0, 0, 0, 0}};
    PyObject *a[2], *kwc, *poly = NULL, *res = NULL, *used = NULL, *out = NULL;
    ssda_poly_fit_config_t cfg;
    ssda_poly_fit_result_t r;
    ssda_poly_t *p;
    uint16_t w, h;
    Py_buffer b;
    Py_ssize_t n;
    void *work = NULL;
    int e, have = 0;
    (void)self;
    memset(&cfg, 0, sizeof cfg);
    if (ssdapy_args(args, "poly_fit", 2, 2, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (ssdapy_fields(kwc, &cfg, f) != 0 || ssdapy_kw_done(kwc, "poly_fit") != 0 ||
        ssdapy_size2(a[1], "size", 0, 65535, &w, &h) != 0 || pairs_get(a[0], &b, &n) != 0) {
        goto done;
    }
    have = 1;
    {
        const Py_ssize_t shape[1] = {n};
        if ((poly = poly_new(&p)) == NULL || (res = ssdapy_np_typed(1, shape, "uint32")) == NULL ||
            (used = ssdapy_np_typed(1, shape, "uint8")) == NULL) {
            goto done;
        }
    }
    if ((work = PyMem_Malloc(SSDA_POLY_FIT_WORK_SIZE(n) + 1u)) == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    {
        uint32_t *rq = ssdapy_np_data(res);
        uint8_t *uq = ssdapy_np_data(used);
        if (rq == NULL || uq == NULL) {
            goto done;
        }
        SSDAPY_NOGIL(e = ssda_poly_fit(b.buf, (size_t)n, w, h, &cfg, p, rq, uq, &r, work,
                                       SSDA_POLY_FIT_WORK_SIZE(n)));
    }
    out = e == SSDA_OK ? fit_object(poly, res, used, &r) : ssdapy_error(e, "ssda_poly_fit");
done:
    PyMem_Free(work);
    if (have) {
        PyBuffer_Release(&b);
    }
    Py_XDECREF(poly);
    Py_XDECREF(res);
    Py_XDECREF(used);
    Py_DECREF(kwc);
    return out;
}

/* ---- shade ---- */

typedef struct {
    const uint8_t *in;
    uint8_t *out;
    size_t n, h, row_bytes; /* images, rows, bytes per packed row */
    uint16_t w;
    uint8_t format, mode;
    int centre; /* set centre (cx, cy) */
    uint16_t cx, cy;
    ssda_shade_t sh;
    const char *failed;
} shade_job_t;

static int shade_run(shade_job_t *j)
{
    size_t i, y;
    int e;
    j->failed = "ssda_shade_init";
    if ((e = ssda_shade_init(&j->sh, j->w, (uint16_t)j->h, j->format)) != SSDA_OK) {
        return e;
    }
    j->failed = "ssda_shade_add_row";
    for (i = 0; i < j->n * j->h; i++) {
        if ((e = ssda_shade_add_row(&j->sh, j->in + i * j->row_bytes)) != SSDA_OK) {
            return e;
        }
    }
    j->failed = "ssda_shade_finish";
    if ((e = ssda_shade_finish(&j->sh, j->mode)) != SSDA_OK) {
        return e;
    }
    j->failed = "ssda_shade_set_centre";
    if (j->centre && (e = ssda_shade_set_centre(&j->sh, j->cx, j->cy)) != SSDA_OK) {
        return e;
    }
    j->failed = "ssda_shade_apply_row";
    for (i = 0; i < j->n; i++) {
        for (y = 0; y < j->h; y++) {
            const size_t at = (i * j->h + y) * j->row_bytes;
            if ((e = ssda_shade_apply_row(&j->sh, (uint32_t)y, j->in + at, j->out + at)) !=
                SSDA_OK) {
                return e;
            }
        }
    }
    return SSDA_OK;
}

static PyObject *shade_object(PyObject *corr, const ssda_shade_t *sh)
{
    const Py_ssize_t s33[2] = {3, 3};
    PyObject *o = PyStructSequence_New(shade_type), *k;
    int32_t *d;
    if (o == NULL) {
        return NULL;
    }
    k = ssdapy_np_typed(2, s33, "int32");
    if (k == NULL || (d = ssdapy_np_data(k)) == NULL) {
        Py_XDECREF(k);
        Py_DECREF(o);
        return NULL;
    }
    memcpy(d, sh->k_q8, sizeof sh->k_q8);
    Py_INCREF(corr);
    PyStructSequence_SET_ITEM(o, 0, corr);
    PyStructSequence_SET_ITEM(o, 1, k);
    PyStructSequence_SET_ITEM(o, 2, PyLong_FromUnsignedLong(sh->centre_x));
    PyStructSequence_SET_ITEM(o, 3, PyLong_FromUnsignedLong(sh->centre_y));
    PyStructSequence_SET_ITEM(o, 4, PyLong_FromLong(sh->centre_q8));
    PyStructSequence_SET_ITEM(o, 5, PyLong_FromUnsignedLong(sh->images));
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

static PyObject *py_shade(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc, *v, *np = NULL, *in = NULL, *corr = NULL, *out = NULL;
    shade_job_t j;
    Py_buffer b;
    int e, have = 0;
    (void)self;
    memset(&j, 0, sizeof j);
    if (ssdapy_args(args, "shade", 1, 1, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if ((v = ssdapy_kw_take(kwc, "mode")) != NULL) {
        int m;
        e = ssdapy_enum(v, "mode", centres, &m);
        Py_DECREF(v);
        if (e != 0) {
            goto done;
        }
        j.mode = (uint8_t)m;
    }
    if ((v = ssdapy_kw_take(kwc, "centre")) != NULL) {
        e = v == Py_None ? 0 : ssdapy_size2(v, "centre", 0, 65535, &j.cx, &j.cy);
        j.centre = v != Py_None;
        Py_DECREF(v);
        if (e != 0) {
            goto done;
        }
    }
    if (ssdapy_kw_done(kwc, "shade") != 0 || (np = PyImport_ImportModule("numpy")) == NULL ||
        (in = PyObject_CallMethod(np, "ascontiguousarray", "O", a[0])) == NULL) {
        goto done;
    }
    if (PyObject_GetBuffer(in, &b, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | PyBUF_ND) != 0) {
        goto done;
    }
    have = 1;
    {
        const char *f = b.format != NULL ? b.format : "B";
        f += (*f == '<' || *f == '=' || *f == '@') ? 1 : 0;
        if (!((f[0] == 'B' && b.itemsize == 1) || (f[0] == 'H' && b.itemsize == 2)) ||
            f[1] != '\0') {
            PyErr_Format(PyExc_TypeError, "images must be uint8 or uint16, not format '%s'", f);
            goto done;
        }
    }
    if (b.ndim != 2 && b.ndim != 3) {
        PyErr_SetString(PyExc_ValueError, "images must be one (h, w) image or (n, h, w)");
        goto done;
    }
    j.n = b.ndim == 3 ? (size_t)b.shape[0] : 1u;
    j.h = (size_t)b.shape[b.ndim - 2];
    if (b.shape[b.ndim - 1] > 65535 || j.h > 65535 || j.n < 1) {
        PyErr_SetString(PyExc_ValueError, "images must be 1..65535 px a side, at least one");
        goto done;
    }
    j.w = (uint16_t)b.shape[b.ndim - 1];
    j.format = b.itemsize == 1 ? (uint8_t)SSDA_PIX_U8 : (uint8_t)SSDA_PIX_U16;
    j.row_bytes = (size_t)j.w * (size_t)b.itemsize;
    j.in = b.buf;
    if ((corr = PyObject_CallMethod(np, "empty_like", "O", in)) == NULL ||
        (j.out = ssdapy_np_data(corr)) == NULL) {
        goto done;
    }
    SSDAPY_NOGIL(e = shade_run(&j));
    out = e == SSDA_OK ? shade_object(corr, &j.sh) : ssdapy_error(e, j.failed);
done:
    if (have) {
        PyBuffer_Release(&b);
    }
    Py_XDECREF(corr);
    Py_XDECREF(in);
    Py_XDECREF(np);
    Py_DECREF(kwc);
    return out;
}

/* ---- control points ---- */

static const ssdapy_name_t reg_metrics[] = {
    {"absncc", SSDA_REGISTER_ABSNCC}, {"ncc", SSDA_REGISTER_NCC}, {"sad", SSDA_REGISTER_SAD},
    {NULL, 0}};

static const ssdapy_field_t reg_cfg_fields[] = {
    {"grid_x", offsetof(ssda_register_config_t, grid_x), 2, 0, 65535},
    {"grid_y", offsetof(ssda_register_config_t, grid_y), 2, 0, 65535},
    {"window", offsetof(ssda_register_config_t, window), 2, 0, 65535},
    {"search", offsetof(ssda_register_config_t, search), 2, 0, 65535},
    {"step", offsetof(ssda_register_config_t, step), 2, 0, 65535},
    {"min_rho_q30", offsetof(ssda_register_config_t, min_rho_q30), 4, INT32_MIN, INT32_MAX},
    {"min_texture", offsetof(ssda_register_config_t, min_texture), 4, 0, 0xFFFFFFFFll},
    {"offset_x", offsetof(ssda_register_config_t, offset_x), 4, INT32_MIN, INT32_MAX},
    {"offset_y", offsetof(ssda_register_config_t, offset_y), 4, INT32_MIN, INT32_MAX},
    {NULL, 0, 0, 0, 0}};

static PyObject *py_register_points(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc, *pts = NULL, *out = NULL;
    ssdapy_src_arg_t r, m;
    ssda_register_config_t cfg;
    ssda_register_point_t *p;
    size_t accepted = 0, ws;
    void *work = NULL;
    int e = SSDA_OK, raised, have_r = 0, have_m = 0;
    (void)self;
    memset(&cfg, 0, sizeof cfg);
    if (ssdapy_args(args, "register_points", 2, 2, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (ssdapy_fields(kwc, &cfg, reg_cfg_fields) != 0) {
        goto done;
    }
    if (ssdapy_kw_enum(kwc, "metric", reg_metrics, &cfg.metric) != 0) {
        goto done;
    }
    if (ssdapy_kw_done(kwc, "register_points") != 0 ||
        ssdapy_src_arg_get(a[0], "ref", &r, NULL) != 0) {
        goto done;
    }
    have_r = 1;
    if (ssdapy_src_arg_get(a[1], "mov", &m, &r) != 0) {
        goto done;
    }
    have_m = 1;
    {
        const Py_ssize_t shape[2] = {cfg.grid_y != 0u ? cfg.grid_y : SSDA_REGISTER_DEFAULT_GRID,
                                     cfg.grid_x != 0u ? cfg.grid_x : SSDA_REGISTER_DEFAULT_GRID};
        const size_t win = cfg.window != 0u ? cfg.window : SSDA_REGISTER_DEFAULT_WINDOW;
        const size_t area = cfg.search != 0u ? cfg.search : SSDA_REGISTER_DEFAULT_SEARCH;
        if ((pts = ssdapy_np_empty(2, shape, point_dtype)) == NULL ||
            (p = ssdapy_np_data(pts)) == NULL) {
            goto done;
        }
        /* a window wider than the area: the library names that error first */
        ws = win <= area && area <= 4096u ? SSDA_REGISTER_WORK_SIZE(win, area, 2u) : 8u;
        if ((work = PyMem_Malloc(ws)) == NULL) {
            PyErr_NoMemory();
            goto done;
        }
        SSDAPY_NOGIL(e = ssda_register_points(r.src, m.src, &cfg, p,
                                              (size_t)(shape[0] * shape[1]), &accepted, work, ws));
    }
    raised = ssdapy_src_arg_release(&m);
    raised |= ssdapy_src_arg_release(&r);
    have_r = have_m = 0;
    if (!raised) {
        out = e == SSDA_OK ? Py_BuildValue("(On)", pts, (Py_ssize_t)accepted)
                           : ssdapy_error(e, "ssda_register_points");
    }
done:
    if (have_m) {
        ssdapy_src_arg_release(&m);
    }
    if (have_r) {
        ssdapy_src_arg_release(&r);
    }
    PyMem_Free(work);
    Py_XDECREF(pts);
    Py_DECREF(kwc);
    return out;
}

/* ---- warp ---- */

static const ssdapy_name_t resamples[] = {
    {"nearest", SSDA_WARP_NEAREST}, {"bilinear", SSDA_WARP_BILINEAR}, {NULL, 0}};

/* The sink: segments into the output array (no Python call). */
typedef struct {
    uint8_t *out;
    size_t stride; /* bytes per output row */
    size_t bpp;
} warp_out_t;

static int warp_sink(void *context, uint32_t x, uint32_t y, uint32_t n, const void *pixels)
{
    const warp_out_t *o = context;
    memcpy(o->out + (size_t)y * o->stride + (size_t)x * o->bpp, pixels, (size_t)n * o->bpp);
    return 0;
}

static int warp_run(ssda_warp_config_t *wc, ssda_source_t *src, ssda_warp_stats_t *st)
{
    ssda_warp_t job;
    int e = ssda_warp_init(&job, wc, src);
    return e != SSDA_OK ? e : ssda_warp_run(&job, st);
}

static PyObject *py_warp(PyObject *self, PyObject *args, PyObject *kw)
{
    static const ssdapy_field_t f[] = {
        {"fill", offsetof(ssda_warp_config_t, fill), 2, 0, 65535},
        {"tile_w", offsetof(ssda_warp_config_t, tile_w), 2, 0, 65535},
        {"tile_h", offsetof(ssda_warp_config_t, tile_h), 2, 0, 65535},
        {NULL, 0, 0, 0, 0}};
    PyObject *a[2], *kwc, *img = NULL, *out = NULL;
    ssdapy_src_arg_t s;
    ssda_warp_config_t wc;
    ssda_warp_stats_t st;
    ssda_poly_t map;
    warp_out_t wo;
    int e = SSDA_OK, have = 0, raised;
    (void)self;
    memset(&wc, 0, sizeof wc);
    wc.resample = SSDA_WARP_BILINEAR;
    if (ssdapy_args(args, "warp", 2, 2, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (ssdapy_fields(kwc, &wc, f) != 0) {
        goto done;
    }
    if (ssdapy_kw_enum(kwc, "resample", resamples, &wc.resample) != 0) {
        goto done;
    }
    if (ssdapy_kw_done(kwc, "warp") != 0 || poly_get(a[1], &map) != 0 ||
        ssdapy_src_arg_get(a[0], "source", &s, NULL) != 0) {
        goto done;
    }
    have = 1;
    {
        const Py_ssize_t shape[2] = {map.ref_h, map.ref_w};
        const uint8_t fmt = s.format;
        wo.bpp = fmt == SSDA_PIX_U16 ? 2u : 1u;
        wo.stride = (size_t)map.ref_w * wo.bpp;
        if ((img = ssdapy_np_typed(2, shape, wo.bpp == 2u ? "uint16" : "uint8")) == NULL ||
            (wo.out = ssdapy_np_data(img)) == NULL) {
            goto done;
        }
        wc.row_size = (size_t)(map.ref_w > 0u ? map.ref_w : 1u) * wo.bpp;
        if ((wc.row = PyMem_Malloc(wc.row_size)) == NULL) {
            PyErr_NoMemory();
            goto done;
        }
    }
    wc.map = &map;
    wc.sink = warp_sink;
    wc.context = &wo;
    SSDAPY_NOGIL(e = warp_run(&wc, s.src, &st));
    raised = ssdapy_src_arg_release(&s);
    have = 0;
    if (!raised) {
        out = e == SSDA_OK ? Py_BuildValue("(OKK)", img, (unsigned long long)st.filled,
                                           (unsigned long long)st.moves)
                           : ssdapy_error(e, "ssda_warp_run");
    }
done:
    if (have) {
        ssdapy_src_arg_release(&s);
    }
    PyMem_Free(wc.row);
    Py_XDECREF(img);
    Py_DECREF(kwc);
    return out;
}

static PyMethodDef methods[] = {
    {"warp", (PyCFunction)(void (*)(void))py_warp, METH_VARARGS | METH_KEYWORDS,
     "warp(source, poly, /, *, resample='bilinear', fill=0, tile_w=0, tile_h=0)\n--\n\n"
     "Resample source (a 2-D uint8 / uint16 array or a Source, streamed through\n"
     "its arena) through the map poly onto poly's reference grid (ssda_warp_*,\n"
     "ssda/warp.h): returns (image (ref_h, ref_w) of the source's dtype, filled,\n"
     "moves). fill: the value where the source has no pixel; tiles as\n"
     "ssda_warp_plan picks (0) or given. The GIL is released."},
    {"register_points", (PyCFunction)(void (*)(void))py_register_points,
     METH_VARARGS | METH_KEYWORDS,
     "register_points(ref, mov, /, *, grid_x=4, grid_y=4, window=20, search=40, step=0, "
     "metric='absncc', min_rho_q30=0.65*2**30, min_texture=0, offset_x=0, offset_y=0)\n--\n\n"
     "A control point in every cell of a grid over ref (seed 002;\n"
     "ssda_register_points, ssda/register.h): the most textured window of the cell\n"
     "searched in mov around the same place (plus offset). ref, mov: 2-D uint8 or\n"
     "uint16 arrays or Sources of one format. Returns (points, accepted): points a\n"
     "(grid_y, grid_x) REGISTER_POINT_DTYPE array (ref_x_q8, ref_y_q8, mov_x_q8,\n"
     "mov_y_q8, rho_q30, sad, pixel_ops, texture, cell_x, cell_y, status); the OK\n"
     "points' first four fields are poly_fit's pairs. The GIL is released."},
    {"poly_init", (PyCFunction)(void (*)(void))py_poly_init, METH_VARARGS | METH_KEYWORDS,
     "poly_init(size, /, *, order=2)\n--\n\n"
     "The identity map on a (w, h) reference grid (ssda_poly_init, ssda/poly.h): a\n"
     "one-record POLY_DTYPE array (u_q24, v_q24 Q40.24 coefficients, cx, cy, kx,\n"
     "ky, order, ref_w, ref_h), which may be edited and passed to poly_eval."},
    {"poly_eval", (PyCFunction)(void (*)(void))py_poly_eval, METH_VARARGS | METH_KEYWORDS,
     "poly_eval(poly, x, y, /)\n--\n\n"
     "(u_q8, v_q8) = floor(256 * moving x, y) at reference pixel (x, y), exact\n"
     "(ssda_poly_eval)."},
    {"poly_fit", (PyCFunction)(void (*)(void))py_poly_fit, METH_VARARGS | METH_KEYWORDS,
     "poly_fit(pairs, size, /, *, order=2, max_residual_q8=512)\n--\n\n"
     "Least-squares polynomial map from the reference to the moving image with\n"
     "outlier rejection (seed 002; ssda_poly_fit): pairs an (n, 4) int32 array of\n"
     "ref_x, ref_y, mov_x, mov_y in Q8 px, size the reference grid (w, h). Returns a\n"
     "PolyFit (poly, residual_q8, used, rms_q8, max_q8, cond, n_used, rejected,\n"
     "refinements, within_bound, max_leverage_q15, weak). The GIL is released."},
    {"shade", (PyCFunction)(void (*)(void))py_shade, METH_VARARGS | METH_KEYWORDS,
     "shade(images, /, *, mode='max', centre=None)\n--\n\n"
     "The seed's shading function (DC and one cycle per direction) of the images\n"
     "(one (h, w) or several (n, h, w), uint8 or uint16), removed from each keeping\n"
     "the level at the shading centre (ssda_shade_*; mode 'max' or 'min' picks the\n"
     "centre, centre=(x, y) sets it). Returns a ShadeResult (corrected, k_q8,\n"
     "centre_x, centre_y, centre_q8, images)."},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_reg(PyObject *m)
{
    static const char *const names[] = {"u_q24", "v_q24", "cx",    "cy",   "kx",
                                        "ky",    "order", "ref_w", "ref_h"};
    static const char *const formats[] = {"(10,)i8", "(10,)i8", "i4", "i4", "u1",
                                          "u1",      "u1",      "u2", "u2"};
    static const size_t offsets[] = {
        offsetof(ssda_poly_t, u_q24), offsetof(ssda_poly_t, v_q24), offsetof(ssda_poly_t, cx),
        offsetof(ssda_poly_t, cy),    offsetof(ssda_poly_t, kx),    offsetof(ssda_poly_t, ky),
        offsetof(ssda_poly_t, order), offsetof(ssda_poly_t, ref_w), offsetof(ssda_poly_t, ref_h)};
    static const char *const pnames[] = {"ref_x_q8", "ref_y_q8", "mov_x_q8", "mov_y_q8",
                                         "rho_q30", "sad", "pixel_ops", "texture", "cell_x",
                                         "cell_y", "status"};
    static const char *const pformats[] = {"i4", "i4", "i4", "i4", "i4", "u8",
                                           "u8", "u4", "u2", "u2", "u1"};
    static const size_t poffs[] = {
        offsetof(ssda_register_point_t, pair.ref_x_q8), offsetof(ssda_register_point_t, pair.ref_y_q8),
        offsetof(ssda_register_point_t, pair.mov_x_q8), offsetof(ssda_register_point_t, pair.mov_y_q8),
        offsetof(ssda_register_point_t, rho_q30),       offsetof(ssda_register_point_t, sad),
        offsetof(ssda_register_point_t, pixel_ops),     offsetof(ssda_register_point_t, texture),
        offsetof(ssda_register_point_t, cell_x),        offsetof(ssda_register_point_t, cell_y),
        offsetof(ssda_register_point_t, status)};
    point_dtype = ssdapy_np_struct_dtype(11, pnames, pformats, poffs, sizeof(ssda_register_point_t));
    if (point_dtype == NULL) {
        return -1;
    }
    Py_INCREF(point_dtype);
    if (PyModule_AddObject(m, "REGISTER_POINT_DTYPE", point_dtype) != 0 ||
        PyModule_AddIntConstant(m, "REGISTER_OK", SSDA_REGISTER_OK) != 0 ||
        PyModule_AddIntConstant(m, "REGISTER_FLAT", SSDA_REGISTER_FLAT) != 0 ||
        PyModule_AddIntConstant(m, "REGISTER_LOW_RHO", SSDA_REGISTER_LOW_RHO) != 0 ||
        PyModule_AddIntConstant(m, "REGISTER_BORDER", SSDA_REGISTER_BORDER) != 0 ||
        PyModule_AddIntConstant(m, "REGISTER_OUTSIDE", SSDA_REGISTER_OUTSIDE) != 0) {
        return -1;
    }
    fit_type = ssdapy_struct_type(m, "ssda.PolyFit", "Result of poly_fit.", fit_fields, 12);
    shade_type = ssdapy_struct_type(m, "ssda.ShadeResult", "Result of shade.", shade_fields, 6);
    poly_dtype = ssdapy_np_struct_dtype(9, names, formats, offsets, sizeof(ssda_poly_t));
    if (fit_type == NULL || shade_type == NULL || poly_dtype == NULL) {
        return -1;
    }
    Py_INCREF(poly_dtype);
    if (PyModule_AddObject(m, "POLY_DTYPE", poly_dtype) != 0) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
