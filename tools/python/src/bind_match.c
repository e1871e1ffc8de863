/* bind_match.c - ssda.match, ssda.sad_at (ssda/match.h), the search options
   shared by every search-based call, and the MatchResult type. */
#include "ssdapy.h"

static PyTypeObject *match_result_type;

static PyStructSequence_Field match_result_fields[] = {
    {"x", "best top-left column in the area, px"},
    {"y", "best top-left row in the area, px"},
    {"sad", "sum of absolute differences there, full (an all-cut fallback's too)"},
    {"exact", "True: (x, y, sad) is the true minimum by the tie rule"},
    {"pixel_ops", "absolute differences computed, plus bound work"},
    {"positions", "position evaluations"},
    {"completed", "positions summed over all pixels"},
    {NULL, NULL}};

PyObject *ssdapy_match_result(const ssda_match_result_t *r)
{
    PyObject *o = PyStructSequence_New(match_result_type);
    if (o == NULL) {
        return NULL;
    }
    PyStructSequence_SET_ITEM(o, 0, PyLong_FromUnsignedLong(r->x));
    PyStructSequence_SET_ITEM(o, 1, PyLong_FromUnsignedLong(r->y));
    PyStructSequence_SET_ITEM(o, 2, PyLong_FromUnsignedLongLong(r->sad));
    PyStructSequence_SET_ITEM(o, 3, PyBool_FromLong(r->exact));
    PyStructSequence_SET_ITEM(o, 4, PyLong_FromUnsignedLongLong(r->pixel_ops));
    PyStructSequence_SET_ITEM(o, 5, PyLong_FromUnsignedLong(r->positions));
    PyStructSequence_SET_ITEM(o, 6, PyLong_FromUnsignedLong(r->completed));
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

static const ssdapy_name_t thresholds[] = {
    {"auto", SSDA_THRESHOLD_AUTO},   {"none", SSDA_THRESHOLD_NONE},
    {"fixed", SSDA_THRESHOLD_FIXED}, {"ramp", SSDA_THRESHOLD_RAMP},
    {"auto_ramp", SSDA_THRESHOLD_AUTO_RAMP}, {NULL, 0}};
static const ssdapy_name_t scans[] = {
    {"raster", SSDA_SCAN_RASTER}, {"predict", SSDA_SCAN_PREDICT},
    {"coarse", SSDA_SCAN_COARSE}, {NULL, 0}};
static const ssdapy_name_t orders[] = {
    {"rows", SSDA_ORDER_ROWS}, {"spread", SSDA_ORDER_SPREAD}, {NULL, 0}};


static int take_uint(PyObject *kw, const char *name, unsigned long long hi,
                     unsigned long long *dst)
{
    PyObject *v = ssdapy_kw_take(kw, name);
    int rc = 0;
    if (v != NULL) {
        rc = ssdapy_uint(v, name, 0, hi, dst);
        Py_DECREF(v);
    }
    return rc;
}

int ssdapy_match_options(PyObject *kw, ssda_match_config_t *cfg, int allow_predict)
{
    unsigned long long k = 0, lambda = 0, fixed = 0, step = 0;
    PyObject *v;
    PyObject *scan = PyDict_GetItemString(kw, "scan"); /* borrowed */
    int scan_given = scan != NULL && scan != Py_None;
    memset(cfg, 0, sizeof *cfg);
    cfg->flags = SSDA_MATCH_BOUNDS; /* exact either way; less work on a host */
    if (ssdapy_kw_enum(kw, "threshold", thresholds, &cfg->threshold) != 0 ||
        ssdapy_kw_enum(kw, "scan", scans, &cfg->scan) != 0 ||
        ssdapy_kw_enum(kw, "order", orders, &cfg->order) != 0 ||
        take_uint(kw, "k_q8", 65535u, &k) != 0 ||
        take_uint(kw, "lambda_q8", 0xFFFFFFFFu, &lambda) != 0 ||
        take_uint(kw, "fixed_threshold", UINT64_MAX, &fixed) != 0 ||
        take_uint(kw, "coarse_step", 65535u, &step) != 0) {
        return -1;
    }
    cfg->k_q8 = (uint16_t)k;
    cfg->lambda_q8 = (uint32_t)lambda;
    cfg->fixed_threshold = fixed;
    cfg->coarse_step = (uint16_t)step;
    if ((v = ssdapy_kw_take(kw, "bounds")) != NULL) {
        int b = PyObject_IsTrue(v);
        Py_DECREF(v);
        if (b < 0) {
            return -1;
        }
        if (!b) {
            cfg->flags = 0;
        }
    }
    if (allow_predict) {
        const int got = ssdapy_kw_xy(kw, "predict", &cfg->predict_x, &cfg->predict_y);
        if (got < 0) {
            return -1;
        }
        if (got > 0 && !scan_given) {
            cfg->scan = SSDA_SCAN_PREDICT;
        }
    }
    return 0;
}

/* Parse (area, window, options) and check the two images. */
static int search_args(PyObject *args, PyObject *kw, const char *func, Py_ssize_t extra,
                       ssdapy_image_t *area, ssdapy_image_t *win, PyObject **rest,
                       PyObject **kwc)
{
    PyObject *a[4];
    *kwc = NULL;
    if (ssdapy_args(args, func, 2 + extra, 2 + extra, a) != 0 ||
        ssdapy_image_get(a[0], "area", area) != 0) {
        return -1;
    }
    if (ssdapy_image_get(a[1], "window", win) != 0) {
        ssdapy_image_release(area);
        return -1;
    }
    if (extra > 0) {
        rest[0] = a[2];
        rest[1] = a[3];
    }
    if ((*kwc = ssdapy_kw_copy(kw)) == NULL) {
        ssdapy_image_release(area);
        ssdapy_image_release(win);
        return -1;
    }
    return 0;
}

/* blocks=None (default) is the ssda tool's choice: the block levels
   (SSDA_MATCH_BLOCKS) with the bounds under the AUTO threshold, where they
   change the work only; True asks for them anyway (the library refuses them
   without bounds: SSDA_ERR_ARG), False leaves them out. */
static int match_blocks(PyObject *kw, ssda_match_config_t *cfg)
{
    PyObject *v = ssdapy_kw_take(kw, "blocks");
    int on = (cfg->flags & SSDA_MATCH_BOUNDS) != 0u && cfg->threshold == SSDA_THRESHOLD_AUTO;
    if (v != NULL) {
        on = v == Py_None ? on : PyObject_IsTrue(v);
        Py_DECREF(v);
        if (on < 0) {
            return -1;
        }
    }
    if (on) {
        cfg->flags |= SSDA_MATCH_BLOCKS;
    }
    return 0;
}

/* The search runs in ssda_match_search with its state in one heap block
   with the bounds' work buffer (state first: PyMem_Malloc's alignment, and
   sizeof(ssda_match_state_t) a multiple of 8 keeps the work aligned too),
   as a firmware holds it in static storage: the same results as ssda_match,
   little C stack in each thread. */
static PyObject *py_match(PyObject *self, PyObject *args, PyObject *kw)
{
    ssdapy_image_t area, win;
    ssda_match_config_t cfg;
    ssda_match_result_t res;
    PyObject *kwc, *out = NULL;
    unsigned char *block = NULL;
    size_t work_size = 0;
    int e;
    (void)self;
    if (search_args(args, kw, "match", 0, &area, &win, NULL, &kwc) != 0) {
        return NULL;
    }
    if (ssdapy_match_options(kwc, &cfg, 1) != 0 || match_blocks(kwc, &cfg) != 0 ||
        ssdapy_kw_done(kwc, "match") != 0) {
        goto done;
    }
    if (win.view.width > area.view.width || win.view.height > area.view.height) {
        cfg.flags = 0; /* the library reports the size error */
    } else if ((cfg.flags & SSDA_MATCH_BLOCKS) != 0u) {
        work_size = SSDA_MATCH_WORK_SIZE_BLOCKS(area.view.width, area.view.height,
                                                win.view.width, win.view.height);
    } else if ((cfg.flags & SSDA_MATCH_BOUNDS) != 0u) {
        work_size = SSDA_MATCH_WORK_SIZE(area.view.width, area.view.height, win.view.width,
                                         win.view.height);
    }
    if ((block = PyMem_Malloc(sizeof(ssda_match_state_t) + work_size)) == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    if (work_size != 0) {
        cfg.work = block + sizeof(ssda_match_state_t);
        cfg.work_size = work_size;
    }
    SSDAPY_NOGIL(e = ssda_match_search((ssda_match_state_t *)(void *)block, &area.view,
                                       &win.view, &cfg, &res));
    out = e == SSDA_OK ? ssdapy_match_result(&res) : ssdapy_error(e, "ssda_match_search");
done:
    PyMem_Free(block);
    Py_DECREF(kwc);
    ssdapy_image_release(&area);
    ssdapy_image_release(&win);
    return out;
}

static PyObject *py_sad_at(PyObject *self, PyObject *args, PyObject *kw)
{
    ssdapy_image_t area, win;
    PyObject *kwc, *xy[2], *out = NULL;
    unsigned long long x, y;
    uint64_t sad = 0;
    int e;
    (void)self;
    if (search_args(args, kw, "sad_at", 2, &area, &win, xy, &kwc) != 0) {
        return NULL;
    }
    if (ssdapy_kw_done(kwc, "sad_at") != 0 || ssdapy_uint(xy[0], "x", 0, 65535u, &x) != 0 ||
        ssdapy_uint(xy[1], "y", 0, 65535u, &y) != 0) {
        goto done;
    }
    SSDAPY_NOGIL(e = ssda_sad_at(&area.view, &win.view, (uint16_t)x, (uint16_t)y, &sad));
    out = e == SSDA_OK ? PyLong_FromUnsignedLongLong(sad) : ssdapy_error(e, "ssda_sad_at");
done:
    Py_DECREF(kwc);
    ssdapy_image_release(&area);
    ssdapy_image_release(&win);
    return out;
}

static PyMethodDef methods[] = {
    {"match", (PyCFunction)(void (*)(void))py_match, METH_VARARGS | METH_KEYWORDS,
     "match(area, window, /, *, threshold='auto', scan='raster', order='rows', "
     "bounds=True, blocks=None, predict=None, k_q8=0, lambda_q8=0, fixed_threshold=0,\n"
     "coarse_step=0)\n"
     "--\n\n"
     "Where window fits best in area: ssda_match_search (ssda/match.h; the results of\n"
     "ssda_match, its state in the binding's memory). Both are 2-D uint8 or\n"
     "uint16 arrays of one dtype (viewed where possible, else copied). Returns a\n"
     "MatchResult (x, y, sad, exact, pixel_ops, positions, completed); x, y is the\n"
     "top-left of the best placement, ties to the smallest sad, then y, then x.\n"
     "threshold: 'auto' (exact), 'none' (brute force), 'fixed' (fixed_threshold),\n"
     "'ramp' (lambda_q8, k_q8), 'auto_ramp' (k_q8); scan: 'raster', 'predict'\n"
     "(rings around predict=(x, y), implied by predict), 'coarse' (coarse_step);\n"
     "order: 'rows' or 'spread'; bounds: successive-elimination bounds (exact\n"
     "either way; the binding allocates their work buffer); blocks: the multilevel\n"
     "block bounds too (SSDA_MATCH_BLOCKS; None: with bounds under 'auto', as the\n"
     "ssda tool; exact either way, less work on large windows; needs bounds).\n"
     "The GIL is released during the search."},
    {"sad_at", (PyCFunction)(void (*)(void))py_sad_at, METH_VARARGS | METH_KEYWORDS,
     "sad_at(area, window, x, y, /)\n--\n\n"
     "The full SAD of window placed with its top-left at (x, y) of area (ssda_sad_at)."},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_match(PyObject *m)
{
    match_result_type = ssdapy_struct_type(m, "ssda.MatchResult",
                                           "Outcome of one search (ssda_match_result_t).",
                                           match_result_fields, 7);
    if (match_result_type == NULL) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
