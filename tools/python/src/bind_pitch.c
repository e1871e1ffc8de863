/* bind_pitch.c - ssda.Pitch (ssda/pitch.h): a streaming AMDF pitch state
   that takes int16 sample arrays and returns its estimates as a structured
   numpy array (ssda_pitch_estimate_t's layout). ssda.pitch() (the package)
   runs one over a whole signal. */
#include "ssdapy.h"
#include "ssda/pitch.h"

#include <stddef.h>

typedef struct {
    PyObject_HEAD
    ssda_pitch_t state;
    void *buffer;  /* PyMem: the state's sample buffer */
    int ready;     /* initialised */
    int busy;      /* a push is running (another thread may not enter) */
} PitchObject;

static PyTypeObject *info_type;
static PyObject *estimate_dtype;

static PyStructSequence_Field info_fields[] = {
    {"sample_rate_hz", NULL}, {"lag_min", "floor(rate / f0_max), samples"},
    {"lag_max", "ceil(rate / f0_min), samples"}, {"frame_len", "K, samples per sum"},
    {"hop", "samples between estimates"}, {"span", "K + lag_max + 1: samples per estimate"},
    {"chunk", "samples between early-exit tests"},
    {"full_diffs", "absolute differences per frame of a plain full-search AMDF"},
    {"threshold_q15", NULL}, {"voicing_q15", NULL}, {"silence_mad", NULL},
    {"lowpass_hz", "0 without the input low-pass"}, {"lowpass_q15", NULL}, {"flags", NULL},
    {NULL, NULL}};

static int pitch_init(PyObject *self_o, PyObject *args, PyObject *kw)
{
    static const struct {
        const char *name;
        unsigned long long lo, hi;
        size_t offset, bytes;
    } fields[] = {
        {"f0_min_hz", 0, 65535u, offsetof(ssda_pitch_config_t, f0_min_hz), 2},
        {"f0_max_hz", 0, 65535u, offsetof(ssda_pitch_config_t, f0_max_hz), 2},
        {"frame_len", 0, 65535u, offsetof(ssda_pitch_config_t, frame_len), 2},
        {"hop", 0, 65535u, offsetof(ssda_pitch_config_t, hop), 2},
        {"threshold_q15", 0, 65535u, offsetof(ssda_pitch_config_t, threshold_q15), 2},
        {"voicing_q15", 0, 65535u, offsetof(ssda_pitch_config_t, voicing_q15), 2},
        {"silence_mad", 0, 65535u, offsetof(ssda_pitch_config_t, silence_mad), 2},
        {"chunk", 0, 65535u, offsetof(ssda_pitch_config_t, chunk), 2},
        {"lowpass_hz", 0, 65535u, offsetof(ssda_pitch_config_t, lowpass_hz), 2},
    };
    static const struct {
        const char *name;
        uint8_t bit;
    } flags[] = {{"track", SSDA_PITCH_TRACK}, {"full", SSDA_PITCH_FULL},
                 {"no_filter", SSDA_PITCH_NO_FILTER}, {"parabolic", SSDA_PITCH_PARABOLIC},
                 {"no_octave", SSDA_PITCH_NO_OCTAVE}, {"no_below_range", SSDA_PITCH_NO_BELOW_RANGE}};
    PitchObject *self = (PitchObject *)self_o;
    ssda_pitch_config_t cfg;
    PyObject *a[1], *kwc, *v;
    unsigned long long u;
    size_t i, bytes;
    void *buf;
    int e;
    if (self->busy) {
        PyErr_SetString(PyExc_RuntimeError, "Pitch object in use by another thread");
        return -1;
    }
    if (ssdapy_args(args, "Pitch", 1, 1, a) != 0 ||
        ssdapy_uint(a[0], "sample_rate_hz", 0, 0xFFFFFFFFu, &u) != 0 ||
        (kwc = ssdapy_kw_copy(kw)) == NULL) {
        return -1;
    }
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = (uint32_t)u;
    for (i = 0; i < sizeof fields / sizeof fields[0]; i++) {
        if ((v = ssdapy_kw_take(kwc, fields[i].name)) != NULL) {
            int rc = ssdapy_uint(v, fields[i].name, fields[i].lo, fields[i].hi, &u);
            Py_DECREF(v);
            if (rc != 0) {
                goto fail;
            }
            *(uint16_t *)((char *)&cfg + fields[i].offset) = (uint16_t)u;
        }
    }
    for (i = 0; i < sizeof flags / sizeof flags[0]; i++) {
        if ((v = ssdapy_kw_take(kwc, flags[i].name)) != NULL) {
            int b = PyObject_IsTrue(v);
            Py_DECREF(v);
            if (b < 0) {
                goto fail;
            }
            cfg.flags = (uint8_t)(b ? cfg.flags | flags[i].bit : cfg.flags & ~flags[i].bit);
        }
    }
    if (ssdapy_kw_done(kwc, "Pitch") != 0) {
        goto fail;
    }
    Py_CLEAR(kwc);
    if ((e = ssda_pitch_buffer_size(&cfg, &bytes)) != SSDA_OK) {
        ssdapy_error(e, "ssda_pitch_buffer_size");
        return -1;
    }
    if ((buf = PyMem_Malloc(bytes)) == NULL) {
        PyErr_NoMemory();
        return -1;
    }
    if ((e = ssda_pitch_init(&self->state, &cfg, buf, bytes)) != SSDA_OK) {
        PyMem_Free(buf);
        ssdapy_error(e, "ssda_pitch_init");
        return -1;
    }
    PyMem_Free(self->buffer);
    self->buffer = buf;
    self->ready = 1;
    return 0;
fail:
    Py_XDECREF(kwc);
    return -1;
}

static void pitch_dealloc(PyObject *self_o)
{
    PitchObject *self = (PitchObject *)self_o;
    PyTypeObject *tp = Py_TYPE(self_o);
    PyMem_Free(self->buffer);
    tp->tp_free(self_o);
    Py_DECREF(tp);
}

static int check_ready(PitchObject *self)
{
    if (!self->ready) {
        PyErr_SetString(PyExc_RuntimeError, "Pitch object not initialised");
        return -1;
    }
    if (self->busy) {
        PyErr_SetString(PyExc_RuntimeError, "Pitch object in use by another thread");
        return -1;
    }
    return 0;
}

/* Push every sample, collecting the estimates in a growing raw buffer
   (PyMem_Raw*: no GIL needed). Returns the count, or -1 (out of memory) or
   a library error (< -1 never: the library's codes are returned as is, and
   SSDA_ERR_NULL is -1, which cannot happen here). */
static int push_all(ssda_pitch_t *p, const int16_t *x, size_t n, ssda_pitch_estimate_t **out,
                    size_t *count, int *lib_err)
{
    size_t pos = 0, cap = 0, used;
    ssda_pitch_estimate_t est, *v = NULL;
    *count = 0;
    *lib_err = SSDA_OK;
    while (pos < n) {
        int e = ssda_pitch_push(p, x + pos, n - pos, &used, &est);
        if (e < 0) {
            *lib_err = e;
            break;
        }
        pos += used;
        if (e == 1) {
            if (*count == cap) {
                size_t ncap = cap != 0u ? 2u * cap : 256u;
                ssda_pitch_estimate_t *nv = PyMem_RawRealloc(v, ncap * sizeof *nv);
                if (nv == NULL) {
                    PyMem_RawFree(v);
                    return -1;
                }
                v = nv;
                cap = ncap;
            }
            v[(*count)++] = est;
        }
    }
    *out = v;
    return 0;
}

static PyObject *pitch_push(PyObject *self_o, PyObject *arg)
{
    PitchObject *self = (PitchObject *)self_o;
    ssdapy_samples_t s;
    ssda_pitch_estimate_t *est = NULL;
    size_t count = 0;
    int rc, e;
    PyObject *arr = NULL;
    if (check_ready(self) != 0 || ssdapy_samples_get(arg, "samples", &s) != 0) {
        return NULL;
    }
    self->busy = 1;
    SSDAPY_NOGIL(rc = push_all(&self->state, s.data, s.count, &est, &count, &e));
    self->busy = 0;
    ssdapy_samples_release(&s);
    if (rc != 0) {
        return PyErr_NoMemory();
    }
    if (e != SSDA_OK) {
        /* samples before the error were consumed; its estimates are lost */
        PyMem_RawFree(est);
        return ssdapy_error(e, "ssda_pitch_push");
    }
    {
        const Py_ssize_t shape[1] = {(Py_ssize_t)count};
        void *data;
        arr = ssdapy_np_empty(1, shape, estimate_dtype);
        if (arr != NULL && count > 0u) {
            if ((data = ssdapy_np_data(arr)) == NULL) {
                Py_CLEAR(arr);
            } else {
                memcpy(data, est, count * sizeof *est);
            }
        }
    }
    PyMem_RawFree(est);
    return arr;
}

static PyObject *pitch_reset(PyObject *self_o, PyObject *unused)
{
    PitchObject *self = (PitchObject *)self_o;
    int e;
    (void)unused;
    if (check_ready(self) != 0) {
        return NULL;
    }
    if ((e = ssda_pitch_reset(&self->state)) != SSDA_OK) {
        return ssdapy_error(e, "ssda_pitch_reset");
    }
    Py_RETURN_NONE;
}

static PyObject *pitch_get_info(PyObject *self_o, void *closure)
{
    PitchObject *self = (PitchObject *)self_o;
    ssda_pitch_info_t i;
    PyObject *o;
    int e;
    Py_ssize_t k;
    (void)closure;
    if (!self->ready) {
        PyErr_SetString(PyExc_RuntimeError, "Pitch object not initialised");
        return NULL;
    }
    if ((e = ssda_pitch_get_info(&self->state, &i)) != SSDA_OK) {
        return ssdapy_error(e, "ssda_pitch_get_info");
    }
    {
        const unsigned long v[] = {i.sample_rate_hz, i.lag_min, i.lag_max, i.frame_len,
                                   i.hop, i.span, i.chunk, i.full_diffs, i.threshold_q15,
                                   i.voicing_q15, i.silence_mad, i.lowpass_hz,
                                   i.lowpass_q15, i.flags};
        if ((o = PyStructSequence_New(info_type)) == NULL) {
            return NULL;
        }
        for (k = 0; k < (Py_ssize_t)(sizeof v / sizeof v[0]); k++) {
            PyStructSequence_SET_ITEM(o, k, PyLong_FromUnsignedLong(v[k]));
        }
    }
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

static PyMethodDef pitch_methods[] = {
    {"push", pitch_push, METH_O,
     "push($self, samples, /)\n--\n\n"
     "Feed a 1-D int16 array (any strides; viewed or copied). Returns the estimates\n"
     "completed by these samples as a structured array (fields frame, center, lag,\n"
     "period_q16, f0_q16, diffs, confidence_q15, voiced, dip, silent: see\n"
     "ssda_pitch_estimate_t). Estimates do not depend on how the stream is cut.\n"
     "The GIL is released while the samples are analysed."},
    {"reset", pitch_reset, METH_NOARGS,
     "reset($self, /)\n--\n\nForget buffered samples; the next estimate is number 0 again."},
    {NULL, NULL, 0, NULL}};

static PyGetSetDef pitch_getset[] = {
    {"info", pitch_get_info, NULL, "The resolved parameters (PitchInfo).", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

static PyType_Slot pitch_slots[] = {
    {Py_tp_doc,
     "Pitch(sample_rate_hz, /, *, f0_min_hz=0, f0_max_hz=0, frame_len=0, hop=0, "
     "threshold_q15=0, voicing_q15=0, silence_mad=0, chunk=0, lowpass_hz=0, track=False, "
     "full=False, no_filter=False, parabolic=False, no_octave=False, no_below_range=False)\n--\n\n"
     "A streaming AMDF pitch state (ssda_pitch_init, ssda/pitch.h). Options are the\n"
     "fields of ssda_pitch_config_t (0 = the library's default) and its flags as\n"
     "booleans. Its memory (state and sample buffer) is owned by the object."},
    {Py_tp_init, pitch_init},
    {Py_tp_new, PyType_GenericNew},
    {Py_tp_dealloc, pitch_dealloc},
    {Py_tp_methods, pitch_methods},
    {Py_tp_getset, pitch_getset},
    {0, NULL}};

static PyType_Spec pitch_spec = {"ssda.Pitch", sizeof(PitchObject), 0,
                                 Py_TPFLAGS_DEFAULT, pitch_slots};

int ssdapy_init_pitch(PyObject *m)
{
    static const char *const names[] = {"frame", "center", "lag", "period_q16", "f0_q16",
                                        "diffs", "confidence_q15", "voiced", "dip", "silent"};
    static const char *const formats[] = {"u4", "u4", "u4", "u4", "u4",
                                          "u4", "u2", "?",  "?",  "?"};
    static const size_t offsets[] = {
        offsetof(ssda_pitch_estimate_t, frame), offsetof(ssda_pitch_estimate_t, center),
        offsetof(ssda_pitch_estimate_t, lag), offsetof(ssda_pitch_estimate_t, period_q16),
        offsetof(ssda_pitch_estimate_t, f0_q16), offsetof(ssda_pitch_estimate_t, diffs),
        offsetof(ssda_pitch_estimate_t, confidence_q15),
        offsetof(ssda_pitch_estimate_t, voiced), offsetof(ssda_pitch_estimate_t, dip),
        offsetof(ssda_pitch_estimate_t, silent)};
    PyObject *type;
    info_type = ssdapy_struct_type(m, "ssda.PitchInfo",
                                   "Resolved pitch parameters (ssda_pitch_info_t).",
                                   info_fields, 14);
    if (info_type == NULL) {
        return -1;
    }
    estimate_dtype = ssdapy_np_struct_dtype(10, names, formats, offsets,
                                            sizeof(ssda_pitch_estimate_t));
    if (estimate_dtype == NULL) {
        return -1;
    }
    Py_INCREF(estimate_dtype);
    if (PyModule_AddObject(m, "PITCH_ESTIMATE_DTYPE", estimate_dtype) != 0) {
        return -1;
    }
    type = PyType_FromSpec(&pitch_spec);
    if (type == NULL || PyModule_AddObject(m, "Pitch", type) != 0) {
        Py_XDECREF(type);
        return -1;
    }
    return 0;
}
