/* draw.c - vector overlays and pitch plots with cairo. */
#include "draw.h"
#include "atomic_file.h"

#include <cairo.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FONT "DejaVu Sans"
#define PI 3.14159265358979323846

static void set_err(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (err == NULL || errlen == 0) {
        return;
    }
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

static cairo_status_t write_to_file(void *closure, const unsigned char *data, unsigned int len)
{
    return fwrite(data, 1, len, (FILE *)closure) == len ? CAIRO_STATUS_SUCCESS
                                                        : CAIRO_STATUS_WRITE_ERROR;
}

/* Write a finished surface as PNG to fp. */
static int surface_to_stream(cairo_surface_t *s, FILE *fp, const char *name, char *err,
                             size_t errlen)
{
    cairo_status_t st;
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        set_err(err, errlen, "cannot draw '%s': %s", name,
                cairo_status_to_string(cairo_surface_status(s)));
        return -1;
    }
    cairo_surface_flush(s);
    st = cairo_surface_write_to_png_stream(s, write_to_file, fp);
    if (st != CAIRO_STATUS_SUCCESS) {
        set_err(err, errlen, "cannot write '%s': %s", name, cairo_status_to_string(st));
        return -1;
    }
    return 0;
}

/* Open path atomically, let draw() write, commit. */
static int to_path(const char *path, char *err, size_t errlen,
                   int (*draw)(FILE *fp, const char *name, const void *ctx, char *err,
                               size_t errlen),
                   const void *ctx)
{
    atomic_file_t af;
    if (atomic_file_open(&af, path) != 0) {
        set_err(err, errlen, "cannot create '%s': %s", path, strerror(errno));
        return -1;
    }
    if (draw(af.fp, path, ctx, err, errlen) != 0) {
        atomic_file_abort(&af);
        return -1;
    }
    if (atomic_file_commit(&af) != 0) {
        set_err(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

/* Largest of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 x 10^k that is <= v (v > 0). */
static double nice_floor(double v)
{
    static const double m[] = {8.0, 6.0, 5.0, 4.0, 3.0, 2.5, 2.0, 1.5, 1.0};
    double p = pow(10.0, floor(log10(v)));
    size_t i;
    for (i = 0; i < sizeof m / sizeof m[0]; i++) {
        if (m[i] * p <= v * (1.0 + 1e-9)) {
            return m[i] * p;
        }
    }
    return p;
}

static void text_at(cairo_t *cr, double x, double y, double size, int bold, const char *s)
{
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, s);
}

static double text_width(cairo_t *cr, double size, int bold, const char *s)
{
    cairo_text_extents_t e;
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_text_extents(cr, s, &e);
    return e.x_advance;
}

/* ---- vector overlay ---- */

static const double status_rgb[DRAW_STATUS_COUNT][3] = {
    {1.00, 0.85, 0.00}, /* ok: yellow */
    {0.62, 0.62, 0.62}, /* excluded: grey */
    {1.00, 0.25, 0.85}, /* masked: magenta */
    {1.00, 0.50, 0.05}, /* edge: orange */
    {0.50, 0.60, 0.75}, /* flat: blue-grey */
    {0.72, 0.45, 1.00}, /* ambiguous: violet */
    {1.00, 0.18, 0.18}, /* at limit: red */
};

/* Statuses drawn as an arrow (a vector that exists), the others as a mark. */
static int has_arrow(int status)
{
    return status == DRAW_OK || status == DRAW_AT_LIMIT;
}
static const double truth_rgb[3] = {0.10, 0.90, 1.00}; /* cyan */

/* Contrast stretch levels: 0.5 % and 99.5 % of the non-masked pixels. */
static void stretch_levels(const gray_image_t *img, const draw_vectors_opts_t *o,
                           uint32_t *lo, uint32_t *hi)
{
    size_t bins = (size_t)gray_image_max(img) + 1u;
    uint64_t *hist = calloc(bins, sizeof *hist);
    uint64_t total = 0, acc = 0;
    uint32_t x, y;
    size_t i;
    *lo = 0;
    *hi = gray_image_max(img);
    if (hist == NULL) {
        return;
    }
    for (y = 0; y < img->height; y++) {
        for (x = 0; x < img->width; x++) {
            uint32_t v = gray_image_get(img, x, y);
            if (o->have_mask && v == o->mask_value) {
                continue;
            }
            hist[v]++;
            total++;
        }
    }
    if (total > 0) {
        uint64_t cut_lo = total / 200u, cut_hi = total - total / 200u;
        int have_lo = 0;
        for (i = 0; i < bins; i++) {
            acc += hist[i];
            if (!have_lo && acc > cut_lo) {
                *lo = (uint32_t)i;
                have_lo = 1;
            }
            if (acc >= cut_hi) {
                *hi = (uint32_t)i;
                break;
            }
        }
    }
    if (*hi <= *lo) {
        *hi = *lo + 1u;
    }
    free(hist);
}

/* The background as a cairo image (gray in 24..232, so marks stand out). */
static cairo_surface_t *background_surface(const gray_image_t *img,
                                           const draw_vectors_opts_t *o)
{
    uint32_t lo, hi, x, y;
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)img->width,
                                                    (int)img->height);
    unsigned char *data;
    int stride;
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        return s;
    }
    stretch_levels(img, o, &lo, &hi);
    cairo_surface_flush(s);
    data = cairo_image_surface_get_data(s);
    stride = cairo_image_surface_get_stride(s);
    for (y = 0; y < img->height; y++) {
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
        for (x = 0; x < img->width; x++) {
            uint32_t v = gray_image_get(img, x, y);
            uint32_t g;
            if (o->have_mask && v == o->mask_value) {
                row[x] = 0x00101830u; /* fill pixels: dark blue */
                continue;
            }
            v = v < lo ? lo : v > hi ? hi : v;
            g = 24u + (uint32_t)(((uint64_t)(v - lo) * 208u) / (hi - lo));
            row[x] = (g << 16) | (g << 8) | g;
        }
    }
    cairo_surface_mark_dirty(s);
    return s;
}

/* An arrow from (x0, y0) to (x1, y1) in output pixels with a black outline. */
static void arrow(cairo_t *cr, double x0, double y0, double x1, double y1, const double rgb[3],
                  double width)
{
    double dx = x1 - x0, dy = y1 - y0, len = sqrt(dx * dx + dy * dy);
    double head = fmin(fmax(3.2 * width, 0.35 * len), 4.5 * width);
    double ux, uy, bx, by, pass;
    if (len < 1.5) { /* no visible motion: a dot */
        cairo_new_path(cr); /* no line in from a current point (after text) */
        cairo_arc(cr, x0, y0, width * 1.1, 0, 2 * PI);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 1.5);
        cairo_stroke_preserve(cr);
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_fill(cr);
        return;
    }
    ux = dx / len;
    uy = dy / len;
    if (head > len) {
        head = len;
    }
    bx = x1 - ux * head;
    by = y1 - uy * head;
    for (pass = 0; pass < 2; pass++) { /* outline first, colour on top */
        if (pass == 0) {
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_set_line_width(cr, width + 2.5);
        } else {
            cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
            cairo_set_line_width(cr, width);
        }
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_move_to(cr, x0, y0);
        cairo_line_to(cr, bx, by);
        cairo_stroke(cr);
        cairo_move_to(cr, x1, y1);
        cairo_line_to(cr, bx - uy * head * 0.55, by + ux * head * 0.55);
        cairo_line_to(cr, bx + uy * head * 0.55, by - ux * head * 0.55);
        cairo_close_path(cr);
        if (pass == 0) {
            cairo_stroke_preserve(cr);
        }
        cairo_fill(cr);
    }
}

/* The mark of a window that has no vector. */
static void status_mark(cairo_t *cr, double x, double y, int status, double r)
{
    const double *c = status_rgb[status];
    int pass;
    if (status == DRAW_EXCLUDED || status == DRAW_FLAT) { /* the commonest: small, quiet */
        r *= 0.7;
    }
    for (pass = 0; pass < 2; pass++) {
        const int quiet = status == DRAW_EXCLUDED || status == DRAW_FLAT;
        cairo_set_line_width(cr, pass == 0 ? (quiet ? 3.0 : 4.0) : (quiet ? 1.2 : 2.0));
        if (pass == 0) {
            cairo_set_source_rgb(cr, 0, 0, 0);
        } else {
            cairo_set_source_rgb(cr, c[0], c[1], c[2]);
        }
        if (status == DRAW_EXCLUDED) {
            cairo_move_to(cr, x - r, y - r);
            cairo_line_to(cr, x + r, y + r);
            cairo_move_to(cr, x - r, y + r);
            cairo_line_to(cr, x + r, y - r);
        } else if (status == DRAW_MASKED) {
            cairo_rectangle(cr, x - r, y - r, 2 * r, 2 * r);
        } else if (status == DRAW_AMBIGUOUS) {
            cairo_move_to(cr, x, y - 1.3 * r);
            cairo_line_to(cr, x + 1.3 * r, y);
            cairo_line_to(cr, x, y + 1.3 * r);
            cairo_line_to(cr, x - 1.3 * r, y);
            cairo_close_path(cr);
        } else if (status == DRAW_FLAT) { /* a filled dot: outline pass, then fill */
            cairo_new_sub_path(cr);
            cairo_arc(cr, x, y, 0.6 * r, 0, 2 * PI);
            if (pass == 1) {
                cairo_fill(cr);
                continue;
            }
        } else {
            cairo_new_sub_path(cr);
            cairo_arc(cr, x, y, r, 0, 2 * PI);
        }
        cairo_stroke(cr);
    }
}

static double auto_arrow_scale(const draw_vector_t *v, size_t n, double step)
{
    double *len = malloc((n + 1) * sizeof *len), p90 = 0.0;
    size_t i, k = 0;
    if (step <= 0.0) {
        step = 16.0;
    }
    if (len != NULL) {
        for (i = 0; i < n; i++) {
            if (v[i].status == DRAW_OK) {
                len[k++] = hypot(v[i].dx, v[i].dy);
            }
        }
        if (k > 0) { /* 90th percentile by partial selection sort (n is small) */
            size_t want = (k * 9) / 10, a, b;
            for (a = 0; a <= want && a < k; a++) {
                for (b = a + 1; b < k; b++) {
                    if (len[b] < len[a]) {
                        double t = len[a];
                        len[a] = len[b];
                        len[b] = t;
                    }
                }
            }
            p90 = len[want < k ? want : k - 1];
        }
        free(len);
    }
    if (p90 < 0.5) {
        p90 = 0.5;
    }
    return fmax(1.0, nice_floor(step / p90));
}

/* "st", "nd", "rd" or "th" after n (1st, 22nd, 13th). */
const char *ordinal_suffix(unsigned n)
{
    if (n % 100u >= 11u && n % 100u <= 13u) {
        return "th";
    }
    return n % 10u == 1u ? "st" : n % 10u == 2u ? "nd" : n % 10u == 3u ? "rd" : "th";
}

/* The status legend: one swatch and count per status present (vectors
   always), the dots of vectors too short to draw as arrows, then the
   reference arrows if any; wraps at width W. Draws only when draw != 0.
   dot_below: motion (px) under which a vector is drawn as a dot, 0 when
   every dot is a zero motion. Returns
   the number of lines used. */
static int legend_items(cairo_t *cr, const draw_vectors_opts_t *o, const size_t *counts,
                        size_t dots, double dot_below, size_t truths, double W, double y,
                        int draw)
{
    enum { ITEM_TRUTH = DRAW_STATUS_COUNT, ITEM_DOT, ITEM_COUNT };
    static const int order[ITEM_COUNT] = {DRAW_OK,       ITEM_DOT,       DRAW_AT_LIMIT,
                                          DRAW_AMBIGUOUS, DRAW_FLAT,     DRAW_EXCLUDED,
                                          DRAW_MASKED,   DRAW_EDGE,      ITEM_TRUTH};
    static const char *names[DRAW_STATUS_COUNT] = {
        "vector", "excluded (all dark or all bright)", "masked (fill value)",
        "edge (area leaves image)", "flat (no texture, not searched)",
        "ambiguous (another match about as good)",
        "at limit (best match on the border of the search: motion may be larger)"};
    char buf[256];
    double x = 12.0;
    int lines = 1;
    size_t k;
    for (k = 0; k < ITEM_COUNT; k++) {
        int i = order[k];
        double w;
        if (i == ITEM_TRUTH) { /* the reference arrows */
            if (truths == 0) {
                continue;
            }
            snprintf(buf, sizeof buf, "%s",
                     o->truth_label != NULL ? o->truth_label : "known motion (truth)");
        } else if (i == ITEM_DOT) { /* yellow dots are vectors, not another status */
            if (dots == 0) {
                continue;
            }
            if (dot_below <= 0.0) {
                snprintf(buf, sizeof buf, "no motion: %zu", dots);
            } else {
                snprintf(buf, sizeof buf, "motion under %.2g px (too short to draw): %zu",
                         dot_below, dots);
            }
        } else if (counts[i] == 0 && i != DRAW_OK) {
            continue;
        } else if (i == DRAW_OK && o->every > 1) {
            snprintf(buf, sizeof buf, "vector (every %u%s of grid rows and columns drawn): %zu",
                     o->every, ordinal_suffix(o->every), counts[i]);
        } else {
            snprintf(buf, sizeof buf, "%s: %zu", names[i], counts[i]);
        }
        w = 34 + text_width(cr, 13, 0, buf);
        if (x > 12.0 && x + w > W - 8) { /* wrap */
            x = 12.0;
            y += 26.0;
            lines++;
        }
        if (draw) {
            if (i == ITEM_TRUTH) {
                arrow(cr, x, y - 4, x + 26, y - 4, truth_rgb, 1.6);
            } else if (i == ITEM_DOT) {
                arrow(cr, x + 12, y - 4, x + 12, y - 4, status_rgb[DRAW_OK], 2.5);
            } else if (has_arrow(i)) {
                arrow(cr, x, y - 4, x + 26, y - 4, status_rgb[i], 2.5);
            } else {
                status_mark(cr, x + 12, y - 4, i, 5.0);
            }
            cairo_set_source_rgb(cr, 1, 1, 1);
            text_at(cr, x + 34, y, 13, 0, buf);
        }
        x += w + 22;
    }
    return lines;
}

double draw_vectors_zoom(uint32_t w, uint32_t h)
{
    double m = w > h ? w : h, z;
    /* Enlarge small images (integer zoom from 2x keeps pixels crisp), reduce
       huge ones, so the longer side shows at about 900..1600 px. */
    z = m < 900.0 ? 960.0 / m : m > 1600.0 ? 1600.0 / m : 1.0;
    if (z >= 2.0) {
        z = floor(z);
    }
    return z > 12.0 ? 12.0 : z;
}

int draw_vectors_to(FILE *fp, const char *name, const gray_image_t *bg, const draw_vector_t *v,
                    size_t n, const draw_vectors_opts_t *opts, double *scale_used, char *err,
                    size_t errlen)
{
    draw_vectors_opts_t o;
    cairo_surface_t *img_s, *out;
    cairo_t *cr;
    double z, scale, top, bottom, W, H, ox, lw, ref, y;
    size_t counts[DRAW_STATUS_COUNT] = {0}, i, truths = 0, dots = 0, moving_dots = 0;
    double dot_below;
    char buf[256];
    int rc;

    if (opts != NULL) {
        o = *opts;
    } else {
        memset(&o, 0, sizeof o);
    }
    z = draw_vectors_zoom(bg->width, bg->height);
    scale = o.arrow_scale > 0.0 ? o.arrow_scale : auto_arrow_scale(v, n, o.grid_step);
    if (scale_used != NULL) {
        *scale_used = scale;
    }
    top = (o.title != NULL ? 26.0 : 0.0) + (o.subtitle != NULL ? 20.0 : 0.0) + 8.0;
    W = fmax(ceil(bg->width * z), 720.0);
    dot_below = 1.5 / (scale * z); /* arrow() draws a dot under 1.5 output px */
    for (i = 0; i < n; i++) {
        int st = v[i].status >= 0 && v[i].status < DRAW_STATUS_COUNT ? v[i].status : DRAW_EDGE;
        counts[st]++;
        truths += v[i].has_truth != 0;
        dots += st == DRAW_OK && hypot(v[i].dx, v[i].dy) < dot_below;
        moving_dots += st == DRAW_OK && hypot(v[i].dx, v[i].dy) < dot_below &&
                       (v[i].dx != 0.0 || v[i].dy != 0.0);
    }
    if (moving_dots == 0) { /* the legend then says "no motion" */
        dot_below = 0.0;
    }
    { /* wide enough for the title lines; tall enough for the legend */
        cairo_surface_t *scratch = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 8, 8);
        cairo_t *m_cr = cairo_create(scratch);
        if (o.title != NULL) {
            W = fmax(W, ceil(text_width(m_cr, 16, 1, o.title)) + 20.0);
        }
        if (o.subtitle != NULL) {
            W = fmax(W, ceil(text_width(m_cr, 13, 0, o.subtitle)) + 20.0);
        }
        bottom = 48.0 + 26.0 * legend_items(m_cr, &o, counts, dots, dot_below, truths, W, 0.0, 0);
        cairo_destroy(m_cr);
        cairo_surface_destroy(scratch);
    }
    H = ceil(bg->height * z) + top + bottom;
    ox = floor((W - ceil(bg->width * z)) / 2.0);

    img_s = background_surface(bg, &o);
    out = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)W, (int)H);
    cr = cairo_create(out);
    cairo_set_source_rgb(cr, 0.11, 0.11, 0.13);
    cairo_paint(cr);

    cairo_save(cr);
    cairo_translate(cr, ox, top);
    cairo_scale(cr, z, z);
    cairo_set_source_surface(cr, img_s, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr),
                             z >= 2.0 ? CAIRO_FILTER_NEAREST : CAIRO_FILTER_GOOD);
    cairo_rectangle(cr, 0, 0, bg->width, bg->height);
    cairo_fill(cr);
    cairo_restore(cr);

    /* Marks and arrows, in output pixels. */
    lw = fmin(3.0, fmax(1.5, o.grid_step * z / 14.0));
    for (i = 0; i < n; i++) {
        int st = v[i].status >= 0 && v[i].status < DRAW_STATUS_COUNT ? v[i].status : DRAW_EDGE;
        double tx = ox + (v[i].x + 0.5) * z, ty = top + (v[i].y + 0.5) * z;
        if (has_arrow(st)) {
            arrow(cr, tx, ty, tx + v[i].dx * scale * z, ty + v[i].dy * scale * z,
                  status_rgb[st], lw);
        } else {
            status_mark(cr, tx, ty, st, fmax(3.5, lw * 1.8));
        }
        if (v[i].has_truth) { /* on top and thinner: a cyan core where both agree */
            arrow(cr, tx, ty, tx + v[i].tdx * scale * z, ty + v[i].tdy * scale * z, truth_rgb,
                  fmax(1.0, lw * 0.45));
        }
    }

    /* Title lines. */
    cairo_set_source_rgb(cr, 1, 1, 1);
    y = 0.0;
    if (o.title != NULL) {
        text_at(cr, 10, y + 20, 16, 1, o.title);
        y += 26.0;
    }
    if (o.subtitle != NULL) {
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
        text_at(cr, 10, y + 15, 13, 0, o.subtitle);
    }

    /* Legend, then the scale arrow on the last line. */
    y = H - bottom + 24.0;
    y += 26.0 * (legend_items(cr, &o, counts, dots, dot_below, truths, W, y, 1) - 1);
    /* Scale: a reference arrow of a round motion drawn 60..150 px long. */
    ref = nice_floor(120.0 / (scale * z));
    y += 28.0;
    arrow(cr, 12, y - 4, 12 + ref * scale * z, y - 4, status_rgb[DRAW_OK], 2.5);
    if (z != 1.0) {
        snprintf(buf, sizeof buf, "= %g px of motion   (arrows drawn %g x longer than the "
                 "motion; image shown at %.3g x)", ref, scale, z);
    } else {
        snprintf(buf, sizeof buf, "= %g px of motion   (arrows drawn %g x longer than the "
                 "motion)", ref, scale);
    }
    cairo_set_source_rgb(cr, 1, 1, 1);
    text_at(cr, 12 + ref * scale * z + 10, y, 13, 0, buf);
    cairo_destroy(cr);
    cairo_surface_destroy(img_s);
    rc = surface_to_stream(out, fp, name, err, errlen);
    cairo_surface_destroy(out);
    return rc;
}

typedef struct {
    const gray_image_t *bg;
    const draw_vector_t *v;
    size_t n;
    const draw_vectors_opts_t *opts;
    double *scale_used;
} vectors_ctx_t;

static int vectors_cb(FILE *fp, const char *name, const void *ctx, char *err, size_t errlen)
{
    const vectors_ctx_t *c = ctx;
    return draw_vectors_to(fp, name, c->bg, c->v, c->n, c->opts, c->scale_used, err, errlen);
}

int draw_vectors_png(const char *path, const gray_image_t *bg, const draw_vector_t *v,
                     size_t n, const draw_vectors_opts_t *opts, double *scale_used,
                     char *err, size_t errlen)
{
    vectors_ctx_t c = {bg, v, n, opts, scale_used};
    return to_path(path, err, errlen, vectors_cb, &c);
}

/* ---- pitch plot ---- */

/* Tick step: 1, 2 or 5 x 10^k giving about `want` ticks over span. */
static double tick_step(double span, int want)
{
    double raw = span / want, p = pow(10.0, floor(log10(raw))), r = raw / p;
    return (r < 1.5 ? 1.0 : r < 3.5 ? 2.0 : r < 7.5 ? 5.0 : 10.0) * p;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median spacing of a track's frames (for breaking lines at gaps). */
static double frame_spacing(const draw_track_t *t)
{
    if (t->n < 2) {
        return 1.0;
    }
    return (t->t[t->n - 1] - t->t[0]) / (double)(t->n - 1);
}

/* The mark of an estimate beyond the y range: a triangle with its base at
   y pointing up (above the range) or down (below it). */
static void pitch_triangle(cairo_t *cr, double x, double y, int up)
{
    double tip = up ? y - 6 : y + 6;
    cairo_move_to(cr, x, tip);
    cairo_line_to(cr, x - 3.5, y);
    cairo_line_to(cr, x + 3.5, y);
    cairo_close_path(cr);
    cairo_fill(cr);
}

int draw_pitch_to(FILE *fp, const char *name, const draw_pitch_opts_t *o, char *err,
                  size_t errlen)
{
    const double W = 1100.0, H = 560.0, L = 78.0, R = 24.0, T = 62.0, PH = 330.0,
                 WT = T + PH + 16.0, WH = 80.0;
    const double PW = W - L - R;
    double tmax = 0.0, f_lo = o->fmin, f_hi = o->fmax, step, v;
    cairo_surface_t *s;
    cairo_t *cr;
    size_t i, beyond = 0;
    int pass, rc;
    char buf[64];

    /* Axes ranges from the data unless given: the 2nd..98th percentile of the
       voiced values, so a few wild frames do not squash the plot (frames
       beyond the range are marked on its edge). */
    {
        double lo = 0.0, hi = 0.0, *vals;
        size_t nv = 0;
        const draw_track_t *tr[2] = {&o->estimate, &o->reference};
        vals = malloc((o->estimate.n + o->reference.n + 1u) * sizeof *vals);
        for (pass = 0; pass < 2; pass++) {
            for (i = 0; i < tr[pass]->n; i++) {
                if (tr[pass]->t[i] > tmax) {
                    tmax = tr[pass]->t[i];
                }
                if (tr[pass]->f0[i] > 0.0 && vals != NULL) {
                    vals[nv++] = tr[pass]->f0[i];
                }
            }
        }
        if (nv > 0) {
            qsort(vals, nv, sizeof *vals, cmp_double);
            lo = vals[(nv * 2u) / 100u];
            hi = vals[nv - 1u - (nv * 2u) / 100u];
        }
        free(vals);
        if (o->samples != NULL && o->sample_rate > 0) {
            tmax = fmax(tmax, (double)o->sample_count / o->sample_rate);
        }
        if (hi <= 0.0) {
            lo = 50.0;
            hi = 500.0;
        }
        if (f_lo <= 0.0) {
            f_lo = fmax(0.0, lo - 0.15 * (hi - lo) - 5.0);
        }
        if (f_hi <= 0.0) {
            f_hi = hi + 0.15 * (hi - lo) + 5.0;
        }
        if (f_hi <= f_lo) {
            f_hi = f_lo + 1.0;
        }
        if (tmax <= 0.0) {
            tmax = 1.0;
        }
    }
#define PX(t) (L + (t) / tmax * PW)
#define PY(f) (T + PH - ((f) - f_lo) / (f_hi - f_lo) * PH)

    s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)W, (int)H);
    cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0.97, 0.97, 0.98);
    cairo_rectangle(cr, L, T, PW, PH);
    cairo_fill(cr);

    cairo_set_source_rgb(cr, 0, 0, 0);
    if (o->title != NULL) {
        text_at(cr, L, 24, 17, 1, o->title);
    }
    if (o->subtitle != NULL) {
        cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
        text_at(cr, L, 46, 13, 0, o->subtitle);
    }

    /* Grid and tick labels. */
    cairo_set_line_width(cr, 1.0);
    step = tick_step(f_hi - f_lo, 6);
    for (v = ceil(f_lo / step) * step; v <= f_hi + 1e-9; v += step) {
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.88);
        cairo_move_to(cr, L, floor(PY(v)) + 0.5);
        cairo_line_to(cr, L + PW, floor(PY(v)) + 0.5);
        cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%g", v);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text_at(cr, L - 8 - text_width(cr, 12, 0, buf), PY(v) + 4, 12, 0, buf);
    }
    step = tick_step(tmax, 10);
    for (v = 0.0; v <= tmax + 1e-9; v += step) {
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.88);
        cairo_move_to(cr, floor(PX(v)) + 0.5, T);
        cairo_line_to(cr, floor(PX(v)) + 0.5, WT + WH);
        cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%g", v);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text_at(cr, PX(v) - text_width(cr, 12, 0, buf) / 2, WT + WH + 18, 12, 0, buf);
    }
    text_at(cr, L + PW / 2 - 24, WT + WH + 38, 13, 0, "time (s)");
    cairo_save(cr);
    cairo_move_to(cr, 22, T + PH / 2 + 24);
    cairo_rotate(cr, -PI / 2);
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 13);
    cairo_show_text(cr, "f0 (Hz)");
    cairo_restore(cr);

    /* Waveform strip: min/max per column. */
    if (o->samples != NULL && o->sample_count > 0 && o->sample_rate > 0) {
        int col, peak = 1;
        size_t k;
        for (k = 0; k < o->sample_count; k++) { /* scale the loudest sample to the strip */
            int a = o->samples[k] < 0 ? -o->samples[k] : o->samples[k];
            peak = a > peak ? a : peak;
        }
        cairo_set_source_rgb(cr, 0.97, 0.97, 0.98);
        cairo_rectangle(cr, L, WT, PW, WH);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.45, 0.45, 0.5);
        cairo_set_line_width(cr, 1.0);
        for (col = 0; col < (int)PW; col++) {
            size_t a = (size_t)((double)col / PW * tmax * o->sample_rate);
            size_t b = (size_t)((double)(col + 1) / PW * tmax * o->sample_rate);
            int lo = 0, hi = 0;
            if (a >= o->sample_count) {
                break;
            }
            if (b > o->sample_count) {
                b = o->sample_count;
            }
            for (k = a; k < b; k++) {
                lo = o->samples[k] < lo ? o->samples[k] : lo;
                hi = o->samples[k] > hi ? o->samples[k] : hi;
            }
            cairo_move_to(cr, L + col + 0.5, WT + WH / 2 - 0.95 * hi / peak * WH / 2);
            cairo_line_to(cr, L + col + 0.5, WT + WH / 2 - 0.95 * lo / peak * WH / 2 + 0.5);
            cairo_stroke(cr);
        }
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text_at(cr, L - 8 - text_width(cr, 11, 0, "waveform"), WT + WH / 2 + 4, 11, 0,
                "waveform");
    }

    /* Tracks, clipped to the plot. */
    cairo_save(cr);
    cairo_rectangle(cr, L, T, PW, PH);
    cairo_clip(cr);
    for (pass = 0; pass < 2; pass++) {
        const draw_track_t *tr = pass == 0 ? &o->reference : &o->estimate;
        double gap = 2.5 * frame_spacing(tr);
        int open = 0;
        if (pass == 0) {
            cairo_set_source_rgba(cr, 0.25, 0.55, 1.0, 0.45);
            cairo_set_line_width(cr, 7.0);
        } else {
            cairo_set_source_rgb(cr, 0.85, 0.15, 0.1);
            cairo_set_line_width(cr, 1.6);
        }
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        for (i = 0; i < tr->n; i++) {
            if (tr->f0[i] <= 0.0) {
                open = 0;
                continue;
            }
            if (open && tr->t[i] - tr->t[i - 1] <= gap) {
                cairo_line_to(cr, PX(tr->t[i]), PY(tr->f0[i]));
            } else {
                cairo_move_to(cr, PX(tr->t[i]), PY(tr->f0[i]));
                cairo_line_to(cr, PX(tr->t[i]) + 0.01, PY(tr->f0[i]));
            }
            open = 1;
        }
        cairo_stroke(cr);
        if (pass == 1 && tr->n <= (size_t)PW) { /* dots when frames are sparse enough */
            for (i = 0; i < tr->n; i++) {
                if (tr->f0[i] > 0.0) {
                    cairo_new_sub_path(cr);
                    cairo_arc(cr, PX(tr->t[i]), PY(tr->f0[i]), 2.2, 0, 2 * PI);
                }
            }
            cairo_fill(cr);
        }
    }
    cairo_restore(cr);
    /* Estimates beyond the y range: small triangles on the edge they pass. */
    cairo_set_source_rgb(cr, 0.85, 0.15, 0.1);
    for (i = 0; i < o->estimate.n; i++) {
        double f = o->estimate.f0[i], x = PX(o->estimate.t[i]);
        if (f <= 0.0 || (f >= f_lo && f <= f_hi)) {
            continue;
        }
        beyond++;
        pitch_triangle(cr, x, f > f_hi ? T - 1 : T + PH + 1, f > f_hi);
    }
    if (beyond > 0) { /* their legend: bottom right, clear of the data and the axis title */
        snprintf(buf, sizeof buf, "f0 beyond the axis range: %zu frame%s", beyond,
                 beyond == 1 ? "" : "s");
        v = L + PW - text_width(cr, 12, 0, buf);
        cairo_set_source_rgb(cr, 0.85, 0.15, 0.1);
        pitch_triangle(cr, v - 24, WT + WH + 38 - 10, 1);
        pitch_triangle(cr, v - 12, WT + WH + 38 - 10, 0);
        cairo_set_source_rgb(cr, 0, 0, 0);
        text_at(cr, v, WT + WH + 38, 12, 0, buf);
    }

    /* Frame and legend. */
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, L + 0.5, T + 0.5, PW - 1, PH - 1);
    cairo_stroke(cr);
    {
        const char *est_label = "estimate (unvoiced frames not drawn)";
        double tw = text_width(cr, 12, 0, est_label);
        /* top right, above the plot, clear of the data */
        double lx = L + PW - tw - 40, ly = o->reference.n > 0 ? 22 : 44;
        cairo_set_source_rgb(cr, 0.85, 0.15, 0.1);
        cairo_set_line_width(cr, 2.0);
        cairo_move_to(cr, lx, ly - 4);
        cairo_line_to(cr, lx + 28, ly - 4);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        text_at(cr, lx + 36, ly, 12, 0, est_label);
        if (o->reference.n > 0) {
            cairo_set_source_rgba(cr, 0.25, 0.55, 1.0, 0.45);
            cairo_set_line_width(cr, 7.0);
            cairo_move_to(cr, lx, ly + 18);
            cairo_line_to(cr, lx + 28, ly + 18);
            cairo_stroke(cr);
            cairo_set_source_rgb(cr, 0, 0, 0);
            text_at(cr, lx + 36, ly + 22, 12, 0,
                    o->reference_label != NULL ? o->reference_label : "reference");
        }
    }
#undef PX
#undef PY
    cairo_destroy(cr);
    rc = surface_to_stream(s, fp, name, err, errlen);
    cairo_surface_destroy(s);
    return rc;
}

static int pitch_cb(FILE *fp, const char *name, const void *ctx, char *err, size_t errlen)
{
    return draw_pitch_to(fp, name, ctx, err, errlen);
}

int draw_pitch_png(const char *path, const draw_pitch_opts_t *opts, char *err, size_t errlen)
{
    return to_path(path, err, errlen, pitch_cb, opts);
}
