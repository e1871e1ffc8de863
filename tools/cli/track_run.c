/* track_run.c - options, run, JSON and overlay of grid tracking (track, compare). */
#include "track_run.h"
#include "track_metric.h"
#include "track_wave.h"
#include "img_source.h"
#include "json_out.h"
#include "median.h"
#include "progress.h"
#include "ssda/grad.h"
#include "ssda/ncc.h"
#include "ssda/stream.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char track_opts_help[] =
    "grid:\n"
    "  --window N|WxH    window size, px (default 16, the seed's)\n"
    "  --search N|WxH    search area size, px, centred on the window (default 32)\n"
    "  --step N|XxY      grid step, px (default: the window size)\n"
    "  --roi X,Y,W,H     lay the grid in this rectangle of SECOND (default: all)\n"
    "search:\n"
    "  --threshold MODE  auto (default, exact), none, fixed:T, ramp:LAMBDA[:K],\n"
    "                    auto-ramp[:K]  (see ssda match --help)\n"
    "  --predict P       neighbour (default: median of the solved left, up and\n"
    "                    up-right vectors), left (the seed's), or none\n"
    "  --scan ORDER      raster, predict or coarse (coarse needs --predict none)\n"
    "  --order ROWS      rows (default) or spread\n"
    "  --no-bounds       no successive-elimination bounds (default: bounds on;\n"
    "                    exact either way, bounds do less work)\n"
    "vector quality (each window gets a status; only 'ok' vectors are trusted):\n"
    "  --flat LEVEL      'flat' (not searched) when the window's mean absolute\n"
    "                    deviation is below LEVEL, sample units (default 1.25;\n"
    "                    0 = no test)\n"
    "  --unique RATIO    'ambiguous' when a placement outside the 5x5 square around\n"
    "                    the best has a SAD within RATIO times the best's (default\n"
    "                    1.10, 1.004..4; off = no test; exact thresholds only)\n"
    "  --unique-radius R that square's radius, 1 or 2 (default 2)\n"
    "  --no-subpixel     whole-pixel vectors only (sub_dx = dx, sub_dy = dy)\n"
    "  'at_limit': the best placement is on the border of the search area (the\n"
    "  motion may be larger: try a larger --search)\n"
    "windows to skip:\n"
    "  --exclude [LEVEL[:COUNT]]  skip textureless windows (the seed's rule): a window\n"
    "                    is excluded when fewer than COUNT of its pixels lie on one\n"
    "                    side of brightness LEVEL. Defaults: LEVEL = mean of SECOND\n"
    "                    (fill pixels ignored), COUNT = window pixels / 16\n"
    "  --mask-value V    windows or areas holding V are 'masked' (GOES fill: 4095)\n"
    "  --grad            apply the Fig. 8 differential operator to both images first\n"
    "  --mem BYTES       track from block-streamed images within BYTES of memory\n"
    "                    (at least a band of one grid column's search areas and\n"
    "                    windows; below it the run is refused and says how much)\n"
    "outputs:\n"
    "  --json FILE|-     write the vectors as JSON (- = stdout)\n"
    "  --overlay OUT.png draw the vectors over SECOND (a grid too dense to read is\n"
    "                    drawn every k-th row and column; stderr says so)\n"
    "  --arrow-scale S   arrows drawn S times the motion (default: automatic)\n"
    "  --relax N         clean the field by relaxation labelling (the seed 003's\n"
    "                    section 4), N iterations: JSON windows gain relax_dx,\n"
    "                    relax_dy (px) and changed; the overlay draws the cleaned\n"
    "                    vectors as a second (cyan) arrow, the changed ones pink\n"
    "  --relax-keep      with --relax: keep vectors whose most likely class is their\n"
    "                    own (without it those are smoothed too: changed is false,\n"
    "                    yet relax_dx, relax_dy may differ from sub_dx, sub_dy)\n"
    "  --relax-median    clean by the normalised median test instead (same fields)\n"
    "  --metric M        sad, ncc or absncc: JSON windows gain rho, the correlation\n"
    "                    coefficient at their placement; with ncc (largest rho) or\n"
    "                    absncc (largest |rho|) the vectors come from the exact\n"
    "                    correlation search over each searched window's area\n"
    "                    (SAD's ok, ambiguous, at_limit), which a gain or offset\n"
    "                    between the images does not change; it decides ok or\n"
    "                    at_limit (best on the border; no ambiguous test)\n"
    "  --quiet           no progress bar\n";

void track_opts_init(track_opts_t *o)
{
    memset(o, 0, sizeof *o);
    o->cfg.predict = SSDA_TRACK_PREDICT_MEDIAN;
    o->cfg.match.flags = SSDA_MATCH_BOUNDS; /* exact, and the least work on a host */
    o->cfg.flags = SSDA_TRACK_UNIQUE;       /* dropped in inexact modes unless asked */
}

/* "N" or "WxH", each 1..65535. */
static int parse_size(const char *s, uint16_t *w, uint16_t *h)
{
    char buf[40];
    char *x;
    uint32_t a, b;
    if (s == NULL || strlen(s) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    x = strchr(buf, 'x');
    if (x == NULL) {
        if (cli_parse_u32(buf, 1, 65535, &a) != 0) {
            return -1;
        }
        b = a;
    } else {
        *x = '\0';
        if (cli_parse_u32(buf, 1, 65535, &a) != 0 || cli_parse_u32(x + 1, 1, 65535, &b) != 0) {
            return -1;
        }
    }
    *w = (uint16_t)a;
    *h = (uint16_t)b;
    return 0;
}

/* "LEVEL[:COUNT]"; LEVEL may be "mean". */
static int parse_exclude(const char *s, uint32_t *level, int *level_given, uint32_t *count)
{
    char buf[40];
    char *colon;
    if (strlen(s) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    colon = strchr(buf, ':');
    if (colon != NULL) {
        *colon = '\0';
        if (cli_parse_u32(colon + 1, 1, 65535u * 65535u / 2u, count) != 0) {
            return -1;
        }
    }
    if (strcmp(buf, "mean") == 0) {
        *level_given = 0;
        return 0;
    }
    if (cli_parse_u32(buf, 0, 65534, level) != 0) {
        return -1;
    }
    *level_given = 1;
    return 0;
}

/* BYTES with an optional K, M or G suffix (powers of 1024). */
static int parse_bytes(const char *s, uint64_t *out)
{
    char *end;
    unsigned long long v;
    uint64_t mul = 1;
    if (*s < '0' || *s > '9') {
        return -1;
    }
    errno = 0;
    v = strtoull(s, &end, 10);
    if (errno != 0) {
        return -1;
    }
    if (*end == 'K' || *end == 'k') {
        mul = 1024u;
        end++;
    } else if (*end == 'M' || *end == 'm') {
        mul = 1024u * 1024u;
        end++;
    } else if (*end == 'G' || *end == 'g') {
        mul = 1024u * 1024u * 1024u;
        end++;
    }
    if (*end != '\0' || v == 0 || v > UINT64_MAX / mul) {
        return -1;
    }
    *out = v * mul;
    return 0;
}

/* Report a bad value of the current option (a->bad set). */
static void bad_value(cli_args_t *a, const char *fmt, const char *v)
{
    cli_usage_error(a->cmd, fmt, v);
    a->bad = 1;
}

/* --window, --search, --step, --roi. */
static int take_grid(cli_args_t *a, track_opts_t *o)
{
    const char *v;
    if (cli_opt(a, "--window", &v)) {
        if (v != NULL && parse_size(v, &o->cfg.win_w, &o->cfg.win_h) != 0) {
            bad_value(a, "bad --window '%s' (N or WxH, 1..65535)", v);
        }
    } else if (cli_opt(a, "--search", &v)) {
        if (v != NULL && parse_size(v, &o->cfg.search_w, &o->cfg.search_h) != 0) {
            bad_value(a, "bad --search '%s' (N or WxH, 1..65535)", v);
        }
    } else if (cli_opt(a, "--step", &v)) {
        if (v != NULL && parse_size(v, &o->cfg.step_x, &o->cfg.step_y) != 0) {
            bad_value(a, "bad --step '%s' (N or XxY, 1..65535)", v);
        }
    } else if (cli_opt(a, "--roi", &v)) {
        if (v != NULL && (cli_parse_list_u32(v, 0, 65535, o->roi, 4) != 0 || o->roi[2] == 0 ||
                          o->roi[3] == 0)) {
            bad_value(a, "bad --roi '%s' (X,Y,W,H with W, H >= 1)", v);
        }
        o->have_roi = 1;
    } else {
        return 0;
    }
    return 1;
}

/* --threshold, --scan, --order, --bounds, --no-bounds, --predict. */
static int take_search(cli_args_t *a, track_opts_t *o)
{
    const char *v;
    if (cli_opt(a, "--threshold", &v)) {
        if (v != NULL && cli_parse_threshold(v, &o->cfg.match) != 0) {
            bad_value(a, "bad --threshold '%s' (auto, none, fixed:T, ramp:LAMBDA[:K], "
                         "auto-ramp[:K])", v);
        }
    } else if (cli_opt(a, "--scan", &v)) {
        if (v != NULL && cli_parse_scan(v, &o->cfg.match) != 0) {
            bad_value(a, "bad --scan '%s' (raster, predict, coarse)", v);
        }
        o->scan_given = 1;
    } else if (cli_opt(a, "--order", &v)) {
        if (v != NULL && cli_parse_order(v, &o->cfg.match) != 0) {
            bad_value(a, "bad --order '%s' (rows, spread)", v);
        }
    } else if (cli_flag(a, "--bounds")) {
        o->cfg.match.flags |= SSDA_MATCH_BOUNDS;
    } else if (cli_flag(a, "--no-bounds")) {
        o->cfg.match.flags &= (uint8_t)~SSDA_MATCH_BOUNDS;
    } else if (cli_opt(a, "--predict", &v)) {
        if (v == NULL) {
            return 1;
        }
        if (strcmp(v, "neighbour") == 0 || strcmp(v, "neighbor") == 0 ||
            strcmp(v, "median") == 0) {
            o->cfg.predict = SSDA_TRACK_PREDICT_MEDIAN;
        } else if (strcmp(v, "left") == 0) {
            o->cfg.predict = SSDA_TRACK_PREDICT_LEFT;
        } else if (strcmp(v, "none") == 0) {
            o->cfg.predict = SSDA_TRACK_PREDICT_NONE;
        } else {
            bad_value(a, "bad --predict '%s' (neighbour, left, none)", v);
        }
    } else {
        return 0;
    }
    return 1;
}

/* --exclude [LEVEL[:COUNT]]: an optional value, "--exclude=SPEC" or a
   following argument that parses as one. */
static void take_exclude(cli_args_t *a, track_opts_t *o)
{
    uint32_t level = 0, count = 0;
    int given = 0;
    const char *v = a->inline_value;
    o->exclude = 1;
    o->exclude_argi = a->i - 1;
    if (v == NULL && a->i < a->argc &&
        parse_exclude(a->argv[a->i], &level, &given, &count) == 0) {
        v = a->argv[a->i++];
    }
    if (v == NULL) {
        return;
    }
    if (parse_exclude(v, &level, &given, &count) != 0) {
        bad_value(a, "bad --exclude '%s' (LEVEL[:COUNT] or mean[:COUNT])", v);
        return;
    }
    o->exclude_level_given = given;
    o->exclude_level = level;
    o->exclude_count = count;
}

/* --exclude, --mask-value, --grad, --mem. */
static int take_skip(cli_args_t *a, track_opts_t *o)
{
    const char *v;
    uint32_t u = 0; /* read below only after a parsed value */
    if (a->name_len == 9 && strncmp(a->name, "--exclude", 9) == 0) {
        take_exclude(a, o);
    } else if (cli_opt(a, "--mask-value", &v)) {
        if (v != NULL && cli_parse_u32(v, 0, 65535, &u) != 0) {
            bad_value(a, "bad --mask-value '%s' (0..65535)", v);
        }
        o->cfg.flags |= SSDA_TRACK_MASK;
        o->cfg.mask_value = (uint16_t)u;
    } else if (cli_flag(a, "--grad")) {
        o->grad = 1;
    } else if (cli_opt(a, "--mem", &v)) {
        if (v != NULL && parse_bytes(v, &o->mem) != 0) {
            bad_value(a, "bad --mem '%s' (bytes, optional K/M/G suffix)", v);
        }
        o->have_mem = 1;
    } else {
        return 0;
    }
    return 1;
}

/* --flat, --unique, --unique-radius, --no-subpixel. */
static int take_quality(cli_args_t *a, track_opts_t *o)
{
    const char *v;
    double d = 0.0;
    uint32_t u = 0;
    if (cli_opt(a, "--flat", &v)) {
        if (v != NULL && cli_parse_double(v, 0.0, 65535.0, &d) != 0) {
            bad_value(a, "bad --flat '%s' (mean absolute deviation in sample units, "
                         "0..65535; 0 = no test)", v);
        }
        o->cfg.flags = (uint8_t)(d > 0.0 ? o->cfg.flags & ~SSDA_TRACK_NO_FLAT
                                         : o->cfg.flags | SSDA_TRACK_NO_FLAT);
        o->cfg.flat_q8 = (uint32_t)(d * 256.0 + 0.5);
        if (d > 0.0 && o->cfg.flat_q8 == 0u) {
            o->cfg.flat_q8 = 1u; /* the smallest level, 1/256 */
        }
    } else if (cli_opt(a, "--unique", &v)) {
        if (v != NULL && strcmp(v, "off") == 0) {
            o->cfg.flags &= (uint8_t)~SSDA_TRACK_UNIQUE;
            o->unique_given = 0;
        } else if (v != NULL && (cli_parse_double(v, 257.0 / 256.0, 4.0, &d) != 0)) {
            bad_value(a, "bad --unique '%s' (a ratio, 1.004..4, or off)", v);
        } else if (v != NULL) {
            o->cfg.flags |= SSDA_TRACK_UNIQUE;
            o->cfg.unique_q8 = (uint16_t)(d * 256.0 + 0.5);
            o->unique_given = 1;
        }
    } else if (cli_opt(a, "--unique-radius", &v)) {
        if (v != NULL && cli_parse_u32(v, 1, 2, &u) != 0) {
            bad_value(a, "bad --unique-radius '%s' (1 or 2)", v);
        }
        o->cfg.unique_radius = (uint8_t)u;
    } else if (cli_flag(a, "--no-subpixel")) {
        o->cfg.flags |= SSDA_TRACK_NO_SUBPIXEL;
    } else {
        return 0;
    }
    return 1;
}

/* --json, --overlay, --arrow-scale, --quiet. */
static int take_output(cli_args_t *a, track_opts_t *o)
{
    const char *v;
    if (cli_opt(a, "--json", &v)) {
        o->json_path = v;
    } else if (cli_opt(a, "--overlay", &v)) {
        o->overlay_path = v;
    } else if (cli_opt(a, "--arrow-scale", &v)) {
        if (v != NULL && cli_parse_double(v, 0.01, 1000.0, &o->arrow_scale) != 0) {
            bad_value(a, "bad --arrow-scale '%s' (0.01..1000)", v);
        }
    } else if (cli_flag(a, "--quiet") || cli_flag(a, "-q")) {
        o->quiet = 1;
    } else if (cli_opt(a, "--relax", &v)) {
        if (v != NULL && cli_parse_u32(v, 0, 1000, &o->relax) != 0) {
            bad_value(a, "bad --relax '%s' (0..1000 iterations)", v);
        }
    } else if (cli_flag(a, "--relax-median")) {
        o->relax_median = 1;
    } else if (cli_flag(a, "--relax-keep")) {
        o->relax_keep = 1;
    } else if (cli_opt(a, "--metric", &v)) {
        if (v != NULL && (o->metric = track_metric_parse(v)) < 0) {
            o->metric = 0;
            bad_value(a, "bad --metric '%s' (sad, ncc, absncc)", v);
        }
    } else {
        return 0;
    }
    if (o->relax != 0u && o->relax_median) {
        a->bad = cli_usage_error(a->cmd, "give --relax N or --relax-median, not both");
    }
    return 1;
}

int track_opts_take(cli_args_t *a, void *opts)
{
    track_opts_t *o = opts;
    return take_grid(a, o) || take_search(a, o) || take_quality(a, o) || take_skip(a, o) ||
           take_output(a, o);
}

int track_check_positionals(const cli_args_t *a, const track_opts_t *o)
{
    if (a->npos > 2 && o->exclude && a->pos_argi[2] == o->exclude_argi + 1) {
        return cli_usage_error(a->cmd, "unexpected argument '%s': not a value of --exclude "
                               "(LEVEL[:COUNT] or mean[:COUNT]; --exclude=VALUE)", a->pos[2]);
    }
    return cli_positionals(a, 2, "need FIRST.png and SECOND.png");
}

int track_parse_args(const char *cmd, int argc, char **argv, void (*help)(void),
                     track_opts_t *o, const char **first, const char **second)
{
    cli_args_t a;
    int rc;
    track_opts_init(o);
    cli_args_begin(&a, cmd, argc, argv);
    if ((rc = cli_scan_options(&a, help, track_opts_take, o)) != CLI_OK) {
        return rc;
    }
    if ((rc = track_check_positionals(&a, o)) != CLI_OK) {
        return rc;
    }
    *first = a.pos[0];
    *second = a.pos[1];
    if (cli_is_stdout(o->overlay_path) && cli_is_stdout(o->json_path)) {
        return cli_usage_error(cmd, "--json and --overlay cannot both go to stdout");
    }
    cli_warn_png_name(cmd, "--overlay", o->overlay_path);
    if (cli_output_check(cmd, o->json_path) != 0 || cli_output_check(cmd, o->overlay_path) != 0) {
        return CLI_INPUT;
    }
    return CLI_OK;
}

const char *track_status_name(int status)
{
    switch (status) {
    case SSDA_TRACK_OK: return "ok";
    case SSDA_TRACK_EXCLUDED: return "excluded";
    case SSDA_TRACK_MASKED: return "masked";
    case SSDA_TRACK_EDGE: return "edge";
    case SSDA_TRACK_FLAT: return "flat";
    case SSDA_TRACK_AMBIGUOUS: return "ambiguous";
    case SSDA_TRACK_AT_LIMIT: return "at_limit";
    default: return "unknown";
    }
}

/* ---- pre-processing ---- */

/* The Fig. 8 operator into a same-size 16-bit image (border 0), so window
   coordinates stay those of the input. With a mask, every output pixel whose
   3 x 3 neighbourhood holds the fill value becomes 65535, the new fill value
   (the shift keeps real values below it). */
static int grad_image(const char *cmd, const gray_image_t *in, int masked, uint32_t mask,
                      unsigned shift, gray_image_t *out)
{
    ssda_view_t src;
    ssda_grad_out_t go;
    uint32_t sat = 0, x, y;
    int e;
    if (in->width < 3 || in->height < 3) {
        cli_input_error(cmd, "--grad needs images of at least 3 x 3 pixels");
        return -1;
    }
    if (gray_image_alloc(out, in->width, in->height, 16) != 0) {
        cli_input_error(cmd, "out of memory");
        return -1;
    }
    gray_image_view(in, &src);
    go.data = (uint8_t *)out->pixels + out->stride + 2u;
    go.size = (size_t)out->stride * out->height - out->stride - 2u;
    go.stride = out->stride;
    go.format = SSDA_PIX_U16;
    go.shift = (uint8_t)shift;
    e = ssda_grad(&src, &go, &sat);
    if (e != SSDA_OK) {
        cli_input_error(cmd, "--grad failed: %s", ssda_strerror(e));
        gray_image_free(out);
        return -1;
    }
    if (masked) {
        for (y = 0; y < in->height; y++) {
            for (x = 0; x < in->width; x++) {
                if (gray_image_get(in, x, y) == mask) {
                    uint32_t yy, xx;
                    for (yy = y > 0 ? y - 1 : 0; yy <= y + 1 && yy < in->height; yy++) {
                        for (xx = x > 0 ? x - 1 : 0; xx <= x + 1 && xx < in->width; xx++) {
                            ((uint16_t *)out->pixels)[(size_t)yy * in->width + xx] = 65535u;
                        }
                    }
                }
            }
        }
    }
    return 0;
}

/* Largest sample of an image, fill pixels ignored. */
static uint32_t image_max(const gray_image_t *img, int masked, uint32_t mask)
{
    uint32_t x, y, m = 0;
    for (y = 0; y < img->height; y++) {
        for (x = 0; x < img->width; x++) {
            uint32_t v = gray_image_get(img, x, y);
            if (!(masked && v == mask) && v > m) {
                m = v;
            }
        }
    }
    return m;
}

/* Mean of an image rounded down, fill pixels ignored (the default texture level). */
static uint32_t image_mean(const gray_image_t *img, int masked, uint32_t mask)
{
    uint64_t sum = 0, n = 0;
    uint32_t x, y;
    for (y = 0; y < img->height; y++) {
        for (x = 0; x < img->width; x++) {
            uint32_t v = gray_image_get(img, x, y);
            if (!(masked && v == mask)) {
                sum += v;
                n++;
            }
        }
    }
    return n > 0 ? (uint32_t)(sum / n) : 0u;
}

/* ---- block-streamed tracking (--mem) ---- */

/* Plate bytes of FIRST (fs) or SECOND for a strip of n grid columns: a
   band of its search areas (windows) as wide as the strip, at most the
   image wide. */
static size_t strip_bytes(const ssda_track_grid_t *g, uint8_t format, uint32_t n, bool fs,
                          uint32_t img_w)
{
    size_t w = SSDA_STREAM_STRIP_W(n, g->step_x, fs ? g->search_w : g->win_w);
    return SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, w < img_w ? w : img_w, fs ? g->search_h : g->win_h,
                            format, 1, 0);
}

/* Split mem bytes into the two plates: read-once strips of as many grid
   columns as fit (SECOND gets its strip, FIRST the rest), at least one
   column, or all of them when the result depends on the order (`full`:
   median prediction). Returns 0, or -1 when mem is
   below that minimum (*need set: the library refuses less, issue 22, as
   it re-read rows without bound). More memory never gives fewer columns,
   so the amplification never grows with it (issue 14, item 4). */
static int split_arena(const ssda_track_grid_t *g, uint8_t format, uint64_t mem, bool full,
                       uint32_t first_w, uint32_t second_w, size_t *first, size_t *second,
                       size_t *need)
{
    const uint32_t n_min = full ? g->cols : 1u;
    uint32_t n;
    *need = strip_bytes(g, format, n_min, true, first_w) +
            strip_bytes(g, format, n_min, false, second_w);
    if (mem < *need) {
        return -1;
    }
    for (n = g->cols; n > n_min; n--) {
        if ((uint64_t)strip_bytes(g, format, n, true, first_w) +
                strip_bytes(g, format, n, false, second_w) <= mem) {
            break;
        }
    }
    *second = strip_bytes(g, format, n, false, second_w);
    *first = (size_t)(mem - *second);
    return 0;
}

/* Track through two block-streamed sources inside o->mem bytes of plates. */
static int track_streamed(const char *cmd, const track_opts_t *o, track_result_t *r)
{
    ssda_source_t sf, ss;
    img_device_t df, ds;
    size_t af, as, need, whole;
    void *arena_f = NULL, *arena_s = NULL;
    uint8_t format = r->first.bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
    int e;
    const bool full = r->cfg.predict == SSDA_TRACK_PREDICT_MEDIAN;
    if (split_arena(&r->grid, format, o->mem, full, r->first.width, r->second.width, &af, &as,
                    &need) != 0) {
        return cli_usage_error(cmd, "--mem %llu is below the useful minimum: %zu bytes, a band "
                               "of %s search areas and windows (%s)",
                               (unsigned long long)o->mem, need,
                               full ? "every grid column's" : "one grid column's",
                               full ? "--predict neighbour needs the whole grid width; "
                                      "--predict left needs one column"
                                    : "less would re-read rows without bound");
    }
    /* A plate never needs more than its whole image: --mem 10G on a small
       pair allocates what the images need, not 10 GB. */
    whole = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, r->first.width, r->first.height, format, 1, 0);
    af = af < whole ? af : whole;
    whole = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, r->second.width, r->second.height, format, 1, 0);
    as = as < whole ? as : whole;
    arena_f = malloc(af);
    arena_s = malloc(as);
    if (arena_f == NULL || arena_s == NULL) {
        free(arena_f);
        free(arena_s);
        return cli_input_error(cmd, "out of memory for --mem %llu", (unsigned long long)o->mem);
    }
    e = img_source_init(&sf, &r->first, &df, arena_f, af);
    if (e == SSDA_OK) {
        e = img_source_init(&ss, &r->second, &ds, arena_s, as);
    }
    if (e == SSDA_OK) {
        e = ssda_stream_track(&sf, &ss, &r->cfg, r->vec, r->grid.count, &r->stats);
    }
    if (e == SSDA_OK) {
        r->bytes_read = sf.stats.bytes_read + ss.stats.bytes_read;
        r->reads = sf.stats.reads + ss.stats.reads;
        r->arena_first = af;
        r->arena_second = as;
    }
    free(arena_f);
    free(arena_s);
    if (e != SSDA_OK) {
        return cli_usage_error(cmd, "streamed tracking refused these options: %s",
                               ssda_strerror(e));
    }
    return CLI_OK;
}

/* ---- the run ---- */

void track_result_free(track_result_t *r)
{
    free(r->clean);
    r->clean = NULL;
    free(r->rho_q30);
    gray_image_free(&r->first);
    gray_image_free(&r->second);
    gray_image_free(&r->second_orig);
    free(r->vec);
    memset(r, 0, sizeof *r);
}

/* AUTO or NONE with the raster or predict scan: the modes whose SADs are
   exact, where uniqueness and the sub-pixel fit run. */
static int exact_mode(const ssda_match_config_t *m)
{
    return m->scan != SSDA_SCAN_COARSE &&
           (m->threshold == SSDA_THRESHOLD_AUTO || m->threshold == SSDA_THRESHOLD_NONE);
}

static const char *predict_name(uint8_t predict)
{
    static const char *names[] = {"none", "left", "neighbour"};
    return names[predict % 3u];
}

/* What the library runs: with a prediction a raster scan is run as a
   PREDICT scan (track.h). The config then says so, and the JSON and the
   summary report what ran; an explicit --scan raster is warned about. */
static void resolve_scan(const char *cmd, const track_opts_t *o, ssda_track_config_t *cfg)
{
    if (cfg->predict == SSDA_TRACK_PREDICT_NONE || cfg->match.scan != SSDA_SCAN_RASTER) {
        return;
    }
    if (o->scan_given) {
        fprintf(stderr, "ssda %s: warning: --scan raster is run as --scan predict with "
                "--predict %s (each search starts at the predicted vector); --predict none "
                "for a raster scan\n", cmd, predict_name(cfg->predict));
    }
    cfg->match.scan = SSDA_SCAN_PREDICT;
}

/* Read FIRST and SECOND; keep SECOND as read for the overlay. */
static int load_inputs(const char *cmd, const char *first_path, const char *second_path,
                       const track_opts_t *o, track_result_t *r)
{
    uint32_t maxval;
    if (cli_load_png_pair(cmd, first_path, second_path, &r->first, &r->second) != 0) {
        return CLI_INPUT;
    }
    if (r->first.width != r->second.width || r->first.height != r->second.height) {
        /* allowed (the library lays both in one pixel coordinate system), but
           more often a wrong pair than a deliberate one */
        fprintf(stderr, "ssda %s: note: the images differ in size (FIRST %u x %u, SECOND "
                "%u x %u); windows of SECOND are searched at the same coordinates in FIRST\n",
                cmd, r->first.width, r->first.height, r->second.width, r->second.height);
    }
    maxval = gray_image_max(&r->second);
    if ((o->cfg.flags & SSDA_TRACK_MASK) && o->cfg.mask_value > maxval) {
        return cli_usage_error(cmd, "--mask-value %u is beyond these %u-bit images",
                               o->cfg.mask_value, maxval == 255 ? 8 : 16);
    }
    if (o->overlay_path != NULL) {
        /* the overlay shows SECOND as read, also when tracking on gradients */
        if (gray_image_alloc(&r->second_orig, r->second.width, r->second.height,
                             r->second.bits) != 0) {
            return cli_input_error(cmd, "out of memory");
        }
        memcpy(r->second_orig.pixels, r->second.pixels,
               (size_t)r->second.stride * r->second.height);
    }
    return CLI_OK;
}

/* --grad: both images replaced by their Fig. 8 gradients (16-bit; with a
   mask, 65535 becomes the fill value). */
static int apply_grad(const char *cmd, const track_opts_t *o, track_result_t *r)
{
    gray_image_t gf, gs;
    int masked = (o->cfg.flags & SSDA_TRACK_MASK) != 0;
    /* smallest shift that keeps 4 * max below 65535 (the fill value) */
    uint32_t m = image_max(&r->first, masked, o->cfg.mask_value);
    uint32_t m2 = image_max(&r->second, masked, o->cfg.mask_value);
    unsigned shift = 0;
    m = m2 > m ? m2 : m;
    while ((4u * m) >> shift >= 65535u) {
        shift++;
    }
    if (grad_image(cmd, &r->first, masked, o->cfg.mask_value, shift, &gf) != 0) {
        return CLI_INPUT;
    }
    if (grad_image(cmd, &r->second, masked, o->cfg.mask_value, shift, &gs) != 0) {
        gray_image_free(&gf);
        return CLI_INPUT;
    }
    gray_image_free(&r->first);
    gray_image_free(&r->second);
    r->first = gf;
    r->second = gs;
    if (masked) {
        r->cfg.mask_value = 65535u;
    }
    return CLI_OK;
}

/* --exclude's level and --roi into the config. */
static int resolve_region(const char *cmd, const track_opts_t *o, track_result_t *r)
{
    if (o->exclude) {
        r->cfg.flags |= SSDA_TRACK_EXCLUDE;
        r->texture_level = o->exclude_level_given
                               ? o->exclude_level
                               : image_mean(&r->second, (o->cfg.flags & SSDA_TRACK_MASK) != 0,
                                            r->cfg.mask_value);
        if (r->texture_level >= gray_image_max(&r->second)) {
            return cli_usage_error(cmd, "--exclude level %u is not below the images' maximum",
                                   o->exclude_level);
        }
        r->cfg.texture_threshold = (uint16_t)r->texture_level;
        r->cfg.texture_min_count = o->exclude_count;
    }
    if (o->have_roi) {
        if (o->roi[0] + o->roi[2] > r->second.width || o->roi[1] + o->roi[3] > r->second.height) {
            return cli_usage_error(cmd, "--roi %u,%u,%u,%u is not inside SECOND (%u x %u)",
                                   o->roi[0], o->roi[1], o->roi[2], o->roi[3], r->second.width,
                                   r->second.height);
        }
        r->cfg.roi_x = (uint16_t)o->roi[0];
        r->cfg.roi_y = (uint16_t)o->roi[1];
        r->cfg.roi_w = (uint16_t)o->roi[2];
        r->cfg.roi_h = (uint16_t)o->roi[3];
    }
    return CLI_OK;
}

/* Warnings on a grid that runs but not as a user would expect: a search
   area with no room (every vector 0), an odd margin (a one-sided range). */
static void warn_grid(const char *cmd, const ssda_track_grid_t *g)
{
    uint32_t mx = (uint32_t)g->search_w - g->win_w, my = (uint32_t)g->search_h - g->win_h;
    if (mx == 0 || my == 0) {
        const char *what = mx == 0 && my == 0 ? "dx and dy" : mx == 0 ? "dx" : "dy";
        fprintf(stderr, "ssda %s: warning: search area %ux%u leaves the %ux%u window no room "
                "to move: every %s is 0 (vectors range over +-(search - window) / 2; "
                "e.g. --search %ux%u)\n",
                cmd, g->search_w, g->search_h, g->win_w, g->win_h, what, 2u * g->win_w,
                2u * g->win_h);
    }
    if (mx % 2u != 0 || my % 2u != 0) {
        /* the area starts (search - window) / 2 px before the window, rounded down */
        fprintf(stderr, "ssda %s: warning: search %ux%u and window %ux%u leave an odd margin: "
                "dx ranges over -%u..+%u, dy over -%u..+%u (one px more left or up than right "
                "or down); an even search - window gives a symmetric range\n",
                cmd, g->search_w, g->search_h, g->win_w, g->win_h, mx - mx / 2u, mx / 2u,
                my - my / 2u, my / 2u);
    }
}

/* The grid of the config on SECOND (sizes resolved as the library does). */
static int resolve_grid(const char *cmd, track_result_t *r)
{
    const ssda_track_config_t *c = &r->cfg;
    uint32_t ww, wh, sw, sh;
    if (ssda_track_grid(c, (uint16_t)r->second.width, (uint16_t)r->second.height,
                        &r->grid) == SSDA_OK) {
        warn_grid(cmd, &r->grid);
        return CLI_OK;
    }
    /* the sizes as resolved: 0 in the config means the library's default */
    ww = c->win_w ? c->win_w : SSDA_TRACK_DEFAULT_WIN;
    wh = c->win_h ? c->win_h : SSDA_TRACK_DEFAULT_WIN;
    sw = c->search_w ? c->search_w : 2u * ww;
    sh = c->search_h ? c->search_h : 2u * wh;
    sw = sw < SSDA_MAX_DIM ? sw : SSDA_MAX_DIM;
    sh = sh < SSDA_MAX_DIM ? sh : SSDA_MAX_DIM;
    return cli_usage_error(cmd, "no grid fits: window %ux%u, search %ux%u in a %ux%u region "
                           "(the search area must be at least the window, the window inside "
                           "the region)",
                           ww, wh, sw, sh, c->roi_w ? c->roi_w : r->second.width,
                           c->roi_h ? c->roi_h : r->second.height);
}

/* The bounds' work buffer (per thread). In RAM: the shared bound tables
   (track.h, SSDA_TRACK_WORK_SIZE_SHARED: 592 944 B for the 2500-px-wide
   GOES image), which each call of the wavefront builds for its band of
   windows instead of every search building its own, unless they would
   exceed TRACK_SHARED_MAX (search areas hundreds of rows high on wide
   images). Streamed (--mem): per-window tables; the plates are the memory
   budget there, and the shared tables hold 2 * (search_h - 3) + 1 rows of
   the whole image width. */
#define TRACK_SHARED_MAX ((uint64_t)64u << 20)
static size_t bounds_work_size(const track_opts_t *o, const track_result_t *r)
{
    const ssda_track_grid_t *g = &r->grid;
    const uint64_t rows = g->search_h > 3u ? 2u * ((uint64_t)g->search_h - 3u) + 1u : 1u;
    /* the table part of SSDA_TRACK_WORK_SIZE_SHARED in 64 bits */
    const uint64_t tables = (rows * r->first.width + (uint64_t)(g->win_w / 4u) * (g->win_h / 4u)) *
                            sizeof(uint32_t);
    if (!o->have_mem && tables <= TRACK_SHARED_MAX) {
        return SSDA_TRACK_WORK_SIZE_SHARED(r->first.width, g->search_w, g->search_h, g->win_w,
                                           g->win_h);
    }
    return SSDA_TRACK_WORK_SIZE(g->search_w, g->search_h, g->win_w, g->win_h);
}

/* --exclude's count (default: window pixels / 16, at least 1), the vector
   array and the bounds buffer (*work, malloc'ed; NULL without bounds). */
static int alloc_run(const char *cmd, const track_opts_t *o, track_result_t *r, void **work)
{
    uint64_t pixels = (uint64_t)r->grid.win_w * r->grid.win_h;
    if (o->exclude) {
        r->texture_min_count = o->exclude_count != 0 ? o->exclude_count
                               : pixels / 16u > 0    ? (uint32_t)(pixels / 16u)
                                                     : 1u;
        if (2u * (uint64_t)r->texture_min_count > pixels) {
            return cli_usage_error(cmd, "--exclude count %u is more than half the window's "
                                   "pixels", o->exclude_count);
        }
    }
    r->vec = calloc(r->grid.count, sizeof *r->vec);
    if (r->vec == NULL) {
        return cli_input_error(cmd, "out of memory for %u windows", r->grid.count);
    }
    /* A search area larger than FIRST leaves every window EDGE: nothing is
       searched, and the bounds buffer for such an area (17 GB for 65535 x
       65535) would be allocated for nothing (found by fuzz_cli). */
    if (r->grid.search_w > r->first.width || r->grid.search_h > r->first.height) {
        r->cfg.match.flags &= (uint8_t)~SSDA_MATCH_BOUNDS;
    }
    *work = NULL;
    if ((r->cfg.match.flags & SSDA_MATCH_BOUNDS) || (r->cfg.flags & SSDA_TRACK_UNIQUE)) {
        /* the bounds tables, then the uniqueness list; without bounds the
           list alone */
        r->cfg.match.work_size = (r->cfg.match.flags & SSDA_MATCH_BOUNDS)
                                     ? bounds_work_size(o, r)
                                     : SSDA_MATCH_UNIQUE_WORK;
        if ((*work = malloc(r->cfg.match.work_size)) == NULL) {
            return cli_input_error(cmd, "out of memory");
        }
        r->cfg.match.work = *work;
    }
    return CLI_OK;
}

/* Track from the images in memory: a wavefront of fixed bands of grid
   rows over ssda_track_row (track_wave.c) on --threads N threads (default
   every core), also on one thread, so that the counts (pixel_ops with the
   shared bound tables) are the same for any N and with or without the
   progress bar. Returns an ssda error code. */
static int run_in_ram(const track_opts_t *o, track_result_t *r)
{
    ssda_view_t vf, vs;
    progress_t prog;
    int e;
    gray_image_view(&r->first, &vf);
    gray_image_view(&r->second, &vs);
    progress_begin(&prog, "tracking", r->grid.rows, o->quiet);
    e = track_wave(&vf, &vs, &r->cfg, &r->grid, cli_threads(), r->vec, &r->stats, &prog);
    progress_end(&prog);
    /* RAM sources: every pixel of both images was loaded once. */
    r->bytes_read = (uint64_t)r->first.stride * r->first.height +
                    (uint64_t)r->second.stride * r->second.height;
    return e;
}

/* More than a quarter of the searched windows at the limit: the motion is
   likely larger than the search reaches (or the brightness changed, which
   pulls SAD's minima to the border). */
static void warn_at_limit(const char *cmd, const track_opts_t *o, const track_result_t *r)
{
    const ssda_track_stats_t *s = &r->stats;
    const uint32_t searched = s->ok + s->ambiguous + s->at_limit;
    const int sad = o->metric != TRACK_METRIC_NCC && o->metric != TRACK_METRIC_ABSNCC;
    if (searched == 0u || 4u * (uint64_t)s->at_limit <= searched) {
        return;
    }
    fprintf(stderr, "ssda %s: warning: %u of %u searched windows are 'at_limit' (best match "
            "on the border of the %ux%u search area): the motion may be larger than it "
            "reaches, try --search %ux%u%s\n",
            cmd, s->at_limit, searched, r->grid.search_w, r->grid.search_h,
            2u * r->grid.search_w - r->grid.win_w, 2u * r->grid.search_h - r->grid.win_h,
            sad ? "; or the brightness changed between the images, try --metric ncc or --grad"
                : "");
}

/* No window is ok: say why (the run itself is valid). */
static void warn_nothing_tracked(const char *cmd, const track_result_t *r)
{
    const ssda_track_stats_t *s = &r->stats;
    if (s->ok > 0 || s->windows == 0) {
        return;
    }
    if (s->edge == s->windows) {
        fprintf(stderr, "ssda %s: warning: nothing to track: every one of the %u windows is "
                "'edge' (its %ux%u search area leaves FIRST, %u x %u); a smaller --search or "
                "larger images\n",
                cmd, s->windows, r->grid.search_w, r->grid.search_h, r->first.width,
                r->first.height);
    } else if (s->ambiguous + s->at_limit == 0u) {
        fprintf(stderr, "ssda %s: warning: nothing to track: of %u windows %u excluded (no "
                "texture), %u flat (no texture; --flat LEVEL), %u masked (fill value), %u edge "
                "(search area leaves FIRST)\n",
                cmd, s->windows, s->excluded, s->flat, s->masked, s->edge);
    } else {
        fprintf(stderr, "ssda %s: warning: no window is 'ok': of %u windows %u ambiguous "
                "(another match about as good; --unique RATIO), %u at_limit (best match on the "
                "border of the search; --search), %u flat, %u excluded, %u masked, %u edge\n",
                cmd, s->windows, s->ambiguous, s->at_limit, s->flat, s->excluded, s->masked,
                s->edge);
    }
}

/* Every step of track_run but the loading; 0 or a CLI code (printed). */
static int prepare_and_track(const char *cmd, const track_opts_t *o, track_result_t *r)
{
    void *work = NULL;
    double t0;
    int rc;
    if ((o->grad && (rc = apply_grad(cmd, o, r)) != CLI_OK) ||
        (rc = resolve_region(cmd, o, r)) != CLI_OK || (rc = resolve_grid(cmd, r)) != CLI_OK ||
        (rc = alloc_run(cmd, o, r, &work)) != CLI_OK) {
        free(work);
        return rc;
    }
    t0 = progress_now();
    if (o->have_mem) {
        rc = track_streamed(cmd, o, r);
    } else if ((rc = run_in_ram(o, r)) != SSDA_OK) {
        rc = cli_usage_error(cmd, "tracking refused these options: %s", ssda_strerror(rc));
    }
    r->secs = progress_now() - t0;
    free(work);
    r->cfg.match.work = NULL;
    return rc;
}

int relax_field(const ssda_relax_grid_t *g, uint32_t iterations, int median, int keep,
                ssda_relax_vector_t *out, size_t count)
{
    ssda_relax_config_t c;
    int e;
    if (median) {
        return ssda_relax_median(g, NULL, out, count);
    }
    memset(&c, 0, sizeof c);
    c.iterations = (uint16_t)iterations;
    c.flags = keep ? SSDA_RELAX_KEEP : 0u;
    c.work_size = SSDA_RELAX_WORK_SIZE(g->cols, g->rows);
    c.work = malloc(c.work_size);
    e = c.work == NULL ? SSDA_ERR_NULL : ssda_relax_labels(g, &c, out, count);
    free(c.work);
    return e;
}

/* --relax N or --relax-median on the tracked grid: the sub-pixel vectors
   (Q8; whole pixels with --no-subpixel), so that a vector the cleaning
   keeps keeps its fraction. */
static int clean_field(const char *cmd, const track_opts_t *o, track_result_t *r)
{
    ssda_relax_grid_t g;
    uint32_t k;
    int e;
    if (o->relax == 0u && !o->relax_median) {
        return CLI_OK;
    }
    r->clean = calloc(r->grid.count + 1u, sizeof *r->clean);
    if (r->clean == NULL) {
        return cli_input_error(cmd, "out of memory");
    }
    memset(&g, 0, sizeof g);
    g.dx = &r->vec[0].sub_dx_q8;
    g.dy = &r->vec[0].sub_dy_q8;
    g.status = &r->vec[0].status; /* SSDA_TRACK_OK = 0: valid */
    g.stride = sizeof r->vec[0];
    g.frac_bits = 8;
    g.cols = r->grid.cols;
    g.rows = r->grid.rows;
    e = relax_field(&g, o->relax, o->relax_median, o->relax_keep, r->clean, r->grid.count);
    if (e != SSDA_OK) {
        return cli_input_error(cmd, "cleaning the field failed: %s", ssda_strerror(e));
    }
    for (k = 0; k < r->grid.count; k++) {
        r->changed += (r->clean[k].flags & SSDA_RELAX_CHANGED) != 0u;
    }
    return CLI_OK;
}

int track_run(const char *cmd, const char *first_path, const char *second_path,
              const track_opts_t *o, track_result_t *r)
{
    int rc;
    memset(r, 0, sizeof *r);
    /* The library refuses this with a bare SSDA_ERR_ARG; say which rule. */
    if (o->cfg.match.scan == SSDA_SCAN_COARSE && o->cfg.predict != SSDA_TRACK_PREDICT_NONE) {
        return cli_usage_error(cmd, "--scan coarse needs --predict none (with a prediction "
                               "every window is searched outward from its predicted vector)");
    }
    r->cfg = o->cfg;
    resolve_scan(cmd, o, &r->cfg);
    if ((r->cfg.flags & SSDA_TRACK_UNIQUE) && !exact_mode(&r->cfg.match)) {
        if (o->unique_given) {
            return cli_usage_error(cmd, "--unique needs an exact search (--threshold auto or "
                                   "none, --scan raster or predict): the test needs exact SADs");
        }
        r->cfg.flags &= (uint8_t)~SSDA_TRACK_UNIQUE; /* the default: not in this mode */
    }
    if (o->relax_keep && o->relax == 0u) {
        return cli_usage_error(cmd, "--relax-keep needs --relax N");
    }
    if (o->metric != TRACK_METRIC_NONE) { /* refused before the tracking, not after it */
        const uint32_t ww = o->cfg.win_w ? o->cfg.win_w : SSDA_TRACK_DEFAULT_WIN;
        const uint32_t wh = o->cfg.win_h ? o->cfg.win_h : SSDA_TRACK_DEFAULT_WIN;
        if (ww * wh > SSDA_NCC_MAX_PIXELS) {
            return cli_usage_error(cmd, "--metric: window %ux%u; the correlation coefficient "
                                   "takes windows of at most %u pixels", ww, wh,
                                   SSDA_NCC_MAX_PIXELS);
        }
    }
    rc = load_inputs(cmd, first_path, second_path, o, r);
    if (rc == CLI_OK) {
        rc = prepare_and_track(cmd, o, r);
    }
    if (rc == CLI_OK) {
        rc = track_metric_apply(cmd, o, r);
    }
    if (rc == CLI_OK) { /* on the final statuses (--metric may change them) */
        warn_at_limit(cmd, o, r);
        warn_nothing_tracked(cmd, r);
    }
    if (rc == CLI_OK) {
        rc = clean_field(cmd, o, r);
    }
    if (rc != CLI_OK) {
        track_result_free(r);
    }
    return rc;
}

uint64_t track_brute_ops(const track_result_t *r)
{
    const ssda_track_grid_t *g = &r->grid;
    uint64_t per = (uint64_t)(g->search_w - g->win_w + 1u) * (g->search_h - g->win_h + 1u) *
                   g->win_w * g->win_h;
    return per * (r->stats.windows - r->stats.edge - r->stats.masked);
}

uint64_t track_work_ops(const track_result_t *r)
{
    return r->stats.pixel_ops + r->stats.check_pixels;
}

double track_median_motion(const track_result_t *r, int axis)
{
    int32_t *v = malloc((r->grid.count + 1u) * sizeof *v);
    double m;
    uint32_t k, n = 0;
    if (v == NULL) {
        return 0.0;
    }
    for (k = 0; k < r->grid.count; k++) {
        if (r->vec[k].status == SSDA_TRACK_OK) {
            v[n++] = axis == 0 ? r->vec[k].sub_dx_q8 : r->vec[k].sub_dy_q8;
        }
    }
    /* a selection: a qsort of every ok vector, four times a run, cost
       about 1 % of a GOES run */
    m = median_q8(v, n);
    free(v);
    return m;
}

/* ---- outputs ---- */

/* Least distance between drawn windows on the overlay, output px: closer,
   arrowheads and marks run together. */
#define OVERLAY_MIN_SPACING 22.0

/* ---- JSON (docs/cli.md) ---- */

static cJSON *json_grid(const ssda_track_grid_t *g)
{
    cJSON *grid = cJSON_CreateObject();
    cJSON *roi = cJSON_CreateArray();
    cJSON_AddNumberToObject(grid, "cols", g->cols);
    cJSON_AddNumberToObject(grid, "rows", g->rows);
    cJSON_AddNumberToObject(grid, "window_w", g->win_w);
    cJSON_AddNumberToObject(grid, "window_h", g->win_h);
    cJSON_AddNumberToObject(grid, "search_w", g->search_w);
    cJSON_AddNumberToObject(grid, "search_h", g->search_h);
    cJSON_AddNumberToObject(grid, "step_x", g->step_x);
    cJSON_AddNumberToObject(grid, "step_y", g->step_y);
    cJSON_AddItemToArray(roi, cJSON_CreateNumber(g->roi_x));
    cJSON_AddItemToArray(roi, cJSON_CreateNumber(g->roi_y));
    cJSON_AddItemToArray(roi, cJSON_CreateNumber(g->roi_w));
    cJSON_AddItemToArray(roi, cJSON_CreateNumber(g->roi_h));
    cJSON_AddItemToObject(grid, "roi", roi);
    return grid;
}

static cJSON *json_options(const track_result_t *r, const track_opts_t *o)
{
    cJSON *opt = cJSON_CreateObject();
    char tname[64];
    cli_threshold_name(&r->cfg.match, tname, sizeof tname);
    cJSON_AddStringToObject(opt, "threshold", tname);
    cJSON_AddStringToObject(opt, "scan", cli_scan_name(&r->cfg.match));
    cJSON_AddStringToObject(opt, "predict", predict_name(r->cfg.predict));
    cJSON_AddBoolToObject(opt, "bounds", (r->cfg.match.flags & SSDA_MATCH_BOUNDS) != 0);
    cJSON_AddBoolToObject(opt, "grad", o->grad);
    cJSON_AddStringToObject(opt, "cleaning", o->relax_median ? "median" : o->relax ? "relax" : "none");
    if (o->relax != 0u) {
        cJSON_AddNumberToObject(opt, "relax_iterations", o->relax);
        cJSON_AddBoolToObject(opt, "relax_keep", o->relax_keep != 0);
    }
    track_metric_json_options(opt, o);
    if (r->cfg.flags & SSDA_TRACK_EXCLUDE) {
        cJSON *ex = cJSON_AddObjectToObject(opt, "exclude");
        cJSON_AddNumberToObject(ex, "level", r->texture_level);
        cJSON_AddNumberToObject(ex, "min_count", r->texture_min_count);
    } else {
        cJSON_AddNullToObject(opt, "exclude");
    }
    if (o->cfg.flags & SSDA_TRACK_MASK) {
        cJSON_AddNumberToObject(opt, "mask_value", o->cfg.mask_value);
    } else {
        cJSON_AddNullToObject(opt, "mask_value");
    }
    if (r->cfg.flags & SSDA_TRACK_NO_FLAT) {
        cJSON_AddNullToObject(opt, "flat");
    } else {
        json_out_add_fixed(opt, "flat", (r->cfg.flat_q8 ? r->cfg.flat_q8
                                                        : SSDA_TRACK_DEFAULT_FLAT_Q8) / 256.0, 8);
    }
    if (r->cfg.flags & SSDA_TRACK_UNIQUE) {
        cJSON *u = cJSON_AddObjectToObject(opt, "unique");
        json_out_add_fixed(u, "ratio", (r->cfg.unique_q8 ? r->cfg.unique_q8
                                                         : SSDA_MATCH_DEFAULT_UNIQUE_Q8) / 256.0, 8);
        cJSON_AddNumberToObject(u, "radius", r->cfg.unique_radius ? r->cfg.unique_radius
                                                                  : SSDA_MATCH_DEFAULT_UNIQUE_RADIUS);
    } else {
        cJSON_AddNullToObject(opt, "unique");
    }
    /* the correlation search fits its own peak in every mode */
    cJSON_AddBoolToObject(opt, "subpixel", !(r->cfg.flags & SSDA_TRACK_NO_SUBPIXEL) &&
                                               (exact_mode(&r->cfg.match) ||
                                                o->metric == TRACK_METRIC_NCC ||
                                                o->metric == TRACK_METRIC_ABSNCC));
    return opt;
}

static cJSON *json_stats(const track_result_t *r, const track_opts_t *o)
{
    cJSON *st = cJSON_CreateObject();
    json_out_add_u64(st, "pixel_ops", r->stats.pixel_ops);
    json_out_add_u64(st, "bytes_read", r->bytes_read);
    json_out_add_u64(st, "brute_force_ops", track_brute_ops(r));
    json_out_add_u64(st, "positions", r->stats.positions);
    json_out_add_u64(st, "completed", r->stats.completed);
    json_out_add_u64(st, "check_pixels", r->stats.check_pixels);
    cJSON_AddNumberToObject(st, "windows", r->stats.windows);
    cJSON_AddNumberToObject(st, "ok", r->stats.ok);
    cJSON_AddNumberToObject(st, "excluded", r->stats.excluded);
    cJSON_AddNumberToObject(st, "masked", r->stats.masked);
    cJSON_AddNumberToObject(st, "edge", r->stats.edge);
    cJSON_AddNumberToObject(st, "flat", r->stats.flat);
    cJSON_AddNumberToObject(st, "ambiguous", r->stats.ambiguous);
    cJSON_AddNumberToObject(st, "at_limit", r->stats.at_limit);
    json_out_add_fixed(st, "time_s", r->secs, 6);
    track_metric_json_stats(st, o, r);
    if (o->have_mem) {
        json_out_add_u64(st, "mem_bytes", o->mem);
        json_out_add_u64(st, "plate_bytes_first", r->arena_first);
        json_out_add_u64(st, "plate_bytes_second", r->arena_second);
        json_out_add_u64(st, "reads", r->reads);
    }
    return st;
}

typedef struct {
    const track_result_t *r;
    const int32_t (*ref)[2];
} window_items_t;

/* Window k of the "windows" array (made while printing: json_out_lazy_t). */
static cJSON *json_window(void *ctx, size_t k)
{
    const window_items_t *w = ctx;
    const ssda_track_vector_t *v = &w->r->vec[k];
    cJSON *item = cJSON_CreateObject();
    cJSON_AddNumberToObject(item, "x", v->x);
    cJSON_AddNumberToObject(item, "y", v->y);
    cJSON_AddNumberToObject(item, "dx", v->dx);
    cJSON_AddNumberToObject(item, "dy", v->dy);
    /* Q8 values: exact in 8 decimals */
    json_out_add_q8(item, "sub_dx", v->sub_dx_q8);
    json_out_add_q8(item, "sub_dy", v->sub_dy_q8);
    json_out_add_u64(item, "sad", v->sad);
    if (v->texture_q8 != 0u || v->status == SSDA_TRACK_FLAT) {
        json_out_add_q8(item, "texture", v->texture_q8);
    } else {
        cJSON_AddNullToObject(item, "texture");
    }
    if (v->unique_q8 != SSDA_MATCH_UNIQUE_NONE) {
        json_out_add_q8(item, "unique", v->unique_q8);
    } else {
        cJSON_AddNullToObject(item, "unique");
    }
    cJSON_AddStringToObject(item, "status", track_status_name(v->status));
    cJSON_AddBoolToObject(item, "exact", v->exact);
    if (w->ref != NULL && v->status == SSDA_TRACK_OK) {
        cJSON_AddNumberToObject(item, "ref_dx", w->ref[k][0]);
        cJSON_AddNumberToObject(item, "ref_dy", w->ref[k][1]);
    }
    if (w->r->clean != NULL && (w->r->clean[k].flags & SSDA_RELAX_VALID) != 0u) {
        json_out_add_fixed(item, "relax_dx", w->r->clean[k].dx_q8 / 256.0, 4);
        json_out_add_fixed(item, "relax_dy", w->r->clean[k].dy_q8 / 256.0, 4);
        cJSON_AddBoolToObject(item, "changed", (w->r->clean[k].flags & SSDA_RELAX_CHANGED) != 0u);
    }
    track_metric_json_window(item, w->r, k);
    return item;
}

int track_write_json(const char *cmd, FILE *f, const track_result_t *r, const track_opts_t *o,
                     const int32_t (*ref)[2], cJSON *extra)
{
    cJSON *doc = json_out_object(), *m;
    window_items_t items;
    json_out_lazy_t lazy;
    int rc;
    cJSON_AddNumberToObject(doc, "width", r->second.width);
    cJSON_AddNumberToObject(doc, "height", r->second.height);
    cJSON_AddNumberToObject(doc, "bits", r->second.bits);
    cJSON_AddItemToObject(doc, "grid", json_grid(&r->grid));
    cJSON_AddItemToObject(doc, "options", json_options(r, o));
    while (extra != NULL && (m = extra->child) != NULL) { /* moved, in order */
        cJSON_AddItemToObject(doc, m->string, cJSON_DetachItemViaPointer(extra, m));
    }
    cJSON_Delete(extra);
    cJSON_AddArrayToObject(doc, "windows"); /* placeholder: made while printing */
    cJSON_AddItemToObject(doc, "stats", json_stats(r, o));
    items.r = r;
    items.ref = ref;
    lazy.name = "windows";
    lazy.count = r->grid.count;
    lazy.item = json_window;
    lazy.ctx = &items;
    rc = json_out_print(f, doc, &lazy);
    cJSON_Delete(doc);
    return rc == 0 ? 0 : (cli_input_error(cmd, "out of memory for the JSON"), -1);
}

static int draw_status(uint8_t status)
{
    switch (status) {
    case SSDA_TRACK_OK: return DRAW_OK;
    case SSDA_TRACK_EXCLUDED: return DRAW_EXCLUDED;
    case SSDA_TRACK_MASKED: return DRAW_MASKED;
    case SSDA_TRACK_FLAT: return DRAW_FLAT;
    case SSDA_TRACK_AMBIGUOUS: return DRAW_AMBIGUOUS;
    case SSDA_TRACK_AT_LIMIT: return DRAW_AT_LIMIT;
    default: return DRAW_EDGE;
    }
}

/* The part of SECOND (as read) the grid covers, plus the search margin, so
   a small --roi is drawn large instead of lost in a reduced whole image;
   *x0, *y0: its top-left in SECOND. Returns 0 or -1 (out of memory). */
static int overlay_background(const gray_image_t *src, const ssda_track_grid_t *g,
                              gray_image_t *bg, uint32_t *x0, uint32_t *y0)
{
    uint32_t mx = (g->search_w - g->win_w) / 2u, my = (g->search_h - g->win_h) / 2u;
    uint32_t x1 = (uint32_t)g->roi_x + g->roi_w + mx, y1 = (uint32_t)g->roi_y + g->roi_h + my, y;
    *x0 = g->roi_x > mx ? g->roi_x - mx : 0u;
    *y0 = g->roi_y > my ? g->roi_y - my : 0u;
    x1 = x1 < src->width ? x1 : src->width;
    y1 = y1 < src->height ? y1 : src->height;
    if (gray_image_alloc(bg, x1 - *x0, y1 - *y0, src->bits) != 0) {
        return -1;
    }
    for (y = *y0; y < y1; y++) {
        memcpy((uint8_t *)bg->pixels + (size_t)(y - *y0) * bg->stride,
               (const uint8_t *)src->pixels + (size_t)y * src->stride +
                   (size_t)*x0 * (src->bits / 8u),
               bg->stride);
    }
    return 0;
}

int track_write_overlay(const char *cmd, FILE *f, const char *name, const track_result_t *r,
                        const track_opts_t *o, const double (*truth)[2],
                        const char *truth_label, const char *title, const char *subtitle)
{
    draw_vector_t *dv = calloc(r->grid.count + 1u, sizeof *dv);
    draw_vectors_opts_t dopt;
    gray_image_t bg = {0};
    const ssda_track_grid_t *g = &r->grid;
    char err[512];
    uint32_t k, x0, y0, step, every = 1, off_c, off_r, n = 0;
    double zstep;
    int rc;
    if (dv == NULL || overlay_background(&r->second_orig, g, &bg, &x0, &y0) != 0) {
        free(dv);
        cli_input_error(cmd, "out of memory");
        return -1;
    }
    /* A dense grid on a reduced picture is a carpet of arrowheads: draw only
       every k-th column and row (centred), so drawn windows are at least
       OVERLAY_MIN_SPACING output px apart. The JSON keeps every window. */
    /* only along an axis with more than one window (one window: nothing to thin) */
    step = g->cols > 1u && (g->rows == 1u || g->step_x < g->step_y) ? g->step_x : g->step_y;
    zstep = step * draw_vectors_zoom(bg.width, bg.height);
    while ((g->cols > 1u || g->rows > 1u) && zstep * every < OVERLAY_MIN_SPACING) {
        every++;
    }
    off_c = ((g->cols - 1u) % every) / 2u;
    off_r = ((g->rows - 1u) % every) / 2u;
    for (k = 0; k < r->grid.count; k++) {
        const ssda_track_vector_t *v = &r->vec[k];
        if ((k % g->cols) % every != off_c || (k / g->cols) % every != off_r) {
            continue;
        }
        dv[n].x = v->x - x0 + (r->grid.win_w - 1) / 2.0;
        dv[n].y = v->y - y0 + (r->grid.win_h - 1) / 2.0;
        dv[n].dx = v->sub_dx_q8 / 256.0;
        dv[n].dy = v->sub_dy_q8 / 256.0;
        dv[n].status = draw_status(v->status);
        if (truth != NULL && v->status == SSDA_TRACK_OK) {
            dv[n].has_truth = 1;
            dv[n].tdx = truth[k][0];
            dv[n].tdy = truth[k][1];
        } else if (truth == NULL && r->clean != NULL &&
                   (r->clean[k].flags & SSDA_RELAX_VALID) != 0u) {
            /* --relax / --relax-median: the cleaned vector as the second
               arrow, the changed ones marked (as ssda flow draws them) */
            dv[n].has_truth = 1;
            dv[n].tdx = r->clean[k].dx_q8 / 256.0;
            dv[n].tdy = r->clean[k].dy_q8 / 256.0;
            if ((r->clean[k].flags & SSDA_RELAX_CHANGED) != 0u) {
                dv[n].status = DRAW_CHANGED;
            }
        }
        n++;
    }
    if (every > 1) {
        fprintf(stderr, "ssda %s: note: the overlay draws every %u%s vector of each grid row "
                "and column (all %u would be %.0f px apart); --roi X,Y,W,H or a larger "
                "--step shows more detail, the JSON has every window\n",
                cmd, every, ordinal_suffix(every), g->count, zstep);
    }
    memset(&dopt, 0, sizeof dopt);
    dopt.title = title;
    dopt.truth_label = truth != NULL || r->clean == NULL ? truth_label
                       : o->relax_median                 ? "after the median test"
                                                         : "after relaxation";
    dopt.subtitle = subtitle;
    dopt.arrow_scale = o->arrow_scale;
    dopt.grid_step = (double)step * every; /* arrows scale to the drawn spacing */
    dopt.every = every;
    dopt.have_mask = (o->cfg.flags & SSDA_TRACK_MASK) != 0;
    dopt.mask_value = o->cfg.mask_value;
    rc = draw_vectors_to(f, name, &bg, dv, n, &dopt, NULL, err, sizeof err);
    free(dv);
    gray_image_free(&bg);
    if (rc != 0) {
        cli_input_error(cmd, "%s", err);
    }
    return rc;
}
