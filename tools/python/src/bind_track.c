/* bind_track.c - ssda.track and ssda.track_grid (ssda/track.h): grid
   tracking, with vectors returned as a structured numpy array that the
   library writes directly (its dtype is ssda_track_vector_t's layout). */
#include "ssdapy.h"

#include <stddef.h>

static PyTypeObject *grid_type, *stats_type, *result_type;
static PyObject *vector_dtype;

static PyStructSequence_Field grid_fields[] = {
    {"count", "windows, cols * rows"}, {"cols", "windows per grid row"},
    {"rows", "windows per grid column"}, {"win_w", NULL}, {"win_h", NULL},
    {"search_w", NULL}, {"search_h", NULL}, {"step_x", NULL}, {"step_y", NULL},
    {"roi_x", NULL}, {"roi_y", NULL}, {"roi_w", NULL}, {"roi_h", NULL}, {NULL, NULL}};

static PyStructSequence_Field stats_fields[] = {
    {"pixel_ops", "sum of the searches' pixel_ops"}, {"positions", NULL}, {"completed", NULL},
    {"check_pixels", "pixels read by the mask, exclusion and flat tests"}, {"windows", NULL},
    {"ok", NULL}, {"excluded", NULL}, {"masked", NULL}, {"edge", NULL}, {"flat", NULL},
    {"ambiguous", NULL}, {"at_limit", NULL}, {NULL, NULL}};

static PyStructSequence_Field result_fields[] = {
    {"vectors", "rows x cols structured array: sad, dx, dy, sub_dx_q8, sub_dy_q8, "
                "texture_q8, x, y, unique_q8, status, exact"},
    {"grid", "the Grid the options gave"},
    {"stats", "TrackStats: totals over the call"},
    {NULL, NULL}};

static PyObject *grid_object(const ssda_track_grid_t *g)
{
    const unsigned long long v[] = {g->count, g->cols, g->rows, g->win_w, g->win_h,
                                    g->search_w, g->search_h, g->step_x, g->step_y,
                                    g->roi_x, g->roi_y, g->roi_w, g->roi_h};
    return ssdapy_struct_seq(grid_type, v, (Py_ssize_t)(sizeof v / sizeof v[0]));
}

static PyObject *stats_object(const ssda_track_stats_t *s)
{
    const unsigned long long v[] = {s->pixel_ops, s->positions, s->completed,
                                    s->check_pixels, s->windows, s->ok, s->excluded,
                                    s->masked, s->edge, s->flat, s->ambiguous, s->at_limit};
    return ssdapy_struct_seq(stats_type, v, (Py_ssize_t)(sizeof v / sizeof v[0]));
}

PyObject *ssdapy_track_vectors(const ssda_track_grid_t *g, ssda_track_vector_t **data)
{
    const Py_ssize_t shape[2] = {g->rows, g->cols};
    PyObject *a = ssdapy_np_empty(2, shape, vector_dtype);
    if (a == NULL) {
        return NULL;
    }
    *data = ssdapy_np_data(a);
    if (*data == NULL) {
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

PyObject *ssdapy_track_result(PyObject *vectors, const ssda_track_grid_t *g,
                              const ssda_track_stats_t *s)
{
    PyObject *o = PyStructSequence_New(result_type), *go, *so;
    if (o == NULL) {
        return NULL;
    }
    go = grid_object(g);
    so = stats_object(s);
    if (go == NULL || so == NULL) {
        Py_XDECREF(go);
        Py_XDECREF(so);
        Py_DECREF(o);
        return NULL;
    }
    Py_INCREF(vectors);
    PyStructSequence_SET_ITEM(o, 0, vectors);
    PyStructSequence_SET_ITEM(o, 1, go);
    PyStructSequence_SET_ITEM(o, 2, so);
    return o;
}

static const ssdapy_name_t predicts[] = {
    {"median", SSDA_TRACK_PREDICT_MEDIAN}, {"left", SSDA_TRACK_PREDICT_LEFT},
    {"none", SSDA_TRACK_PREDICT_NONE}, {NULL, 0}};

/* Take one optional option with a parser; absent or None keeps the default. */
#define TAKE(name, parse)                                                    \
    do {                                                                     \
        PyObject *v_ = ssdapy_kw_take(kw, name);                             \
        int rc_ = 0;                                                         \
        if (v_ != NULL) {                                                    \
            rc_ = (parse);                                                   \
            Py_DECREF(v_);                                                   \
        }                                                                    \
        if (rc_ != 0) {                                                      \
            return -1;                                                       \
        }                                                                    \
    } while (0)

static int parse_roi(PyObject *v, ssda_track_config_t *cfg)
{
    PyObject *seq = PySequence_Fast(v, "roi must be (x, y, width, height)");
    unsigned long long r[4];
    Py_ssize_t i;
    int rc = 0;
    if (seq == NULL) {
        return -1;
    }
    if (PySequence_Fast_GET_SIZE(seq) != 4) {
        PyErr_SetString(PyExc_ValueError, "roi must be (x, y, width, height)");
        rc = -1;
    }
    for (i = 0; i < 4 && rc == 0; i++) {
        rc = ssdapy_uint(PySequence_Fast_GET_ITEM(seq, i), "roi", i < 2 ? 0 : 1, 65535u,
                         &r[i]);
    }
    Py_DECREF(seq);
    if (rc == 0) {
        cfg->roi_x = (uint16_t)r[0];
        cfg->roi_y = (uint16_t)r[1];
        cfg->roi_w = (uint16_t)r[2];
        cfg->roi_h = (uint16_t)r[3];
    }
    return rc;
}

static int parse_flag(PyObject *v, uint8_t *flags, uint8_t bit)
{
    int b = PyObject_IsTrue(v);
    if (b < 0) {
        return -1;
    }
    *flags = (uint8_t)(b ? (*flags | bit) : (*flags & ~bit));
    return 0;
}

static int parse_u(PyObject *v, const char *name, unsigned long long hi, void *dst, int bytes)
{
    unsigned long long u;
    if (ssdapy_uint(v, name, 0, hi, &u) != 0) {
        return -1;
    }
    if (bytes == 1) {
        *(uint8_t *)dst = (uint8_t)u;
    } else if (bytes == 2) {
        *(uint16_t *)dst = (uint16_t)u;
    } else {
        *(uint32_t *)dst = (uint32_t)u;
    }
    return 0;
}

static int parse_predict(PyObject *v, uint8_t *dst)
{
    int e;
    if (ssdapy_enum(v, "predict", predicts, &e) != 0) {
        return -1;
    }
    *dst = (uint8_t)e;
    return 0;
}

static int parse_mask(PyObject *v, ssda_track_config_t *cfg)
{
    if (parse_u(v, "mask_value", 65535u, &cfg->mask_value, 2) != 0) {
        return -1;
    }
    cfg->flags |= SSDA_TRACK_MASK;
    return 0;
}

/* The quality options (issue 15), as the ssda tool has them: flat test and
   sub-pixel fit on, uniqueness on in the exact modes (dropped in the others
   unless unique=True is given, which the library then refuses). */
static int quality_options(PyObject *kw, ssda_track_config_t *cfg, int *unique_given)
{
    uint8_t on = SSDA_TRACK_UNIQUE, flat = 1, sub = 1;
    PyObject *u = ssdapy_kw_take(kw, "unique");
    if (u != NULL) {
        int rc = parse_flag(u, &on, SSDA_TRACK_UNIQUE);
        *unique_given = PyObject_IsTrue(u) == 1;
        Py_DECREF(u);
        if (rc != 0) {
            return -1;
        }
    }
    cfg->flags |= on;
    TAKE("flat", parse_flag(v_, &flat, 1));
    TAKE("subpixel", parse_flag(v_, &sub, 1));
    cfg->flags |= (uint8_t)((flat ? 0u : SSDA_TRACK_NO_FLAT) | (sub ? 0u : SSDA_TRACK_NO_SUBPIXEL));
    TAKE("flat_q8", parse_u(v_, "flat_q8", 65535u * 256u, &cfg->flat_q8, 4));
    TAKE("unique_q8", parse_u(v_, "unique_q8", 1024u, &cfg->unique_q8, 2));
    TAKE("unique_radius", parse_u(v_, "unique_radius", 2u, &cfg->unique_radius, 1));
    return 0;
}

int ssdapy_track_options(PyObject *kw, ssda_track_config_t *cfg)
{
    int unique_given = 0;
    const ssda_match_config_t *m = &cfg->match;
    memset(cfg, 0, sizeof *cfg);
    cfg->predict = SSDA_TRACK_PREDICT_MEDIAN;
    if (quality_options(kw, cfg, &unique_given) != 0) {
        return -1;
    }
    TAKE("window", ssdapy_size2(v_, "window", 1, 65535u, &cfg->win_w, &cfg->win_h));
    TAKE("search", ssdapy_size2(v_, "search", 1, 65535u, &cfg->search_w, &cfg->search_h));
    TAKE("step", ssdapy_size2(v_, "step", 1, 65535u, &cfg->step_x, &cfg->step_y));
    TAKE("roi", parse_roi(v_, cfg));
    TAKE("predict", parse_predict(v_, &cfg->predict));
    TAKE("exclude", parse_flag(v_, &cfg->flags, SSDA_TRACK_EXCLUDE));
    TAKE("texture_threshold", parse_u(v_, "texture_threshold", 65535u,
                                      &cfg->texture_threshold, 2));
    TAKE("texture_min_count", parse_u(v_, "texture_min_count", 0xFFFFFFFFu,
                                      &cfg->texture_min_count, 4));
    TAKE("mask_value", parse_mask(v_, cfg));
    if (ssdapy_match_options(kw, &cfg->match, 0) != 0) {
        return -1;
    }
    if (!unique_given && (m->scan == SSDA_SCAN_COARSE || (m->threshold != SSDA_THRESHOLD_AUTO &&
                                                           m->threshold != SSDA_THRESHOLD_NONE))) {
        cfg->flags &= (uint8_t)~SSDA_TRACK_UNIQUE; /* the default, not in this mode */
    }
    return 0;
}

int ssdapy_track_work(ssda_track_config_t *cfg, const ssda_track_grid_t *g, void **work)
{
    *work = NULL;
    if ((cfg->match.flags & SSDA_MATCH_BOUNDS) == 0u && (cfg->flags & SSDA_TRACK_UNIQUE) == 0u) {
        return 0;
    }
    /* the bounds tables and the uniqueness list; PyMem's blocks are
       aligned for 8-byte values */
    cfg->match.work_size = SSDA_TRACK_WORK_SIZE(g->search_w, g->search_h, g->win_w, g->win_h);
    if ((*work = PyMem_Malloc(cfg->match.work_size)) == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    cfg->match.work = *work;
    return 0;
}

static PyObject *py_track(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc = NULL, *vec = NULL, *out = NULL;
    ssdapy_image_t first, second;
    ssda_track_config_t cfg;
    ssda_track_grid_t g;
    ssda_track_stats_t stats;
    ssda_track_vector_t *v = NULL;
    void *work = NULL;
    int e;
    (void)self;
    if (ssdapy_args(args, "track", 2, 2, a) != 0 ||
        ssdapy_image_get(a[0], "first", &first) != 0) {
        return NULL;
    }
    if (ssdapy_image_get(a[1], "second", &second) != 0) {
        ssdapy_image_release(&first);
        return NULL;
    }
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || ssdapy_track_options(kwc, &cfg) != 0 ||
        ssdapy_kw_done(kwc, "track") != 0) {
        goto done;
    }
    e = ssda_track_grid(&cfg, second.view.width, second.view.height, &g);
    if (e != SSDA_OK) {
        ssdapy_error(e, "ssda_track_grid");
        goto done;
    }
    if (ssdapy_track_work(&cfg, &g, &work) != 0) {
        goto done;
    }
    if ((vec = ssdapy_track_vectors(&g, &v)) == NULL) {
        goto done;
    }
    SSDAPY_NOGIL(e = ssda_track(&first.view, &second.view, &cfg, v, g.count, &stats));
    out = e == SSDA_OK ? ssdapy_track_result(vec, &g, &stats) : ssdapy_error(e, "ssda_track");
done:
    Py_XDECREF(vec);
    Py_XDECREF(kwc);
    PyMem_Free(work);
    ssdapy_image_release(&first);
    ssdapy_image_release(&second);
    return out;
}

static PyObject *py_track_grid(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc, *out = NULL;
    unsigned long long w, h;
    ssda_track_config_t cfg;
    ssda_track_grid_t g;
    int e;
    (void)self;
    if (ssdapy_args(args, "track_grid", 2, 2, a) != 0 ||
        ssdapy_uint(a[0], "width", 0, 65535u, &w) != 0 ||
        ssdapy_uint(a[1], "height", 0, 65535u, &h) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (ssdapy_track_options(kwc, &cfg) == 0 && ssdapy_kw_done(kwc, "track_grid") == 0) {
        e = ssda_track_grid(&cfg, (uint16_t)w, (uint16_t)h, &g);
        out = e == SSDA_OK ? grid_object(&g) : ssdapy_error(e, "ssda_track_grid");
    }
    Py_DECREF(kwc);
    return out;
}

#define TRACK_OPTS                                                                    \
    "window=16, search=None, step=None, roi=None, predict='median', exclude=False, "  \
    "texture_threshold=0, texture_min_count=0, mask_value=None, threshold='auto', "   \
    "scan='raster', order='rows', bounds=True, k_q8=0, lambda_q8=0, flat=True, "      \
    "unique=None, subpixel=True, flat_q8=0, unique_q8=0, unique_radius=0, "           \
    "fixed_threshold=0, coarse_step=0"

static PyMethodDef methods[] = {
    {"track", (PyCFunction)(void (*)(void))py_track, METH_VARARGS | METH_KEYWORDS,
     "track(first, second, /, *, " TRACK_OPTS ")\n--\n\n"
     "Motion vectors on a grid of windows of second, each searched in the area of\n"
     "first centred on it (ssda_track, ssda/track.h). first and second are 2-D uint8\n"
     "or uint16 arrays of one dtype. Returns TrackResult(vectors, grid, stats):\n"
     "vectors is a (rows, cols) structured array with fields sad, dx, dy (motion\n"
     "from first to second, px), sub_dx_q8, sub_dy_q8 (sub-pixel motion, 1/256 px),\n"
     "texture_q8 (the window's mean absolute deviation, 1/256), x, y (window\n"
     "top-left in second), unique_q8 (ambiguous windows: second-best SAD over\n"
     "best, 1/256; else MATCH_UNIQUE_NONE), status (TRACK_OK, TRACK_FLAT,\n"
     "TRACK_AMBIGUOUS, TRACK_AT_LIMIT, TRACK_EXCLUDED, TRACK_MASKED, TRACK_EDGE;\n"
     "trust TRACK_OK vectors) and exact. flat, unique, subpixel: the quality\n"
     "tests (on, as in the ssda tool; unique only in the exact modes unless\n"
     "given); flat_q8, unique_q8, unique_radius: their levels (0 = the library's\n"
     "defaults 320, 282, 2).\n"
     "window, search, step: N or (w, h) (defaults 16, twice the window, the\n"
     "window); roi: (x, y, w, h) of second; predict: 'median' (default), 'left'\n"
     "(the seed's) or 'none'; exclude: skip textureless windows (texture_threshold,\n"
     "texture_min_count; 0 = the library's defaults); mask_value: windows or areas\n"
     "holding it are TRACK_MASKED; search options as in match (no predict=).\n"
     "The GIL is released while tracking."},
    {"track_grid", (PyCFunction)(void (*)(void))py_track_grid, METH_VARARGS | METH_KEYWORDS,
     "track_grid(width, height, /, *, " TRACK_OPTS ")\n--\n\n"
     "The Grid that track would lay on a second image of width x height pixels\n"
     "(ssda_track_grid)."},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_track(PyObject *m)
{
    static const char *const names[] = {"sad", "dx", "dy", "sub_dx_q8", "sub_dy_q8",
                                        "texture_q8", "x", "y", "unique_q8", "status",
                                        "exact"};
    static const char *const formats[] = {"u8", "i4", "i4", "i4", "i4", "u4",
                                          "u2", "u2", "u2", "u1", "?"};
    static const size_t offsets[] = {
        offsetof(ssda_track_vector_t, sad), offsetof(ssda_track_vector_t, dx),
        offsetof(ssda_track_vector_t, dy), offsetof(ssda_track_vector_t, sub_dx_q8),
        offsetof(ssda_track_vector_t, sub_dy_q8), offsetof(ssda_track_vector_t, texture_q8),
        offsetof(ssda_track_vector_t, x), offsetof(ssda_track_vector_t, y),
        offsetof(ssda_track_vector_t, unique_q8), offsetof(ssda_track_vector_t, status),
        offsetof(ssda_track_vector_t, exact)};
    _Static_assert(sizeof(bool) == 1, "numpy '?' is one byte");
    grid_type = ssdapy_struct_type(m, "ssda.Grid", "A tracking grid (ssda_track_grid_t).",
                                   grid_fields, 13);
    stats_type = ssdapy_struct_type(m, "ssda.TrackStats",
                                    "Totals over one tracking call (ssda_track_stats_t).",
                                    stats_fields, 12);
    result_type = ssdapy_struct_type(m, "ssda.TrackResult",
                                     "Result of track / stream_track.", result_fields, 3);
    if (grid_type == NULL || stats_type == NULL || result_type == NULL) {
        return -1;
    }
    vector_dtype = ssdapy_np_struct_dtype(11, names, formats, offsets,
                                          sizeof(ssda_track_vector_t));
    if (vector_dtype == NULL) {
        return -1;
    }
    Py_INCREF(vector_dtype);
    if (PyModule_AddObject(m, "TRACK_VECTOR_DTYPE", vector_dtype) != 0 ||
        PyModule_AddIntConstant(m, "TRACK_OK", SSDA_TRACK_OK) != 0 ||
        PyModule_AddIntConstant(m, "TRACK_EXCLUDED", SSDA_TRACK_EXCLUDED) != 0 ||
        PyModule_AddIntConstant(m, "TRACK_MASKED", SSDA_TRACK_MASKED) != 0 ||
        PyModule_AddIntConstant(m, "TRACK_EDGE", SSDA_TRACK_EDGE) != 0 ||
        PyModule_AddIntConstant(m, "TRACK_FLAT", SSDA_TRACK_FLAT) != 0 ||
        PyModule_AddIntConstant(m, "TRACK_AMBIGUOUS", SSDA_TRACK_AMBIGUOUS) != 0 ||
        PyModule_AddIntConstant(m, "TRACK_AT_LIMIT", SSDA_TRACK_AT_LIMIT) != 0 ||
        PyModule_AddIntConstant(m, "MATCH_UNIQUE_NONE", SSDA_MATCH_UNIQUE_NONE) != 0) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
