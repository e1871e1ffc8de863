/* bind_shape.c - shape matching (seed 001): ssda.contour (ssda_loops_contour),
   ssda.fd (ssda_fd_compute), ssda.fd_match and ssda.fd_match_fixed
   (ssda/fourier.h). Descriptors are records of FD_DTYPE, ssda_fd_t's
   layout, so arrays of them go to ssda.symreg as they are. */
#include "ssdapy.h"
#include "ssda/fourier.h"
#include "ssda/loops.h"

#include <stddef.h>

PyObject *ssdapy_fd_dtype;
static PyTypeObject *contour_type, *fd_match_type;

static PyStructSequence_Field contour_fields[] = {
    {"points", "(samples, 2) int32 array: x, y of each sample, Q8 px (pixel centres at "
               "multiples of 256), counter-clockwise on screen"},
    {"perimeter_q8", "length of the outer boundary, Q8 px"},
    {NULL, NULL}};

static PyStructSequence_Field fd_match_fields[] = {
    {"s_q16", "scale b / a, Q16"},
    {"phi", "rotation a -> b, turns (2**32 per turn), from +x towards +y"},
    {"alpha", "start shift, turns: b's first sample is a's point alpha / 2**32 round"},
    {"e2_q16", "E^2, the seed's normalised error, Q16 (0 identical)"},
    {"s", "s_q16 / 65536"},
    {"phi_deg", "phi in degrees, -180 < phi_deg <= 180"},
    {"alpha_turns", "alpha / 2**32"},
    {"e2", "e2_q16 / 65536"},
    {NULL, NULL}};

double ssdapy_turns_deg(uint32_t turns); /* shared with bind_symreg.c */

double ssdapy_turns_deg(uint32_t turns)
{
    const double d = turns * (360.0 / 4294967296.0); /* as the ssda tool prints it */
    return d > 180.0 ? d - 360.0 : d;
}

/* The first nonzero pixel of a mask in raster order; -1 if none. */
static int first_pixel(const ssda_view_t *v, uint16_t *x, uint16_t *y)
{
    uint32_t r, c;
    for (r = 0; r < v->height; r++) {
        const uint8_t *row = ssda_view_row(v, r);
        for (c = 0; c < v->width; c++) {
            if (row[c] != 0u) {
                *x = (uint16_t)c;
                *y = (uint16_t)r;
                return 0;
            }
        }
    }
    return -1;
}

static PyObject *py_contour(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc = NULL, *start = NULL, *pts = NULL, *out = NULL;
    ssdapy_image_t mask;
    ssda_loops_config_t lc; /* only for its samples field's range */
    uint16_t x = 0, y = 0;
    uint32_t perimeter = 0;
    void *data;
    int e;
    static const ssdapy_field_t fields[] = {
        {"samples", offsetof(ssda_loops_config_t, samples), 2, 0, 65535}, {NULL, 0, 0, 0, 0}};
    (void)self;
    if (ssdapy_args(args, "contour", 1, 1, a) != 0 || ssdapy_image_get(a[0], "mask", &mask) != 0) {
        return NULL;
    }
    memset(&lc, 0, sizeof lc);
    lc.samples = SSDA_LOOPS_DEFAULT_SAMPLES;
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || ssdapy_fields(kwc, &lc, fields) != 0) {
        goto done;
    }
    start = ssdapy_kw_take(kwc, "start");
    if (ssdapy_kw_done(kwc, "contour") != 0) {
        goto done;
    }
    if (start != NULL) {
        if (ssdapy_size2(start, "start", 0, 65535u, &x, &y) != 0) {
            goto done;
        }
    } else if (mask.view.format == SSDA_PIX_U8 && first_pixel(&mask.view, &x, &y) != 0) {
        PyErr_SetString(PyExc_ValueError, "mask has no nonzero pixel");
        goto done;
    }
    {
        const Py_ssize_t shape[2] = {lc.samples, 2};
        PyObject *dt = PyUnicode_FromString("int32");
        pts = dt != NULL ? ssdapy_np_empty(2, shape, dt) : NULL;
        Py_XDECREF(dt);
    }
    if (pts == NULL || (data = ssdapy_np_data(pts)) == NULL) {
        goto done;
    }
    SSDAPY_NOGIL(e = ssda_loops_contour(&mask.view, x, y, lc.samples, data, &perimeter));
    if (e != SSDA_OK) {
        ssdapy_error(e, "ssda_loops_contour");
        goto done;
    }
    if ((out = PyStructSequence_New(contour_type)) != NULL) {
        Py_INCREF(pts);
        PyStructSequence_SET_ITEM(out, 0, pts);
        PyStructSequence_SET_ITEM(out, 1, PyLong_FromUnsignedLong(perimeter));
        if (PyErr_Occurred()) {
            Py_CLEAR(out);
        }
    }
done:
    Py_XDECREF(pts);
    Py_XDECREF(start);
    Py_XDECREF(kwc);
    ssdapy_image_release(&mask);
    return out;
}

/* An int32 array of shape (n, 2) or (k, n, 2), C-contiguous (copied into
   one if not). */
static int get_points(PyObject *o, Py_buffer *b, PyObject **contig, Py_ssize_t *k,
                      Py_ssize_t *n)
{
    PyObject *np, *arr;
    *contig = NULL;
    np = PyImport_ImportModule("numpy");
    if (np == NULL) {
        return -1;
    }
    arr = PyObject_CallMethod(np, "ascontiguousarray", "O", o);
    Py_DECREF(np);
    if (arr == NULL) {
        return -1;
    }
    if (PyObject_GetBuffer(arr, b, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) != 0) {
        Py_DECREF(arr);
        return -1;
    }
    if (!(b->itemsize == 4 && b->format != NULL &&
          (strcmp(b->format, "i") == 0 || strcmp(b->format, "=i") == 0 ||
           strcmp(b->format, "<i") == 0 || (strcmp(b->format, "l") == 0)))) {
        PyErr_Format(PyExc_TypeError, "points must be an int32 array (Q8 px), got format '%s'",
                     b->format != NULL ? b->format : "?");
    } else if ((b->ndim != 2 && b->ndim != 3) || b->shape[b->ndim - 1] != 2) {
        PyErr_SetString(PyExc_ValueError, "points must have shape (n, 2) or (k, n, 2)");
    } else {
        *k = b->ndim == 3 ? b->shape[0] : 1;
        *n = b->shape[b->ndim - 2];
        *contig = arr;
        return 0;
    }
    PyBuffer_Release(b);
    Py_DECREF(arr);
    return -1;
}

static PyObject *py_fd(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc, *contig = NULL, *out = NULL;
    Py_buffer b;
    Py_ssize_t k = 0, n = 0, i;
    unsigned long long order = 0;
    ssda_fd_t *fds;
    int e = SSDA_OK;
    (void)self;
    if (ssdapy_args(args, "fd", 1, 1, a) != 0 || (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return NULL;
    }
    {
        PyObject *v = ssdapy_kw_take(kwc, "order");
        int rc = v != NULL ? ssdapy_uint(v, "order", 0, 0xFFFFFFFFu, &order) : 0;
        Py_XDECREF(v);
        if (rc != 0 || ssdapy_kw_done(kwc, "fd") != 0) {
            Py_DECREF(kwc);
            return NULL;
        }
    }
    Py_DECREF(kwc);
    if (get_points(a[0], &b, &contig, &k, &n) != 0) {
        return NULL;
    }
    {
        const Py_ssize_t shape[1] = {k};
        out = ssdapy_np_empty(b.ndim == 3 ? 1 : 0, shape, ssdapy_fd_dtype);
    }
    if (out == NULL || (fds = ssdapy_np_data(out)) == NULL) {
        Py_CLEAR(out);
        goto done;
    }
    if ((unsigned long long)n > 0xFFFFFFFFull) {
        n = 0; /* the library refuses n = 0 as out of range */
    }
    Py_BEGIN_ALLOW_THREADS
    for (i = 0; i < k && e == SSDA_OK; i++) {
        e = ssda_fd_compute((const ssda_point_q8_t *)b.buf + i * n, (uint32_t)n,
                            (uint32_t)order, &fds[i]);
    }
    Py_END_ALLOW_THREADS
    if (e != SSDA_OK) {
        Py_CLEAR(out);
        ssdapy_error(e, "ssda_fd_compute");
    }
done:
    PyBuffer_Release(&b);
    Py_DECREF(contig);
    return out;
}

/* One descriptor record (a 0-d or 1-element FD_DTYPE array, or one entry). */
static int get_fd(PyObject *o, const char *what, ssda_fd_t *fd)
{
    Py_buffer b;
    Py_ssize_t count;
    if (ssdapy_records(o, what, ssdapy_fd_dtype, &b, &count) != 0) {
        return -1;
    }
    if (count != 1) {
        PyBuffer_Release(&b);
        PyErr_Format(PyExc_ValueError, "%s must be one descriptor, got %zd", what, count);
        return -1;
    }
    memcpy(fd, b.buf, sizeof *fd);
    PyBuffer_Release(&b);
    return 0;
}

static PyObject *match_object(const ssda_fd_match_t *m)
{
    PyObject *o = PyStructSequence_New(fd_match_type);
    if (o == NULL) {
        return NULL;
    }
    PyStructSequence_SET_ITEM(o, 0, PyLong_FromUnsignedLong(m->s_q16));
    PyStructSequence_SET_ITEM(o, 1, PyLong_FromUnsignedLong(m->phi));
    PyStructSequence_SET_ITEM(o, 2, PyLong_FromUnsignedLong(m->alpha));
    PyStructSequence_SET_ITEM(o, 3, PyLong_FromUnsignedLong(m->e2_q16));
    PyStructSequence_SET_ITEM(o, 4, PyFloat_FromDouble(m->s_q16 / 65536.0));
    PyStructSequence_SET_ITEM(o, 5, PyFloat_FromDouble(ssdapy_turns_deg(m->phi)));
    PyStructSequence_SET_ITEM(o, 6, PyFloat_FromDouble(m->alpha / 4294967296.0));
    PyStructSequence_SET_ITEM(o, 7, PyFloat_FromDouble(m->e2_q16 / 65536.0));
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

static PyObject *py_fd_match(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[4];
    ssda_fd_t fa, fb;
    ssda_fd_match_t m;
    unsigned long long s = 0, phi = 0;
    int fixed, e;
    (void)self;
    if (kw != NULL && PyDict_Size(kw) != 0) {
        ssdapy_kw_done(kw, "fd_match");
        return NULL;
    }
    if (ssdapy_args(args, "fd_match", 2, 4, a) != 0) {
        return NULL;
    }
    fixed = a[2] != NULL;
    if ((fixed && a[3] == NULL) || get_fd(a[0], "a", &fa) != 0 || get_fd(a[1], "b", &fb) != 0 ||
        (fixed && (ssdapy_uint(a[2], "s_q16", 0, 0xFFFFFFFFu, &s) != 0 ||
                   ssdapy_uint(a[3], "phi", 0, 0xFFFFFFFFu, &phi) != 0))) {
        if (!PyErr_Occurred()) {
            PyErr_SetString(PyExc_TypeError, "fd_match(a, b) or fd_match(a, b, s_q16, phi)");
        }
        return NULL;
    }
    if (fixed) {
        SSDAPY_NOGIL(e = ssda_fd_match_fixed(&fa, &fb, (uint32_t)s, (uint32_t)phi, &m));
    } else {
        SSDAPY_NOGIL(e = ssda_fd_match(&fa, &fb, &m));
    }
    return e == SSDA_OK ? match_object(&m)
                        : ssdapy_error(e, fixed ? "ssda_fd_match_fixed" : "ssda_fd_match");
}

static PyMethodDef methods[] = {
    {"contour", (PyCFunction)(void (*)(void))py_contour, METH_VARARGS | METH_KEYWORDS,
     "contour(mask, /, *, start=None, samples=64)\n--\n\n"
     "The outer boundary of a set of pixels, resampled (ssda_loops_contour,\n"
     "ssda/loops.h): the 8-connected set of nonzero pixels of the 2-D uint8 mask\n"
     "that holds start=(x, y), which must be the set's first pixel in raster order\n"
     "(default: the mask's first nonzero pixel). samples: a power of two, 8..1024.\n"
     "Returns Contour(points, perimeter_q8); points (samples, 2) int32, Q8 px."},
    {"fd", (PyCFunction)(void (*)(void))py_fd, METH_VARARGS | METH_KEYWORDS,
     "fd(points, /, *, order=0)\n--\n\n"
     "Fourier descriptors a_1..a_order, a_-1..a_-order of a contour (ssda_fd_compute,\n"
     "ssda/fourier.h): points (n, 2) int32 Q8 px, n a power of two 8..1024, or\n"
     "(k, n, 2) for k contours. order: 1..16, below n / 2 (0 = 10, the seed's).\n"
     "Returns a record (0-d array) or k records of FD_DTYPE (ssda_fd_t)."},
    {"fd_match", (PyCFunction)(void (*)(void))py_fd_match, METH_VARARGS | METH_KEYWORDS,
     "fd_match(a, b, s_q16=None, phi=None, /)\n--\n\n"
     "The scale s, rotation phi and start shift alpha taking descriptor a to b and\n"
     "their error E^2 (ssda_fd_match); with s_q16 and phi given, the best alpha for\n"
     "them (ssda_fd_match_fixed). Returns FdMatch (the library's integers and\n"
     "s, phi_deg, alpha_turns, e2 as floats)."},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_shape(PyObject *m)
{
    static const char *const names[] = {"pos", "neg", "energy_q16", "order"};
    static const char *const formats[] = {"(16,2)i4", "(16,2)i4", "u8", "u4"};
    static const size_t offsets[] = {offsetof(ssda_fd_t, pos), offsetof(ssda_fd_t, neg),
                                     offsetof(ssda_fd_t, energy_q16),
                                     offsetof(ssda_fd_t, order)};
    _Static_assert(SSDA_FD_MAX_ORDER == 16u, "FD_DTYPE's (16,2) arrays");
    contour_type = ssdapy_struct_type(m, "ssda.Contour", "Result of contour.",
                                      contour_fields, 2);
    fd_match_type = ssdapy_struct_type(m, "ssda.FdMatch",
                                       "Result of fd_match (ssda_fd_match_t).", fd_match_fields,
                                       8);
    if (contour_type == NULL || fd_match_type == NULL) {
        return -1;
    }
    ssdapy_fd_dtype = ssdapy_np_struct_dtype(4, names, formats, offsets, sizeof(ssda_fd_t));
    if (ssdapy_fd_dtype == NULL) {
        return -1;
    }
    Py_INCREF(ssdapy_fd_dtype);
    if (PyModule_AddObject(m, "FD_DTYPE", ssdapy_fd_dtype) != 0) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
