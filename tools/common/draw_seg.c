/* draw_seg.c - histogram mixtures and label pictures with cairo (draw_seg.h). */
#include "draw_seg.h"
#include "tool_err.h"

#include <cairo.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define FONT "DejaVu Sans"
#define PI 3.14159265358979323846

static cairo_status_t write_fp(void *closure, const unsigned char *data, unsigned int len)
{
    return fwrite(data, 1, len, (FILE *)closure) == len ? CAIRO_STATUS_SUCCESS
                                                        : CAIRO_STATUS_WRITE_ERROR;
}

static int finish(cairo_surface_t *s, cairo_t *cr, FILE *fp, const char *name, char *err,
                  size_t errlen)
{
    int rc = 0;
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    if (st == CAIRO_STATUS_SUCCESS) {
        cairo_surface_flush(s);
        st = cairo_surface_write_to_png_stream(s, write_fp, fp);
    }
    if (st != CAIRO_STATUS_SUCCESS) {
        tool_set_err(err, errlen, "cannot draw '%s': %s", name, cairo_status_to_string(st));
        rc = -1;
    }
    cairo_surface_destroy(s);
    return rc;
}

static void text_at(cairo_t *cr, double x, double y, double size, int bold, const char *s)
{
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, s);
}

void draw_label_rgb(uint32_t k, double rgb[3])
{
    /* a qualitative palette (Tableau 10, then 6 more) */
    static const double pal[16][3] = {
        {0.12, 0.47, 0.71}, {1.00, 0.50, 0.05}, {0.17, 0.63, 0.17}, {0.84, 0.15, 0.16},
        {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29}, {0.89, 0.47, 0.76}, {0.74, 0.74, 0.13},
        {0.09, 0.75, 0.81}, {0.50, 0.50, 0.50}, {0.68, 0.78, 0.91}, {1.00, 0.73, 0.47},
        {0.60, 0.87, 0.54}, {1.00, 0.60, 0.59}, {0.77, 0.69, 0.84}, {0.97, 0.71, 0.82}};
    if (k == 0u) {
        rgb[0] = rgb[1] = rgb[2] = 0.30;
        return;
    }
    memcpy(rgb, pal[(k - 1u) % 16u], 3 * sizeof(double));
}

/* ---- histograms ---- */

#define HP_W 960.0
#define HP_H 280.0
#define LABEL_MAX_H 4000.0 /* label panels: tallest drawn, px */
#define HP_L 70.0
#define HP_R 250.0

/* The occupied bins, with a margin: [lo, hi]. */
static void occupied(const draw_hist_panel_t *p, uint32_t *lo, uint32_t *hi)
{
    uint32_t z, first = p->bins, last = 0;
    for (z = 0; z < p->bins; z++) {
        if (p->hist[z] != 0u) {
            first = z < first ? z : first;
            last = z;
        }
    }
    if (first > last) {
        first = 0;
        last = p->bins - 1u;
    }
    *lo = first > 5u ? first - 5u : 0u;
    *hi = last + 5u < p->bins ? last + 5u : p->bins - 1u;
    if (*hi <= *lo) {
        *hi = *lo + 1u;
    }
}

static double comp_count(const draw_hist_panel_t *p, uint32_t k, double z)
{
    const double t = (z - p->mean[k]) / p->sigma[k];
    return p->total * p->weight[k] / (p->sigma[k] * sqrt(2.0 * PI)) * exp(-0.5 * t * t);
}

/* A panel's plotting frame: bins lo..hi across, counts 0..ymax up. */
typedef struct {
    double left, top, w, h; /* px */
    uint32_t lo, hi;
    double ymax;
} frame_t;

static double px_of(const frame_t *f, double v)
{
    return f->left + (v - (double)f->lo + 0.5) / ((double)(f->hi - f->lo) + 1.0) * f->w;
}

static double py_of(const frame_t *f, double c)
{
    return f->top + f->h - c / f->ymax * f->h;
}

/* The frame, x ticks every 1, 2, 5 x 10^k bins, axis labels. */
static void hist_axes(cairo_t *cr, const frame_t *f)
{
    double step = pow(10.0, floor(log10((double)(f->hi - f->lo + 1u) / 5.0))), x;
    char s[64];
    step = (f->hi - f->lo + 1u) / step > 10.0 ? step * 2.0 : step;
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, f->left, f->top, f->w, f->h);
    cairo_stroke(cr);
    for (x = ceil(f->lo / step) * step; x <= f->hi; x += step) {
        cairo_move_to(cr, px_of(f, x), f->top + f->h);
        cairo_line_to(cr, px_of(f, x), f->top + f->h + 5.0);
        cairo_stroke(cr);
        snprintf(s, sizeof s, "%.0f", x);
        text_at(cr, px_of(f, x) - 10.0, f->top + f->h + 18.0, 10, 0, s);
    }
    text_at(cr, f->left + f->w / 2.0 - 40.0, f->top + f->h + 34.0, 11, 0, "feature value (bin)");
    snprintf(s, sizeof s, "%.0f", f->ymax / 1.08);
    text_at(cr, 6.0, py_of(f, f->ymax / 1.08) + 4.0, 10, 0, s);
    text_at(cr, 6.0, f->top + f->h, 10, 0, "0");
}

/* The histogram as grey bars; each component (its label's colour) and
   their sum (black), sampled 4 times per bin. */
static void hist_curves(cairo_t *cr, const draw_hist_panel_t *p, const frame_t *f)
{
    uint32_t z, k;
    cairo_set_source_rgb(cr, 0.72, 0.72, 0.72);
    for (z = f->lo; z <= f->hi; z++) {
        const double x0 = px_of(f, (double)z - 0.5), x1 = px_of(f, (double)z + 0.5);
        cairo_rectangle(cr, x0, py_of(f, (double)p->hist[z]), x1 - x0,
                        py_of(f, 0.0) - py_of(f, (double)p->hist[z]));
    }
    cairo_fill(cr);
    cairo_save(cr);
    cairo_rectangle(cr, f->left, f->top, f->w, f->h);
    cairo_clip(cr);
    for (k = 0; k <= p->count; k++) {
        double rgb[3] = {0, 0, 0}, v;
        int first = 1;
        if (k < p->count) {
            draw_label_rgb(k + 1u, rgb);
        }
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_set_line_width(cr, k < p->count ? 1.6 : 2.2);
        for (v = f->lo - 0.5; v <= f->hi + 0.5; v += 0.25) {
            double c = 0.0;
            uint32_t j;
            for (j = 0; j < p->count; j++) {
                c += (k == p->count || j == k) ? comp_count(p, j, v) : 0.0;
            }
            if (first) {
                cairo_move_to(cr, px_of(f, v), py_of(f, c));
                first = 0;
            } else {
                cairo_line_to(cr, px_of(f, v), py_of(f, c));
            }
        }
        cairo_stroke(cr);
    }
    cairo_restore(cr);
}

static void hist_legend(cairo_t *cr, const draw_hist_panel_t *p, double top)
{
    uint32_t k;
    char s[160];
    for (k = 0; k <= p->count; k++) {
        double rgb[3] = {0, 0, 0};
        const double ly = top + 12.0 + 15.0 * k;
        if (k < p->count) {
            draw_label_rgb(k + 1u, rgb);
            snprintf(s, sizeof s, "%u: w %.3f, mean %.1f, sd %.2f", (unsigned)(k + 1u), p->weight[k],
                     p->mean[k], p->sigma[k]);
        } else {
            snprintf(s, sizeof s, "sum of the components");
        }
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_rectangle(cr, HP_W - HP_R + 12.0, ly - 8.0, 14.0, 8.0);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        text_at(cr, HP_W - HP_R + 32.0, ly, 10.5, 0, s);
    }
    cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
    text_at(cr, HP_W - HP_R + 12.0, top + 12.0 + 15.0 * (p->count + 1u), 10.5, 0,
            "grey: histogram");
}

static void hist_panel(cairo_t *cr, const draw_hist_panel_t *p, double y0)
{
    frame_t f;
    uint32_t z, k;
    f.left = HP_L;
    f.top = y0 + 30.0;
    f.w = HP_W - HP_L - HP_R;
    f.h = HP_H - 70.0;
    f.ymax = 1.0;
    occupied(p, &f.lo, &f.hi);
    for (z = f.lo; z <= f.hi; z++) {
        double sum = 0.0;
        f.ymax = p->hist[z] > f.ymax ? p->hist[z] : f.ymax;
        for (k = 0; k < p->count; k++) {
            sum += comp_count(p, k, z);
        }
        f.ymax = sum > f.ymax ? sum : f.ymax;
    }
    f.ymax *= 1.08;
    cairo_set_source_rgb(cr, 0, 0, 0);
    text_at(cr, HP_L, y0 + 20.0, 14, 1, p->title);
    hist_axes(cr, &f);
    hist_curves(cr, p, &f);
    hist_legend(cr, p, f.top);
}

int draw_hist_to(FILE *fp, const char *name, const char *title, const draw_hist_panel_t *p,
                 size_t n, char *err, size_t errlen)
{
    const double head = title != NULL ? 34.0 : 6.0;
    double need = 0.0;
    cairo_surface_t *s;
    cairo_t *cr;
    size_t i;
    for (i = 0; i < n; i++) {
        /* a legend longer than the panel grows it */
        const double lh = 60.0 + 15.0 * (p[i].count + 2u);
        need += lh > HP_H ? lh : HP_H;
    }
    s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)HP_W, (int)(head + need));
    cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    if (title != NULL) {
        cairo_set_source_rgb(cr, 0, 0, 0);
        text_at(cr, 12.0, 24.0, 16, 1, title);
    }
    need = head;
    for (i = 0; i < n; i++) {
        const double lh = 60.0 + 15.0 * (p[i].count + 2u);
        hist_panel(cr, &p[i], need);
        need += lh > HP_H ? lh : HP_H;
    }
    return finish(s, cr, fp, name, err, errlen);
}

/* ---- label pictures ---- */

int draw_labels_to(FILE *fp, const char *name, const char *title, uint32_t width,
                   uint32_t height, const draw_label_panel_t *p, size_t n, char *err,
                   size_t errlen)
{
    const double head = title != NULL ? 34.0 : 8.0;
    /* panels 240..700 px wide; a tall image is reduced to at most
       LABEL_MAX_H px, so that no surface passes cairo's 32767 px (a
       512 x 40960 image crashed here, a 20 x 7180 strip was refused) */
    const double zw = width > 700u ? 700.0 / width : (width < 240u ? 240.0 / width : 1.0);
    const double zoom = height * zw > LABEL_MAX_H ? LABEL_MAX_H / height : zw;
    const int pw = (int)ceil(width * zoom), ph = (int)ceil(height * zoom);
    const int slot = pw > 240 ? pw : 240; /* the legend's width at least */
    uint32_t maxk = 0, x, y;
    cairo_surface_t *s, *img;
    cairo_t *cr;
    size_t i;
    unsigned char *data;
    int stride;
    for (i = 0; i < n; i++) {
        maxk = p[i].count > maxk ? p[i].count : maxk;
    }
    s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)(n * (slot + 16) + 16),
                                   (int)(head + ph + 30.0 + 16.0 * (maxk + 2u)));
    cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    if (title != NULL) {
        text_at(cr, 12.0, 24.0, 16, 1, title);
    }
    /* each panel sampled at its drawn size (nearest pixel of the labels) */
    img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, pw, ph);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        tool_set_err(err, errlen, "cannot draw '%s': %s", name,
                     cairo_status_to_string(cairo_surface_status(img)));
        cairo_surface_destroy(img);
        cairo_destroy(cr);
        cairo_surface_destroy(s);
        return -1;
    }
    stride = cairo_image_surface_get_stride(img);
    for (i = 0; i < n; i++) {
        const double x0 = 16.0 + i * (slot + 16.0);
        uint32_t k;
        cairo_surface_flush(img);
        data = cairo_image_surface_get_data(img);
        for (y = 0; y < (uint32_t)ph; y++) {
            uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
            const double fy = (y + 0.5) / zoom;
            const uint32_t sy = fy >= height ? height - 1u : (uint32_t)fy;
            for (x = 0; x < (uint32_t)pw; x++) {
                const double fx = (x + 0.5) / zoom;
                const uint32_t sx = fx >= width ? width - 1u : (uint32_t)fx;
                const size_t at = (size_t)sy * width + sx;
                double rgb[3];
                if (p[i].nodata != NULL && p[i].nodata[at] != 0u) {
                    rgb[0] = rgb[1] = rgb[2] = 0.0;
                } else if (p[i].contour != NULL && p[i].contour[at] != 0u) {
                    rgb[0] = rgb[1] = rgb[2] = 1.0;
                } else {
                    draw_label_rgb(p[i].labels[at], rgb);
                }
                row[x] = ((uint32_t)(rgb[0] * 255.0 + 0.5) << 16) |
                         ((uint32_t)(rgb[1] * 255.0 + 0.5) << 8) | (uint32_t)(rgb[2] * 255.0 + 0.5);
            }
        }
        cairo_surface_mark_dirty(img);
        cairo_save(cr);
        cairo_translate(cr, x0, head);
        cairo_set_source_surface(cr, img, 0, 0);
        cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
        cairo_paint(cr);
        cairo_restore(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        text_at(cr, x0, head + ph + 18.0, 13, 1, p[i].title);
        for (k = 0; k <= p[i].count; k++) {
            double rgb[3];
            const double ly = head + ph + 36.0 + 16.0 * k;
            draw_label_rgb(k, rgb);
            cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
            cairo_rectangle(cr, x0, ly - 10.0, 14.0, 12.0);
            cairo_fill(cr);
            cairo_set_source_rgb(cr, 0, 0, 0);
            text_at(cr, x0 + 20.0, ly, 11, 0, p[i].legend[k]);
        }
    }
    cairo_surface_destroy(img);
    return finish(s, cr, fp, name, err, errlen);
}
