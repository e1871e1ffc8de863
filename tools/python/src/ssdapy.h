/*
 * ssdapy.h - what the binding's feature files share: the module's state
 * (numpy, the exception class, result types), images and sample arrays from
 * the buffer protocol (a view where the layout allows one, else a copy),
 * integer and option parsing with clear errors, and library errors raised
 * as ssda.Error.
 *
 * A feature is one file bind_<feature>.c with an init function
 * (ssdapy_init_<feature>) that adds its functions and types to the module;
 * module.c calls every init in its table. Each function parses and checks
 * its arguments with the GIL held, releases it (SSDAPY_NOGIL) around the
 * library call, and raises on any error: TypeError / ValueError for what the
 * binding checks (dtype, shape, option names and ranges), ssda.Error with
 * the library's code for what the library refuses.
 */
#ifndef SSDAPY_H
#define SSDAPY_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "ssda/ssda.h"
#include "ssda/match.h"
#include "ssda/stream.h"
#include "ssda/track.h"
#include "ssda/view.h"

/* ---- module state (filled by module.c and the feature inits) ---- */

typedef struct {
    PyObject *error;      /* ssda.Error */
    PyObject *np_empty;   /* numpy.empty */
    PyObject *np_dtype;   /* numpy.dtype */
    PyObject *np_frombuffer; /* numpy.frombuffer */
    unsigned long long copies; /* inputs copied because no view was possible
                                  (ssda._ssda._copies(), for the tests) */
} ssdapy_state_t;

extern ssdapy_state_t ssdapy;

/* Run a statement without the GIL (the library never calls Python, except
   through callbacks, which take the GIL back themselves). */
#define SSDAPY_NOGIL(stmt)                                                   \
    do {                                                                     \
        Py_BEGIN_ALLOW_THREADS stmt;                                         \
        Py_END_ALLOW_THREADS                                                 \
    } while (0)

/* ---- errors ---- */

/* Raise ssda.Error for a library error code: message "func: <ssda_strerror>
   (code N)", attributes code and message. Returns NULL. */
PyObject *ssdapy_error(int code, const char *func);

/* ---- images and samples ---- */

/* An image argument: a 2-D uint8 or uint16 array (any object with the
   buffer protocol). view points into the caller's memory when its layout
   allows (rows of contiguous pixels, positive row stride a multiple of the
   pixel size, uint16 rows aligned), else into a contiguous copy. */
typedef struct {
    Py_buffer buf;
    int have_buf;
    void *copy;         /* PyMem_Malloc'ed copy, or NULL */
    ssda_view_t view;
} ssdapy_image_t;

/* Fill *img from obj (what names the argument in messages). Returns 0, or
   -1 with TypeError (not a buffer, wrong dtype) or ValueError (not 2-D,
   a side of 0 or above 65535) set. Release with ssdapy_image_release. */
int ssdapy_image_get(PyObject *obj, const char *what, ssdapy_image_t *img);
void ssdapy_image_release(ssdapy_image_t *img);

/* A writable 2-D array the library writes into: its layout must allow a
   view (no copy is written back), format as given (1 = uint8, 2 = uint16),
   shape h x w. Returns 0, or -1 with TypeError / ValueError set. */
int ssdapy_out_image_get(PyObject *obj, const char *what, uint8_t format, Py_ssize_t h,
                         Py_ssize_t w, ssdapy_image_t *img);

/* A 1-D int16 sample array, viewed or copied like an image. */
typedef struct {
    Py_buffer buf;
    int have_buf;
    int16_t *copy;
    const int16_t *data;
    size_t count;
} ssdapy_samples_t;

int ssdapy_samples_get(PyObject *obj, const char *what, ssdapy_samples_t *s);
void ssdapy_samples_release(ssdapy_samples_t *s);

/* ---- arguments ---- */

/* Unsigned integer in lo..hi (numpy integers accepted): 0 or -1 with
   TypeError / ValueError naming the argument. */
int ssdapy_uint(PyObject *o, const char *name, unsigned long long lo, unsigned long long hi,
                unsigned long long *out);
int ssdapy_int(PyObject *o, const char *name, long long lo, long long hi, long long *out);

/* A size given as N or (W, H), each lo..hi. */
int ssdapy_size2(PyObject *o, const char *name, unsigned lo, unsigned hi, uint16_t *w,
                 uint16_t *h);

/* A name from a table ending with {NULL, 0}: 0 or -1 with ValueError
   listing the accepted names. */
typedef struct {
    const char *name;
    int value;
} ssdapy_name_t;
int ssdapy_enum(PyObject *o, const char *what, const ssdapy_name_t *table, int *out);
/* The keyword `name` as a name of table into *dst (absent or None: *dst
   kept). Returns 0 or -1 with an exception. */
/* The keyword `name` as a pair (x, y) of int32 into *x, *y: 1 when given,
   0 when absent or None (unchanged), -1 with an exception. */
int ssdapy_kw_xy(PyObject *kw, const char *name, int32_t *x, int32_t *y);
int ssdapy_kw_enum(PyObject *kw, const char *name, const ssdapy_name_t *table, uint8_t *dst);

/* Integer fields of a C config struct taken from keyword arguments by
   name: each in lo..hi, stored in `bytes` bytes (1, 2 or 4; signed when
   lo < 0). A table ends with {NULL}. Returns 0 or -1 with an exception. */
typedef struct {
    const char *name;
    size_t offset;
    int bytes;
    long long lo, hi;
} ssdapy_field_t;
int ssdapy_fields(PyObject *kw, void *base, const ssdapy_field_t *fields);
/* A boolean keyword setting or clearing bit in *flags (absent: unchanged). */
int ssdapy_flag(PyObject *kw, const char *name, uint8_t *flags, uint8_t bit);

/* Keyword arguments are taken one by one from a private copy of the call's
   kwargs, so that option groups (match options inside track options) are
   parsed by one function each; ssdapy_kw_done then rejects any left over. */
PyObject *ssdapy_kw_copy(PyObject *kw);          /* new dict (kw may be NULL) */
PyObject *ssdapy_kw_take(PyObject *kw, const char *name); /* new ref or NULL (absent) */
int ssdapy_kw_done(PyObject *kw, const char *func);      /* 0, or -1 with TypeError */

/* Positional arguments: exactly n (or between n and max) objects. */
int ssdapy_args(PyObject *args, const char *func, Py_ssize_t n, Py_ssize_t max,
                PyObject **out);

/* ---- results ---- */

/* numpy.empty(shape, dtype) as a new reference; ndim 0 or more. */
PyObject *ssdapy_np_empty(int ndim, const Py_ssize_t *shape, PyObject *dtype);
/* A struct sequence of `type` whose n fields are the integers v[0..n). */
PyObject *ssdapy_struct_seq(PyTypeObject *type, const unsigned long long *v, Py_ssize_t n);
/* numpy.empty with the dtype named by a string ("uint8", "int32", ...). */
PyObject *ssdapy_np_typed(int ndim, const Py_ssize_t *shape, const char *dtype);
/* A structured numpy dtype from names, formats and offsets (n fields) and
   the C struct's size, so that the library writes straight into it. */
PyObject *ssdapy_np_struct_dtype(Py_ssize_t n, const char *const *names,
                                 const char *const *formats, const size_t *offsets,
                                 size_t itemsize);
/* Pointer to a C-contiguous writable array's data (the array made by
   ssdapy_np_empty); NULL with an exception set otherwise. */
void *ssdapy_np_data(PyObject *array);

/* A C-contiguous numpy array of records of `dtype` (one of the binding's
   structured dtypes): *b holds its buffer (release it), *count its records.
   Returns 0, or -1 with TypeError (another dtype) or ValueError (not
   contiguous) naming what. */
int ssdapy_records(PyObject *obj, const char *what, PyObject *dtype, Py_buffer *b,
                   Py_ssize_t *count);

/* A struct-sequence type (a named tuple in C) added to the module. */
PyTypeObject *ssdapy_struct_type(PyObject *module, const char *name, const char *doc,
                                 PyStructSequence_Field *fields, int n_in_sequence);

/* ---- sources as job arguments (bind_stream.c) ---- */

/* A Source object (marked busy until released) or an array viewed in
   place as an in-RAM source. other: the job's other argument (a Source
   given twice is the library's to judge), or NULL. */
typedef struct {
    void *obj;              /* the Source object, or NULL */
    ssda_source_t local;    /* an array's in-RAM source */
    ssdapy_image_t img;
    int have_img;
    ssda_source_t *src;
    uint16_t width, height;
    uint8_t format;         /* SSDA_PIX_U8 / _U16 */
} ssdapy_src_arg_t;

/* 0, or -1 with an exception (what names the argument). */
int ssdapy_src_arg_get(PyObject *o, const char *what, ssdapy_src_arg_t *a,
                       const ssdapy_src_arg_t *other);
/* Release; 1 when the Source's read() raised (that exception is restored
   unless another is set), else 0. */
int ssdapy_src_arg_release(ssdapy_src_arg_t *a);

/* ---- feature inits (module.c calls these) ---- */

int ssdapy_init_match(PyObject *m);
int ssdapy_init_track(PyObject *m);
int ssdapy_init_grad(PyObject *m);
int ssdapy_init_pitch(PyObject *m);
int ssdapy_init_stream(PyObject *m);
int ssdapy_init_ncc(PyObject *m);
int ssdapy_init_shape(PyObject *m);
int ssdapy_init_symreg(PyObject *m);
int ssdapy_init_seg(PyObject *m);
int ssdapy_init_flow(PyObject *m);
int ssdapy_init_reg(PyObject *m);

/* numpy dtype of ssda_fd_t (bind_shape.c), shared with bind_symreg.c. */
extern PyObject *ssdapy_fd_dtype;

/* Shared by the search and tracking features (bind_match.c): take the
   search options (threshold, scan, order, bounds, k_q8, lambda_q8,
   fixed_threshold, predict, coarse_step) from kw into *cfg, starting from
   the binding's defaults (bounds on). *bounds tells whether a work buffer
   is needed. Returns 0 or -1 with an exception. */
int ssdapy_match_options(PyObject *kw, ssda_match_config_t *cfg, int allow_predict);
/* A MatchResult from a library result. */
PyObject *ssdapy_match_result(const ssda_match_result_t *r);
/* Take the tracking options (bind_track.c) into *cfg; cfg->match.work is
   left NULL (see ssdapy_track_work). */
int ssdapy_track_options(PyObject *kw, ssda_track_config_t *cfg);
/* The work buffer cfg needs (bounds tables, uniqueness list) on grid g, set
   into cfg; *work (PyMem) is freed by the caller. 0, or -1 (MemoryError). */
int ssdapy_track_work(ssda_track_config_t *cfg, const ssda_track_grid_t *g, void **work);
/* The TrackResult of a finished tracking call: vectors (rows x cols
   structured array, written by the library), grid and stats. */
PyObject *ssdapy_track_vectors(const ssda_track_grid_t *g, ssda_track_vector_t **data);
PyObject *ssdapy_track_result(PyObject *vectors, const ssda_track_grid_t *g,
                              const ssda_track_stats_t *s);

#endif /* SSDAPY_H */
