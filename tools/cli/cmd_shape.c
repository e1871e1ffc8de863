/* cmd_shape.c - `ssda shape A.png B.png`: Fourier-descriptor match of the
   largest closed contour of two silhouettes (seed 001, eqs. 1-12). */
#include "cli.h"
#include "json_out.h"
#include "ssda/fourier.h"
#include "ssda/loops.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: ssda shape A.png B.png [options]\n"
    "\n"
    "Matches the outer contour of the largest object of two silhouettes by\n"
    "Granlund Fourier descriptors (Ishii and Hattori 1985, eqs. 1-12): B's contour\n"
    "~ s exp(i phi) times A's, started alpha / (2 pi) of the way round A's.\n"
    "Prints s (scale B/A), phi_deg (rotation A -> B, from +x towards +y, i.e.\n"
    "clockwise on screen), alpha (radians) and E2, the seed's normalised error\n"
    "(0 identical, 1 nothing in common).\n"
    "\n"
    "The object: pixels >= --threshold (white on black; --invert for black on\n"
    "white), its largest 8-connected set, traced round its outside.\n"
    "\n"
    "options:\n"
    "  --json F          s, phi_deg, alpha, e2 and both contours' facts (\"-\": stdout)\n"
    "  --threshold N     object pixels are >= N, 1..255 (128)\n"
    "  --invert          object pixels are < N instead\n"
    "  --samples N       contour samples, a power of two 8..1024 (256)\n"
    "  --order N         descriptor order, 1..16 (10, the seed's)\n"
    "  -q, --quiet       no summary on stdout\n"
    "  -h, --help        this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input (no object in an image), 2 usage.\n";

typedef struct {
    uint32_t area, perimeter_q8, x, y;
    double cx, cy;
} object_t;

/* Binarise img into mask (1 = object) and keep only its largest
   8-connected set; facts of that set into *ob. Returns 0, or -1 when the
   image has no object pixel. */
static int largest_object(const gray_image_t *img, uint32_t thr, int invert, uint8_t *mask,
                          object_t *ob)
{
    const uint32_t w = img->width, h = img->height;
    uint32_t *label = calloc((size_t)w * h, sizeof *label), *stack = NULL;
    uint32_t x, y, next = 0, best = 0, best_area = 0;
    size_t i;
    if (label == NULL || (stack = malloc((size_t)w * h * sizeof *stack)) == NULL) {
        free(label);
        return -2;
    }
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const int on = (gray_image_get(img, x, y) >= thr) != (invert != 0);
            mask[(size_t)y * w + x] = (uint8_t)on;
        }
    }
    for (i = 0; i < (size_t)w * h; i++) { /* label 8-connected sets, keep the largest */
        size_t top = 0;
        uint32_t area = 0;
        if (!mask[i] || label[i]) {
            continue;
        }
        label[i] = ++next;
        stack[top++] = (uint32_t)i;
        while (top > 0) {
            const uint32_t p = stack[--top], px = p % w, py = p / w;
            int dx, dy;
            area++;
            for (dy = -1; dy <= 1; dy++) {
                for (dx = -1; dx <= 1; dx++) {
                    const int64_t qx = (int64_t)px + dx, qy = (int64_t)py + dy;
                    size_t q;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) {
                        continue;
                    }
                    q = (size_t)qy * w + (size_t)qx;
                    if (mask[q] && !label[q]) {
                        label[q] = next;
                        stack[top++] = (uint32_t)q;
                    }
                }
            }
        }
        if (area > best_area) {
            best_area = area;
            best = next;
        }
    }
    memset(ob, 0, sizeof *ob);
    for (i = 0; i < (size_t)w * h; i++) {
        mask[i] = (uint8_t)(best != 0 && label[i] == best);
        if (mask[i]) {
            if (ob->area == 0) {
                ob->x = (uint32_t)(i % w);
                ob->y = (uint32_t)(i / w);
            }
            ob->area++;
            ob->cx += (double)(i % w);
            ob->cy += (double)(i / w);
        }
    }
    free(label);
    free(stack);
    if (ob->area == 0) {
        return -1;
    }
    ob->cx /= ob->area;
    ob->cy /= ob->area;
    return 0;
}

static int descriptors(const char *cmd, const char *path, uint32_t thr, int invert,
                       uint32_t samples, uint32_t order, ssda_fd_t *fd, object_t *ob)
{
    gray_image_t img = {0};
    ssda_point_q8_t *pts = malloc(samples * sizeof *pts);
    uint8_t *mask = NULL;
    ssda_view_t v;
    int rc = -1, e;
    if (pts == NULL || cli_load_png(cmd, path, PNG_GRAY_8, &img) != 0) {
        free(pts);
        return -1;
    }
    mask = malloc((size_t)img.width * img.height);
    e = mask == NULL ? -2 : largest_object(&img, thr, invert, mask, ob);
    if (e == -1) {
        cli_input_error(cmd, "'%s' has no object pixel (%s %u; try --invert or --threshold)",
                        path, invert ? "below" : "at or above", thr);
    } else if (e != 0) {
        cli_input_error(cmd, "out of memory");
    } else if ((e = ssda_view_init(&v, mask, (uint16_t)img.width, (uint16_t)img.height,
                                   img.width, SSDA_PIX_U8)) != SSDA_OK ||
               (e = ssda_loops_contour(&v, (uint16_t)ob->x, (uint16_t)ob->y, samples, pts,
                                       &ob->perimeter_q8)) != SSDA_OK ||
               (e = ssda_fd_compute(pts, samples, order, fd)) != SSDA_OK) {
        cli_input_error(cmd, "'%s': contour: %s", path, ssda_strerror(e));
    } else if (fd->energy_q16 == 0) {
        cli_input_error(cmd, "'%s': the object is a single pixel", path);
    } else {
        rc = 0;
    }
    free(mask);
    free(pts);
    gray_image_free(&img);
    return rc;
}

static cJSON *object_json(const char *path, const object_t *ob)
{
    cJSON *o = cJSON_CreateObject();
    const double c[2] = {ob->cx, ob->cy};
    json_out_add_string(o, "path", path);
    cJSON_AddNumberToObject(o, "area", ob->area);
    cJSON_AddNumberToObject(o, "perimeter", ob->perimeter_q8 / 256.0);
    cJSON_AddItemToObject(o, "centroid", cJSON_CreateDoubleArray(c, 2));
    return o;
}

typedef struct {
    const char *json;
    uint32_t thr, samples, order;
    int invert, quiet;
} shape_opts_t;

/* The options into o; CLI_OK, or the exit code (--help: CLI_OK with
   *done set). */
static int parse(cli_args_t *a, shape_opts_t *o, int *done)
{
    const char *v;
    while (cli_next(a)) {
        if (cli_flag(a, "--help") || cli_flag(a, "-h")) {
            fputs(help, stdout);
            *done = 1;
            return CLI_OK;
        } else if (cli_opt(a, "--json", &v)) {
            o->json = v;
        } else if (cli_opt(a, "--threshold", &v)) {
            if (v != NULL && cli_parse_u32(v, 1, 255, &o->thr) != 0) {
                return cli_usage_error(a->cmd, "bad --threshold '%s' (1..255)", v);
            }
        } else if (cli_flag(a, "--invert")) {
            o->invert = 1;
        } else if (cli_opt(a, "--samples", &v)) {
            if (v != NULL && (cli_parse_u32(v, 8, 1024, &o->samples) != 0 ||
                              (o->samples & (o->samples - 1)) != 0)) {
                return cli_usage_error(a->cmd, "bad --samples '%s' (a power of two, 8..1024)", v);
            }
        } else if (cli_opt(a, "--order", &v)) {
            if (v != NULL && cli_parse_u32(v, 1, SSDA_FD_MAX_ORDER, &o->order) != 0) {
                return cli_usage_error(a->cmd, "bad --order '%s' (1..16)", v);
            }
        } else if (cli_flag(a, "--quiet") || cli_flag(a, "-q")) {
            o->quiet = 1;
        } else {
            return cli_unknown(a);
        }
        if (a->bad) {
            return CLI_USAGE;
        }
    }
    if (a->bad) {
        return CLI_USAGE;
    }
    if (a->npos != 2) {
        return cli_usage_error(a->cmd, "need A.png and B.png");
    }
    if (2u * o->order >= o->samples) {
        return cli_usage_error(a->cmd, "--order %u needs more than %u samples", o->order,
                               2u * o->order);
    }
    return CLI_OK;
}

/* phi in degrees, -180..180. */
static double phi_deg(uint32_t phi)
{
    const double d = phi * (360.0 / 4294967296.0);
    return d > 180.0 ? d - 360.0 : d;
}

static double alpha_rad(uint32_t alpha)
{
    return alpha * (2.0 * 3.14159265358979323846 / 4294967296.0);
}

/* --json (atomic; "-" stdout). */
static int write_json(const cli_args_t *a, const shape_opts_t *o, const ssda_fd_match_t *m,
                      const object_t *oa, const object_t *ob)
{
    cli_outputs_t out;
    cJSON *doc = json_out_object();
    FILE *f;
    int bad;
    cJSON_AddNumberToObject(doc, "s", m->s_q16 / 65536.0);
    cJSON_AddNumberToObject(doc, "phi_deg", phi_deg(m->phi));
    cJSON_AddNumberToObject(doc, "alpha", alpha_rad(m->alpha));
    cJSON_AddNumberToObject(doc, "alpha_frac", m->alpha / 4294967296.0);
    cJSON_AddNumberToObject(doc, "e2", m->e2_q16 / 65536.0);
    cJSON_AddNumberToObject(doc, "samples", o->samples);
    cJSON_AddNumberToObject(doc, "order", o->order);
    cJSON_AddItemToObject(doc, "a", object_json(a->pos[0], oa));
    cJSON_AddItemToObject(doc, "b", object_json(a->pos[1], ob));
    cli_outputs_begin(&out, a->cmd);
    bad = (f = cli_outputs_open(&out, o->json)) == NULL || json_out_print(f, doc, NULL) != 0;
    cJSON_Delete(doc);
    if (bad) {
        cli_outputs_abort(&out);
        return f == NULL ? CLI_INPUT : cli_input_error(a->cmd, "out of memory for the JSON");
    }
    return cli_outputs_commit(&out);
}

static void summary(const cli_args_t *a, const ssda_fd_match_t *m, const object_t *oa,
                    const object_t *ob)
{
    printf("A %s: area %u px, perimeter %.1f px\n", cli_basename(a->pos[0]), oa->area,
           oa->perimeter_q8 / 256.0);
    printf("B %s: area %u px, perimeter %.1f px\n", cli_basename(a->pos[1]), ob->area,
           ob->perimeter_q8 / 256.0);
    printf("s %.5f  phi %.3f deg  alpha %.4f rad (%.2f %% of the way round)  E2 %.5f\n",
           m->s_q16 / 65536.0, phi_deg(m->phi), alpha_rad(m->alpha),
           100.0 * (m->alpha / 4294967296.0), m->e2_q16 / 65536.0);
}

int cmd_shape(int argc, char **argv)
{
    cli_args_t a;
    shape_opts_t o = {NULL, 128, 256, 10, 0, 0};
    int rc, done = 0;
    ssda_fd_t fa, fb;
    ssda_fd_match_t m;
    object_t oa, ob;
    cli_args_begin(&a, "shape", argc, argv);
    if ((rc = parse(&a, &o, &done)) != CLI_OK || done) {
        return rc;
    }
    if (descriptors(a.cmd, a.pos[0], o.thr, o.invert, o.samples, o.order, &fa, &oa) != 0 ||
        descriptors(a.cmd, a.pos[1], o.thr, o.invert, o.samples, o.order, &fb, &ob) != 0) {
        return CLI_INPUT;
    }
    if ((rc = ssda_fd_match(&fa, &fb, &m)) != SSDA_OK) {
        return cli_input_error(a.cmd, "match: %s", ssda_strerror(rc));
    }
    if (o.json != NULL && (rc = write_json(&a, &o, &m, &oa, &ob)) != CLI_OK) {
        return rc;
    }
    if (!o.quiet && !(o.json != NULL && strcmp(o.json, "-") == 0)) {
        summary(&a, &m, &oa, &ob);
    }
    return CLI_OK;
}
