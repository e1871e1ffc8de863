/* bind_grad.c - ssda.grad (ssda/grad.h): the seed's Fig. 8 operator. */
#include "ssdapy.h"
#include "ssda/grad.h"

static PyTypeObject *grad_result_type;

static PyStructSequence_Field grad_result_fields[] = {
    {"image", "(h - 2, w - 2) array of E' >> shift; pixel (x, y) is centred on input "
              "pixel (x + 1, y + 1)"},
    {"saturated", "samples stored at the output maximum (0 with the safe shift)"},
    {NULL, NULL}};

/* The output format: out's item size, else dtype= (None: uint16). */
static int out_format(PyObject *dtype, PyObject *out, uint8_t *format)
{
    PyObject *d, *ch;
    int rc = -1;
    if (out != NULL) {
        Py_buffer b;
        if (dtype != NULL) {
            PyErr_SetString(PyExc_TypeError, "grad() takes dtype or out, not both");
            return -1;
        }
        if (!PyObject_CheckBuffer(out) || PyObject_GetBuffer(out, &b, PyBUF_RECORDS_RO) != 0) {
            PyErr_Clear();
            PyErr_Format(PyExc_TypeError, "out must be a writable 2-D uint8 or uint16 array, "
                         "got %s", Py_TYPE(out)->tp_name);
            return -1;
        }
        *format = b.itemsize == 1 ? SSDA_PIX_U8 : SSDA_PIX_U16; /* checked with the view */
        PyBuffer_Release(&b);
        return 0;
    }
    if (dtype == NULL) {
        *format = SSDA_PIX_U16;
        return 0;
    }
    d = PyObject_CallFunctionObjArgs(ssdapy.np_dtype, dtype, NULL);
    if (d == NULL) {
        return -1;
    }
    ch = PyObject_GetAttrString(d, "char");
    if (ch != NULL && PyUnicode_Check(ch) && PyUnicode_CompareWithASCIIString(ch, "B") == 0) {
        *format = SSDA_PIX_U8;
        rc = 0;
    } else if (ch != NULL && PyUnicode_Check(ch) &&
               PyUnicode_CompareWithASCIIString(ch, "H") == 0) {
        *format = SSDA_PIX_U16;
        rc = 0;
    } else if (ch != NULL) {
        PyErr_Format(PyExc_TypeError, "dtype must be uint8 or uint16, got %S", d);
    }
    Py_XDECREF(ch);
    Py_DECREF(d);
    return rc;
}

/* The library's error for a source it refuses before any output is looked at
   (smaller than 3 x 3). */
static PyObject *source_error(const ssda_view_t *src)
{
    uint8_t dummy[2];
    ssda_grad_out_t go = {dummy, 0, 0, SSDA_PIX_U8, 0};
    return ssdapy_error(ssda_grad(src, &go, NULL), "ssda_grad");
}

/* Whether two views' byte ranges intersect. */
static int overlaps(const ssda_view_t *a, const ssda_view_t *b)
{
    const char *a0 = a->data, *b0 = b->data;
    const char *a1 = a0 + (size_t)(a->height - 1u) * a->stride + (size_t)a->width * a->format;
    const char *b1 = b0 + (size_t)(b->height - 1u) * b->stride + (size_t)b->width * b->format;
    return a0 < b1 && b0 < a1;
}

static PyObject *py_grad(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc, *dtype = NULL, *shift_o = NULL, *out_o = NULL, *arr = NULL,
             *res = NULL;
    ssdapy_image_t src, dst;
    ssda_grad_out_t go;
    unsigned long long shift;
    uint32_t saturated = 0;
    uint8_t format = SSDA_PIX_U16;
    int e, have_dst = 0;
    (void)self;
    if (ssdapy_args(args, "grad", 1, 1, a) != 0 || ssdapy_image_get(a[0], "image", &src) != 0) {
        return NULL;
    }
    if ((kwc = ssdapy_kw_copy(kw)) == NULL) {
        goto done;
    }
    dtype = ssdapy_kw_take(kwc, "dtype");
    shift_o = ssdapy_kw_take(kwc, "shift");
    out_o = ssdapy_kw_take(kwc, "out");
    if (ssdapy_kw_done(kwc, "grad") != 0 || out_format(dtype, out_o, &format) != 0) {
        goto done;
    }
    shift = SSDA_GRAD_SAFE_SHIFT(src.view.format, format);
    if (shift_o != NULL && ssdapy_uint(shift_o, "shift", 0, 255u, &shift) != 0) {
        goto done;
    }
    if (src.view.width < 3u || src.view.height < 3u) {
        source_error(&src.view);
        goto done;
    }
    if (out_o != NULL) {
        arr = out_o;
        Py_INCREF(arr);
    } else {
        const Py_ssize_t shape[2] = {src.view.height - 2, src.view.width - 2};
        PyObject *dt = PyUnicode_FromString(format == SSDA_PIX_U8 ? "uint8" : "uint16");
        arr = dt != NULL ? ssdapy_np_empty(2, shape, dt) : NULL;
        Py_XDECREF(dt);
        if (arr == NULL) {
            goto done;
        }
    }
    if (ssdapy_out_image_get(arr, "out", format, src.view.height - 2, src.view.width - 2,
                             &dst) != 0) {
        goto done;
    }
    have_dst = 1;
    if (overlaps(&src.view, &dst.view)) {
        PyErr_SetString(PyExc_ValueError, "out must not overlap image (the operator reads "
                        "input pixels after writing outputs)");
        goto done;
    }
    go.data = (void *)dst.view.data;
    go.stride = dst.view.stride;
    go.size = SSDA_GRAD_SIZE_STRIDED(src.view.width, src.view.height, dst.view.stride, format);
    go.format = format;
    go.shift = (uint8_t)shift;
    SSDAPY_NOGIL(e = ssda_grad(&src.view, &go, &saturated));
    if (e != SSDA_OK) {
        ssdapy_error(e, "ssda_grad");
        goto done;
    }
    res = PyStructSequence_New(grad_result_type);
    if (res != NULL) {
        Py_INCREF(arr);
        PyStructSequence_SET_ITEM(res, 0, arr);
        PyStructSequence_SET_ITEM(res, 1, PyLong_FromUnsignedLong(saturated));
        if (PyErr_Occurred()) {
            Py_CLEAR(res);
        }
    }
done:
    if (have_dst) {
        ssdapy_image_release(&dst);
    }
    Py_XDECREF(arr);
    Py_XDECREF(dtype);
    Py_XDECREF(shift_o);
    Py_XDECREF(out_o);
    Py_XDECREF(kwc);
    ssdapy_image_release(&src);
    return res;
}

static PyMethodDef methods[] = {
    {"grad", (PyCFunction)(void (*)(void))py_grad, METH_VARARGS | METH_KEYWORDS,
     "grad(image, /, *, dtype=None, shift=None, out=None)\n--\n\n"
     "The seed's Fig. 8 differential operator (ssda_grad, ssda/grad.h) on a 2-D uint8\n"
     "or uint16 image of at least 3 x 3. Returns GradResult(image, saturated): a\n"
     "(h - 2, w - 2) array of E' >> shift, output pixel (x, y) centred on input\n"
     "pixel (x + 1, y + 1). dtype: 'uint16' (default) or 'uint8'; shift: default\n"
     "the smallest that never saturates (0 for 8-bit in, 16-bit out: E' exact);\n"
     "out: a writable array of that shape with contiguous rows to write into\n"
     "(e.g. big[1:-1, 1:-1] to keep the input's coordinates)."},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_grad(PyObject *m)
{
    grad_result_type = ssdapy_struct_type(m, "ssda.GradResult", "Result of grad.",
                                          grad_result_fields, 2);
    if (grad_result_type == NULL) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
