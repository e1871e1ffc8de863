/* draw.c - vector overlays and pitch plots with cairo. */
#include "draw.h"
#include "tool_err.h"
#include "atomic_file.h"

#include <cairo.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FONT "DejaVu Sans"
#define PI 3.14159265358979323846

typedef struct {
    FILE *fp;
    int write_errno; /* errno of a failed write (ENOSPC, EFBIG), else 0 */
} png_sink_t;

static cairo_status_t write_to_file(void *closure, const unsigned char *data, unsigned int len)
{
    png_sink_t *sink = closure;
    errno = 0;
    if (fwrite(data, 1, len, sink->fp) == len) {
        return CAIRO_STATUS_SUCCESS;
    }
    sink->write_errno = errno != 0 ? errno : EIO;
    return CAIRO_STATUS_WRITE_ERROR;
}

/* Write a finished surface as PNG to fp. */
static int surface_to_stream(cairo_surface_t *s, FILE *fp, const char *name, char *err,
                             size_t errlen)
{
    cairo_status_t st;
    png_sink_t sink;
    sink.fp = fp;
    sink.write_errno = 0;
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        tool_set_err(err, errlen, "cannot draw '%s': %s", name,
                cairo_status_to_string(cairo_surface_status(s)));
        return -1;
    }
    cairo_surface_flush(s);
    st = cairo_surface_write_to_png_stream(s, write_to_file, &sink);
    if (st != CAIRO_STATUS_SUCCESS) {
        tool_set_err(err, errlen, "cannot write '%s': %s", name,
                sink.write_errno != 0 ? strerror(sink.write_errno) : cairo_status_to_string(st));
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
        tool_set_err(err, errlen, "cannot create '%s': %s", path, atomic_file_strerror(errno));
        return -1;
    }
    if (draw(af.fp, path, ctx, err, errlen) != 0) {
        atomic_file_abort(&af);
        return -1;
    }
    if (atomic_file_commit(&af) != 0) {
        tool_set_err(err, errlen, "cannot write '%s': %s", path, atomic_file_strerror(errno));
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

/* The overlay's layout: zoom, arrow scale, margins, what the legend lists. */
typedef struct {
    double z, scale;        /* output px per image px; arrow length / motion */
    double top, bottom;     /* margins above (titles) and below (legend), px */
    double W, H, ox;        /* picture size; image's left edge */
    double dot_below;       /* motions drawn as dots (0: none moving) */
    size_t counts[DRAW_STATUS_COUNT], truths, dots;
} vectors_layout_t;

static int status_of(const draw_vector_t *v)
{
    return v->status >= 0 && v->status < DRAW_STATUS_COUNT ? v->status : DRAW_EDGE;
}

static void vectors_layout(const gray_image_t *bg, const draw_vector_t *v, size_t n,
                           const draw_vectors_opts_t *o, vectors_layout_t *l)
{
    size_t i, moving_dots = 0;
    cairo_surface_t *scratch;
    cairo_t *m_cr;
    memset(l, 0, sizeof *l);
    l->z = draw_vectors_zoom(bg->width, bg->height);
    l->scale = o->arrow_scale > 0.0 ? o->arrow_scale : auto_arrow_scale(v, n, o->grid_step);
    l->top = (o->title != NULL ? 26.0 : 0.0) + (o->subtitle != NULL ? 20.0 : 0.0) + 8.0;
    l->W = fmax(ceil(bg->width * l->z), 720.0);
    l->dot_below = 1.5 / (l->scale * l->z); /* arrow() draws a dot under 1.5 output px */
    for (i = 0; i < n; i++) {
        int st = status_of(&v[i]), dot = st == DRAW_OK && hypot(v[i].dx, v[i].dy) < l->dot_below;
        l->counts[st]++;
        l->truths += v[i].has_truth != 0;
        l->dots += dot;
        moving_dots += dot && (v[i].dx != 0.0 || v[i].dy != 0.0);
    }
    if (moving_dots == 0) { /* the legend then says "no motion" */
        l->dot_below = 0.0;
    }
    /* wide enough for the title lines; tall enough for the legend */
    scratch = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 8, 8);
    m_cr = cairo_create(scratch);
    if (o->title != NULL) {
        l->W = fmax(l->W, ceil(text_width(m_cr, 16, 1, o->title)) + 20.0);
    }
    if (o->subtitle != NULL) {
        l->W = fmax(l->W, ceil(text_width(m_cr, 13, 0, o->subtitle)) + 20.0);
    }
    l->bottom = 48.0 + 26.0 * legend_items(m_cr, o, l->counts, l->dots, l->dot_below, l->truths,
                                           l->W, 0.0, 0);
    cairo_destroy(m_cr);
    cairo_surface_destroy(scratch);
    l->H = ceil(bg->height * l->z) + l->top + l->bottom;
    l->ox = floor((l->W - ceil(bg->width * l->z)) / 2.0);
}

/* The dark page and the image, scaled. */
static void vectors_background(cairo_t *cr, const gray_image_t *bg, const draw_vectors_opts_t *o,
                               const vectors_layout_t *l)
{
    cairo_surface_t *img_s = background_surface(bg, o);
    cairo_set_source_rgb(cr, 0.11, 0.11, 0.13);
    cairo_paint(cr);
    cairo_save(cr);
    cairo_translate(cr, l->ox, l->top);
    cairo_scale(cr, l->z, l->z);
    cairo_set_source_surface(cr, img_s, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr),
                             l->z >= 2.0 ? CAIRO_FILTER_NEAREST : CAIRO_FILTER_GOOD);
    cairo_rectangle(cr, 0, 0, bg->width, bg->height);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img_s);
}

/* Marks and arrows, in output pixels. */
static void vectors_marks(cairo_t *cr, const draw_vector_t *v, size_t n,
                          const draw_vectors_opts_t *o, const vectors_layout_t *l)
{
    double lw = fmin(3.0, fmax(1.5, o->grid_step * l->z / 14.0)), k = l->scale * l->z;
    size_t i;
    for (i = 0; i < n; i++) {
        int st = status_of(&v[i]);
        double tx = l->ox + (v[i].x + 0.5) * l->z, ty = l->top + (v[i].y + 0.5) * l->z;
        if (has_arrow(st)) {
            arrow(cr, tx, ty, tx + v[i].dx * k, ty + v[i].dy * k, status_rgb[st], lw);
        } else {
            status_mark(cr, tx, ty, st, fmax(3.5, lw * 1.8));
        }
        if (v[i].has_truth) { /* on top and thinner: a cyan core where both agree */
            arrow(cr, tx, ty, tx + v[i].tdx * k, ty + v[i].tdy * k, truth_rgb,
                  fmax(1.0, lw * 0.45));
        }
    }
}

/* Title lines, the legend, then the scale arrow on the last line: a
   reference arrow of a round motion drawn 60..150 px long. */
static void vectors_text(cairo_t *cr, const draw_vectors_opts_t *o, const vectors_layout_t *l)
{
    double y = 0.0, ref, k = l->scale * l->z;
    char buf[256];
    cairo_set_source_rgb(cr, 1, 1, 1);
    if (o->title != NULL) {
        text_at(cr, 10, y + 20, 16, 1, o->title);
        y += 26.0;
    }
    if (o->subtitle != NULL) {
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
        text_at(cr, 10, y + 15, 13, 0, o->subtitle);
    }
    y = l->H - l->bottom + 24.0;
    y += 26.0 * (legend_items(cr, o, l->counts, l->dots, l->dot_below, l->truths, l->W, y, 1) - 1);
    ref = nice_floor(120.0 / k);
    y += 28.0;
    arrow(cr, 12, y - 4, 12 + ref * k, y - 4, status_rgb[DRAW_OK], 2.5);
    if (l->z != 1.0) {
        snprintf(buf, sizeof buf, "= %g px of motion   (arrows drawn %g x longer than the "
                 "motion; image shown at %.3g x)", ref, l->scale, l->z);
    } else {
        snprintf(buf, sizeof buf, "= %g px of motion   (arrows drawn %g x longer than the "
                 "motion)", ref, l->scale);
    }
    cairo_set_source_rgb(cr, 1, 1, 1);
    text_at(cr, 12 + ref * k + 10, y, 13, 0, buf);
}

int draw_vectors_to(FILE *fp, const char *name, const gray_image_t *bg, const draw_vector_t *v,
                    size_t n, const draw_vectors_opts_t *opts, double *scale_used, char *err,
                    size_t errlen)
{
    draw_vectors_opts_t o;
    vectors_layout_t l;
    cairo_surface_t *out;
    cairo_t *cr;
    int rc;
    if (opts != NULL) {
        o = *opts;
    } else {
        memset(&o, 0, sizeof o);
    }
    vectors_layout(bg, v, n, &o, &l);
    if (scale_used != NULL) {
        *scale_used = l.scale;
    }
    out = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)l.W, (int)l.H);
    cr = cairo_create(out);
    vectors_background(cr, bg, &o, &l);
    vectors_marks(cr, v, n, &o, &l);
    vectors_text(cr, &o, &l);
    cairo_destroy(cr);
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

/* The pitch plot's geometry (output px) and ranges. */
typedef struct {
    double W, H;   /* picture */
    double L, PW;  /* plot left edge and width */
    double T, PH;  /* plot top edge and height */
    double WT, WH; /* waveform strip top and height */
    double tmax;   /* time axis 0..tmax, s */
    double f_lo, f_hi;
} pitch_plot_t;

static double plot_x(const pitch_plot_t *p, double t)
{
    return p->L + t / p->tmax * p->PW;
}

static double plot_y(const pitch_plot_t *p, double f)
{
    return p->T + p->PH - (f - p->f_lo) / (p->f_hi - p->f_lo) * p->PH;
}

/* Axes ranges from the data unless given: the 2nd..98th percentile of the
   voiced values, so a few wild frames do not squash the plot (frames beyond
   the range are marked on its edge). */
static void pitch_ranges(const draw_pitch_opts_t *o, pitch_plot_t *p)
{
    double lo = 0.0, hi = 0.0, *vals;
    size_t nv = 0, i;
    int pass;
    const draw_track_t *tr[2] = {&o->estimate, &o->reference};
    p->tmax = 0.0;
    vals = malloc((o->estimate.n + o->reference.n + 1u) * sizeof *vals);
    for (pass = 0; pass < 2; pass++) {
        for (i = 0; i < tr[pass]->n; i++) {
            p->tmax = tr[pass]->t[i] > p->tmax ? tr[pass]->t[i] : p->tmax;
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
        p->tmax = fmax(p->tmax, (double)o->sample_count / o->sample_rate);
    }
    if (hi <= 0.0) {
        lo = 50.0;
        hi = 500.0;
    }
    p->f_lo = o->fmin > 0.0 ? o->fmin : fmax(0.0, lo - 0.15 * (hi - lo) - 5.0);
    p->f_hi = o->fmax > 0.0 ? o->fmax : hi + 0.15 * (hi - lo) + 5.0;
    if (p->f_hi <= p->f_lo) {
        p->f_hi = p->f_lo + 1.0;
    }
    if (p->tmax <= 0.0) {
        p->tmax = 1.0;
    }
}

/* Background, title and subtitle. */
static void pitch_background(cairo_t *cr, const draw_pitch_opts_t *o, const pitch_plot_t *p)
{
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0.97, 0.97, 0.98);
    cairo_rectangle(cr, p->L, p->T, p->PW, p->PH);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    if (o->title != NULL) {
        text_at(cr, p->L, 24, 17, 1, o->title);
    }
    if (o->subtitle != NULL) {
        cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
        text_at(cr, p->L, 46, 13, 0, o->subtitle);
    }
}

/* Grid lines, tick labels and axis titles. */
static void pitch_axes(cairo_t *cr, const pitch_plot_t *p)
{
    char buf[64];
    double step = tick_step(p->f_hi - p->f_lo, 6), v;
    cairo_set_line_width(cr, 1.0);
    for (v = ceil(p->f_lo / step) * step; v <= p->f_hi + 1e-9; v += step) {
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.88);
        cairo_move_to(cr, p->L, floor(plot_y(p, v)) + 0.5);
        cairo_line_to(cr, p->L + p->PW, floor(plot_y(p, v)) + 0.5);
        cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%g", v);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text_at(cr, p->L - 8 - text_width(cr, 12, 0, buf), plot_y(p, v) + 4, 12, 0, buf);
    }
    step = tick_step(p->tmax, 10);
    for (v = 0.0; v <= p->tmax + 1e-9; v += step) {
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.88);
        cairo_move_to(cr, floor(plot_x(p, v)) + 0.5, p->T);
        cairo_line_to(cr, floor(plot_x(p, v)) + 0.5, p->WT + p->WH);
        cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%g", v);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text_at(cr, plot_x(p, v) - text_width(cr, 12, 0, buf) / 2, p->WT + p->WH + 18, 12, 0,
                buf);
    }
    text_at(cr, p->L + p->PW / 2 - 24, p->WT + p->WH + 38, 13, 0, "time (s)");
    cairo_save(cr);
    cairo_move_to(cr, 22, p->T + p->PH / 2 + 24);
    cairo_rotate(cr, -PI / 2);
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 13);
    cairo_show_text(cr, "f0 (Hz)");
    cairo_restore(cr);
}

/* Waveform strip: min/max per column, the loudest sample filling it. */
static void pitch_waveform(cairo_t *cr, const draw_pitch_opts_t *o, const pitch_plot_t *p)
{
    int col, peak = 1;
    size_t k;
    if (o->samples == NULL || o->sample_count == 0 || o->sample_rate == 0) {
        return;
    }
    for (k = 0; k < o->sample_count; k++) {
        int a = o->samples[k] < 0 ? -o->samples[k] : o->samples[k];
        peak = a > peak ? a : peak;
    }
    cairo_set_source_rgb(cr, 0.97, 0.97, 0.98);
    cairo_rectangle(cr, p->L, p->WT, p->PW, p->WH);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.45, 0.45, 0.5);
    cairo_set_line_width(cr, 1.0);
    for (col = 0; col < (int)p->PW; col++) {
        size_t a = (size_t)((double)col / p->PW * p->tmax * o->sample_rate);
        size_t b = (size_t)((double)(col + 1) / p->PW * p->tmax * o->sample_rate);
        int lo = 0, hi = 0;
        if (a >= o->sample_count) {
            break;
        }
        b = b > o->sample_count ? o->sample_count : b;
        for (k = a; k < b; k++) {
            lo = o->samples[k] < lo ? o->samples[k] : lo;
            hi = o->samples[k] > hi ? o->samples[k] : hi;
        }
        cairo_move_to(cr, p->L + col + 0.5, p->WT + p->WH / 2 - 0.95 * hi / peak * p->WH / 2);
        cairo_line_to(cr, p->L + col + 0.5,
                      p->WT + p->WH / 2 - 0.95 * lo / peak * p->WH / 2 + 0.5);
        cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    text_at(cr, p->L - 8 - text_width(cr, 11, 0, "waveform"), p->WT + p->WH / 2 + 4, 11, 0,
            "waveform");
}

/* One track: lines through voiced frames, broken at gaps; the estimate
   (estimate = 1) also as dots when its frames are sparse enough. */
static void pitch_track_line(cairo_t *cr, const draw_track_t *tr, int estimate,
                             const pitch_plot_t *p)
{
    double gap = 2.5 * frame_spacing(tr);
    int open = 0;
    size_t i;
    if (!estimate) {
        cairo_set_source_rgba(cr, 0.25, 0.55, 1.0, 0.45);
        cairo_set_line_width(cr, 7.0);
    } else {
        cairo_set_source_rgb(cr, 0.85, 0.15, 0.1);
        cairo_set_line_width(cr, 1.6);
    }
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (i = 0; i < tr->n; i++) {
        double x = plot_x(p, tr->t[i]), y = plot_y(p, tr->f0[i]);
        if (tr->f0[i] <= 0.0) {
            open = 0;
            continue;
        }
        if (open && tr->t[i] - tr->t[i - 1] <= gap) {
            cairo_line_to(cr, x, y);
        } else {
            cairo_move_to(cr, x, y);
            cairo_line_to(cr, x + 0.01, y);
        }
        open = 1;
    }
    cairo_stroke(cr);
    if (estimate && tr->n <= (size_t)p->PW) {
        for (i = 0; i < tr->n; i++) {
            if (tr->f0[i] > 0.0) {
                cairo_new_sub_path(cr);
                cairo_arc(cr, plot_x(p, tr->t[i]), plot_y(p, tr->f0[i]), 2.2, 0, 2 * PI);
            }
        }
        cairo_fill(cr);
    }
}

/* Estimates beyond the y range: small triangles on the edge they pass, and
   their legend at the bottom right, clear of the data and the axis title. */
static void pitch_beyond(cairo_t *cr, const draw_pitch_opts_t *o, const pitch_plot_t *p)
{
    size_t i, beyond = 0;
    char buf[64];
    double v;
    cairo_set_source_rgb(cr, 0.85, 0.15, 0.1);
    for (i = 0; i < o->estimate.n; i++) {
        double f = o->estimate.f0[i];
        if (f <= 0.0 || (f >= p->f_lo && f <= p->f_hi)) {
            continue;
        }
        beyond++;
        pitch_triangle(cr, plot_x(p, o->estimate.t[i]), f > p->f_hi ? p->T - 1 : p->T + p->PH + 1,
                       f > p->f_hi);
    }
    if (beyond == 0) {
        return;
    }
    snprintf(buf, sizeof buf, "f0 beyond the axis range: %zu frame%s", beyond,
             beyond == 1 ? "" : "s");
    v = p->L + p->PW - text_width(cr, 12, 0, buf);
    cairo_set_source_rgb(cr, 0.85, 0.15, 0.1);
    pitch_triangle(cr, v - 24, p->WT + p->WH + 38 - 10, 1);
    pitch_triangle(cr, v - 12, p->WT + p->WH + 38 - 10, 0);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text_at(cr, v, p->WT + p->WH + 38, 12, 0, buf);
}

/* The plot's frame, and the legend top right, above the plot. */
static void pitch_legend(cairo_t *cr, const draw_pitch_opts_t *o, const pitch_plot_t *p)
{
    const char *est_label = "estimate (unvoiced frames not drawn)";
    double tw, lx, ly;
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, p->L + 0.5, p->T + 0.5, p->PW - 1, p->PH - 1);
    cairo_stroke(cr);
    tw = text_width(cr, 12, 0, est_label);
    lx = p->L + p->PW - tw - 40;
    ly = o->reference.n > 0 ? 22 : 44;
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

int draw_pitch_to(FILE *fp, const char *name, const draw_pitch_opts_t *o, char *err,
                  size_t errlen)
{
    pitch_plot_t p;
    cairo_surface_t *s;
    cairo_t *cr;
    int rc;
    p.W = 1100.0;
    p.H = 560.0;
    p.L = 78.0;
    p.PW = p.W - p.L - 24.0;
    p.T = 62.0;
    p.PH = 330.0;
    p.WT = p.T + p.PH + 16.0;
    p.WH = 80.0;
    pitch_ranges(o, &p);
    s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)p.W, (int)p.H);
    cr = cairo_create(s);
    pitch_background(cr, o, &p);
    pitch_axes(cr, &p);
    pitch_waveform(cr, o, &p);
    cairo_save(cr); /* tracks clipped to the plot */
    cairo_rectangle(cr, p.L, p.T, p.PW, p.PH);
    cairo_clip(cr);
    pitch_track_line(cr, &o->reference, 0, &p);
    pitch_track_line(cr, &o->estimate, 1, &p);
    cairo_restore(cr);
    pitch_beyond(cr, o, &p);
    pitch_legend(cr, o, &p);
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
