/*
 * peers_chart.c - ssda-peers-chart: the speed ratios of the peer benchmarks
 * as one PNG bar chart (cairo). Each ratio is "peer time / ssda time" for
 * the same job in the same process run: right of 1 ssda is faster, left of
 * 1 the peer is. Log scale; bars coloured by peer.
 *
 * usage: ssda-peers-chart OUT.png [--subtitle TEXT] RATIOS.tsv...
 *   RATIOS.tsv: lines "group<TAB>label<TAB>value" (label ends in "vs PEER").
 */
#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"

#define MAX_ROWS 256

typedef struct {
    char group[96], label[128];
    double value;
} row_t;

static const struct {
    const char *peer;
    double r, g, b;
} k_colours[] = {
    {"TM_SQDIFF", 0.15, 0.40, 0.75},        {"TM_CCOEFF_NORMED", 0.50, 0.30, 0.70},
    {"ssda none", 0.45, 0.45, 0.45},        {"aubio yinfast", 0.70, 0.45, 0.10},
    {"aubio yin", 0.90, 0.55, 0.15},
};

static void colour_of(const char *label, double *r, double *g, double *b)
{
    const char *vs = strstr(label, "vs ");
    *r = *g = *b = 0.3;
    for (size_t k = 0; vs != NULL && k < sizeof k_colours / sizeof k_colours[0]; k++) {
        if (!strcmp(vs + 3, k_colours[k].peer)) {
            *r = k_colours[k].r;
            *g = k_colours[k].g;
            *b = k_colours[k].b;
            return;
        }
    }
}

static int read_rows(const char *path, row_t *rows, size_t *n)
{
    char line[512];
    FILE *fp = fopen(path, "r");
    if (fp == NULL) {
        perror(path);
        return -1;
    }
    while (fgets(line, sizeof line, fp) != NULL && *n < MAX_ROWS) {
        char *t1 = strchr(line, '\t'), *t2 = t1 ? strchr(t1 + 1, '\t') : NULL;
        row_t *r = &rows[*n];
        if (t2 == NULL) {
            continue;
        }
        *t1 = *t2 = '\0';
        snprintf(r->group, sizeof r->group, "%.95s", line);
        snprintf(r->label, sizeof r->label, "%.127s", t1 + 1);
        r->value = atof(t2 + 1);
        if (r->value > 0.0) {
            (*n)++;
        }
    }
    fclose(fp);
    return 0;
}

/* Gather the rows of each group together: groups in order of first
   appearance, rows in file order within a group (a stable reordering). */
static void group_rows(row_t *rows, size_t n)
{
    static row_t sorted[MAX_ROWS];
    static unsigned char taken[MAX_ROWS];
    size_t k = 0;
    memset(taken, 0, sizeof taken);
    for (size_t i = 0; i < n; i++) {
        if (taken[i]) {
            continue;
        }
        for (size_t j = i; j < n; j++) {
            if (!taken[j] && !strcmp(rows[j].group, rows[i].group)) {
                sorted[k++] = rows[j];
                taken[j] = 1;
            }
        }
    }
    memcpy(rows, sorted, n * sizeof *rows);
}

static cairo_status_t write_fp(void *closure, const unsigned char *data, unsigned int len)
{
    return fwrite(data, 1, len, closure) == len ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

static void text(cairo_t *cr, double x, double y, const char *s, double size, int bold,
                 int align_right)
{
    cairo_text_extents_t ext;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_text_extents(cr, s, &ext);
    cairo_move_to(cr, align_right ? x - ext.x_advance : x, y);
    cairo_show_text(cr, s);
}

/* The chart's geometry: the value axis runs log10 from lo to hi. */
typedef struct {
    double width, left, right, row_h, group_h, top, height, lo, hi;
} chart_t;

static double xpos(const chart_t *c, double v)
{
    return c->left + (c->right - c->left) * (log10(v) - log10(c->lo)) /
                         (log10(c->hi) - log10(c->lo));
}

/* Decade grid lines and labels, and the target for tracking: 10x
   faster than TM_SQDIFF (dashed). */
static void draw_grid(cairo_t *cr, const chart_t *c)
{
    static const double dash[] = {5.0, 4.0};
    char buf[64];
    double x;
    for (double d = c->lo; d <= c->hi * 1.001; d *= 10.0) {
        double grey = d > 0.99 && d < 1.01 ? 0.0 : 0.8;
        x = xpos(c, d);
        cairo_set_source_rgb(cr, grey, grey, grey);
        cairo_set_line_width(cr, d > 0.99 && d < 1.01 ? 1.5 : 1.0);
        cairo_move_to(cr, x, c->top - 10);
        cairo_line_to(cr, x, c->height - 40);
        cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%gx", d);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        text(cr, x - 10, c->height - 24, buf, 11, 0, 0);
    }
    x = xpos(c, 10.0);
    cairo_set_source_rgb(cr, 0.1, 0.6, 0.2);
    cairo_set_dash(cr, dash, 2, 0);
    cairo_move_to(cr, x, c->top - 10);
    cairo_line_to(cr, x, c->height - 40);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    text(cr, x + 4, c->top - 12, "tracking target: 10x TM_SQDIFF", 10, 0, 0);
}

/* One bar per row from 1x to its value, under its group's heading. */
static void draw_rows(cairo_t *cr, const chart_t *c, const row_t *rows, size_t n)
{
    char buf[64];
    double y = c->top;
    for (size_t i = 0; i < n; i++) {
        double r, g, b, x1 = xpos(c, 1.0), xv = xpos(c, rows[i].value);
        if (i == 0 || strcmp(rows[i].group, rows[i - 1].group) != 0) {
            cairo_set_source_rgb(cr, 0, 0, 0);
            text(cr, 20, y + 20, rows[i].group, 13, 1, 0);
            y += c->group_h;
        }
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        text(cr, c->left - 8, y + 14, rows[i].label, 11, 0, 1);
        colour_of(rows[i].label, &r, &g, &b);
        cairo_set_source_rgb(cr, r, g, b);
        cairo_rectangle(cr, xv < x1 ? xv : x1, y + 3, fabs(xv - x1), c->row_h - 6);
        cairo_fill(cr);
        snprintf(buf, sizeof buf, rows[i].value >= 1.0 ? "%.1fx" : "%.2fx", rows[i].value);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        if (xv >= x1) {
            text(cr, xv + 4, y + 14, buf, 10, 0, 0);
        } else {
            text(cr, xv - 4, y + 14, buf, 10, 0, 1);
        }
        y += c->row_h;
    }
}

/* The surface as a PNG, written atomically. Returns 0 or 1. */
static int write_png(cairo_surface_t *surf, const char *out)
{
    atomic_file_t af;
    if (atomic_file_open(&af, out) != 0) {
        perror(out);
        return 1;
    }
    if (cairo_surface_write_to_png_stream(surf, write_fp, af.fp) != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "%s: cannot write the PNG\n", out);
        atomic_file_abort(&af);
        return 1;
    }
    if (atomic_file_commit(&af) != 0) {
        perror(out);
        return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    static row_t rows[MAX_ROWS];
    size_t n = 0, groups = 0;
    const char *out = NULL, *subtitle = NULL;
    chart_t c = {1100, 420, 1040, 20, 30, 80, 0, 0.1, 100.0};
    cairo_surface_t *surf;
    cairo_t *cr;
    int rc;

    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--subtitle") && i + 1 < argc) {
            subtitle = argv[++i];
        } else if (out == NULL) {
            out = argv[i];
        } else if (read_rows(argv[i], rows, &n) != 0) {
            return 1;
        }
    }
    if (out == NULL || n == 0) {
        fprintf(stderr, "usage: ssda-peers-chart OUT.png [--subtitle TEXT] RATIOS.tsv...\n");
        return 2;
    }
    group_rows(rows, n);
    for (size_t i = 0; i < n; i++) {
        groups += i == 0 || strcmp(rows[i].group, rows[i - 1].group) != 0;
        while (rows[i].value < c.lo * 1.5) c.lo /= 10.0;
        while (rows[i].value > c.hi / 1.5) c.hi *= 10.0;
    }
    c.height = c.top + (double)groups * c.group_h + (double)n * c.row_h + 50;
    surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)c.width, (int)c.height);
    cr = cairo_create(surf);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, 20, 28, "ssda's speed against its peers: peer time / ssda time, same job, same run",
         17, 1, 0);
    text(cr, 20, 50, subtitle ? subtitle : "right of 1: ssda faster; left of 1: the peer is faster (log scale)",
         12, 0, 0);
    draw_grid(cr, &c);
    draw_rows(cr, &c, rows, n);
    cairo_destroy(cr);
    rc = write_png(surf, out);
    cairo_surface_destroy(surf);
    return rc;
}
