/* bind_symreg.c - registration by closed loops (seed 001): ssda.edges
   (ssda/edge.h), ssda.loops (edges, loops and their descriptors, the chain
   `ssda symreg` runs on each image) and ssda.symreg (ssda/symreg.h). Loops,
   descriptors and pairs are records in the library's own layouts. */
#include "ssdapy.h"
#include "ssda/edge.h"
#include "ssda/fourier.h"
#include "ssda/loops.h"
#include "ssda/symreg.h"

#include <stddef.h>

double ssdapy_turns_deg(uint32_t turns); /* bind_shape.c */

static PyTypeObject *edges_type, *edge_stats_type, *loops_type, *loop_stats_type,
    *symreg_type;
static PyObject *loop_dtype, *pair_dtype;

static PyStructSequence_Field edges_fields[] = {
    {"map", "(h, w) uint16 edge map: bits 0-7 strength, 8-9 direction, 10 ON (edge.h)"},
    {"stats", "EdgeStats of the refinement, or None with refine=False"},
    {NULL, NULL}};
static PyStructSequence_Field edge_stats_fields[] = {
    {"thinned", NULL}, {"ends", NULL}, {"ends_dropped", NULL}, {"extended", NULL},
    {"extend_joined", NULL}, {"closed_t", NULL}, {"closed_i", NULL}, {"closed_v", NULL},
    {"branch", NULL}, {"conn", NULL}, {"end", NULL}, {NULL, NULL}};
static PyStructSequence_Field loops_fields[] = {
    {"loops", "LOOP_DTYPE records (ssda_loop_t without its pointer), in raster order"},
    {"contours", "(n, samples, 2) int32: each loop's contour, Q8 px"},
    {"descriptors", "FD_DTYPE records: each contour's Fourier descriptors"},
    {"map", "the final (h, w) uint16 edge map (the loops' cycles ON)"},
    {"edge_stats", "EdgeStats"}, {"loop_stats", "LoopStats"}, {NULL, NULL}};
static PyStructSequence_Field loop_stats_fields[] = {
    {"pruned", NULL}, {"regions", NULL}, {"border", NULL}, {"too_small", NULL},
    {"too_large", NULL}, {"too_dark", NULL}, {"too_long", NULL}, {"loops", NULL},
    {"dropped", NULL}, {NULL, NULL}};
static PyStructSequence_Field symreg_fields[] = {
    {"affine", "(2, 3) float64: MOV x = a x + b y + c, MOV y = d x + e y + f (REF px)"},
    {"affine_q", "(a_q16, b_q16, c_q8, d_q16, e_q16, f_q8): the library's integers"},
    {"pairs", "PAIR_DTYPE records of the winning registration (ssda_symreg_pair_t)"},
    {"rms_q8", NULL}, {"scale_q16", NULL}, {"rotation", "turns"},
    {"rms", "rms_q8 / 256, px"}, {"scale", "scale_q16 / 65536"},
    {"rotation_deg", "rotation in degrees, -180 < r <= 180"},
    {"candidates", NULL}, {"nuclei", NULL}, {"best_nucleus", NULL}, {"matches", NULL},
    {"skipped", NULL}, {NULL, NULL}};

static const ssdapy_field_t refine_fields[] = {
    {"extend_min", offsetof(ssda_edge_refine_config_t, extend_min), 1, 0, 255},
    {"spur_min", offsetof(ssda_edge_refine_config_t, spur_min), 1, 0, 255},
    {"gap_max", offsetof(ssda_edge_refine_config_t, gap_max), 1, 0, 255},
    {"fit_len", offsetof(ssda_edge_refine_config_t, fit_len), 1, 0, 255},
    {"extend_max", offsetof(ssda_edge_refine_config_t, extend_max), 1, 0, 255},
    {"i_angle_deg", offsetof(ssda_edge_refine_config_t, i_angle_deg), 1, 0, 255},
    {"i_area_max", offsetof(ssda_edge_refine_config_t, i_area_max), 1, 0, 255},
    {"v_angle_deg", offsetof(ssda_edge_refine_config_t, v_angle_deg), 1, 0, 255},
    {NULL, 0, 0, 0, 0}};
static const ssdapy_field_t loops_cfg_fields[] = {
    {"grey_min", offsetof(ssda_loops_config_t, grey_min), 2, -1, 255},
    {"shape_max", offsetof(ssda_loops_config_t, shape_max), 2, 0, 65535},
    {"area_min", offsetof(ssda_loops_config_t, area_min), 4, 0, 0xFFFFFFFFll},
    {"area_max", offsetof(ssda_loops_config_t, area_max), 4, 0, 0xFFFFFFFFll},
    {"samples", offsetof(ssda_loops_config_t, samples), 2, 0, 65535},
    {NULL, 0, 0, 0, 0}};
#define U32F(field) {#field, offsetof(ssda_symreg_config_t, field), 4, 0, 0xFFFFFFFFll}
static const ssdapy_field_t symreg_cfg_fields[] = {
    {"nuclei", offsetof(ssda_symreg_config_t, nuclei), 2, 0, 65535},
    {"min_pairs", offsetof(ssda_symreg_config_t, min_pairs), 2, 0, 65535},
    U32F(e2_nucleus_q16), U32F(e2_grow_q16), U32F(e2_final_q16), U32F(scale_min_q16),
    U32F(scale_max_q16), U32F(area_ratio_q8), U32F(reach_q16), U32F(reach_min_q8),
    U32F(resid_max_q8), U32F(resid_mean_q8), U32F(shear_q16), {NULL, 0, 0, 0, 0}};


static PyObject *edge_stats_object(const ssda_edge_stats_t *s)
{
    const unsigned long long v[] = {s->thinned, s->ends, s->ends_dropped, s->extended, s->extend_joined,
                          s->closed_t, s->closed_i, s->closed_v, s->branch, s->conn, s->end};
    return ssdapy_struct_seq(edge_stats_type, v, (Py_ssize_t)(sizeof v / sizeof v[0]));
}

static PyObject *loop_stats_object(const ssda_loops_stats_t *s)
{
    const unsigned long long v[] = {s->pruned, s->regions, s->border, s->too_small, s->too_large,
                          s->too_dark, s->too_long, s->loops, s->dropped};
    return ssdapy_struct_seq(loop_stats_type, v, (Py_ssize_t)(sizeof v / sizeof v[0]));
}


static PyObject *head(PyObject *array, Py_ssize_t n)
{
    PyObject *stop = PyLong_FromSsize_t(n), *sl, *r;
    if (stop == NULL) {
        return NULL;
    }
    sl = PySlice_New(NULL, stop, NULL);
    Py_DECREF(stop);
    if (sl == NULL) {
        return NULL;
    }
    r = PyObject_GetItem(array, sl);
    Py_DECREF(sl);
    return r;
}

/* The options of the edge stage: strength, refine (bool), refine fields. */
typedef struct {
    uint8_t strength;
    int refine;
    ssda_edge_refine_config_t rc;
} edge_opts_t;

static int edge_options(PyObject *kw, edge_opts_t *o)
{
    static const ssdapy_field_t f[] = {
        {"strength", offsetof(edge_opts_t, strength), 1, 0, 255}, {NULL, 0, 0, 0, 0}};
    PyObject *v;
    memset(o, 0, sizeof *o);
    o->refine = 1;
    if (ssdapy_fields(kw, o, f) != 0 || ssdapy_fields(kw, &o->rc, refine_fields) != 0 ||
        ssdapy_flag(kw, "no_close", &o->rc.no_close, 1u) != 0) {
        return -1;
    }
    if ((v = ssdapy_kw_take(kw, "refine")) != NULL) {
        o->refine = PyObject_IsTrue(v);
        Py_DECREF(v);
        if (o->refine < 0) {
            return -1;
        }
    }
    return 0;
}

/* Ends provisioned for the refinement: one per 16 pixels is far above what
   edges of real images leave (as `ssda symreg`); more are counted in
   ends_dropped. */
static size_t ends_for(uint32_t w, uint32_t h)
{
    return (size_t)w * h / 16u + 64u;
}

/* Detect (and refine) into map; work of work_size bytes. GIL released. */
static int run_edges(const ssda_view_t *v, const edge_opts_t *o, uint16_t *map, uint8_t *ring,
                     void *work, size_t edge_work, ssda_edge_stats_t *st)
{
    int e = ssda_edge_detect(v, o->strength, map, SSDA_EDGE_MAP_SIZE(v->width, v->height),
                             ring, SSDA_EDGE_RING_SIZE(v->width));
    if (e == SSDA_OK && o->refine) {
        e = ssda_edge_refine(map, v->width, v->height, &o->rc, work, edge_work, st);
    }
    return e;
}

static PyObject *py_edges(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc = NULL, *map = NULL, *out = NULL, *st_o = NULL;
    ssdapy_image_t img;
    edge_opts_t o;
    ssda_edge_stats_t st;
    uint8_t *ring = NULL;
    void *work = NULL, *m;
    size_t ew;
    int e;
    (void)self;
    if (ssdapy_args(args, "edges", 1, 1, a) != 0 || ssdapy_image_get(a[0], "image", &img) != 0) {
        return NULL;
    }
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || edge_options(kwc, &o) != 0 ||
        ssdapy_kw_done(kwc, "edges") != 0) {
        goto done;
    }
    ew = SSDA_EDGE_WORK_SIZE(ends_for(img.view.width, img.view.height));
    {
        const Py_ssize_t shape[2] = {img.view.height, img.view.width};
        map = ssdapy_np_typed(2, shape, "uint16");
    }
    ring = PyMem_Malloc(SSDA_EDGE_RING_SIZE(img.view.width));
    work = PyMem_Malloc(ew);
    if (map == NULL || (m = ssdapy_np_data(map)) == NULL) {
        goto done;
    }
    if (ring == NULL || work == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    SSDAPY_NOGIL(e = run_edges(&img.view, &o, m, ring, work, ew, &st));
    if (e != SSDA_OK) {
        ssdapy_error(e, o.refine ? "ssda_edge_detect / ssda_edge_refine" : "ssda_edge_detect");
        goto done;
    }
    if (o.refine) {
        st_o = edge_stats_object(&st);
    } else {
        st_o = Py_None;
        Py_INCREF(st_o);
    }
    if (st_o != NULL && (out = PyStructSequence_New(edges_type)) != NULL) {
        Py_INCREF(map);
        PyStructSequence_SET_ITEM(out, 0, map);
        PyStructSequence_SET_ITEM(out, 1, st_o);
        st_o = NULL;
    }
done:
    Py_XDECREF(st_o);
    Py_XDECREF(map);
    Py_XDECREF(kwc);
    PyMem_Free(ring);
    PyMem_Free(work);
    ssdapy_image_release(&img);
    return out;
}

typedef struct {
    const ssda_view_t *v;
    edge_opts_t eo;
    ssda_loops_config_t lc;
    uint32_t order, max_loops, samples, n;
    uint16_t *map;
    uint8_t *ring;
    void *work;
    size_t edge_work, loop_work;
    ssda_loop_t *loops;
    ssda_point_q8_t *points;
    ssda_fd_t *fds;
    ssda_edge_stats_t es;
    ssda_loops_stats_t ls;
    const char *failed;
} chain_t;

/* Edges, loops, descriptors (no GIL). Returns the library's code; c->failed
   names the call that failed. */
static int run_chain(chain_t *c)
{
    uint32_t i;
    int e = run_edges(c->v, &c->eo, c->map, c->ring, c->work, c->edge_work, &c->es);
    c->failed = "ssda_edge_detect / ssda_edge_refine";
    if (e != SSDA_OK) {
        return e;
    }
    c->failed = "ssda_loops_find";
    e = ssda_loops_find(c->map, c->v, &c->lc, c->work, c->loop_work, c->loops, c->max_loops,
                        c->points, SSDA_LOOPS_POINTS_SIZE(c->max_loops, c->samples), &c->n,
                        &c->ls);
    c->failed = "ssda_fd_compute";
    for (i = 0; e == SSDA_OK && i < c->n; i++) {
        e = ssda_fd_compute(c->loops[i].contour, c->samples, c->order, &c->fds[i]);
    }
    return e;
}

static PyObject *py_loops(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[1], *kwc = NULL, *map = NULL, *lo = NULL, *pts = NULL, *fds = NULL,
             *out = NULL, *v;
    ssdapy_image_t img;
    chain_t c;
    unsigned long long u;
    int e;
    (void)self;
    if (ssdapy_args(args, "loops", 1, 1, a) != 0 || ssdapy_image_get(a[0], "image", &img) != 0) {
        return NULL;
    }
    memset(&c, 0, sizeof c);
    c.v = &img.view;
    c.max_loops = SSDA_SYMREG_MAX_LOOPS;
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || edge_options(kwc, &c.eo) != 0 ||
        ssdapy_fields(kwc, &c.lc, loops_cfg_fields) != 0) {
        goto done;
    }
    if ((v = ssdapy_kw_take(kwc, "order")) != NULL) {
        int rc = ssdapy_uint(v, "order", 0, 0xFFFFFFFFu, &u);
        Py_DECREF(v);
        if (rc != 0) {
            goto done;
        }
        c.order = (uint32_t)u;
    }
    if ((v = ssdapy_kw_take(kwc, "max_loops")) != NULL) {
        int rc = ssdapy_uint(v, "max_loops", 0, 0xFFFFFFFFu, &u);
        Py_DECREF(v);
        if (rc != 0) {
            goto done;
        }
        c.max_loops = (uint32_t)u;
    }
    if (ssdapy_kw_done(kwc, "loops") != 0) {
        goto done;
    }
    {
        /* loops are disjoint regions of at least area_min pixels */
        const uint32_t amin = c.lc.area_min != 0u ? c.lc.area_min : SSDA_LOOPS_DEFAULT_AREA_MIN;
        const uint64_t most = (uint64_t)img.view.width * img.view.height / amin + 1u;
        const uint32_t area_max = c.lc.area_max != 0u ? c.lc.area_max
                                                      : SSDA_LOOPS_DEFAULT_AREA_MAX;
        if (most < c.max_loops) {
            c.max_loops = (uint32_t)most;
        }
        c.samples = c.lc.samples != 0u ? c.lc.samples : SSDA_LOOPS_DEFAULT_SAMPLES;
        if (c.samples > SSDA_LOOPS_MAX_SAMPLES) {
            c.samples = SSDA_LOOPS_MAX_SAMPLES; /* ssda_loops_find refuses it anyway */
        }
        c.edge_work = SSDA_EDGE_WORK_SIZE(ends_for(img.view.width, img.view.height));
        c.loop_work = SSDA_LOOPS_WORK_SIZE(area_max);
    }
    {
        const Py_ssize_t mshape[2] = {img.view.height, img.view.width};
        const Py_ssize_t lshape[1] = {c.max_loops};
        const Py_ssize_t pshape[3] = {c.max_loops, c.samples, 2};
        map = ssdapy_np_typed(2, mshape, "uint16");
        lo = map != NULL ? ssdapy_np_empty(1, lshape, loop_dtype) : NULL;
        pts = lo != NULL ? ssdapy_np_typed(3, pshape, "int32") : NULL;
        fds = pts != NULL ? ssdapy_np_empty(1, lshape, ssdapy_fd_dtype) : NULL;
    }
    if (fds == NULL || (c.map = ssdapy_np_data(map)) == NULL ||
        (c.loops = ssdapy_np_data(lo)) == NULL || (c.points = ssdapy_np_data(pts)) == NULL ||
        (c.fds = ssdapy_np_data(fds)) == NULL) {
        goto done;
    }
    c.ring = PyMem_Malloc(SSDA_EDGE_RING_SIZE(img.view.width));
    c.work = PyMem_Malloc(c.edge_work > c.loop_work ? c.edge_work : c.loop_work);
    if (c.ring == NULL || c.work == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    SSDAPY_NOGIL(e = run_chain(&c));
    if (e != SSDA_OK) {
        ssdapy_error(e, c.failed);
        goto done;
    }
    if ((out = PyStructSequence_New(loops_type)) != NULL) {
        PyStructSequence_SET_ITEM(out, 0, head(lo, c.n));
        PyStructSequence_SET_ITEM(out, 1, head(pts, c.n));
        PyStructSequence_SET_ITEM(out, 2, head(fds, c.n));
        Py_INCREF(map);
        PyStructSequence_SET_ITEM(out, 3, map);
        PyStructSequence_SET_ITEM(out, 4, c.eo.refine ? edge_stats_object(&c.es)
                                                      : (Py_INCREF(Py_None), Py_None));
        PyStructSequence_SET_ITEM(out, 5, loop_stats_object(&c.ls));
        if (PyErr_Occurred()) {
            Py_CLEAR(out);
        }
    }
done:
    PyMem_Free(c.ring);
    PyMem_Free(c.work);
    Py_XDECREF(map);
    Py_XDECREF(lo);
    Py_XDECREF(pts);
    Py_XDECREF(fds);
    Py_XDECREF(kwc);
    ssdapy_image_release(&img);
    return out;
}

/* loops and descriptors of a LoopsResult (or any object with both). */
typedef struct {
    Py_buffer lb, fb;
    int have_l, have_f;
    Py_ssize_t n;
} side_t;

static void side_release(side_t *s)
{
    if (s->have_l) {
        PyBuffer_Release(&s->lb);
    }
    if (s->have_f) {
        PyBuffer_Release(&s->fb);
    }
    s->have_l = s->have_f = 0;
}

static int side_get(PyObject *o, const char *what, side_t *s)
{
    PyObject *l = PyObject_GetAttrString(o, "loops"), *f;
    Py_ssize_t nf;
    char name[64];
    memset(s, 0, sizeof *s);
    f = l != NULL ? PyObject_GetAttrString(o, "descriptors") : NULL;
    if (f == NULL) {
        Py_XDECREF(l);
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "%s must be a LoopsResult (ssda.loops), got %s", what,
                     Py_TYPE(o)->tp_name);
        return -1;
    }
    snprintf(name, sizeof name, "%s.loops", what);
    s->have_l = ssdapy_records(l, name, loop_dtype, &s->lb, &s->n) == 0;
    snprintf(name, sizeof name, "%s.descriptors", what);
    s->have_f = s->have_l && ssdapy_records(f, name, ssdapy_fd_dtype, &s->fb, &nf) == 0;
    Py_DECREF(l);
    Py_DECREF(f);
    if (!s->have_f) {
        side_release(s);
        return -1;
    }
    if (nf != s->n) {
        side_release(s);
        PyErr_Format(PyExc_ValueError, "%s: %zd loops but %zd descriptors", what, s->n, nf);
        return -1;
    }
    return 0;
}

static PyObject *symreg_object(const ssda_symreg_result_t *r, PyObject *pairs)
{
    const ssda_symreg_affine_t *t = &r->affine;
    PyObject *o, *aff;
    const Py_ssize_t shape[2] = {2, 3};
    double *A;
    Py_ssize_t i;
    const uint32_t tail[] = {r->candidates, r->nuclei, r->best_nucleus, r->matches, r->skipped};
    aff = ssdapy_np_typed(2, shape, "float64");
    if (aff == NULL || (A = ssdapy_np_data(aff)) == NULL) {
        Py_XDECREF(aff);
        return NULL;
    }
    A[0] = t->a_q16 / 65536.0; /* as the ssda tool writes them */
    A[1] = t->b_q16 / 65536.0;
    A[2] = t->c_q8 / 256.0;
    A[3] = t->d_q16 / 65536.0;
    A[4] = t->e_q16 / 65536.0;
    A[5] = t->f_q8 / 256.0;
    if ((o = PyStructSequence_New(symreg_type)) == NULL) {
        Py_DECREF(aff);
        return NULL;
    }
    PyStructSequence_SET_ITEM(o, 0, aff);
    PyStructSequence_SET_ITEM(o, 1, Py_BuildValue("(llllll)", (long)t->a_q16, (long)t->b_q16,
                                                  (long)t->c_q8, (long)t->d_q16,
                                                  (long)t->e_q16, (long)t->f_q8));
    Py_INCREF(pairs);
    PyStructSequence_SET_ITEM(o, 2, pairs);
    PyStructSequence_SET_ITEM(o, 3, PyLong_FromUnsignedLong(r->rms_q8));
    PyStructSequence_SET_ITEM(o, 4, PyLong_FromUnsignedLong(r->scale_q16));
    PyStructSequence_SET_ITEM(o, 5, PyLong_FromUnsignedLong(r->rotation));
    PyStructSequence_SET_ITEM(o, 6, PyFloat_FromDouble(r->rms_q8 / 256.0));
    PyStructSequence_SET_ITEM(o, 7, PyFloat_FromDouble(r->scale_q16 / 65536.0));
    PyStructSequence_SET_ITEM(o, 8, PyFloat_FromDouble(ssdapy_turns_deg(r->rotation)));
    for (i = 0; i < 5; i++) {
        PyStructSequence_SET_ITEM(o, 9 + i, PyLong_FromUnsignedLong(tail[i]));
    }
    if (PyErr_Occurred()) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

static PyObject *py_symreg(PyObject *self, PyObject *args, PyObject *kw)
{
    PyObject *a[2], *kwc = NULL, *pairs = NULL, *out = NULL, *sel;
    side_t ref, mov;
    ssda_symreg_config_t cfg;
    ssda_symreg_result_t res;
    void *work = NULL, *pp;
    size_t ws;
    int e;
    (void)self;
    if (ssdapy_args(args, "symreg", 2, 2, a) != 0 || side_get(a[0], "ref", &ref) != 0) {
        return NULL;
    }
    if (side_get(a[1], "mov", &mov) != 0) {
        side_release(&ref);
        return NULL;
    }
    memset(&cfg, 0, sizeof cfg);
    if ((kwc = ssdapy_kw_copy(kw)) == NULL || ssdapy_fields(kwc, &cfg, symreg_cfg_fields) != 0 ||
        ssdapy_kw_done(kwc, "symreg") != 0) {
        goto done;
    }
    ws = SSDA_SYMREG_WORK_SIZE(ref.n, mov.n,
                               cfg.nuclei != 0u ? cfg.nuclei : SSDA_SYMREG_DEFAULT_NUCLEI);
    {
        const Py_ssize_t shape[1] = {ref.n};
        pairs = ssdapy_np_empty(1, shape, pair_dtype);
    }
    if (pairs == NULL || (pp = ssdapy_np_data(pairs)) == NULL) {
        goto done;
    }
    if ((work = PyMem_Malloc(ws)) == NULL) {
        PyErr_NoMemory();
        goto done;
    }
    SSDAPY_NOGIL(e = ssda_symreg(ref.lb.buf, ref.fb.buf, (uint32_t)ref.n, mov.lb.buf, mov.fb.buf,
                                 (uint32_t)mov.n, &cfg, work, ws, pp, (uint32_t)ref.n, &res));
    if (e != SSDA_OK) {
        ssdapy_error(e, "ssda_symreg");
        goto done;
    }
    if ((sel = head(pairs, res.pairs)) != NULL) {
        out = symreg_object(&res, sel);
        Py_DECREF(sel);
    }
done:
    PyMem_Free(work);
    Py_XDECREF(pairs);
    Py_XDECREF(kwc);
    side_release(&ref);
    side_release(&mov);
    return out;
}

#define EDGE_OPTS                                                                    \
    "strength=0, refine=True, extend_min=0, spur_min=0, gap_max=0, fit_len=0, "      \
    "extend_max=0, i_angle_deg=0, i_area_max=0, v_angle_deg=0, no_close=False"

static PyMethodDef methods[] = {
    {"edges", (PyCFunction)(void (*)(void))py_edges, METH_VARARGS | METH_KEYWORDS,
     "edges(image, /, *, " EDGE_OPTS ")\n--\n\n"
     "The seed 001 edge stage on a 2-D uint8 image of at least 5 x 5: the 5 x 5\n"
     "two-region operator and ridge thinning (ssda_edge_detect; strength: threshold,\n"
     "0 = 15), then, unless refine=False, the 3 x 3 thinning, end extension and gap\n"
     "closing (ssda_edge_refine; the other options are ssda_edge_refine_config_t's\n"
     "fields, 0 = the seed's). Returns Edges(map, stats)."},
    {"loops", (PyCFunction)(void (*)(void))py_loops, METH_VARARGS | METH_KEYWORDS,
     "loops(image, /, *, " EDGE_OPTS ", grey_min=0, shape_max=0, area_min=0, area_max=0, "
     "samples=0, order=0, max_loops=4096)\n--\n\n"
     "Closed loops of a 2-D uint8 image as symbols, the chain `ssda symreg` runs on\n"
     "each image: edges (as edges()), ssda_loops_find (grey_min -1 = no grey filter;\n"
     "0 = the seed's values) and each contour's Fourier descriptors (order).\n"
     "Returns LoopsResult(loops, contours, descriptors, map, edge_stats, loop_stats);\n"
     "loops beyond max_loops are counted in loop_stats.dropped. The GIL is released."},
    {"symreg", (PyCFunction)(void (*)(void))py_symreg, METH_VARARGS | METH_KEYWORDS,
     "symreg(ref, mov, /, *, nuclei=0, min_pairs=0, e2_nucleus_q16=0, e2_grow_q16=0, "
     "e2_final_q16=0, scale_min_q16=0, scale_max_q16=0, area_ratio_q8=0, reach_q16=0, "
     "reach_min_q8=0, resid_max_q8=0, resid_mean_q8=0, shear_q16=0)\n--\n\n"
     "Registers MOV to REF by their loops (ssda_symreg, ssda/symreg.h): ref and mov\n"
     "are LoopsResults of loops(). Options: ssda_symreg_config_t's fields (0 = the\n"
     "defaults). Returns SymregResult: affine (2 x 3, REF px -> MOV px), its\n"
     "integers, the pairs (PAIR_DTYPE records; none when no registration was\n"
     "found), rms, scale, rotation_deg and the search's counts."},
    {NULL, NULL, 0, NULL}};

int ssdapy_init_symreg(PyObject *m)
{
    static const char *const lnames[] = {"cx_q8", "cy_q8", "area", "perimeter_q8",
                                         "mean_q8", "x0", "y0", "x1", "y1"};
    static const char *const lformats[] = {"i4", "i4", "u4", "u4", "u4", "u2", "u2", "u2", "u2"};
    static const size_t loffsets[] = {
        offsetof(ssda_loop_t, cx_q8), offsetof(ssda_loop_t, cy_q8),
        offsetof(ssda_loop_t, area), offsetof(ssda_loop_t, perimeter_q8),
        offsetof(ssda_loop_t, mean_q8), offsetof(ssda_loop_t, x0), offsetof(ssda_loop_t, y0),
        offsetof(ssda_loop_t, x1), offsetof(ssda_loop_t, y1)};
    static const char *const pnames[] = {"ref", "mov", "s_q16", "phi", "e2_q16",
                                         "e2_fixed_q16", "resid_q8"};
    static const char *const pformats[] = {"u2", "u2", "u4", "u4", "u4", "u4", "u4"};
    static const size_t poffsets[] = {
        offsetof(ssda_symreg_pair_t, ref), offsetof(ssda_symreg_pair_t, mov),
        offsetof(ssda_symreg_pair_t, s_q16), offsetof(ssda_symreg_pair_t, phi),
        offsetof(ssda_symreg_pair_t, e2_q16), offsetof(ssda_symreg_pair_t, e2_fixed_q16),
        offsetof(ssda_symreg_pair_t, resid_q8)};
    edges_type = ssdapy_struct_type(m, "ssda.Edges", "Result of edges.", edges_fields, 2);
    edge_stats_type = ssdapy_struct_type(m, "ssda.EdgeStats",
                                         "What ssda_edge_refine did (ssda_edge_stats_t).",
                                         edge_stats_fields, 11);
    loops_type = ssdapy_struct_type(m, "ssda.LoopsResult", "Result of loops.", loops_fields, 6);
    loop_stats_type = ssdapy_struct_type(m, "ssda.LoopStats",
                                         "What ssda_loops_find saw (ssda_loops_stats_t).",
                                         loop_stats_fields, 9);
    symreg_type = ssdapy_struct_type(m, "ssda.SymregResult",
                                     "Result of symreg (ssda_symreg_result_t).", symreg_fields,
                                     14);
    if (edges_type == NULL || edge_stats_type == NULL || loops_type == NULL ||
        loop_stats_type == NULL || symreg_type == NULL) {
        return -1;
    }
    loop_dtype = ssdapy_np_struct_dtype(9, lnames, lformats, loffsets, sizeof(ssda_loop_t));
    pair_dtype = ssdapy_np_struct_dtype(7, pnames, pformats, poffsets,
                                        sizeof(ssda_symreg_pair_t));
    if (loop_dtype == NULL || pair_dtype == NULL) {
        return -1;
    }
    Py_INCREF(loop_dtype);
    Py_INCREF(pair_dtype);
    if (PyModule_AddObject(m, "LOOP_DTYPE", loop_dtype) != 0 ||
        PyModule_AddObject(m, "PAIR_DTYPE", pair_dtype) != 0) {
        return -1;
    }
    return PyModule_AddFunctions(m, methods);
}
