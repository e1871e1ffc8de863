/* cmd_symreg.c - `ssda symreg REF.png MOV.png`: registration of two images by
   their closed loops (seed 001): edges, loops, Fourier descriptors, nuclei
   grown into an affine transform. */
#include "cli.h"
#include "draw_loops.h"
#include "json_out.h"
#include "loops_run.h"
#include "warp_affine.h"
#include "ssda/symreg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: ssda symreg REF.png MOV.png [options]\n"
    "\n"
    "Registers MOV to REF by closed loops of edges (Ishii and Hattori 1985): 5x5\n"
    "two-region edges, thinning, gap closing, the regions the edges enclose as\n"
    "symbols, Fourier descriptors matched with optimal scale, rotation and start\n"
    "point, and an affine transform grown from the best pairs by least squares on\n"
    "the loops' centroids. Works across rotation, scale and brightness changes\n"
    "when both images hold closed outlines (buildings, fields, blobs); needs at\n"
    "least 6 loops matched (--min-pairs).\n"
    "\n"
    "Prints the transform REF (x, y) -> MOV (a x + b y + c, d x + e y + f), the\n"
    "pairs and the RMS residual of the centroids.\n"
    "\n"
    "outputs:\n"
    "  --json F          loops_ref, loops_mov (counts), pairs (both centroids, s,\n"
    "                    phi_deg, e2, ...), affine [a,b,c,d,e,f], rms (\"-\": stdout)\n"
    "  --overlay F.png   both images, their loops, matched pairs joined\n"
    "  -o OUT.png        MOV resampled onto REF's grid (bilinear; outside: 0)\n"
    "loops (defaults: the seed's):\n"
    "  --strength N      edge strength for the ridge thinning, 1..255 (15)\n"
    "  --grey-min N      keep loops of mean grey >= N in both, 0..255 (50; 0 = all)\n"
    "  --grey-min-ref N, --grey-min-mov N   the same per image\n"
    "  --area MIN,MAX    loop area in pixels (50,1000)\n"
    "  --shape N         largest perimeter^2 / area (30)\n"
    "  --gap N           reach of the T, I, V gap closing, px, 1..64 (10)\n"
    "  --samples N       contour samples, a power of two 8..1024 (64)\n"
    "  --order N         Fourier descriptor order, 1..16 (10)\n"
    "registration:\n"
    "  --nuclei N        nucleus pairs tried, 1..1000 (100; the seed used about 30)\n"
    "  --min-pairs N     pairs a registration needs, 3.. (6; the seed's least is 3)\n"
    "  --scale MIN,MAX   scales MOV/REF searched, e.g. 0.5,2 (default)\n"
    "  -q, --quiet       no summary on stdout\n"
    "  -h, --help        this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input or no registration (too few loops found or\n"
    "matched: the message names the counts), 2 usage.\n";

typedef struct {
    const char *json, *overlay, *out;
    loops_run_cfg_t ref, mov;
    ssda_symreg_config_t reg;
    int quiet;
} symreg_opts_t;

static int parse_ratio_pair(const char *s, double lo, double hi, double *a, double *b)
{
    char buf[64];
    char *comma;
    if (strlen(s) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    comma = strchr(buf, ',');
    if (comma == NULL) {
        return -1;
    }
    *comma = '\0';
    if (cli_parse_double(buf, lo, hi, a) != 0 || cli_parse_double(comma + 1, lo, hi, b) != 0 ||
        *a > *b) {
        return -1;
    }
    return 0;
}

/* grey_min of a loops config from 0..255 (0: no grey filter). */
static int16_t grey_of(uint32_t u)
{
    return u == 0 ? (int16_t)SSDA_LOOPS_GREY_ANY : (int16_t)u;
}

#define NEED_U32(name, lo_, hi_, range)                                                   \
    if (v == NULL) { /* cli_opt said so */                                                \
        return -1;                                                                        \
    }                                                                                     \
    if (cli_parse_u32(v, lo_, hi_, &u) != 0) {                                            \
        cli_usage_error(a->cmd, "bad " name " '%s' (" range ")", v);                      \
        return -1;                                                                        \
    }

/* An option of the loops' stages into o; 0 if not one, 1 taken, -1 after
   a usage error. */
static int take_loops(cli_args_t *a, symreg_opts_t *o)
{
    const char *v = NULL;
    uint32_t u = 0;
    int32_t lo, hi;
    if (cli_opt(a, "--strength", &v)) {
        NEED_U32("--strength", 1, 255, "1..255");
        o->ref.strength = o->mov.strength = (uint8_t)u;
    } else if (cli_opt(a, "--grey-min", &v)) {
        NEED_U32("--grey-min", 0, 255, "0..255");
        o->ref.loops.grey_min = o->mov.loops.grey_min = grey_of(u);
    } else if (cli_opt(a, "--grey-min-ref", &v)) {
        NEED_U32("--grey-min-ref", 0, 255, "0..255");
        o->ref.loops.grey_min = grey_of(u);
    } else if (cli_opt(a, "--grey-min-mov", &v)) {
        NEED_U32("--grey-min-mov", 0, 255, "0..255");
        o->mov.loops.grey_min = grey_of(u);
    } else if (cli_opt(a, "--area", &v)) {
        if (v == NULL) {
            return -1;
        }
        if (cli_parse_pair(v, 1, 1 << 20, &lo, &hi) != 0 || lo > hi) {
            cli_usage_error(a->cmd, "bad --area '%s' (MIN,MAX in 1..1048576)", v);
            return -1;
        }
        o->ref.loops.area_min = o->mov.loops.area_min = (uint32_t)lo;
        o->ref.loops.area_max = o->mov.loops.area_max = (uint32_t)hi;
    } else if (cli_opt(a, "--shape", &v)) {
        NEED_U32("--shape", 1, 65535, "1..65535");
        o->ref.loops.shape_max = o->mov.loops.shape_max = (uint16_t)u;
    } else if (cli_opt(a, "--gap", &v)) {
        NEED_U32("--gap", 1, 64, "1..64");
        o->ref.refine.gap_max = o->mov.refine.gap_max = (uint8_t)u;
    } else {
        return 0;
    }
    return a->bad ? -1 : 1;
}

/* An option of the descriptors or the registration into o; as take_loops. */
static int take_registration(cli_args_t *a, symreg_opts_t *o)
{
    const char *v = NULL;
    uint32_t u = 0;
    double d1, d2;
    if (cli_opt(a, "--samples", &v)) {
        NEED_U32("--samples", 8, 1024, "a power of two, 8..1024");
        if ((u & (u - 1)) != 0) {
            cli_usage_error(a->cmd, "bad --samples '%s' (a power of two, 8..1024)", v);
            return -1;
        }
        o->ref.loops.samples = o->mov.loops.samples = (uint16_t)u;
    } else if (cli_opt(a, "--order", &v)) {
        NEED_U32("--order", 1, SSDA_FD_MAX_ORDER, "1..16");
        o->ref.order = o->mov.order = u;
    } else if (cli_opt(a, "--nuclei", &v)) {
        NEED_U32("--nuclei", 1, 1000, "1..1000");
        o->reg.nuclei = (uint16_t)u;
    } else if (cli_opt(a, "--min-pairs", &v)) {
        NEED_U32("--min-pairs", 3, SSDA_SYMREG_MAX_LOOPS, "3..4096");
        o->reg.min_pairs = (uint16_t)u;
    } else if (cli_opt(a, "--scale", &v)) {
        if (v == NULL) {
            return -1;
        }
        if (parse_ratio_pair(v, 1.0 / 16.0, 16.0, &d1, &d2) != 0) {
            cli_usage_error(a->cmd, "bad --scale '%s' (MIN,MAX within 1/16..16)", v);
            return -1;
        }
        o->reg.scale_min_q16 = (uint32_t)lround(d1 * 65536.0);
        o->reg.scale_max_q16 = (uint32_t)lround(d2 * 65536.0);
    } else {
        return 0;
    }
    return a->bad ? -1 : 1;
}
#undef NEED_U32

/* One option into o; 0 if not ours, 1 taken, -1 after a usage error. */
static int take(cli_args_t *a, symreg_opts_t *o)
{
    const char *v = NULL;
    int t;
    if (cli_opt(a, "--json", &v)) {
        o->json = v;
    } else if (cli_opt(a, "--overlay", &v)) {
        o->overlay = v;
    } else if (cli_opt(a, "-o", &v)) {
        o->out = v;
    } else if (cli_flag(a, "--quiet") || cli_flag(a, "-q")) {
        o->quiet = 1;
    } else if ((t = take_loops(a, o)) != 0 || (t = take_registration(a, o)) != 0) {
        return t;
    } else {
        return 0;
    }
    return a->bad ? -1 : 1;
}

/* The options into o; CLI_OK, or the exit code (--help: CLI_OK with
   *done set). */
static int parse(cli_args_t *a, symreg_opts_t *o, int *done)
{
    int t;
    while (cli_next(a)) {
        if (cli_flag(a, "--help") || cli_flag(a, "-h")) {
            fputs(help, stdout);
            *done = 1;
            return CLI_OK;
        }
        t = take(a, o);
        if (t < 0 || a->bad) {
            return CLI_USAGE;
        }
        if (t == 0) {
            return cli_unknown(a);
        }
    }
    if (a->bad) {
        return CLI_USAGE;
    }
    if (a->npos != 2) {
        return cli_usage_error(a->cmd, "need REF.png and MOV.png");
    }
    return CLI_OK;
}

static double deg(uint32_t turns)
{
    const double d = turns * (360.0 / 4294967296.0);
    return d > 180.0 ? d - 360.0 : d;
}

static void affine_doubles(const ssda_symreg_affine_t *t, double A[6])
{
    A[0] = t->a_q16 / 65536.0;
    A[1] = t->b_q16 / 65536.0;
    A[2] = t->c_q8 / 256.0;
    A[3] = t->d_q16 / 65536.0;
    A[4] = t->e_q16 / 65536.0;
    A[5] = t->f_q8 / 256.0;
}

static cJSON *point(int32_t x_q8, int32_t y_q8)
{
    const double v[2] = {x_q8 / 256.0, y_q8 / 256.0};
    return cJSON_CreateDoubleArray(v, 2);
}

static cJSON *pair_json(const ssda_symreg_pair_t *p, const loops_run_t *r, const loops_run_t *m)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "ref_index", p->ref);
    cJSON_AddNumberToObject(o, "mov_index", p->mov);
    cJSON_AddItemToObject(o, "ref", point(r->loops[p->ref].cx_q8, r->loops[p->ref].cy_q8));
    cJSON_AddItemToObject(o, "mov", point(m->loops[p->mov].cx_q8, m->loops[p->mov].cy_q8));
    cJSON_AddNumberToObject(o, "s", p->s_q16 / 65536.0);
    cJSON_AddNumberToObject(o, "phi_deg", deg(p->phi));
    cJSON_AddNumberToObject(o, "e2", p->e2_q16 / 65536.0);
    cJSON_AddNumberToObject(o, "e2_fixed", p->e2_fixed_q16 / 65536.0);
    cJSON_AddNumberToObject(o, "resid", p->resid_q8 / 256.0);
    cJSON_AddNumberToObject(o, "ref_area", r->loops[p->ref].area);
    cJSON_AddNumberToObject(o, "mov_area", m->loops[p->mov].area);
    return o;
}

/* The document (json_out.h's layout); 0, or -1 out of memory. */
static int write_json(FILE *f, const char *ref_path, const char *mov_path, const loops_run_t *r,
                      const loops_run_t *m, const ssda_symreg_result_t *res,
                      const ssda_symreg_pair_t *pairs)
{
    cJSON *doc = json_out_object(), *arr;
    double A[6];
    uint32_t i;
    int rc;
    affine_doubles(&res->affine, A);
    json_out_add_string(doc, "ref", ref_path);
    json_out_add_string(doc, "mov", mov_path);
    cJSON_AddNumberToObject(doc, "loops_ref", r->n);
    cJSON_AddNumberToObject(doc, "loops_mov", m->n);
    arr = cJSON_AddArrayToObject(doc, "pairs");
    for (i = 0; i < res->pairs; i++) {
        cJSON_AddItemToArray(arr, pair_json(&pairs[i], r, m));
    }
    cJSON_AddItemToObject(doc, "affine", cJSON_CreateDoubleArray(A, 6));
    cJSON_AddNumberToObject(doc, "rms", res->rms_q8 / 256.0);
    cJSON_AddNumberToObject(doc, "scale", res->scale_q16 / 65536.0);
    cJSON_AddNumberToObject(doc, "rotation_deg", deg(res->rotation));
    cJSON_AddNumberToObject(doc, "candidates", res->candidates);
    cJSON_AddNumberToObject(doc, "nuclei", res->nuclei);
    /* the library's buffers: each image's chain, and the registration's work */
    json_out_add_u64(doc, "lib_bytes_ref", r->lib_bytes);
    json_out_add_u64(doc, "lib_bytes_mov", m->lib_bytes);
    json_out_add_u64(doc, "lib_bytes_symreg", SSDA_SYMREG_WORK_SIZE(r->n, m->n, res->nuclei));
    rc = json_out_print(f, doc, NULL);
    cJSON_Delete(doc);
    return rc;
}

static int load8(const char *cmd, const char *path, gray_image_t *g)
{
    if (cli_load_png(cmd, path, PNG_GRAY_8, g) != 0) {
        return -1;
    }
    if (g->width < SSDA_EDGE_MIN_DIM || g->height < SSDA_EDGE_MIN_DIM) {
        cli_input_error(cmd, "'%s' is %u x %u; loops need at least 5 x 5", path, g->width,
                        g->height);
        gray_image_free(g);
        return -1;
    }
    return 0;
}

/* Write every output (all or nothing). */
static int outputs(const char *cmd, const symreg_opts_t *o, const char *ref_path,
                   const char *mov_path, const gray_image_t *ri, const gray_image_t *mi,
                   const loops_run_t *r, const loops_run_t *m, const ssda_symreg_result_t *res,
                   const ssda_symreg_pair_t *pairs)
{
    cli_outputs_t out;
    FILE *f;
    char err[512];
    cli_outputs_begin(&out, cmd);
    if (o->json != NULL) {
        if ((f = cli_outputs_open(&out, o->json)) == NULL ||
            write_json(f, ref_path, mov_path, r, m, res, pairs) != 0) {
            cli_outputs_abort(&out);
            return f == NULL ? CLI_INPUT : cli_input_error(cmd, "out of memory for the JSON");
        }
    }
    if (o->overlay != NULL) {
        draw_loops_side_t sr = {ri, r->loops, r->n, r->samples, NULL};
        draw_loops_side_t sm = {mi, m->loops, m->n, m->samples, NULL};
        draw_loops_pair_t *dp = calloc(res->pairs ? res->pairs : 1u, sizeof *dp);
        char title[300], sub[300], lr[160], lm[160];
        uint32_t i;
        int bad;
        for (i = 0; dp != NULL && i < res->pairs; i++) {
            dp[i].ref = pairs[i].ref;
            dp[i].mov = pairs[i].mov;
        }
        snprintf(lr, sizeof lr, "REF %s: %u loops", cli_basename(ref_path), r->n);
        snprintf(lm, sizeof lm, "MOV %s: %u loops", cli_basename(mov_path), m->n);
        sr.label = lr;
        sm.label = lm;
        snprintf(title, sizeof title, "ssda symreg  %s -> %s", cli_basename(ref_path),
                 cli_basename(mov_path));
        snprintf(sub, sizeof sub,
                 "%u pairs matched (colours, joined);  scale %.4f, rotation %.2f deg, "
                 "centroid RMS %.2f px",
                 res->pairs, res->scale_q16 / 65536.0, deg(res->rotation), res->rms_q8 / 256.0);
        bad = dp == NULL || (f = cli_outputs_open(&out, o->overlay)) == NULL ||
              draw_loops_to(f, o->overlay, &sr, &sm, dp, res->pairs, title, sub, err,
                            sizeof err) != 0;
        free(dp);
        if (bad) {
            cli_outputs_abort(&out);
            return cli_input_error(cmd, "%s", dp == NULL ? "out of memory" : err);
        }
    }
    if (o->out != NULL) {
        gray_image_t w = {0};
        double A[6];
        int bad;
        affine_doubles(&res->affine, A);
        bad = warp_affine(mi, A, ri->width, ri->height, 0, &w) != 0 ||
              (f = cli_outputs_open(&out, o->out)) == NULL ||
              png_write_gray_to(f, o->out, &w, err, sizeof err) != 0;
        gray_image_free(&w);
        if (bad) {
            cli_outputs_abort(&out);
            return cli_input_error(cmd, "cannot write '%s'", o->out);
        }
    }
    return cli_outputs_commit(&out);
}

static void summary(const char *ref_path, const char *mov_path, const loops_run_t *r,
                    const loops_run_t *m, const ssda_symreg_result_t *res,
                    const ssda_symreg_pair_t *pairs)
{
    double A[6];
    uint32_t i;
    affine_doubles(&res->affine, A);
    printf("loops:   REF %s %u, MOV %s %u\n", cli_basename(ref_path), r->n,
           cli_basename(mov_path), m->n);
    printf("pairs:   %u matched (%u candidate nuclei, %u tried)\n", res->pairs, res->candidates,
           res->nuclei);
    for (i = 0; i < res->pairs; i++) {
        const ssda_symreg_pair_t *p = &pairs[i];
        printf("  REF (%7.2f, %7.2f) -> MOV (%7.2f, %7.2f)  s %.3f  phi %7.2f deg  E2 %.4f  "
               "resid %.2f px\n",
               r->loops[p->ref].cx_q8 / 256.0, r->loops[p->ref].cy_q8 / 256.0,
               m->loops[p->mov].cx_q8 / 256.0, m->loops[p->mov].cy_q8 / 256.0,
               p->s_q16 / 65536.0, deg(p->phi), p->e2_q16 / 65536.0, p->resid_q8 / 256.0);
    }
    printf("affine:  MOV x = %.6f x %+.6f y %+.3f\n", A[0], A[1], A[2]);
    printf("         MOV y = %.6f x %+.6f y %+.3f   (REF pixel coordinates)\n", A[3], A[4],
           A[5]);
    printf("scale %.5f, rotation %.3f deg, centroid RMS %.3f px\n", res->scale_q16 / 65536.0,
           deg(res->rotation), res->rms_q8 / 256.0);
}

/* Register; on success CLI_OK with *res, pairs malloc'ed into *pairs_out. */
static int run(const char *cmd, const symreg_opts_t *o, const loops_run_t *r,
               const loops_run_t *m, ssda_symreg_result_t *res, ssda_symreg_pair_t **pairs_out)
{
    const uint32_t k = o->reg.nuclei ? o->reg.nuclei : SSDA_SYMREG_DEFAULT_NUCLEI;
    const size_t wsize = SSDA_SYMREG_WORK_SIZE(r->n, m->n, k);
    void *work = malloc(wsize);
    ssda_symreg_pair_t *pairs = calloc(r->n ? r->n : 1u, sizeof *pairs);
    int e;
    if (work == NULL || pairs == NULL) {
        free(work);
        free(pairs);
        return cli_input_error(cmd, "out of memory");
    }
    e = ssda_symreg(r->loops, r->fds, r->n, m->loops, m->fds, m->n, &o->reg, work, wsize, pairs,
                    r->n, res);
    free(work);
    if (e != SSDA_OK) {
        free(pairs);
        return cli_input_error(cmd, "registration failed: %s", ssda_strerror(e));
    }
    *pairs_out = pairs;
    return CLI_OK;
}

int cmd_symreg(int argc, char **argv)
{
    cli_args_t a;
    symreg_opts_t o;
    gray_image_t ri = {0}, mi = {0};
    loops_run_t r, m;
    ssda_symreg_result_t res;
    ssda_symreg_pair_t *pairs = NULL;
    uint32_t need;
    char err[512];
    int rc = CLI_INPUT, t, help_only = 0;
    memset(&o, 0, sizeof o);
    memset(&r, 0, sizeof r);
    memset(&m, 0, sizeof m);
    cli_args_begin(&a, "symreg", argc, argv);
    if ((t = parse(&a, &o, &help_only)) != CLI_OK || help_only) {
        return t;
    }
    need = o.reg.min_pairs ? o.reg.min_pairs : SSDA_SYMREG_DEFAULT_MIN_PAIRS;
    cli_warn_png_name(a.cmd, "--overlay", o.overlay);
    cli_warn_png_name(a.cmd, "-o", o.out);
    if (load8(a.cmd, a.pos[0], &ri) != 0 || load8(a.cmd, a.pos[1], &mi) != 0) {
        goto done;
    }
    if (loops_run(&ri, &o.ref, &r, err, sizeof err) != 0 ||
        loops_run(&mi, &o.mov, &m, err, sizeof err) != 0) {
        cli_input_error(a.cmd, "%s", err);
        goto done;
    }
    if (r.n < need || m.n < need) {
        cli_input_error(a.cmd,
                        "too few loops: REF has %u, MOV %u; a registration needs at least %u "
                        "matched loops (try --grey-min 0, --area, --strength)",
                        r.n, m.n, need);
        goto done;
    }
    if ((rc = run(a.cmd, &o, &r, &m, &res, &pairs)) != CLI_OK) {
        goto done;
    }
    if (res.pairs == 0) {
        rc = cli_input_error(a.cmd,
                             "no registration: REF %u loops, MOV %u loops, %u candidate pairs, "
                             "%u nuclei tried, none reached %u agreeing pairs",
                             r.n, m.n, res.candidates, res.nuclei, need);
        goto done;
    }
    rc = outputs(a.cmd, &o, a.pos[0], a.pos[1], &ri, &mi, &r, &m, &res, pairs);
    if (rc == CLI_OK && !o.quiet && !(o.json != NULL && strcmp(o.json, "-") == 0) &&
        !(o.overlay != NULL && strcmp(o.overlay, "-") == 0) &&
        !(o.out != NULL && strcmp(o.out, "-") == 0)) {
        summary(a.pos[0], a.pos[1], &r, &m, &res, pairs);
    }
done:
    free(pairs);
    loops_run_free(&r);
    loops_run_free(&m);
    gray_image_free(&ri);
    gray_image_free(&mi);
    return rc;
}
