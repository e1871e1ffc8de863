/* common.c - the binding's shared helpers (ssdapy.h): errors, images and
   samples through the buffer protocol, argument parsing, numpy results. */
#include "ssdapy.h"

#include <stdio.h>
#include <string.h>

ssdapy_state_t ssdapy;

/* ---- errors ---- */

PyObject *ssdapy_error(int code, const char *func)
{
    PyObject *exc, *v;
    const char *msg = ssda_strerror(code);
    exc = PyObject_CallFunction(ssdapy.error, "N",
                                PyUnicode_FromFormat("%s: %s (code %d)", func, msg, code));
    if (exc == NULL) {
        return NULL;
    }
    if ((v = PyLong_FromLong(code)) == NULL || PyObject_SetAttrString(exc, "code", v) != 0) {
        goto done;
    }
    Py_DECREF(v);
    if ((v = PyUnicode_FromString(msg)) == NULL ||
        PyObject_SetAttrString(exc, "message", v) != 0) {
        goto done;
    }
    Py_DECREF(v);
    if ((v = PyUnicode_FromString(func)) == NULL ||
        PyObject_SetAttrString(exc, "function", v) != 0) {
        goto done;
    }
    PyErr_SetObject(ssdapy.error, exc);
done:
    Py_XDECREF(v);
    Py_DECREF(exc);
    return NULL;
}

/* ---- images ---- */

/* The dtype of obj for a message: str(obj.dtype), else the buffer format. */
static PyObject *dtype_name(PyObject *obj, const char *fmt)
{
    PyObject *d = PyObject_GetAttrString(obj, "dtype"), *s;
    if (d == NULL) {
        PyErr_Clear();
        return PyUnicode_FromFormat("format '%s'", fmt != NULL ? fmt : "B");
    }
    s = PyObject_Str(d);
    Py_DECREF(d);
    return s;
}

/* Item letter of a native-order buffer format ('B', 'H', 'h', ...), or 0 for
   a non-native byte order or a compound format. */
static char format_letter(const char *fmt)
{
    const unsigned probe = 1u;
    const int little = *(const unsigned char *)&probe == 1u;
    if (fmt == NULL) {
        return 'B'; /* PEP 3118: NULL means unsigned bytes */
    }
    if (*fmt == '@' || *fmt == '=') {
        fmt++;
    } else if (*fmt == '<' || *fmt == '>' || *fmt == '!') {
        int want_little = *fmt == '<';
        fmt++;
        if (want_little != little && *fmt != 'B' && *fmt != 'b') {
            return 0;
        }
    }
    if (fmt[0] == '\0' || fmt[1] != '\0') {
        return 0;
    }
    return fmt[0];
}

static int type_error(PyObject *obj, const char *what, const char *want, const char *fmt)
{
    PyObject *name = dtype_name(obj, fmt);
    if (name != NULL) {
        PyErr_Format(PyExc_TypeError, "%s must be %s, got dtype %U (convert it with "
                     ".astype() if its values fit)", what, want, name);
        Py_DECREF(name);
    }
    return -1;
}

/* Get a strided buffer of obj, or a TypeError naming what it should be. */
static int get_buffer(PyObject *obj, const char *what, const char *want, int flags,
                      Py_buffer *buf)
{
    if (!PyObject_CheckBuffer(obj)) {
        PyErr_Format(PyExc_TypeError, "%s must be %s (a numpy array), got %s", what, want,
                     Py_TYPE(obj)->tp_name);
        return -1;
    }
    if (PyObject_GetBuffer(obj, buf, flags) != 0) {
        if (PyErr_ExceptionMatches(PyExc_BufferError)) {
            PyErr_Clear();
            PyErr_Format(PyExc_TypeError, "%s must be %s%s, got a %s whose buffer does not "
                         "allow that", what, want, (flags & PyBUF_WRITABLE) ? " (writable)" : "",
                         Py_TYPE(obj)->tp_name);
        }
        return -1;
    }
    return 0;
}

/* Whether rows of w items of size b, rs bytes apart, at p, make a view the
   library takes: contiguous pixels, positive row stride a multiple of b and
   at least a row, within uint32_t, and uint16 data aligned. */
static int viewable(const Py_buffer *v, Py_ssize_t h, Py_ssize_t w, Py_ssize_t b,
                    Py_ssize_t *row_stride)
{
    Py_ssize_t rs = v->ndim == 2 ? v->strides[0] : w * b;
    Py_ssize_t cs = v->strides[v->ndim - 1];
    if (h == 1) {
        rs = w * b; /* the stride of a single row is never used */
    }
    if (w > 1 && cs != b) {
        return 0;
    }
    if (rs <= 0 || rs % b != 0 || rs < w * b || (unsigned long long)rs > 0xFFFFFFFFull) {
        return 0;
    }
    if (b == 2 && ((uintptr_t)v->buf & 1u) != 0u) {
        return 0;
    }
    *row_stride = rs;
    return 1;
}

/* Copy a strided h x w array of b-byte items into packed memory. */
static void *copy_strided(const Py_buffer *v, Py_ssize_t h, Py_ssize_t w, Py_ssize_t b)
{
    char *dst = PyMem_Malloc((size_t)(h * w * b > 0 ? h * w * b : 1));
    Py_ssize_t y, x;
    Py_ssize_t rs = v->ndim == 2 ? v->strides[0] : 0, cs = v->strides[v->ndim - 1];
    if (dst == NULL) {
        PyErr_NoMemory();
        return NULL;
    }
    ssdapy.copies++;
    for (y = 0; y < h; y++) {
        const char *row = (const char *)v->buf + y * rs;
        for (x = 0; x < w; x++) {
            memcpy(dst + (y * w + x) * b, row + x * cs, (size_t)b);
        }
    }
    return dst;
}

static int check_side(Py_ssize_t n, const char *what, const char *axis)
{
    if (n < 1 || n > (Py_ssize_t)SSDA_MAX_DIM) {
        PyErr_Format(PyExc_ValueError, "%s has %zd %s; 1..65535 are accepted", what, n, axis);
        return -1;
    }
    return 0;
}

static int image_setup(PyObject *obj, const char *what, int writable, ssdapy_image_t *img)
{
    static const char want[] = "a 2-D uint8 or uint16 array";
    Py_buffer *v = &img->buf;
    char letter;
    memset(img, 0, sizeof *img);
    if (get_buffer(obj, what, want, writable ? PyBUF_RECORDS : PyBUF_RECORDS_RO, v) != 0) {
        return -1;
    }
    img->have_buf = 1;
    letter = format_letter(v->format);
    if (!((letter == 'B' && v->itemsize == 1) || (letter == 'H' && v->itemsize == 2))) {
        type_error(obj, what, want, v->format);
        goto fail;
    }
    if (v->ndim != 2) {
        PyErr_Format(PyExc_ValueError, "%s must be 2-D (rows, columns), got %d dimension%s",
                     what, v->ndim, v->ndim == 1 ? "" : "s");
        goto fail;
    }
    if (check_side(v->shape[0], what, "rows") != 0 ||
        check_side(v->shape[1], what, "columns") != 0) {
        goto fail;
    }
    return 0;
fail:
    ssdapy_image_release(img);
    return -1;
}

int ssdapy_image_get(PyObject *obj, const char *what, ssdapy_image_t *img)
{
    Py_ssize_t h, w, b, rs;
    const void *data;
    if (image_setup(obj, what, 0, img) != 0) {
        return -1;
    }
    h = img->buf.shape[0];
    w = img->buf.shape[1];
    b = img->buf.itemsize;
    if (viewable(&img->buf, h, w, b, &rs)) {
        data = img->buf.buf;
    } else {
        img->copy = copy_strided(&img->buf, h, w, b);
        if (img->copy == NULL) {
            ssdapy_image_release(img);
            return -1;
        }
        data = img->copy;
        rs = w * b;
    }
    if (ssda_view_init(&img->view, data, (uint16_t)w, (uint16_t)h, (uint32_t)rs,
                       b == 1 ? SSDA_PIX_U8 : SSDA_PIX_U16) != SSDA_OK) {
        PyErr_Format(PyExc_ValueError, "%s: its memory layout cannot be viewed", what);
        ssdapy_image_release(img);
        return -1;
    }
    return 0;
}

int ssdapy_out_image_get(PyObject *obj, const char *what, uint8_t format, Py_ssize_t h,
                         Py_ssize_t w, ssdapy_image_t *img)
{
    Py_ssize_t rs;
    if (image_setup(obj, what, 1, img) != 0) {
        return -1;
    }
    if (img->buf.itemsize != (Py_ssize_t)format) {
        type_error(obj, what, format == 1 ? "a uint8 array" : "a uint16 array",
                   img->buf.format);
        goto fail;
    }
    if (img->buf.shape[0] != h || img->buf.shape[1] != w) {
        PyErr_Format(PyExc_ValueError, "%s must have shape (%zd, %zd), got (%zd, %zd)", what,
                     h, w, img->buf.shape[0], img->buf.shape[1]);
        goto fail;
    }
    if (!viewable(&img->buf, h, w, format, &rs)) {
        PyErr_Format(PyExc_ValueError, "%s must have contiguous rows (column stride = item "
                     "size, positive row stride a multiple of it, uint16 aligned): the "
                     "library writes into it directly", what);
        goto fail;
    }
    /* the view's fields describe the output; data is writable */
    img->view.data = img->buf.buf;
    img->view.width = (uint16_t)w;
    img->view.height = (uint16_t)h;
    img->view.stride = (uint32_t)rs;
    img->view.format = format;
    return 0;
fail:
    ssdapy_image_release(img);
    return -1;
}

void ssdapy_image_release(ssdapy_image_t *img)
{
    if (img->have_buf) {
        PyBuffer_Release(&img->buf);
        img->have_buf = 0;
    }
    PyMem_Free(img->copy);
    img->copy = NULL;
}

/* ---- samples ---- */

int ssdapy_samples_get(PyObject *obj, const char *what, ssdapy_samples_t *s)
{
    static const char want[] = "a 1-D int16 array";
    Py_buffer *v = &s->buf;
    memset(s, 0, sizeof *s);
    if (get_buffer(obj, what, want, PyBUF_RECORDS_RO, v) != 0) {
        return -1;
    }
    s->have_buf = 1;
    if (!(format_letter(v->format) == 'h' && v->itemsize == 2)) {
        type_error(obj, what, want, v->format);
        goto fail;
    }
    if (v->ndim != 1) {
        PyErr_Format(PyExc_ValueError, "%s must be 1-D (one channel), got %d dimensions; mix "
                     "or pick a channel first", what, v->ndim);
        goto fail;
    }
    s->count = (size_t)v->shape[0];
    if (s->count <= 1 || (v->strides[0] == 2 && ((uintptr_t)v->buf & 1u) == 0u)) {
        s->data = v->buf;
    } else {
        s->copy = copy_strided(v, 1, v->shape[0], 2);
        if (s->copy == NULL) {
            goto fail;
        }
        s->data = s->copy;
    }
    return 0;
fail:
    ssdapy_samples_release(s);
    return -1;
}

void ssdapy_samples_release(ssdapy_samples_t *s)
{
    if (s->have_buf) {
        PyBuffer_Release(&s->buf);
        s->have_buf = 0;
    }
    PyMem_Free(s->copy);
    s->copy = NULL;
}

/* ---- arguments ---- */

int ssdapy_uint(PyObject *o, const char *name, unsigned long long lo, unsigned long long hi,
                unsigned long long *out)
{
    long long v;
    if (ssdapy_int(o, name, (long long)lo, hi > (unsigned long long)LLONG_MAX ? LLONG_MAX
                                                                              : (long long)hi,
                   &v) == 0) {
        *out = (unsigned long long)v;
        return 0;
    }
    if (hi <= (unsigned long long)LLONG_MAX || !PyErr_ExceptionMatches(PyExc_ValueError)) {
        return -1;
    }
    /* above LLONG_MAX: only uint64 limits get here */
    PyErr_Clear();
    {
        PyObject *idx = PyNumber_Index(o);
        unsigned long long u;
        if (idx == NULL) {
            return -1;
        }
        u = PyLong_AsUnsignedLongLong(idx);
        Py_DECREF(idx);
        if (PyErr_Occurred() || u < lo || u > hi) {
            PyErr_Clear();
            PyErr_Format(PyExc_ValueError, "%s must be %llu..%llu, got %R", name, lo, hi, o);
            return -1;
        }
        *out = u;
    }
    return 0;
}

int ssdapy_int(PyObject *o, const char *name, long long lo, long long hi, long long *out)
{
    PyObject *idx;
    long long v;
    int overflow = 0;
    if (PyBool_Check(o) || PyFloat_Check(o)) {
        PyErr_Format(PyExc_TypeError, "%s must be an integer, got %s", name,
                     Py_TYPE(o)->tp_name);
        return -1;
    }
    idx = PyNumber_Index(o);
    if (idx == NULL) {
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "%s must be an integer, got %s", name,
                     Py_TYPE(o)->tp_name);
        return -1;
    }
    v = PyLong_AsLongLongAndOverflow(idx, &overflow);
    Py_DECREF(idx);
    if (v == -1 && PyErr_Occurred()) {
        return -1;
    }
    if (overflow != 0 || v < lo || v > hi) {
        PyErr_Format(PyExc_ValueError, "%s must be %lld..%lld, got %R", name, lo, hi, o);
        return -1;
    }
    *out = v;
    return 0;
}

int ssdapy_size2(PyObject *o, const char *name, unsigned lo, unsigned hi, uint16_t *w,
                 uint16_t *h)
{
    unsigned long long a, b;
    if (PyTuple_Check(o) || PyList_Check(o)) {
        PyObject *seq = PySequence_Fast(o, name);
        int rc = -1;
        if (seq == NULL) {
            return -1;
        }
        if (PySequence_Fast_GET_SIZE(seq) != 2) {
            PyErr_Format(PyExc_ValueError, "%s must be N or (width, height)", name);
        } else if (ssdapy_uint(PySequence_Fast_GET_ITEM(seq, 0), name, lo, hi, &a) == 0 &&
                   ssdapy_uint(PySequence_Fast_GET_ITEM(seq, 1), name, lo, hi, &b) == 0) {
            *w = (uint16_t)a;
            *h = (uint16_t)b;
            rc = 0;
        }
        Py_DECREF(seq);
        return rc;
    }
    if (ssdapy_uint(o, name, lo, hi, &a) != 0) {
        return -1;
    }
    *w = *h = (uint16_t)a;
    return 0;
}

int ssdapy_enum(PyObject *o, const char *what, const ssdapy_name_t *table, int *out)
{
    const ssdapy_name_t *t;
    PyObject *names, *joined, *sep;
    if (PyUnicode_Check(o)) {
        for (t = table; t->name != NULL; t++) {
            if (PyUnicode_CompareWithASCIIString(o, t->name) == 0) {
                *out = t->value;
                return 0;
            }
        }
    }
    names = PyList_New(0);
    if (names == NULL) {
        return -1;
    }
    for (t = table; t->name != NULL; t++) {
        PyObject *s = PyUnicode_FromFormat("'%s'", t->name);
        if (s == NULL || PyList_Append(names, s) != 0) {
            Py_XDECREF(s);
            Py_DECREF(names);
            return -1;
        }
        Py_DECREF(s);
    }
    sep = PyUnicode_FromString(", ");
    joined = sep != NULL ? PyUnicode_Join(sep, names) : NULL;
    if (joined != NULL) {
        PyErr_Format(PyUnicode_Check(o) ? PyExc_ValueError : PyExc_TypeError,
                     "%s must be one of %U, got %R", what, joined, o);
    }
    Py_XDECREF(sep);
    Py_XDECREF(joined);
    Py_DECREF(names);
    return -1;
}

int ssdapy_fields(PyObject *kw, void *base, const ssdapy_field_t *f)
{
    for (; f->name != NULL; f++) {
        PyObject *v = ssdapy_kw_take(kw, f->name);
        long long x;
        int rc;
        char *p = (char *)base + f->offset;
        if (v == NULL) {
            continue;
        }
        rc = ssdapy_int(v, f->name, f->lo, f->hi, &x);
        Py_DECREF(v);
        if (rc != 0) {
            return -1;
        }
        if (f->bytes == 1) {
            *(uint8_t *)p = (uint8_t)x;
        } else if (f->bytes == 2) {
            *(uint16_t *)p = (uint16_t)x; /* int16_t fields share the bits */
        } else {
            *(uint32_t *)p = (uint32_t)x;
        }
    }
    return 0;
}

int ssdapy_flag(PyObject *kw, const char *name, uint8_t *flags, uint8_t bit)
{
    PyObject *v = ssdapy_kw_take(kw, name);
    int b;
    if (v == NULL) {
        return 0;
    }
    b = PyObject_IsTrue(v);
    Py_DECREF(v);
    if (b < 0) {
        return -1;
    }
    *flags = (uint8_t)(b ? (*flags | bit) : (*flags & ~bit));
    return 0;
}

int ssdapy_kw_xy(PyObject *kw, const char *name, int32_t *x, int32_t *y)
{
    PyObject *v = ssdapy_kw_take(kw, name), *seq;
    char msg[64];
    long long xy[2];
    int rc = -1;
    if (v == NULL) {
        return 0;
    }
    (void)snprintf(msg, sizeof msg, "%.40s must be (x, y)", name);
    seq = PySequence_Fast(v, msg);
    Py_DECREF(v);
    if (seq == NULL) {
        return -1;
    }
    if (PySequence_Fast_GET_SIZE(seq) != 2) {
        PyErr_SetString(PyExc_ValueError, msg);
    } else if (ssdapy_int(PySequence_Fast_GET_ITEM(seq, 0), name, INT32_MIN, INT32_MAX,
                          &xy[0]) == 0 &&
               ssdapy_int(PySequence_Fast_GET_ITEM(seq, 1), name, INT32_MIN, INT32_MAX,
                          &xy[1]) == 0) {
        *x = (int32_t)xy[0];
        *y = (int32_t)xy[1];
        rc = 1;
    }
    Py_DECREF(seq);
    return rc;
}

int ssdapy_kw_enum(PyObject *kw, const char *name, const ssdapy_name_t *table, uint8_t *dst)
{
    PyObject *v = ssdapy_kw_take(kw, name);
    int e, rc = 0;
    if (v != NULL) {
        rc = ssdapy_enum(v, name, table, &e);
        if (rc == 0) {
            *dst = (uint8_t)e;
        }
        Py_DECREF(v);
    }
    return rc;
}

PyObject *ssdapy_kw_copy(PyObject *kw)
{
    return kw != NULL ? PyDict_Copy(kw) : PyDict_New();
}

PyObject *ssdapy_kw_take(PyObject *kw, const char *name)
{
    PyObject *v = PyDict_GetItemString(kw, name); /* borrowed */
    if (v == NULL || v == Py_None) {
        if (v != NULL) {
            PyDict_DelItemString(kw, name);
        }
        return NULL;
    }
    Py_INCREF(v);
    PyDict_DelItemString(kw, name);
    return v;
}

int ssdapy_kw_done(PyObject *kw, const char *func)
{
    PyObject *key, *value;
    Py_ssize_t pos = 0;
    if (PyDict_Next(kw, &pos, &key, &value)) {
        PyErr_Format(PyExc_TypeError, "%s() got an unexpected keyword argument %R", func, key);
        return -1;
    }
    return 0;
}

int ssdapy_args(PyObject *args, const char *func, Py_ssize_t n, Py_ssize_t max,
                PyObject **out)
{
    Py_ssize_t i, got = PyTuple_GET_SIZE(args);
    if (got < n || got > max) {
        if (n == max) {
            PyErr_Format(PyExc_TypeError, "%s() takes %zd positional argument%s (%zd given)",
                         func, n, n == 1 ? "" : "s", got);
        } else {
            PyErr_Format(PyExc_TypeError, "%s() takes %zd to %zd positional arguments (%zd "
                         "given)", func, n, max, got);
        }
        return -1;
    }
    for (i = 0; i < max; i++) {
        out[i] = i < got ? PyTuple_GET_ITEM(args, i) : NULL;
    }
    return 0;
}

/* ---- results ---- */

PyObject *ssdapy_struct_seq(PyTypeObject *type, const unsigned long long *v, Py_ssize_t n)
{
    PyObject *o = PyStructSequence_New(type);
    Py_ssize_t i;
    if (o == NULL) {
        return NULL;
    }
    for (i = 0; i < n; i++) {
        PyStructSequence_SET_ITEM(o, i, PyLong_FromUnsignedLongLong(v[i]));
    }
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

PyObject *ssdapy_np_typed(int ndim, const Py_ssize_t *shape, const char *dtype)
{
    PyObject *dt = PyUnicode_FromString(dtype), *a;
    if (dt == NULL) {
        return NULL;
    }
    a = ssdapy_np_empty(ndim, shape, dt);
    Py_DECREF(dt);
    return a;
}

PyObject *ssdapy_np_empty(int ndim, const Py_ssize_t *shape, PyObject *dtype)
{
    PyObject *shp = PyTuple_New(ndim), *a;
    int i;
    if (shp == NULL) {
        return NULL;
    }
    for (i = 0; i < ndim; i++) {
        PyObject *n = PyLong_FromSsize_t(shape[i]);
        if (n == NULL) {
            Py_DECREF(shp);
            return NULL;
        }
        PyTuple_SET_ITEM(shp, i, n);
    }
    a = PyObject_CallFunctionObjArgs(ssdapy.np_empty, shp, dtype, NULL);
    Py_DECREF(shp);
    return a;
}

PyObject *ssdapy_np_struct_dtype(Py_ssize_t n, const char *const *names,
                                 const char *const *formats, const size_t *offsets,
                                 size_t itemsize)
{
    PyObject *ln = PyList_New(n), *lf = PyList_New(n), *lo = PyList_New(n), *spec = NULL,
             *dt = NULL;
    Py_ssize_t i;
    if (ln == NULL || lf == NULL || lo == NULL) {
        goto done;
    }
    for (i = 0; i < n; i++) {
        PyObject *a = PyUnicode_FromString(names[i]), *b = PyUnicode_FromString(formats[i]),
                 *c = PyLong_FromSize_t(offsets[i]);
        if (a == NULL || b == NULL || c == NULL) {
            Py_XDECREF(a);
            Py_XDECREF(b);
            Py_XDECREF(c);
            goto done;
        }
        PyList_SET_ITEM(ln, i, a);
        PyList_SET_ITEM(lf, i, b);
        PyList_SET_ITEM(lo, i, c);
    }
    spec = Py_BuildValue("{sOsOsOsn}", "names", ln, "formats", lf, "offsets", lo, "itemsize",
                         (Py_ssize_t)itemsize);
    if (spec != NULL) {
        dt = PyObject_CallFunctionObjArgs(ssdapy.np_dtype, spec, NULL);
    }
done:
    Py_XDECREF(ln);
    Py_XDECREF(lf);
    Py_XDECREF(lo);
    Py_XDECREF(spec);
    return dt;
}

void *ssdapy_np_data(PyObject *array)
{
    Py_buffer b;
    void *p;
    if (PyObject_GetBuffer(array, &b, PyBUF_WRITABLE | PyBUF_C_CONTIGUOUS) != 0) {
        return NULL;
    }
    p = b.buf;
    PyBuffer_Release(&b);
    return p;
}

int ssdapy_records(PyObject *obj, const char *what, PyObject *dtype, Py_buffer *b,
                   Py_ssize_t *count)
{
    PyObject *d = PyObject_GetAttrString(obj, "dtype");
    int same = d != NULL ? PyObject_RichCompareBool(d, dtype, Py_EQ) : 0;
    Py_XDECREF(d);
    PyErr_Clear();
    if (same != 1) {
        PyErr_Format(PyExc_TypeError, "%s must be an array of dtype %R (as this module "
                     "returns it), got %s", what, dtype, Py_TYPE(obj)->tp_name);
        return -1;
    }
    if (PyObject_GetBuffer(obj, b, PyBUF_C_CONTIGUOUS) != 0) {
        PyErr_Clear();
        PyErr_Format(PyExc_ValueError, "%s must be C-contiguous (numpy.ascontiguousarray)",
                     what);
        return -1;
    }
    {
        PyObject *isz = PyObject_GetAttrString(dtype, "itemsize");
        Py_ssize_t itemsize = isz != NULL ? PyLong_AsSsize_t(isz) : -1;
        Py_XDECREF(isz);
        if (itemsize <= 0) {
            PyBuffer_Release(b);
            return -1;
        }
        *count = b->len / itemsize;
    }
    return 0;
}

PyTypeObject *ssdapy_struct_type(PyObject *module, const char *name, const char *doc,
                                 PyStructSequence_Field *fields, int n_in_sequence)
{
    PyStructSequence_Desc desc;
    PyTypeObject *t;
    desc.name = (char *)name;
    desc.doc = (char *)doc;
    desc.fields = fields;
    desc.n_in_sequence = n_in_sequence;
    t = PyStructSequence_NewType(&desc);
    if (t == NULL) {
        return NULL;
    }
    {
        const char *dot = strrchr(name, '.');
        Py_INCREF(t);
        if (PyModule_AddObject(module, dot != NULL ? dot + 1 : name, (PyObject *)t) != 0) {
            Py_DECREF(t);
            Py_DECREF(t);
            return NULL;
        }
    }
    return t;
}
