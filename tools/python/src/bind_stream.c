/* bind_stream.c - ssda.Source, ssda.stream_match, ssda.stream_track
   (ssda/stream.h): images outside Python's memory, read through a Python
   callable or a file-like object while the library runs without the GIL.

   The read callback takes the GIL back, calls Python, and on an exception
   keeps it in the Source and returns SSDA_ERR_IO; the job then stops (the
   library passes the code back unchanged) and the binding raises the
   original exception. A Source is used by one call at a time: a second
   thread gets RuntimeError instead of a race. */
#include "ssdapy.h"
#include "ssda/stream.h"

#include <string.h>

enum { READ_CALLABLE = 0, READ_FILE = 1 };

typedef struct {
    PyObject_HEAD
    ssda_source_t src;
    void *arena;         /* PyMem */
    size_t arena_size;
    PyObject *reader;    /* callable(offset, size) or file-like object */
    int mode;
    uint32_t read_size;
    uint16_t width, height;
    uint8_t format;
    int ready, busy;
    PyObject *exc_type, *exc_value, *exc_tb; /* raised inside read() */
} SourceObject;

static PyTypeObject *source_type, *source_stats_type;

static PyStructSequence_Field source_stats_fields[] = {
    {"bytes_read", "bytes requested from read(), alignment included"},
    {"reads", "read() calls"},
    {"hits", "row spans served from the plate"},
    {"misses", "row spans that moved the plate"},
    {NULL, NULL}};

/* ---- the read callback ---- */

/* Copy what reader gave into buffer: exactly size bytes, or fewer by less
   than read_size (the aligned tail past the image's end, zero-filled). */
static int take_bytes(SourceObject *s, PyObject *got, void *buffer, uint32_t size,
                      uint32_t offset)
{
    Py_buffer b;
    if (PyObject_GetBuffer(got, &b, PyBUF_SIMPLE) != 0) {
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "Source read(%lu, %lu) must return a bytes-like "
                     "object, got %s", (unsigned long)offset, (unsigned long)size,
                     Py_TYPE(got)->tp_name);
        return -1;
    }
    if (b.len > (Py_ssize_t)size || (Py_ssize_t)size - b.len >= (Py_ssize_t)s->read_size) {
        PyErr_Format(PyExc_ValueError, "Source read(%lu, %lu) returned %zd bytes",
                     (unsigned long)offset, (unsigned long)size, b.len);
        PyBuffer_Release(&b);
        return -1;
    }
    memcpy(buffer, b.buf, (size_t)b.len);
    memset((char *)buffer + b.len, 0, size - (size_t)b.len);
    PyBuffer_Release(&b);
    return 0;
}

/* A file-like object: seek(offset), then readinto() straight into the
   library's buffer through a memoryview released afterwards (or read()). */
static int file_read(SourceObject *s, uint32_t offset, void *buffer, uint32_t size)
{
    PyObject *r = PyObject_CallMethod(s->reader, "seek", "k", (unsigned long)offset);
    Py_ssize_t got;
    if (r == NULL) {
        return -1;
    }
    Py_DECREF(r);
    if (PyObject_HasAttrString(s->reader, "readinto")) {
        PyObject *mv = PyMemoryView_FromMemory(buffer, size, PyBUF_WRITE), *rel;
        if (mv == NULL) {
            return -1;
        }
        r = PyObject_CallMethod(s->reader, "readinto", "O", mv);
        rel = PyObject_CallMethod(mv, "release", NULL);
        Py_DECREF(mv);
        if (rel == NULL) { /* the reader kept a view of our buffer */
            Py_XDECREF(r);
            return -1;
        }
        Py_DECREF(rel);
        if (r == NULL) {
            return -1;
        }
        got = PyLong_AsSsize_t(r);
        Py_DECREF(r);
        if (got == -1 && PyErr_Occurred()) {
            return -1;
        }
        if (got < 0 || got > (Py_ssize_t)size ||
            (Py_ssize_t)size - got >= (Py_ssize_t)s->read_size) {
            PyErr_Format(PyExc_EOFError, "Source file: %zd of %lu bytes at offset %lu", got,
                         (unsigned long)size, (unsigned long)offset);
            return -1;
        }
        memset((char *)buffer + got, 0, size - (size_t)got);
        return 0;
    }
    r = PyObject_CallMethod(s->reader, "read", "k", (unsigned long)size);
    if (r == NULL) {
        return -1;
    }
    got = take_bytes(s, r, buffer, size, offset);
    Py_DECREF(r);
    return (int)got;
}

static int source_read(void *context, uint32_t offset, void *buffer, uint32_t size)
{
    SourceObject *s = context;
    PyGILState_STATE g = PyGILState_Ensure();
    int rc;
    if (s->exc_type != NULL) {
        rc = -1; /* an earlier read failed in this job: do not call again */
    } else if (s->mode == READ_FILE) {
        rc = file_read(s, offset, buffer, size);
    } else {
        PyObject *r = PyObject_CallFunction(s->reader, "kk", (unsigned long)offset,
                                            (unsigned long)size);
        rc = r != NULL ? take_bytes(s, r, buffer, size, offset) : -1;
        Py_XDECREF(r);
    }
    if (rc != 0) {
        if (s->exc_type == NULL) {
            PyErr_Fetch(&s->exc_type, &s->exc_value, &s->exc_tb);
        }
        PyErr_Clear();
        rc = SSDA_ERR_IO;
    }
    PyGILState_Release(g);
    return rc;
}

/* ---- Source ---- */

static const ssdapy_name_t layouts[] = {
    {"raster", SSDA_LAYOUT_RASTER}, {"tiled", SSDA_LAYOUT_TILED}, {NULL, 0}};

static int take_u(PyObject *kw, const char *name, unsigned long long hi, uint32_t *dst)
{
    PyObject *v = ssdapy_kw_take(kw, name);
    unsigned long long u;
    int rc = 0;
    if (v != NULL) {
        rc = ssdapy_uint(v, name, 0, hi, &u);
        Py_DECREF(v);
        if (rc == 0) {
            *dst = (uint32_t)u;
        }
    }
    return rc;
}

/* format from dtype= (default uint8) */
static int take_format(PyObject *kw, uint8_t *format)
{
    PyObject *v = ssdapy_kw_take(kw, "dtype"), *d, *ch;
    int rc = -1;
    *format = SSDA_PIX_U8;
    if (v == NULL) {
        return 0;
    }
    d = PyObject_CallFunctionObjArgs(ssdapy.np_dtype, v, NULL);
    Py_DECREF(v);
    if (d == NULL) {
        return -1;
    }
    ch = PyObject_GetAttrString(d, "str");
    if (ch != NULL && PyUnicode_Check(ch) &&
        (PyUnicode_CompareWithASCIIString(ch, "|u1") == 0 ||
         PyUnicode_CompareWithASCIIString(ch, "<u2") == 0 ||
         PyUnicode_CompareWithASCIIString(ch, ">u2") == 0)) {
        *format = PyUnicode_CompareWithASCIIString(ch, "|u1") == 0 ? SSDA_PIX_U8 : SSDA_PIX_U16;
        rc = 0;
        {
            const unsigned probe = 1u;
            const int little = *(const unsigned char *)&probe == 1u;
            if (*format == SSDA_PIX_U16 &&
                PyUnicode_CompareWithASCIIString(ch, little ? ">u2" : "<u2") == 0) {
                PyErr_Format(PyExc_TypeError, "dtype %S: the library reads 16-bit samples "
                             "in this machine's byte order", d);
                rc = -1;
            }
        }
    } else if (ch != NULL) {
        PyErr_Format(PyExc_TypeError, "dtype must be uint8 or uint16, got %S", d);
    }
    Py_XDECREF(ch);
    Py_DECREF(d);
    return rc;
}

static int source_config(PyObject *kw, ssda_source_config_t *c, uint32_t *memory,
                         int *memory_given)
{
    PyObject *v;
    uint32_t layout = 0;
    if (take_format(kw, &c->format) != 0 || take_u(kw, "offset", 0xFFFFFFFFu, &c->offset) != 0 ||
        take_u(kw, "stride", 0xFFFFFFFFu, &c->stride) != 0 ||
        take_u(kw, "tile_stride", 0xFFFFFFFFu, &c->tile_stride) != 0 ||
        take_u(kw, "read_size", 0xFFFFFFFFu, &c->read_size) != 0) {
        return -1;
    }
    if ((v = ssdapy_kw_take(kw, "layout")) != NULL) {
        int e, rc = ssdapy_enum(v, "layout", layouts, &e);
        Py_DECREF(v);
        if (rc != 0) {
            return -1;
        }
        layout = (uint32_t)e;
    }
    c->layout = (uint8_t)layout;
    if ((v = ssdapy_kw_take(kw, "tile")) != NULL) {
        int rc = ssdapy_size2(v, "tile", 1, 65535u, &c->tile_w, &c->tile_h);
        Py_DECREF(v);
        if (rc != 0) {
            return -1;
        }
    }
    *memory_given = PyDict_GetItemString(kw, "memory") != NULL &&
                    PyDict_GetItemString(kw, "memory") != Py_None;
    return take_u(kw, "memory", 0xFFFFFFFFu, memory);
}

static void source_clear_exc(SourceObject *s)
{
    Py_CLEAR(s->exc_type);
    Py_CLEAR(s->exc_value);
    Py_CLEAR(s->exc_tb);
}

static int source_init(PyObject *self_o, PyObject *args, PyObject *kw)
{
    SourceObject *s = (SourceObject *)self_o;
    ssda_source_config_t c;
    PyObject *a[3], *kwc;
    unsigned long long w, h;
    uint32_t memory = 0;
    int memory_given = 0, mode, e;
    size_t arena_size;
    void *arena;
    if (s->busy) {
        PyErr_SetString(PyExc_RuntimeError, "Source in use by another call");
        return -1;
    }
    if (ssdapy_args(args, "Source", 3, 3, a) != 0 ||
        ssdapy_uint(a[1], "width", 0, 65535u, &w) != 0 ||
        ssdapy_uint(a[2], "height", 0, 65535u, &h) != 0) {
        return -1;
    }
    if (PyCallable_Check(a[0])) {
        mode = READ_CALLABLE;
    } else if (PyObject_HasAttrString(a[0], "seek") &&
               (PyObject_HasAttrString(a[0], "readinto") || PyObject_HasAttrString(a[0], "read"))) {
        mode = READ_FILE;
    } else {
        PyErr_Format(PyExc_TypeError, "Source needs read(offset, size) -> bytes or a binary "
                     "file object (seek and readinto or read), got %s", Py_TYPE(a[0])->tp_name);
        return -1;
    }
    if ((kwc = ssdapy_kw_copy(kw)) == NULL) {
        return -1;
    }
    memset(&c, 0, sizeof c);
    c.width = (uint16_t)w;
    c.height = (uint16_t)h;
    if (source_config(kwc, &c, &memory, &memory_given) != 0 || ssdapy_kw_done(kwc, "Source") != 0) {
        Py_DECREF(kwc);
        return -1;
    }
    Py_DECREF(kwc);
    /* default memory: a plate of the whole image (each byte read once) */
    arena_size = memory_given ? memory
                              : SSDA_SOURCE_SIZE(c.layout, c.width != 0u ? c.width : 1u,
                                                 c.height != 0u ? c.height : 1u, c.format,
                                                 c.read_size, c.tile_w);
    if ((arena = PyMem_Malloc(arena_size != 0u ? arena_size : 1u)) == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    c.read = source_read;
    c.context = s;
    c.arena = arena;
    c.arena_size = arena_size;
    if ((e = ssda_source_init(&s->src, &c)) != SSDA_OK) {
        PyMem_Free(arena);
        ssdapy_error(e, "ssda_source_init");
        return -1;
    }
    PyMem_Free(s->arena);
    s->arena = arena;
    s->arena_size = arena_size;
    Py_INCREF(a[0]);
    Py_XSETREF(s->reader, a[0]);
    s->mode = mode;
    s->read_size = c.read_size > 1u ? c.read_size : 1u;
    s->width = c.width;
    s->height = c.height;
    s->format = c.format;
    s->ready = 1;
    source_clear_exc(s);
    return 0;
}

static int source_traverse(PyObject *self_o, visitproc visit, void *arg)
{
    SourceObject *s = (SourceObject *)self_o;
    Py_VISIT(s->reader);
    Py_VISIT(s->exc_type);
    Py_VISIT(s->exc_value);
    Py_VISIT(s->exc_tb);
    Py_VISIT(Py_TYPE(self_o));
    return 0;
}

static int source_clear(PyObject *self_o)
{
    SourceObject *s = (SourceObject *)self_o;
    Py_CLEAR(s->reader);
    source_clear_exc(s);
    return 0;
}

static void source_dealloc(PyObject *self_o)
{
    SourceObject *s = (SourceObject *)self_o;
    PyTypeObject *tp = Py_TYPE(self_o);
    PyObject_GC_UnTrack(self_o);
    source_clear(self_o);
    PyMem_Free(s->arena);
    tp->tp_free(self_o);
    Py_DECREF(tp);
}

static PyObject *source_get_stats(PyObject *self_o, void *closure)
{
    const ssda_source_stats_t *st = &((SourceObject *)self_o)->src.stats;
    const unsigned long long v[] = {st->bytes_read, st->reads, st->hits, st->misses};
    (void)closure;
    return ssdapy_struct_seq(source_stats_type, v, (Py_ssize_t)(sizeof v / sizeof v[0]));
}

static PyObject *source_get_memory(PyObject *self_o, void *closure)
{
    (void)closure;
    return PyLong_FromSize_t(((SourceObject *)self_o)->arena_size);
}

/* ---- sources as job arguments: a Source, or an array viewed in place ---- */

typedef ssdapy_src_arg_t src_arg_t;

static int src_arg_get(PyObject *o, const char *what, src_arg_t *a, const src_arg_t *other);
static int src_arg_release(src_arg_t *a);

int ssdapy_src_arg_get(PyObject *o, const char *what, ssdapy_src_arg_t *a,
                       const ssdapy_src_arg_t *other)
{
    return src_arg_get(o, what, a, other);
}

int ssdapy_src_arg_release(ssdapy_src_arg_t *a)
{
    return src_arg_release(a);
}

static int src_arg_get(PyObject *o, const char *what, src_arg_t *a, const src_arg_t *other)
{
    memset(a, 0, sizeof *a);
    if (PyObject_TypeCheck(o, source_type)) {
        SourceObject *s = (SourceObject *)o;
        if (!s->ready) {
            PyErr_Format(PyExc_RuntimeError, "%s: Source not initialised", what);
            return -1;
        }
        if (other == NULL || other->obj != s) { /* the library judges a source given twice */
            if (s->busy) {
                PyErr_Format(PyExc_RuntimeError, "%s: Source in use by another call", what);
                return -1;
            }
            s->busy = 1;
            source_clear_exc(s);
            a->obj = s;
        }
        a->src = &s->src;
        a->width = s->width;
        a->height = s->height;
        a->format = s->format;
        return 0;
    }
    if (ssdapy_image_get(o, what, &a->img) != 0) {
        return -1;
    }
    a->have_img = 1;
    if (ssda_source_init_view(&a->local, &a->img.view) != SSDA_OK) {
        PyErr_Format(PyExc_ValueError, "%s: cannot be viewed as a source", what);
        ssdapy_image_release(&a->img);
        a->have_img = 0;
        return -1;
    }
    a->src = &a->local;
    a->width = a->img.view.width;
    a->height = a->img.view.height;
    a->format = a->img.view.format;
    return 0;
}

/* Release an argument; if its read() raised, restore that exception
   (returns 1) unless one is already set. */
static int src_arg_release(src_arg_t *a)
{
    int raised = 0;
    if (a->obj != NULL) {
        SourceObject *s = a->obj;
        if (s->exc_type != NULL) {
            if (!PyErr_Occurred()) {
                PyErr_Restore(s->exc_type, s->exc_value, s->exc_tb);
                s->exc_type = s->exc_value = s->exc_tb = NULL;
                raised = 1;
            }
            source_clear_exc(s);
        }
        s->busy = 0;
        a->obj = NULL;
    }
    if (a->have_img) {
        ssdapy_image_release(&a->img);
        a->have_img = 0;
    }
    return raised;
}

/* The outcome of a job: a read() exception wins over the library's code. */
static PyObject *job_outcome(src_arg_t *x, src_arg_t *y, int e, const char *func,
                             PyObject *(*ok)(void *), void *ok_arg)
{
    int raised = src_arg_release(x);
    raised |= src_arg_release(y);
    if (raised) {
        return NULL;
    }
    if (e != SSDA_OK) {
        return ssdapy_error(e, func);
    }
    return ok(ok_arg);
}

static int rect_arg(PyObject *kw, const char *name, ssda_rect_t *r, const src_arg_t *a,
                    int *given)
{
    PyObject *v = ssdapy_kw_take(kw, name), *seq;
    unsigned long long q[4];
    Py_ssize_t i;
    int rc = 0;
    *given = 0;
    r->x = 0;
    r->y = 0;
    r->width = a->width;
    r->height = a->height;
    if (v == NULL) {
        return 0;
    }
    seq = PySequence_Fast(v, "a rectangle must be (x, y, width, height)");
    Py_DECREF(v);
    if (seq == NULL) {
        return -1;
    }
    if (PySequence_Fast_GET_SIZE(seq) != 4) {
        PyErr_Format(PyExc_ValueError, "%s must be (x, y, width, height)", name);
        rc = -1;
    }
    for (i = 0; i < 4 && rc == 0; i++) {
        rc = ssdapy_uint(PySequence_Fast_GET_ITEM(seq, i), name, 0, 65535u, &q[i]);
    }
    Py_DECREF(seq);
    if (rc == 0) {
        r->x = (uint16_t)q[0];
        r->y = (uint16_t)q[1];
        r->width = (uint16_t)q[2];
        r->height = (uint16_t)q[3];
        *given = 1;
    }
    return rc;
}

static PyObject *match_ok(void *r)
{
    return ssdapy_match_result(r);
}

static PyObject *py_stream_match(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc = NULL, *out = NULL;
    src_arg_t area, win;
    ssda_rect_t ar, wr;
    ssda_match_config_t cfg;
    ssda_match_result_t res;
    void *work = NULL;
    int ag, wg, e = SSDA_OK;
    (void)self;
    if (ssdapy_args(args, "stream_match", 2, 2, a) != 0 ||
        src_arg_get(a[0], "area", &area, NULL) != 0) {
        return NULL;
    }
    if (src_arg_get(a[1], "window", &win, &area) != 0) {
        src_arg_release(&area);
        return NULL;
    }
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || rect_arg(kwc, "area_rect", &ar, &area, &ag) != 0 ||
        rect_arg(kwc, "window_rect", &wr, &win, &wg) != 0 ||
        ssdapy_match_options(kwc, &cfg, 1) != 0 || ssdapy_kw_done(kwc, "stream_match") != 0) {
        goto fail;
    }
    if ((cfg.flags & SSDA_MATCH_BOUNDS) != 0u) {
        if (wr.width > ar.width || wr.height > ar.height) {
            cfg.flags = 0; /* the library reports the size error */
        } else {
            cfg.work_size = SSDA_MATCH_WORK_SIZE(ar.width, ar.height, wr.width, wr.height);
            if ((work = PyMem_Malloc(cfg.work_size)) == NULL) {
                PyErr_NoMemory();
                goto fail;
            }
            cfg.work = work;
        }
    }
    SSDAPY_NOGIL(e = ssda_stream_match(area.src, ag ? &ar : NULL, win.src, wg ? &wr : NULL,
                                       &cfg, &res));
    out = job_outcome(&area, &win, e, "ssda_stream_match", match_ok, &res);
    PyMem_Free(work);
    Py_DECREF(kwc);
    return out;
fail:
    PyMem_Free(work);
    Py_XDECREF(kwc);
    src_arg_release(&area);
    src_arg_release(&win);
    return NULL;
}

typedef struct {
    PyObject *vectors;
    ssda_track_grid_t grid;
    ssda_track_stats_t stats;
} track_out_t;

static PyObject *track_ok(void *p)
{
    track_out_t *t = p;
    return ssdapy_track_result(t->vectors, &t->grid, &t->stats);
}

static PyObject *py_stream_track(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc = NULL, *out = NULL;
    src_arg_t first, second;
    ssda_track_config_t cfg;
    track_out_t t;
    ssda_track_vector_t *v = NULL;
    void *work = NULL;
    int e;
    (void)self;
    t.vectors = NULL;
    if (ssdapy_args(args, "stream_track", 2, 2, a) != 0 ||
        src_arg_get(a[0], "first", &first, NULL) != 0) {
        return NULL;
    }
    if (src_arg_get(a[1], "second", &second, &first) != 0) {
        src_arg_release(&first);
        return NULL;
    }
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || ssdapy_track_options(kwc, &cfg) != 0 ||
        ssdapy_kw_done(kwc, "stream_track") != 0) {
        goto fail;
    }
    if ((e = ssda_track_grid(&cfg, second.width, second.height, &t.grid)) != SSDA_OK) {
        ssdapy_error(e, "ssda_track_grid");
        goto fail;
    }
    if (ssdapy_track_work(&cfg, &t.grid, &work) != 0) {
        goto fail;
    }
    if ((t.vectors = ssdapy_track_vectors(&t.grid, &v)) == NULL) {
        goto fail;
    }
    SSDAPY_NOGIL(e = ssda_stream_track(first.src, second.src, &cfg, v, t.grid.count,
                                       &t.stats));
    out = job_outcome(&first, &second, e, "ssda_stream_track", track_ok, &t);
    Py_DECREF(t.vectors);
    PyMem_Free(work);
    Py_DECREF(kwc);
    return out;
fail:
    Py_XDECREF(t.vectors);
    PyMem_Free(work);
    Py_XDECREF(kwc);
    src_arg_release(&first);
    src_arg_release(&second);
    return NULL;
}

static PyObject *source_row(PyObject *self_o, PyObject *args)
{
    PyObject *a[3], *arr = NULL;
    unsigned long long x, y, n;
    src_arg_t sa;
    const uint8_t *px = NULL;
    int e;
    if (ssdapy_args(args, "row", 3, 3, a) != 0 ||
        ssdapy_uint(a[0], "x", 0, 0xFFFFFFFFu, &x) != 0 ||
        ssdapy_uint(a[1], "y", 0, 0xFFFFFFFFu, &y) != 0 ||
        ssdapy_uint(a[2], "n", 0, 0xFFFFFFFFu, &n) != 0 ||
        src_arg_get(self_o, "source", &sa, NULL) != 0) {
        return NULL;
    }
    SSDAPY_NOGIL(e = ssda_source_row(sa.src, (uint32_t)x, (uint32_t)y, (uint32_t)n, &px));
    if (src_arg_release(&sa)) {
        return NULL;
    }
    if (e != SSDA_OK) {
        return ssdapy_error(e, "ssda_source_row");
    }
    {
        const Py_ssize_t shape[1] = {(Py_ssize_t)n};
        uint8_t format = ((SourceObject *)self_o)->format;
        PyObject *dt = PyUnicode_FromString(format == SSDA_PIX_U8 ? "uint8" : "uint16");
        void *data;
        arr = dt != NULL ? ssdapy_np_empty(1, shape, dt) : NULL;
        Py_XDECREF(dt);
        if (arr != NULL) {
            if ((data = ssdapy_np_data(arr)) == NULL) {
                Py_CLEAR(arr);
            } else {
                memcpy(data, px, (size_t)n * format);
            }
        }
    }
    return arr;
}

static PyMethodDef source_methods[] = {
    {"row", source_row, METH_VARARGS,
     "row($self, x, y, n, /)\n--\n\n"
     "A copy of pixels x .. x+n-1 of row y, read through the plate (ssda_source_row)."},
    {NULL, NULL, 0, NULL}};

static PyGetSetDef source_getset[] = {
    {"stats", source_get_stats, NULL, "What the source has cost so far (SourceStats).", NULL},
    {"memory", source_get_memory, NULL, "Bytes of its arena.", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

static PyType_Slot source_slots[] = {
    {Py_tp_doc,
     "Source(read, width, height, /, *, dtype='uint8', offset=0, stride=0, "
     "layout='raster', tile=None, tile_stride=0, read_size=0, memory=None)\n--\n\n"
     "An image of width x height pixels outside Python's memory (ssda_source_init,\n"
     "ssda/stream.h), for stream_match and stream_track. read is a callable\n"
     "read(offset, size) -> bytes-like of size bytes at that byte offset, or a\n"
     "binary file object (seek, then readinto or read). An exception it raises\n"
     "stops the job and propagates. offset, stride, layout ('raster' or 'tiled'),\n"
     "tile (N or (w, h)), tile_stride and read_size are the fields of\n"
     "ssda_source_config_t; memory is the arena in bytes (default: a plate of the\n"
     "whole image, read once). stats: bytes_read, reads, hits, misses."},
    {Py_tp_init, source_init},
    {Py_tp_new, PyType_GenericNew},
    {Py_tp_dealloc, source_dealloc},
    {Py_tp_traverse, source_traverse},
    {Py_tp_clear, source_clear},
    {Py_tp_methods, source_methods},
    {Py_tp_getset, source_getset},
    {0, NULL}};

static PyType_Spec source_spec = {"ssda.Source", sizeof(SourceObject), 0,
                                  Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC, source_slots};

#define STREAM_TRACK_DOC                                                             \
    "stream_track(first, second, /, *, window=16, search=None, step=None, roi=None, " \
    "predict='median', exclude=False, texture_threshold=0, texture_min_count=0, "     \
    "mask_value=None, threshold='auto', scan='raster', order='rows', bounds=True, "   \
    "k_q8=0, lambda_q8=0, fixed_threshold=0, coarse_step=0)\n--\n\n"                  \
    "track with first and/or second a Source (or an array) (ssda_stream_track):\n"   \
    "the same TrackResult as track on the same pixels (see stream.h for the\n"       \
    "prediction modes whose work counts may differ). The GIL is released; read()\n"  \
    "callbacks take it back."

static PyMethodDef methods[] = {
    {"stream_match", (PyCFunction)(void (*)(void))py_stream_match,
     METH_VARARGS | METH_KEYWORDS,
     "stream_match(area, window, /, *, area_rect=None, window_rect=None, "
     "threshold='auto', scan='raster', order='rows', bounds=True, predict=None, k_q8=0, "
     "lambda_q8=0, fixed_threshold=0, coarse_step=0)\n--\n\n"
     "match over a rectangle (x, y, w, h; default whole) of each of two sources,\n"
     "either a Source or an array (ssda_stream_match): the MatchResult that match\n"
     "gives on the same pixels. The GIL is released; read() callbacks take it back."},
    {"stream_track", (PyCFunction)(void (*)(void))py_stream_track,
     METH_VARARGS | METH_KEYWORDS, STREAM_TRACK_DOC},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_stream(PyObject *m)
{
    source_stats_type = ssdapy_struct_type(m, "ssda.SourceStats",
                                           "What a Source has cost (ssda_source_stats_t).",
                                           source_stats_fields, 4);
    if (source_stats_type == NULL) {
        return -1;
    }
    source_type = (PyTypeObject *)PyType_FromSpec(&source_spec);
    if (source_type == NULL) {
        return -1;
    }
    Py_INCREF(source_type);
    if (PyModule_AddObject(m, "Source", (PyObject *)source_type) != 0) {
        Py_DECREF(source_type);
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
