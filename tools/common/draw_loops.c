/* draw_loops.c - the symbolic registration overlay (draw_loops.h). */
#include "draw_loops.h"
#include "tool_err.h"
#include "atomic_file.h"

#include <cairo.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FONT "DejaVu Sans"
#define GAP 16.0    /* px between the two panels (drawing units) */
#define HEAD 44.0   /* title band */

static cairo_status_t write_to_file(void *closure, const unsigned char *data, unsigned int len)
{
    return fwrite(data, 1, len, (FILE *)closure) == len ? CAIRO_STATUS_SUCCESS
                                                        : CAIRO_STATUS_WRITE_ERROR;
}

/* A panel's image, grey levels compressed into 40..215 so colours show. */
static void paint_image(cairo_t *cr, const gray_image_t *img, double ox, double oy, double z)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)img->width,
                                                    (int)img->height);
    unsigned char *data;
    int stride;
    uint32_t x, y;
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(s);
        return;
    }
    cairo_surface_flush(s);
    data = cairo_image_surface_get_data(s);
    stride = cairo_image_surface_get_stride(s);
    for (y = 0; y < img->height; y++) {
        uint32_t *row = (uint32_t *)(void *)(data + (size_t)y * (size_t)stride);
        for (x = 0; x < img->width; x++) {
            const uint32_t g = 40u + gray_image_get(img, x, y) * 175u / 255u;
            row[x] = (g << 16) | (g << 8) | g;
        }
    }
    cairo_surface_mark_dirty(s);
    cairo_save(cr);
    cairo_translate(cr, ox, oy);
    cairo_scale(cr, z, z);
    cairo_set_source_surface(cr, s, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(s);
}

/* A colour per pair from a golden-ratio hue walk. */
static void pair_colour(uint32_t k, double rgb[3])
{
    const double h = (double)((k * 0.6180339887) - (uint32_t)(k * 0.6180339887)) * 6.0;
    const int i = (int)h;
    const double f = h - i, q = 1.0 - f;
    const double v[6][3] = {{1, f, 0}, {q, 1, 0}, {0, 1, f}, {0, q, 1}, {f, 0, 1}, {1, 0, q}};
    rgb[0] = 0.15 + 0.85 * v[i % 6][0];
    rgb[1] = 0.15 + 0.85 * v[i % 6][1];
    rgb[2] = 0.15 + 0.85 * v[i % 6][2];
}

/* Contour of a loop; pixel centres at +0.5 in drawing units. */
static void contour(cairo_t *cr, const ssda_loop_t *l, uint32_t samples, double ox, double oy,
                    double z)
{
    uint32_t k;
    cairo_new_path(cr);
    for (k = 0; k < samples; k++) {
        const double x = ox + (l->contour[k].x_q8 / 256.0 + 0.5) * z;
        const double y = oy + (l->contour[k].y_q8 / 256.0 + 0.5) * z;
        if (k == 0) {
            cairo_move_to(cr, x, y);
        } else {
            cairo_line_to(cr, x, y);
        }
    }
    cairo_close_path(cr);
}

static int colour_of(const draw_loops_pair_t *pairs, uint32_t n, uint32_t i, int ref_side)
{
    uint32_t k;
    for (k = 0; k < n; k++) {
        if ((ref_side ? pairs[k].ref : pairs[k].mov) == i) {
            return (int)k;
        }
    }
    return -1;
}

static void panel(cairo_t *cr, const draw_loops_side_t *s, const draw_loops_pair_t *pairs,
                  uint32_t n_pairs, int ref_side, double ox, double oy, double z)
{
    uint32_t i;
    paint_image(cr, s->img, ox, oy, z);
    for (i = 0; i < s->n; i++) {
        const int k = colour_of(pairs, n_pairs, i, ref_side);
        double rgb[3] = {0.95, 0.85, 0.2};
        contour(cr, &s->loops[i], s->samples, ox, oy, z);
        if (k >= 0) {
            pair_colour((uint32_t)k, rgb);
            cairo_set_line_width(cr, 2.2);
        } else {
            cairo_set_line_width(cr, 1.0);
        }
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_stroke(cr);
    }
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 13);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_move_to(cr, ox + 4, oy - 6);
    cairo_show_text(cr, s->label != NULL ? s->label : "");
}

int draw_loops_to(FILE *fp, const char *name, const draw_loops_side_t *ref,
                   const draw_loops_side_t *mov, const draw_loops_pair_t *pairs,
                   uint32_t n_pairs, const char *title, const char *subtitle, char *err,
                   size_t errlen)
{
    const uint32_t maxw = ref->img->width > mov->img->width ? ref->img->width : mov->img->width;
    const uint32_t maxh = ref->img->height > mov->img->height ? ref->img->height
                                                              : mov->img->height;
    const double z = maxw < 400 ? 2.0 : 1.0;
    const double W = GAP * 3 + (ref->img->width + mov->img->width) * z;
    const double H = HEAD + 24 + maxh * z + GAP;
    const double rx = GAP, mx = GAP * 2 + ref->img->width * z, oy = HEAD + 24;
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)W, (int)H);
    cairo_t *cr = cairo_create(s);
    cairo_status_t st;
    uint32_t k;
    cairo_set_source_rgb(cr, 0.12, 0.12, 0.14);
    cairo_paint(cr);
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 15);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_move_to(cr, GAP, 20);
    cairo_show_text(cr, title != NULL ? title : "");
    cairo_select_font_face(cr, FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 12);
    cairo_move_to(cr, GAP, 38);
    cairo_show_text(cr, subtitle != NULL ? subtitle : "");
    panel(cr, ref, pairs, n_pairs, 1, rx, oy, z);
    panel(cr, mov, pairs, n_pairs, 0, mx, oy, z);
    for (k = 0; k < n_pairs; k++) { /* centroid to centroid across the panels */
        const ssda_loop_t *a = &ref->loops[pairs[k].ref], *b = &mov->loops[pairs[k].mov];
        double rgb[3];
        pair_colour(k, rgb);
        cairo_set_source_rgba(cr, rgb[0], rgb[1], rgb[2], 0.8);
        cairo_set_line_width(cr, 1.2);
        cairo_move_to(cr, rx + (a->cx_q8 / 256.0 + 0.5) * z, oy + (a->cy_q8 / 256.0 + 0.5) * z);
        cairo_line_to(cr, mx + (b->cx_q8 / 256.0 + 0.5) * z, oy + (b->cy_q8 / 256.0 + 0.5) * z);
        cairo_stroke(cr);
    }
    cairo_destroy(cr);
    cairo_surface_flush(s);
    st = cairo_surface_status(s);
    if (st == CAIRO_STATUS_SUCCESS) {
        st = cairo_surface_write_to_png_stream(s, write_to_file, fp);
    }
    cairo_surface_destroy(s);
    if (st != CAIRO_STATUS_SUCCESS) {
        tool_set_err(err, errlen, "cannot write '%s': %s", name, cairo_status_to_string(st));
        return -1;
    }
    return 0;
}

int draw_loops_png(const char *path, const draw_loops_side_t *ref, const draw_loops_side_t *mov,
                   const draw_loops_pair_t *pairs, uint32_t n_pairs, const char *title,
                   const char *subtitle, char *err, size_t errlen)
{
    atomic_file_t af;
    if (atomic_file_open(&af, path) != 0) {
        tool_set_err(err, errlen, "cannot create '%s': %s", path, strerror(errno));
        return -1;
    }
    if (draw_loops_to(af.fp, path, ref, mov, pairs, n_pairs, title, subtitle, err, errlen) != 0) {
        atomic_file_abort(&af);
        return -1;
    }
    if (atomic_file_commit(&af) != 0) {
        tool_set_err(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        return -1;
    }
    return 0;
}
