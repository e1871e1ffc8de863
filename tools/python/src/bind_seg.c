/* bind_seg.c - seed 004: ssda.kl (ssda/kl.h: the K-L transform of a
   3-band image), ssda.mix_hist / mix_fit / mix_lut / mix_label /
   mix_band_pixels (ssda/mixture.h: Gaussian mixtures of a histogram) and
   ssda.region (ssda/region.h: isolated points, contours, counts), the
   library calls of `ssda segment`. */
#include "ssdapy.h"
#include "ssda/kl.h"
#include "ssda/mixture.h"
#include "ssda/region.h"

static PyObject *comp_dtype;
static PyTypeObject *kl_type, *model_type;

static PyStructSequence_Field kl_fields[] = {
    {"features", "(3, h, w) uint16: Z1, Z2, Z3 (KL_NODATA where masked); None with "
                 "features=False"},
    {"matrix_q30", "(3, 3) int32: the matrix diagonalised, Q30"},
    {"vec_q30", "(3, 3) int32: row k the unit eigenvector of eigenvalue k, Q30"},
    {"lambda_q16", "(3,) uint64: eigenvalues, decreasing, Q16"},
    {"zvar_q16", "(3,) uint64: variance of each Z over the counted pixels, Q16"},
    {"mean_q8", "(3,) uint32: band means, Q8"},
    {"count", "pixels counted"},
    {"masked", "nodata pixels skipped"},
    {"sweeps", "Jacobi sweeps run"},
    {"clamped", "feature values clamped to 0 or out_max"},
    {NULL, NULL}};

static PyStructSequence_Field model_fields[] = {
    {"components", "MIX_COMPONENT_DTYPE records sorted by mean: weight_q16, mean_q16, "
                   "sigma_q16 (bins Q16); label k + 1 is component k"},
    {"loglik_q16", "sum over bins of h(z) ln p(z), nats Q16"},
    {"bic_q16", "-2 loglik + (3 count - 1) ln(total), nats Q16"},
    {"count", "components"},
    {"bins", "histogram bins"},
    {"total", "pixels in the histogram"},
    {"iterations", "EM iterations or search cycles of the final fit"},
    {"fit", "'em' or 'search'"},
    {NULL, NULL}};

static const ssdapy_name_t kl_matrices[] = {
    {"correlation", SSDA_KL_CORRELATION}, {"covariance", SSDA_KL_COVARIANCE}, {NULL, 0}};
static const ssdapy_name_t kl_ranges[] = {
    {"sigma", SSDA_KL_RANGE_SIGMA}, {"full", SSDA_KL_RANGE_FULL}, {NULL, 0}};
static const ssdapy_name_t mix_fits[] = {
    {"em", SSDA_MIX_FIT_EM}, {"search", SSDA_MIX_FIT_SEARCH}, {NULL, 0}};
static const ssdapy_name_t mix_inits[] = {
    {"peaks", SSDA_MIX_INIT_PEAKS}, {"quantiles", SSDA_MIX_INIT_QUANTILES}, {NULL, 0}};
static const ssdapy_name_t mix_rules[] = {
    {"band", SSDA_MIX_LABEL_BAND}, {"likely", SSDA_MIX_LABEL_LIKELY}, {NULL, 0}};
static const ssdapy_name_t region_ops[] = {
    {"clean", SSDA_REGION_CLEAN}, {"contour", SSDA_REGION_CONTOUR}, {NULL, 0}};

static const ssdapy_field_t kl_cfg_fields[] = {
    {"nsigma", offsetof(ssda_kl_config_t, nsigma), 1, 0, 255},
    {"out_max", offsetof(ssda_kl_config_t, out_max), 2, 0, 65535},
    {"gain_max_q16", offsetof(ssda_kl_config_t, gain_max_q16), 4, 0, 0xFFFFFFFFll},
    {NULL, 0, 0, 0, 0}};
static const ssdapy_field_t mix_cfg_fields[] = {
    {"components", offsetof(ssda_mix_config_t, components), 1, 0, 255},
    {"max_components", offsetof(ssda_mix_config_t, max_components), 1, 0, 255},
    {"max_iter", offsetof(ssda_mix_config_t, max_iter), 2, 0, 65535},
    {"sigma_min_q16", offsetof(ssda_mix_config_t, sigma_min_q16), 4, 0, 0xFFFFFFFFll},
    {"tol_q24", offsetof(ssda_mix_config_t, tol_q24), 4, 0, 0xFFFFFFFFll},
    {NULL, 0, 0, 0, 0}};



/* A numpy array of n values of dtype from C values. */
static PyObject *array_of(const void *v, Py_ssize_t n, size_t item, const char *dtype,
                          int ndim, const Py_ssize_t *shape)
{
    PyObject *a = ssdapy_np_typed(ndim, shape, dtype);
    void *d;
    if (a == NULL || (d = ssdapy_np_data(a)) == NULL) {
        Py_XDECREF(a);
        return NULL;
    }
    memcpy(d, v, (size_t)n * item);
    return a;
}

/* ---- kl ---- */

/* A (h, w, 3 or 4) uint8 / uint16 image read through its strides: a pixel
   stride that is a positive multiple of the sample size is a view, anything
   else a C-contiguous copy (numpy.ascontiguousarray). */
typedef struct {
    Py_buffer b;
    int have;
    PyObject *copy;
    uint8_t format; /* SSDA_PIX_U8 / _U16 */
} bands_t;

static int bands_get(PyObject *o, bands_t *s)
{
    const char *f;
    s->have = 0;
    s->copy = NULL;
    if (PyObject_GetBuffer(o, &s->b, PyBUF_RECORDS_RO) != 0) {
        PyErr_SetString(PyExc_TypeError, "image must be an (h, w, 3) uint8 or uint16 array");
        return -1;
    }
    s->have = 1;
    f = s->b.format != NULL ? s->b.format : "B";
    f += (*f == '<' || *f == '=' || *f == '@') ? 1 : 0;
    if (!((f[0] == 'B' && s->b.itemsize == 1) || (f[0] == 'H' && s->b.itemsize == 2)) ||
        f[1] != '\0') {
        PyErr_Format(PyExc_TypeError, "image must be uint8 or uint16, not format '%s'", f);
        return -1;
    }
    if (s->b.ndim != 3 || (s->b.shape[2] != 3 && s->b.shape[2] != 4)) {
        PyErr_SetString(PyExc_ValueError, "image must be (h, w, 3) or (h, w, 4)");
        return -1;
    }
    if (s->b.shape[0] < 1 || s->b.shape[1] < 1 || s->b.shape[0] > 65535 || s->b.shape[1] > 65535) {
        PyErr_SetString(PyExc_ValueError, "image sides must be 1..65535");
        return -1;
    }
    s->format = s->b.itemsize == 1 ? (uint8_t)SSDA_PIX_U8 : (uint8_t)SSDA_PIX_U16;
    if (s->b.strides[1] <= 0 || s->b.strides[1] % s->b.itemsize != 0 ||
        s->b.strides[2] % s->b.itemsize != 0 || s->b.strides[0] % s->b.itemsize != 0) {
        PyObject *np = PyImport_ImportModule("numpy");
        s->copy = np != NULL ? PyObject_CallMethod(np, "ascontiguousarray", "O", o) : NULL;
        Py_XDECREF(np);
        PyBuffer_Release(&s->b);
        s->have = 0;
        if (s->copy == NULL || PyObject_GetBuffer(s->copy, &s->b, PyBUF_RECORDS_RO) != 0) {
            return -1;
        }
        s->have = 1;
        ssdapy.copies++;
    }
    return 0;
}

static void bands_release(bands_t *s)
{
    if (s->have) {
        PyBuffer_Release(&s->b);
    }
    Py_XDECREF(s->copy);
}

static void bands_row(const bands_t *s, Py_ssize_t y, ssda_kl_row_t *row)
{
    const char *p = (const char *)s->b.buf + y * s->b.strides[0];
    int k;
    for (k = 0; k < 3; k++) {
        row->band[k] = p + k * s->b.strides[2];
    }
    row->step = (uint32_t)(s->b.strides[1] / s->b.itemsize);
}

typedef struct {
    ssda_kl_acc_config_t ac;
    ssda_kl_config_t kc;
    ssda_kl_acc_t acc;
    ssda_kl_t kl;
    uint16_t *feat; /* (3, h, w) or NULL */
    uint32_t clamped;
    const char *failed;
} kl_job_t;

/* Accumulate, solve, transform (no Python calls: runs without the GIL). */
static int kl_run(const bands_t *s, kl_job_t *j)
{
    const Py_ssize_t h = s->b.shape[0], w = s->b.shape[1];
    ssda_kl_row_t row;
    Py_ssize_t y;
    int e;
    j->failed = "ssda_kl_acc_init";
    if ((e = ssda_kl_acc_init(&j->acc, &j->ac)) != SSDA_OK) {
        return e;
    }
    j->failed = "ssda_kl_acc_add_row";
    for (y = 0; y < h; y++) {
        bands_row(s, y, &row);
        if ((e = ssda_kl_acc_add_row(&j->acc, &row, (uint32_t)w)) != SSDA_OK) {
            return e;
        }
    }
    j->failed = "ssda_kl_solve";
    if ((e = ssda_kl_solve(&j->acc, &j->kc, &j->kl)) != SSDA_OK) {
        return e;
    }
    j->failed = "ssda_kl_transform_row";
    for (y = 0; j->feat != NULL && y < h; y++) {
        uint16_t *const out[3] = {j->feat + (size_t)y * (size_t)w,
                                  j->feat + ((size_t)h + (size_t)y) * (size_t)w,
                                  j->feat + (2u * (size_t)h + (size_t)y) * (size_t)w};
        bands_row(s, y, &row);
        if ((e = ssda_kl_transform_row(&j->kl, &row, (uint32_t)w, out, &j->clamped)) != SSDA_OK) {
            return e;
        }
    }
    return SSDA_OK;
}

static int kl_options(PyObject *kw, kl_job_t *j, int *features)
{
    PyObject *v;
    unsigned long long nd;
    memset(j, 0, sizeof *j);
    *features = 1;
    if (ssdapy_fields(kw, &j->kc, kl_cfg_fields) != 0 ||
        ssdapy_kw_enum(kw, "matrix", kl_matrices, &j->kc.matrix) != 0 ||
        ssdapy_kw_enum(kw, "range", kl_ranges, &j->kc.range) != 0) {
        return -1;
    }
    if ((v = ssdapy_kw_take(kw, "nodata")) != NULL) {
        int rc = v == Py_None ? 0 : ssdapy_uint(v, "nodata", 0, 65535, &nd);
        if (rc == 0 && v != Py_None) {
            j->ac.nodata = (uint16_t)nd;
            j->ac.flags = SSDA_KL_MASK_NODATA;
        }
        Py_DECREF(v);
        if (rc != 0) {
            return -1;
        }
    }
    if ((v = ssdapy_kw_take(kw, "features")) != NULL) {
        *features = PyObject_IsTrue(v);
        Py_DECREF(v);
        if (*features < 0) {
            return -1;
        }
    }
    return 0;
}

static PyObject *kl_object(const kl_job_t *j, PyObject *feat)
{
    static const Py_ssize_t s33[2] = {3, 3}, s3[1] = {3};
    PyObject *o = PyStructSequence_New(kl_type);
    if (o == NULL) {
        return NULL;
    }
    if (feat == NULL) {
        feat = Py_None;
    }
    Py_INCREF(feat);
    PyStructSequence_SET_ITEM(o, 0, feat);
    PyStructSequence_SET_ITEM(o, 1, array_of(j->kl.matrix_q30, 9, 4, "int32", 2, s33));
    PyStructSequence_SET_ITEM(o, 2, array_of(j->kl.vec_q30, 9, 4, "int32", 2, s33));
    PyStructSequence_SET_ITEM(o, 3, array_of(j->kl.lambda_q16, 3, 8, "uint64", 1, s3));
    PyStructSequence_SET_ITEM(o, 4, array_of(j->kl.zvar_q16, 3, 8, "uint64", 1, s3));
    PyStructSequence_SET_ITEM(o, 5, array_of(j->kl.mean_q8, 3, 4, "uint32", 1, s3));
    PyStructSequence_SET_ITEM(o, 6, PyLong_FromUnsignedLong(j->kl.count));
    PyStructSequence_SET_ITEM(o, 7, PyLong_FromUnsignedLong(j->acc.masked));
    PyStructSequence_SET_ITEM(o, 8, PyLong_FromUnsignedLong(j->kl.sweeps));
    PyStructSequence_SET_ITEM(o, 9, PyLong_FromUnsignedLong(j->clamped));
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

static PyObject *py_kl(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc = NULL, *feat = NULL, *out = NULL;
    bands_t s = {0};
    kl_job_t j;
    int features, e;
    (void)self;
    if (ssdapy_args(args, "kl", 1, 1, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL ||
        kl_options(kwc, &j, &features) != 0 || ssdapy_kw_done(kwc, "kl") != 0 ||
        bands_get(a[0], &s) != 0) {
        goto done;
    }
    j.ac.format = s.format;
    if (features) {
        const Py_ssize_t shape[3] = {3, s.b.shape[0], s.b.shape[1]};
        if ((feat = ssdapy_np_typed(3, shape, "uint16")) == NULL ||
            (j.feat = ssdapy_np_data(feat)) == NULL) {
            goto done;
        }
    }
    SSDAPY_NOGIL(e = kl_run(&s, &j));
    out = e == SSDA_OK ? kl_object(&j, feat) : ssdapy_error(e, j.failed);
done:
    Py_XDECREF(feat);
    Py_XDECREF(kwc);
    bands_release(&s);
    return out;
}

/* ---- mixtures ---- */

/* A 1-D contiguous array of dtype format f (item n bytes) as a buffer. */
static int flat_get(PyObject *o, const char *what, char f, Py_ssize_t n, Py_buffer *b)
{
    const char *fmt;
    if (PyObject_GetBuffer(o, b, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) != 0) {
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "%s must be a C-contiguous array", what);
        return -1;
    }
    fmt = b->format != NULL ? b->format : "B";
    fmt += (*fmt == '<' || *fmt == '=' || *fmt == '@') ? 1 : 0;
    if (b->itemsize != n || !(fmt[0] == f || (f == 'I' && fmt[0] == 'L' && n == 4)) ||
        fmt[1] != '\0') {
        PyErr_Format(PyExc_TypeError, "%s must be %s, not format '%s'", what,
                     f == 'H' ? "uint16" : f == 'I' ? "uint32" : "uint8", fmt);
        PyBuffer_Release(b);
        return -1;
    }
    return 0;
}

static PyObject *py_mix_hist(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc, *v, *hist = NULL, *out = NULL;
    unsigned long long bins = 1024, shift = 0;
    uint32_t skipped = 0, *h;
    Py_buffer b;
    int e, have = 0;
    (void)self;
    if (ssdapy_args(args, "mix_hist", 1, 1, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if ((v = ssdapy_kw_take(kwc, "bins")) != NULL) {
        e = ssdapy_uint(v, "bins", 1, SSDA_MIX_MAX_BINS, &bins);
        Py_DECREF(v);
        if (e != 0) {
            goto done;
        }
    }
    if ((v = ssdapy_kw_take(kwc, "shift")) != NULL) {
        e = ssdapy_uint(v, "shift", 0, 15, &shift);
        Py_DECREF(v);
        if (e != 0) {
            goto done;
        }
    }
    if (ssdapy_kw_done(kwc, "mix_hist") != 0 || flat_get(a[0], "values", 'H', 2, &b) != 0) {
        goto done;
    }
    have = 1;
    if ((size_t)(b.len / 2) > 0xFFFFFFFFu) {
        PyErr_SetString(PyExc_ValueError, "values: at most 2**32 - 1");
        goto done;
    }
    {
        const Py_ssize_t shape[1] = {(Py_ssize_t)bins};
        if ((hist = ssdapy_np_typed(1, shape, "uint32")) == NULL || (h = ssdapy_np_data(hist)) == NULL) {
            goto done;
        }
    }
    memset(h, 0, (size_t)bins * 4u);
    SSDAPY_NOGIL(e = ssda_mix_hist_add(h, (uint32_t)bins, b.buf, (uint32_t)(b.len / 2),
                                       (uint32_t)shift, &skipped));
    out = e == SSDA_OK ? Py_BuildValue("(OI)", hist, skipped) : ssdapy_error(e, "ssda_mix_hist_add");
done:
    if (have) {
        PyBuffer_Release(&b);
    }
    Py_XDECREF(hist);
    Py_DECREF(kwc);
    return out;
}

static PyObject *model_object(const ssda_mix_model_t *m)
{
    const Py_ssize_t shape[1] = {(Py_ssize_t)m->count};
    PyObject *o = PyStructSequence_New(model_type), *c;
    void *d;
    if (o == NULL) {
        return NULL;
    }
    c = ssdapy_np_empty(1, shape, comp_dtype);
    if (c == NULL || (d = ssdapy_np_data(c)) == NULL) {
        Py_XDECREF(c);
        Py_DECREF(o);
        return NULL;
    }
    memcpy(d, m->comp, (size_t)m->count * sizeof m->comp[0]);
    PyStructSequence_SET_ITEM(o, 0, c);
    PyStructSequence_SET_ITEM(o, 1, PyLong_FromLongLong(m->loglik_q16));
    PyStructSequence_SET_ITEM(o, 2, PyLong_FromLongLong(m->bic_q16));
    PyStructSequence_SET_ITEM(o, 3, PyLong_FromUnsignedLong(m->count));
    PyStructSequence_SET_ITEM(o, 4, PyLong_FromUnsignedLong(m->bins));
    PyStructSequence_SET_ITEM(o, 5, PyLong_FromUnsignedLong(m->total));
    PyStructSequence_SET_ITEM(o, 6, PyLong_FromUnsignedLong(m->iterations));
    PyStructSequence_SET_ITEM(o, 7,
                              PyUnicode_FromString(m->fit == SSDA_MIX_FIT_EM ? "em" : "search"));
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

/* A MixModel back into the C struct (the fields the look-ups read). */
static int model_get(PyObject *o, ssda_mix_model_t *m)
{
    Py_buffer b;
    Py_ssize_t n;
    unsigned long long v[3];
    int i;
    if (!PyObject_TypeCheck(o, model_type)) {
        PyErr_SetString(PyExc_TypeError, "model must be a MixModel (from mix_fit)");
        return -1;
    }
    memset(m, 0, sizeof *m);
    for (i = 0; i < 3; i++) {
        if (ssdapy_uint(PyStructSequence_GET_ITEM(o, 3 + i), "model field", 0, 0xFFFFFFFFull,
                        &v[i]) != 0) {
            return -1;
        }
    }
    if (ssdapy_records(PyStructSequence_GET_ITEM(o, 0), "model.components", comp_dtype, &b,
                       &n) != 0) {
        return -1;
    }
    if (n != (Py_ssize_t)v[0] || n > (Py_ssize_t)SSDA_MIX_MAX_COMPONENTS) {
        PyBuffer_Release(&b);
        PyErr_SetString(PyExc_ValueError, "model.components must have model.count records");
        return -1;
    }
    memcpy(m->comp, b.buf, (size_t)n * sizeof m->comp[0]);
    PyBuffer_Release(&b);
    m->count = (uint32_t)v[0];
    m->bins = (uint32_t)v[1];
    m->total = (uint32_t)v[2];
    return 0;
}

static PyObject *py_mix_fit(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc, *out = NULL;
    ssda_mix_config_t cfg;
    ssda_mix_model_t m;
    Py_buffer b;
    void *work = NULL;
    size_t ws;
    int e, have = 0;
    (void)self;
    memset(&cfg, 0, sizeof cfg);
    if (ssdapy_args(args, "mix_fit", 1, 1, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (ssdapy_fields(kwc, &cfg, mix_cfg_fields) != 0 ||
        ssdapy_kw_enum(kwc, "fit", mix_fits, &cfg.fit) != 0 ||
        ssdapy_kw_enum(kwc, "init", mix_inits, &cfg.init) != 0 ||
        ssdapy_flag(kwc, "seed_steps", &cfg.flags, SSDA_MIX_SEED_STEPS) != 0 ||
        ssdapy_kw_done(kwc, "mix_fit") != 0 || flat_get(a[0], "hist", 'I', 4, &b) != 0) {
        goto done;
    }
    have = 1;
    ws = SSDA_MIX_WORK_SIZE(b.len / 4 < SSDA_MIX_MAX_BINS ? (size_t)(b.len / 4) : SSDA_MIX_MAX_BINS);
    if ((work = PyMem_Malloc(ws)) == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    SSDAPY_NOGIL(e = ssda_mix_fit(b.buf, (uint32_t)(b.len / 4 > 0xFFFF ? 0xFFFF : b.len / 4), &cfg,
                                  work, ws, &m));
    out = e == SSDA_OK ? model_object(&m) : ssdapy_error(e, "ssda_mix_fit");
done:
    PyMem_Free(work);
    if (have) {
        PyBuffer_Release(&b);
    }
    Py_DECREF(kwc);
    return out;
}

/* (model) and rule / band_q8 keywords. */
static int band_opts(PyObject *kw, uint8_t *rule, unsigned long long *band)
{
    PyObject *v;
    *band = 0;
    if (rule != NULL && ssdapy_kw_enum(kw, "rule", mix_rules, rule) != 0) {
        return -1;
    }
    if ((v = ssdapy_kw_take(kw, "band_q8")) != NULL) {
        int rc = ssdapy_uint(v, "band_q8", 0, 0xFFFFFFFFull, band);
        Py_DECREF(v);
        return rc;
    }
    return 0;
}

static PyObject *py_mix_lut(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc, *lut = NULL, *out = NULL;
    ssda_mix_model_t m;
    unsigned long long band;
    uint8_t rule = SSDA_MIX_LABEL_BAND, *l;
    int e;
    (void)self;
    if (ssdapy_args(args, "mix_lut", 1, 1, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (band_opts(kwc, &rule, &band) != 0 || ssdapy_kw_done(kwc, "mix_lut") != 0 ||
        model_get(a[0], &m) != 0) {
        goto done;
    }
    {
        const Py_ssize_t shape[1] = {(Py_ssize_t)(m.bins > 0u ? m.bins : 1u)};
        if ((lut = ssdapy_np_typed(1, shape, "uint8")) == NULL || (l = ssdapy_np_data(lut)) == NULL) {
            goto done;
        }
    }
    e = ssda_mix_lut(&m, rule, (uint32_t)band, l);
    if (e == SSDA_OK) {
        Py_INCREF(lut);
        out = lut;
    } else {
        ssdapy_error(e, "ssda_mix_lut");
    }
done:
    Py_XDECREF(lut);
    Py_DECREF(kwc);
    return out;
}

static PyObject *py_mix_band_pixels(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc, *out = NULL;
    ssda_mix_model_t m;
    unsigned long long band;
    uint32_t px[SSDA_MIX_MAX_COMPONENTS];
    Py_buffer b;
    int e, have = 0;
    (void)self;
    if (ssdapy_args(args, "mix_band_pixels", 2, 2, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (band_opts(kwc, NULL, &band) != 0 || ssdapy_kw_done(kwc, "mix_band_pixels") != 0 ||
        model_get(a[0], &m) != 0 || flat_get(a[1], "hist", 'I', 4, &b) != 0) {
        goto done;
    }
    have = 1;
    if (b.len / 4 != (Py_ssize_t)m.bins) {
        PyErr_Format(PyExc_ValueError, "hist must have model.bins (%u) bins", m.bins);
        goto done;
    }
    e = ssda_mix_band_pixels(&m, b.buf, (uint32_t)band, px);
    if (e == SSDA_OK) {
        const Py_ssize_t shape[1] = {(Py_ssize_t)m.count};
        out = array_of(px, (Py_ssize_t)m.count, 4, "uint32", 1, shape);
    } else {
        ssdapy_error(e, "ssda_mix_band_pixels");
    }
done:
    if (have) {
        PyBuffer_Release(&b);
    }
    Py_DECREF(kwc);
    return out;
}

static PyObject *py_mix_label(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc, *v, *lab = NULL, *out = NULL;
    unsigned long long shift = 0;
    Py_buffer bv, bl;
    int e, hv = 0, hl = 0;
    (void)self;
    if (ssdapy_args(args, "mix_label", 2, 2, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if ((v = ssdapy_kw_take(kwc, "shift")) != NULL) {
        e = ssdapy_uint(v, "shift", 0, 15, &shift);
        Py_DECREF(v);
        if (e != 0) {
            goto done;
        }
    }
    if (ssdapy_kw_done(kwc, "mix_label") != 0 || flat_get(a[0], "values", 'H', 2, &bv) != 0) {
        goto done;
    }
    hv = 1;
    if (flat_get(a[1], "lut", 'B', 1, &bl) != 0) {
        goto done;
    }
    hl = 1;
    if (bv.len / 2 > 0xFFFFFFFF || bl.len < 1 || bl.len > (Py_ssize_t)SSDA_MIX_MAX_BINS) {
        PyErr_SetString(PyExc_ValueError, "lut must have 1..4096 entries");
        goto done;
    }
    {
        Py_ssize_t shape[8], i, nd = bv.ndim > 0 ? bv.ndim : 1;
        uint8_t *l;
        for (i = 0; i < nd && i < 8; i++) {
            shape[i] = bv.ndim > 0 ? bv.shape[i] : 1;
        }
        if ((lab = ssdapy_np_typed((int)(nd < 8 ? nd : 8), shape, "uint8")) == NULL ||
            (l = ssdapy_np_data(lab)) == NULL) {
            goto done;
        }
        SSDAPY_NOGIL(e = ssda_mix_label_row(bl.buf, (uint32_t)bl.len, bv.buf,
                                            (uint32_t)(bv.len / 2), (uint32_t)shift, l));
    }
    if (e == SSDA_OK) {
        Py_INCREF(lab);
        out = lab;
    } else {
        ssdapy_error(e, "ssda_mix_label_row");
    }
done:
    if (hv) {
        PyBuffer_Release(&bv);
    }
    if (hl) {
        PyBuffer_Release(&bl);
    }
    Py_XDECREF(lab);
    Py_DECREF(kwc);
    return out;
}

/* ---- region ---- */

typedef struct {
    const uint8_t *in;
    uint8_t *out, *ring;
    uint32_t *counts;
    uint16_t w, h;
    uint8_t op;
} region_job_t;

static int region_run(const region_job_t *r)
{
    ssda_region_config_t rc;
    ssda_region_t job;
    uint32_t y, done = 0;
    int e;
    rc.width = r->w;
    rc.height = r->h;
    rc.op = r->op;
    rc.counts = r->counts;
    if ((e = ssda_region_init(&job, &rc, r->ring, SSDA_REGION_RING_SIZE(r->w))) != SSDA_OK) {
        return e;
    }
    for (y = 0; y < r->h; y++) {
        e = ssda_region_push(&job, r->in + (size_t)y * r->w, r->out + (size_t)done * r->w);
        if (e < 0) {
            return e;
        }
        done += (uint32_t)e;
    }
    e = ssda_region_flush(&job, r->out + (size_t)done * r->w);
    return e < 0 ? e : SSDA_OK;
}

static PyObject *py_region(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc, *res = NULL, *cnt = NULL, *out = NULL;
    ssdapy_image_t img;
    region_job_t r;
    int e, with_counts = 0, have = 0;
    (void)self;
    memset(&r, 0, sizeof r);
    if (ssdapy_args(args, "region", 1, 1, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    if (ssdapy_kw_enum(kwc, "op", region_ops, &r.op) != 0) {
        goto done;
    }
    {
        PyObject *v = ssdapy_kw_take(kwc, "counts");
        if (v != NULL) {
            with_counts = PyObject_IsTrue(v);
            Py_DECREF(v);
            if (with_counts < 0) {
                goto done;
            }
        }
    }
    if (ssdapy_kw_done(kwc, "region") != 0 || ssdapy_image_get(a[0], "labels", &img) != 0) {
        goto done;
    }
    have = 1;
    if (img.view.format != SSDA_PIX_U8) {
        PyErr_SetString(PyExc_TypeError, "labels must be uint8");
        goto done;
    }
    r.w = img.view.width;
    r.h = img.view.height;
    {
        const Py_ssize_t shape[2] = {r.h, r.w}, s256[1] = {256};
        if ((res = ssdapy_np_typed(2, shape, "uint8")) == NULL ||
            (r.out = ssdapy_np_data(res)) == NULL ||
            (with_counts && ((cnt = ssdapy_np_typed(1, s256, "uint32")) == NULL ||
                             (r.counts = ssdapy_np_data(cnt)) == NULL))) {
            goto done;
        }
    }
    if (r.counts != NULL) {
        memset(r.counts, 0, 256u * 4u);
    }
    /* the library reads rows: a packed copy when the view's rows are apart */
    if (img.view.stride != r.w) {
        uint8_t *p = PyMem_Malloc((size_t)r.w * r.h);
        uint32_t y;
        if (p == NULL) {
            PyErr_NoMemory();
            goto done;
        }
        for (y = 0; y < r.h; y++) {
            memcpy(p + (size_t)y * r.w, (const uint8_t *)img.view.data + (size_t)y * img.view.stride,
                   r.w);
        }
        r.in = p;
    } else {
        r.in = img.view.data;
    }
    if ((r.ring = PyMem_Malloc(SSDA_REGION_RING_SIZE(r.w))) == NULL) {
        PyErr_NoMemory();
    } else {
        SSDAPY_NOGIL(e = region_run(&r));
        if (e != SSDA_OK) {
            ssdapy_error(e, "ssda_region_push");
        } else if (with_counts) {
            out = Py_BuildValue("(OO)", res, cnt);
        } else {
            Py_INCREF(res);
            out = res;
        }
    }
    PyMem_Free(r.ring);
    if (r.in != img.view.data) {
        PyMem_Free((void *)r.in);
    }
done:
    if (have) {
        ssdapy_image_release(&img);
    }
    Py_XDECREF(res);
    Py_XDECREF(cnt);
    Py_DECREF(kwc);
    return out;
}

static PyMethodDef methods[] = {
    {"kl", (PyCFunction)(void (*)(void))py_kl, METH_VARARGS | METH_KEYWORDS,
     "kl(image, /, *, matrix='correlation', range='sigma', nsigma=4, out_max=1023, "
     "gain_max_q16=4096*65536, nodata=None, features=True)\n--\n\n"
     "The Karhunen-Loeve transform of a 3-band image (seed 004; ssda/kl.h):\n"
     "statistics accumulated exactly (ssda_kl_acc_add_row), eigenvectors by\n"
     "fixed-point Jacobi (ssda_kl_solve), and the feature images Z1..Z3\n"
     "(ssda_kl_transform_row). image: (h, w, 3) or (h, w, 4) uint8 or uint16 (the\n"
     "fourth channel ignored), read in place through its strides. nodata: pixels\n"
     "whose three samples all equal it are skipped and written KL_NODATA.\n"
     "Returns a KlResult; the GIL is released."},
    {"mix_hist", (PyCFunction)(void (*)(void))py_mix_hist, METH_VARARGS | METH_KEYWORDS,
     "mix_hist(values, /, *, bins=1024, shift=0)\n--\n\n"
     "Histogram of uint16 values (any C-contiguous shape): hist[v >> shift] += 1\n"
     "(ssda_mix_hist_add). Returns (hist uint32 array of bins, skipped)."},
    {"mix_fit", (PyCFunction)(void (*)(void))py_mix_fit, METH_VARARGS | METH_KEYWORDS,
     "mix_fit(hist, /, *, components=0, max_components=8, fit='em', init='peaks', "
     "seed_steps=False, max_iter=500, sigma_min_q16=32768, tol_q24=1024)\n--\n\n"
     "Gaussian mixture of a uint32 histogram (ssda_mix_fit, ssda/mixture.h):\n"
     "components 0 chooses K by BIC; fit 'em' or 'search' (the seed's). Returns a\n"
     "MixModel. The binding allocates the work buffer; the GIL is released."},
    {"mix_lut", (PyCFunction)(void (*)(void))py_mix_lut, METH_VARARGS | METH_KEYWORDS,
     "mix_lut(model, /, *, rule='band', band_q8=512)\n--\n\n"
     "Label of every bin (ssda_mix_lut): uint8 array of model.bins; 0 = none."},
    {"mix_label", (PyCFunction)(void (*)(void))py_mix_label, METH_VARARGS | METH_KEYWORDS,
     "mix_label(values, lut, /, *, shift=0)\n--\n\n"
     "lut[v >> shift] for uint16 values (ssda_mix_label_row; 0 beyond the lut):\n"
     "a uint8 array of values' shape."},
    {"mix_band_pixels", (PyCFunction)(void (*)(void))py_mix_band_pixels,
     METH_VARARGS | METH_KEYWORDS,
     "mix_band_pixels(model, hist, /, *, band_q8=512)\n--\n\n"
     "Pixels of hist within band_q8 / 256 sigmas of each component\n"
     "(ssda_mix_band_pixels): uint32 array of model.count."},
    {"region", (PyCFunction)(void (*)(void))py_region, METH_VARARGS | METH_KEYWORDS,
     "region(labels, /, *, op='clean', counts=False)\n--\n\n"
     "Isolated-point removal ('clean') or contour pixels ('contour') of a 2-D\n"
     "uint8 label image (ssda_region_*, streamed by rows). Returns the output\n"
     "labels, or (labels, counts) with counts=True (uint32 per label, 256)."},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_seg(PyObject *m)
{
    static const char *const names[] = {"weight_q16", "mean_q16", "sigma_q16"};
    static const char *const formats[] = {"u4", "u4", "u4"};
    static const size_t offsets[] = {offsetof(ssda_mix_component_t, weight_q16),
                                     offsetof(ssda_mix_component_t, mean_q16),
                                     offsetof(ssda_mix_component_t, sigma_q16)};
    kl_type = ssdapy_struct_type(m, "ssda.KlResult", "Result of kl (ssda_kl_t).", kl_fields, 10);
    model_type = ssdapy_struct_type(m, "ssda.MixModel", "A fitted mixture (ssda_mix_model_t).",
                                    model_fields, 8);
    comp_dtype = ssdapy_np_struct_dtype(3, names, formats, offsets, sizeof(ssda_mix_component_t));
    if (kl_type == NULL || model_type == NULL || comp_dtype == NULL) {
        return -1;
    }
    Py_INCREF(comp_dtype);
    if (PyModule_AddObject(m, "MIX_COMPONENT_DTYPE", comp_dtype) != 0 ||
        PyModule_AddIntConstant(m, "KL_NODATA", SSDA_KL_NODATA) != 0) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
