/*
 * cmd_register.c - `ssda register REF.png MOV.png... -o OUT.png`: the seed's
 * band registration (Nagao et al. 1975, section 3): control points per grid
 * cell, a polynomial map by least squares with outlier rejection, the
 * moving image resampled onto the reference grid; the flicker view and
 * composites to judge it.
 */
#include "cli.h"
#include "img_out.h"
#include "img_source.h"
#include "poly_float.h"
#include "ssda/register.h"
#include "ssda/shade.h"
#include "ssda/warp.h"
#include "ssda/grad.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char help[] =
    "usage: ssda register REF.png MOV.png [MOV2.png ...] -o OUT.png [options]\n"
    "\n"
    "Register each MOV to REF (the seed's band registration): the reference is cut\n"
    "into a grid of cells; in each, the most textured window is searched in an area\n"
    "of MOV; the accepted pairs fix a polynomial map from REF's pixels to MOV's by\n"
    "least squares (while a pair's leave-one-out statistic, its residual /\n"
    "sqrt(1 - leverage), exceeds a bound, the largest is dropped and the map\n"
    "refitted); MOV is resampled through the map onto REF's grid. A map that the\n"
    "points fix weakly (fewer than 2 per term, or a point of leverage above 0.8)\n"
    "is warned about on stderr.\n"
    "\n"
    "options:\n"
    "  -o OUT.png         the registered MOV (repeat once per MOV, in order)\n"
    "  --order 1|2|3      polynomial order (default 2; the seed: 2 or 3)\n"
    "  --grid CxR         cells across and down (default 4x4)\n"
    "  --window N         window side, px (default 20)\n"
    "  --search N         search area side, px (default 40: +-10 px around the\n"
    "                     offset)\n"
    "  --offset X,Y|auto  expected displacement MOV - REF, px; auto (default): the\n"
    "                     largest rho of gradient images (blind to gain and to\n"
    "                     inverted contrast), +-16 px at a scale where the image is\n"
    "                     at most 256 px across (1280 px: +-128 px), refined by\n"
    "                     factors of 4 down to full scale\n"
    "  --metric M         how windows are matched (default absncc):\n"
    "                       absncc  the largest |rho| (the seed: a band whose contrast\n"
    "                               is inverted matches too), accepted if |rho| > R\n"
    "                       ncc     the largest rho, accepted if rho > R\n"
    "                       sad     SSDA: the exact SAD minimum (fast; fails across\n"
    "                               gain changes and inverted contrast)\n"
    "  --min-rho R        acceptance of the correlation metrics (default 0.65)\n"
    "  --max-residual PX  outlier bound of the fit on the leave-one-out statistic,\n"
    "                     px (default 2)\n"
    "  --resample nearest|bilinear   (default bilinear; the seed: nearest)\n"
    "  --fill V           output value where MOV has no pixel (default 0)\n"
    "  --mem BYTES        streamed: MOV's pixels reach the warp and the search\n"
    "                     through plates of BYTES (K/M suffix) in all, as on a\n"
    "                     small processor (default: images in RAM); the search\n"
    "                     needs at least a band of window rows of REF's widest\n"
    "                     cell plus a row of the search area (1280 x 960 16-bit,\n"
    "                     4x4 cells, 20 in 40: 12880 bytes; less is refused,\n"
    "                     naming it), and reads each byte of REF at most once\n"
    "  --shade            remove each image's shading first (the seed's low-pass:\n"
    "                     DC and one cycle per direction, kept at its centre)\n"
    "  --stack FILE.png   REF and the registered MOVs as one PNG: 2 bands -> RGB\n"
    "                     (R = B = REF, G = MOV), 3 -> RGB, 4 -> RGBA\n"
    "  --flicker FILE.gif REF and the registered MOVs alternating, 7/100 s each\n"
    "                     (the seed's flicker view at 15 Hz), looping\n"
    "  --checker FILE.png REF and the first registered MOV in 32 px squares\n"
    "  --diff FILE.png    |REF - first registered MOV|, stretched\n"
    "  --json FILE        control points, residuals, the map (\"-\": stdout)\n"
    "  -q, --quiet        no summary\n"
    "  -h, --help         this text\n"
    "\n"
    "JSON: {\"order\",\"points\":[{\"ref_x\",\"ref_y\",\"mov_x\",\"mov_y\",\"rho\",\n"
    "\"residual\",\"used\",\"status\"}],\"rms\",\"weak\",\"coeffs_x\",\"coeffs_y\",...}: MOV's x and\n"
    "y as polynomials of REF's pixel (x, y), terms 1, x, y, x^2, x*y, y^2, x^3,\n"
    "x^2*y, x*y^2, y^3; several MOVs: {\"registrations\":[...]}.\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input or too few control points for the order (no\n"
    "output written), 2 usage.\n";

#define MAX_MOV 8
#define MAX_CELLS (256 * 256)

typedef struct {
    const char *out[MAX_MOV];
    int nout;
    const char *stack, *flicker, *checker, *diff, *json;
    ssda_register_config_t reg;
    uint8_t order, resample;
    uint32_t max_residual_q8;
    uint16_t fill;
    int auto_offset, shade, quiet, have_mem;
    uint64_t mem;
} reg_opts_t;

/* One MOV's registration. */
typedef struct {
    const char *path;
    gray_image_t img;          /* as loaded (shading removed with --shade) */
    gray_image_t out;          /* registered onto REF's grid */
    ssda_register_point_t *pts;
    size_t ncells, accepted;
    uint32_t *residual;        /* per cell, Q8 (UINT32_MAX: no match) */
    uint8_t *used;
    ssda_poly_t map;
    ssda_poly_fit_result_t fit;
    int32_t off_x, off_y;
    uint64_t bytes_read;
    size_t arena;
    double secs_offset, secs_points, secs_fit, secs_warp;
} reg_one_t;

/* ---- options ---- */

static int parse_size(const char *s, uint64_t *out)
{
    char *end;
    double v = strtod(s, &end);
    double mul = 1;
    if (end == s || v < 0) {
        return -1;
    }
    if (*end == 'K' || *end == 'k') {
        mul = 1024, end++;
    } else if (*end == 'M' || *end == 'm') {
        mul = 1048576, end++;
    }
    if (*end != '\0' || v * mul > 1e12) {
        return -1;
    }
    *out = (uint64_t)(v * mul);
    return 0;
}

static int parse_opts(cli_args_t *a, reg_opts_t *o)
{
    const char *v;
    uint32_t u;
    double d;
    memset(o, 0, sizeof *o);
    o->order = 2;
    o->resample = SSDA_WARP_BILINEAR;
    o->auto_offset = 1;
    o->reg.metric = SSDA_REGISTER_ABSNCC;
    while (cli_next(a)) {
        if (cli_flag(a, "--help") || cli_flag(a, "-h")) {
            fputs(help, stdout);
            return 1;
        } else if (cli_opt(a, "-o", &v) || cli_opt(a, "--output", &v)) {
            if (v != NULL && o->nout < MAX_MOV) {
                o->out[o->nout++] = v;
            } else if (v != NULL) {
                return cli_usage_error(a->cmd, "at most %d outputs", MAX_MOV);
            }
        } else if (cli_opt(a, "--order", &v)) {
            if (v != NULL && cli_parse_u32(v, 1, 3, &u) != 0) {
                return cli_usage_error(a->cmd, "bad --order '%s' (1, 2 or 3)", v);
            }
            o->order = (uint8_t)u;
        } else if (cli_opt(a, "--grid", &v)) {
            unsigned gx, gy;
            char tail;
            if (v != NULL && (sscanf(v, "%ux%u%c", &gx, &gy, &tail) != 2 || gx < 1 || gy < 1 ||
                              gx > 256 || gy > 256)) {
                return cli_usage_error(a->cmd, "bad --grid '%s' (CxR, 1..256 each)", v);
            }
            o->reg.grid_x = (uint16_t)gx;
            o->reg.grid_y = (uint16_t)gy;
        } else if (cli_opt(a, "--window", &v)) {
            if (v != NULL && cli_parse_u32(v, 2, 255, &u) != 0) {
                return cli_usage_error(a->cmd, "bad --window '%s' (2..255)", v);
            }
            o->reg.window = (uint16_t)u;
        } else if (cli_opt(a, "--search", &v)) {
            if (v != NULL && cli_parse_u32(v, 2, 1024, &u) != 0) {
                return cli_usage_error(a->cmd, "bad --search '%s' (2..1024)", v);
            }
            o->reg.search = (uint16_t)u;
        } else if (cli_opt(a, "--offset", &v)) {
            int32_t ox, oy;
            if (v != NULL && strcmp(v, "auto") == 0) {
                o->auto_offset = 1;
            } else if (v != NULL && cli_parse_pair(v, -65535, 65535, &ox, &oy) == 0) {
                o->auto_offset = 0;
                o->reg.offset_x = ox;
                o->reg.offset_y = oy;
            } else if (v != NULL) {
                return cli_usage_error(a->cmd, "bad --offset '%s' (X,Y or auto)", v);
            }
        } else if (cli_opt(a, "--metric", &v)) {
            if (v != NULL && strcmp(v, "sad") == 0) {
                o->reg.metric = SSDA_REGISTER_SAD;
            } else if (v != NULL && strcmp(v, "ncc") == 0) {
                o->reg.metric = SSDA_REGISTER_NCC;
            } else if (v != NULL && strcmp(v, "absncc") == 0) {
                o->reg.metric = SSDA_REGISTER_ABSNCC;
            } else if (v != NULL) {
                return cli_usage_error(a->cmd, "bad --metric '%s' (absncc, ncc, sad)", v);
            }
        } else if (cli_opt(a, "--min-rho", &v)) {
            if (v != NULL && (cli_parse_double(v, 0.0, 1.0, &d) != 0 || d <= 0.0)) {
                return cli_usage_error(a->cmd, "bad --min-rho '%s' (0 < R <= 1)", v);
            }
            o->reg.min_rho_q30 = (int32_t)lround(d * 1073741824.0);
        } else if (cli_opt(a, "--max-residual", &v)) {
            if (v != NULL && cli_parse_double(v, 0.01, 1e6, &d) != 0) {
                return cli_usage_error(a->cmd, "bad --max-residual '%s' (px, > 0)", v);
            }
            o->max_residual_q8 = (uint32_t)lround(d * 256.0);
        } else if (cli_opt(a, "--resample", &v)) {
            if (v != NULL && strcmp(v, "nearest") == 0) {
                o->resample = SSDA_WARP_NEAREST;
            } else if (v != NULL && strcmp(v, "bilinear") == 0) {
                o->resample = SSDA_WARP_BILINEAR;
            } else if (v != NULL) {
                return cli_usage_error(a->cmd, "bad --resample '%s' (nearest, bilinear)", v);
            }
        } else if (cli_opt(a, "--fill", &v)) {
            if (v != NULL && cli_parse_u32(v, 0, 65535, &u) != 0) {
                return cli_usage_error(a->cmd, "bad --fill '%s' (0..65535)", v);
            }
            o->fill = (uint16_t)u;
        } else if (cli_opt(a, "--mem", &v)) {
            if (v != NULL && (parse_size(v, &o->mem) != 0 || o->mem < 256)) {
                return cli_usage_error(a->cmd, "bad --mem '%s' (bytes, K/M suffix, >= 256)", v);
            }
            o->have_mem = 1;
        } else if (cli_flag(a, "--shade")) {
            o->shade = 1;
        } else if (cli_opt(a, "--stack", &o->stack) || cli_opt(a, "--flicker", &o->flicker) ||
                   cli_opt(a, "--checker", &o->checker) || cli_opt(a, "--diff", &o->diff) ||
                   cli_opt(a, "--json", &o->json)) {
            /* stored */
        } else if (cli_flag(a, "--quiet") || cli_flag(a, "-q")) {
            o->quiet = 1;
        } else {
            return cli_unknown(a);
        }
        if (a->bad) {
            return CLI_USAGE;
        }
    }
    if (!a->bad) { /* the library's bare "argument out of range" otherwise */
        const unsigned win = o->reg.window ? o->reg.window : 20u;
        const unsigned search = o->reg.search ? o->reg.search : 40u;
        if (search < win) {
            return cli_usage_error(a->cmd, "--search %u is smaller than the %u px window "
                                   "(--window): the area must hold it; e.g. --search %u "
                                   "for +-10 px", search, win, win + 20u);
        }
    }
    return a->bad ? CLI_USAGE : 0;
}

/* Every cell must hold a window (the library's SSDA_ERR_SIZE, which alone
   would read "bad dimensions"): say which grid or window fits REF. Returns
   CLI_OK, CLI_INPUT (REF smaller than a window) or CLI_USAGE (printed). */
static int check_cells(const char *cmd, const char *path, const gray_image_t *ref,
                       const reg_opts_t *o)
{
    const uint32_t win = o->reg.window ? o->reg.window : 20u;
    const uint32_t gx = o->reg.grid_x ? o->reg.grid_x : 4u, gy = o->reg.grid_y ? o->reg.grid_y : 4u;
    if (ref->width < win || ref->height < win) { /* an image too small: bad input, 1 */
        return cli_input_error(cmd, "'%s' (%u x %u) is smaller than the %u px window (--window)",
                               path, ref->width, ref->height, win);
    }
    if (ref->width / gx < win || ref->height / gy < win) {
        return cli_usage_error(cmd, "--grid %ux%u: cells of %u x %u px in '%s' (%u x %u) are "
                               "smaller than the %u px window; at most %ux%u cells, or a smaller "
                               "--window", gx, gy, ref->width / gx, ref->height / gy, path,
                               ref->width, ref->height, win, ref->width / win, ref->height / win);
    }
    return CLI_OK;
}

/* ---- shading ---- */

static int remove_shading(gray_image_t *img)
{
    ssda_shade_t sh;
    const uint8_t fmt = img->bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
    uint32_t y;
    if (img->width < 3 || img->height < 3 ||
        ssda_shade_init(&sh, (uint16_t)img->width, (uint16_t)img->height, fmt) != SSDA_OK) {
        return -1;
    }
    for (y = 0; y < img->height; y++) {
        (void)ssda_shade_add_row(&sh, (const uint8_t *)img->pixels + (size_t)y * img->stride);
    }
    if (ssda_shade_finish(&sh, SSDA_SHADE_CENTRE_MAX) != SSDA_OK) {
        return -1;
    }
    for (y = 0; y < img->height; y++) {
        uint8_t *row = (uint8_t *)img->pixels + (size_t)y * img->stride;
        (void)ssda_shade_apply_row(&sh, y, row, row);
    }
    return 0;
}

/* ---- the automatic offset: gradient magnitudes at a coarse scale ---- */

/* d8 (an 8-bit display copy) box-averaged by f, then the seed's Fig. 8
   operator (sign-free: inverted contrast gives the same edges). */
static int coarse_grad(const gray_image_t *d8, uint32_t f, gray_image_t *out)
{
    gray_image_t small = {0};
    uint32_t x, y, i, j;
    ssda_view_t sv;
    ssda_grad_out_t go;
    int rc = -1;
    const uint32_t w = d8->width / f, h = d8->height / f;
    if (w < 8 || h < 8 || gray_image_alloc(&small, w, h, 8) != 0 ||
        gray_image_alloc(out, w - 2, h - 2, 8) != 0) {
        goto done;
    }
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint32_t s = 0;
            for (j = 0; j < f; j++) {
                for (i = 0; i < f; i++) {
                    s += gray_image_get(d8, x * f + i, y * f + j);
                }
            }
            ((uint8_t *)small.pixels)[(size_t)y * small.stride + x] = (uint8_t)(s / (f * f));
        }
    }
    (void)gray_image_view(&small, &sv);
    memset(&go, 0, sizeof go);
    go.data = out->pixels;
    go.size = (size_t)out->stride * out->height;
    go.format = SSDA_PIX_U8;
    go.shift = 2;
    rc = ssda_grad(&sv, &go, NULL) == SSDA_OK ? 0 : -1;
done:
    gray_image_free(&small);
    return rc;
}

/* The largest rho of win in area (gradient magnitudes: positive; rho is
   blind to the bands' different gains): its top-left. */
static int level_search(const ssda_view_t *area, const ssda_view_t *win, uint16_t *x, uint16_t *y)
{
    ssda_ncc_config_t nc;
    ssda_ncc_result_t res;
    const size_t ws = SSDA_NCC_WORK_SIZE(area->width, win->width, win->height);
    void *work = malloc(ws);
    int err;
    memset(&nc, 0, sizeof nc);
    nc.metric = SSDA_NCC_RHO;
    nc.work = work;
    nc.work_size = ws;
    err = work != NULL ? ssda_ncc_match(area, win, &nc, &res) : SSDA_ERR_BUFFER;
    free(work);
    if (err != SSDA_OK) {
        return -1;
    }
    *x = res.x;
    *y = res.y;
    return 0;
}

/* The search of one pyramid level: REF's gradient window (the central
   half, at most 128 x 128 px) over MOV's gradient image at scale f, within
   +-reach px (all of it when reach is 0) of the predicted displacement
   (*ox, *oy, px at full scale); the result replaces the prediction. */
static int offset_level(const gray_image_t *ref, const gray_image_t *mov, uint32_t f,
                        uint32_t reach, int32_t *ox, int32_t *oy)
{
    gray_image_t gr = {0}, gm = {0};
    ssda_view_t vr, vm, win, area;
    struct {
        uint16_t x, y;
    } res;
    int rc = -1;
    if (coarse_grad(ref, f, &gr) == 0 && coarse_grad(mov, f, &gm) == 0) {
        const uint32_t ww = gr.width / 2 < 128 ? gr.width / 2 : 128;
        const uint32_t wh = gr.height / 2 < 128 ? gr.height / 2 : 128;
        const int32_t wx = (int32_t)(gr.width - ww) / 2, wy = (int32_t)(gr.height - wh) / 2;
        int32_t ax = 0, ay = 0, aw = (int32_t)gm.width, ah = (int32_t)gm.height;
        (void)gray_image_view(&gr, &vr);
        (void)gray_image_view(&gm, &vm);
        if (reach > 0) { /* the window's predicted place, +-reach */
            ax = wx + *ox / (int32_t)f - (int32_t)reach;
            ay = wy + *oy / (int32_t)f - (int32_t)reach;
            aw = (int32_t)(ww + 2 * reach);
            ah = (int32_t)(wh + 2 * reach);
            ax = ax < 0 ? 0 : ax;
            ay = ay < 0 ? 0 : ay;
            aw = ax + aw > (int32_t)gm.width ? (int32_t)gm.width - ax : aw;
            ah = ay + ah > (int32_t)gm.height ? (int32_t)gm.height - ay : ah;
        }
        if (aw >= (int32_t)ww && ah >= (int32_t)wh &&
            ssda_view_roi(&win, &vr, (uint16_t)wx, (uint16_t)wy, (uint16_t)ww, (uint16_t)wh) ==
                SSDA_OK &&
            ssda_view_roi(&area, &vm, (uint16_t)ax, (uint16_t)ay, (uint16_t)aw, (uint16_t)ah) ==
                SSDA_OK &&
            level_search(&area, &win, &res.x, &res.y) == 0) {
            *ox = (ax + (int32_t)res.x - wx) * (int32_t)f;
            *oy = (ay + (int32_t)res.y - wy) * (int32_t)f;
            rc = 0;
        }
    }
    gray_image_free(&gr);
    gray_image_free(&gm);
    return rc;
}

/* The displacement MOV - REF of the images' centres, px: exact correlation
   searches of gradient images (sign-free: inverted contrast gives the same
   edges; rho: blind to gain) from a scale where the image is at most 256 px
   across (within +-16 px there: a whole-image search found wrong peaks on
   the NIR band) down to full scale by factors of 4, each within +-8 px of
   the level above's answer. */
static int auto_offset(const gray_image_t *ref, const gray_image_t *mov, int32_t *ox, int32_t *oy)
{
    const uint32_t big = ref->width > ref->height ? ref->width : ref->height;
    uint32_t f = 1;
    int32_t x = 0, y = 0;
    gray_image_t r8 = {0}, m8 = {0};
    int rc = -1;
    while (big / f > 256) {
        f *= 2;
    }
    if (img_display8(ref, &r8) == 0 && img_display8(mov, &m8) == 0 &&
        offset_level(&r8, &m8, f, 16, &x, &y) == 0) {
        while (f > 1) {
            f = f >= 4 ? f / 4 : 1;
            if (offset_level(&r8, &m8, f, 8, &x, &y) != 0) {
                break; /* keep the coarser answer */
            }
        }
        *ox = x;
        *oy = y;
        rc = 0;
    }
    gray_image_free(&r8);
    gray_image_free(&m8);
    return rc;
}

/* ---- one registration ---- */

typedef struct {
    gray_image_t *img;
} out_sink_t;

static int put_rows(void *ctx, uint32_t x, uint32_t y, uint32_t n, const void *px)
{
    out_sink_t *o = (out_sink_t *)ctx;
    const size_t bpp = o->img->bits == 16 ? 2u : 1u;
    memcpy((uint8_t *)o->img->pixels + (size_t)y * o->img->stride + x * bpp, px, n * bpp);
    return 0;
}

/* CPU seconds of this process (the figures of docs/registration.md are CPU
   time: a loaded machine stretches wall time). */
static double now_s(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

static int find_points(const char *cmd, const gray_image_t *ref, reg_one_t *r,
                       const reg_opts_t *o)
{
    ssda_source_t sr, sm;
    img_device_t dr, dm;
    void *ar = NULL, *am = NULL, *work = NULL;
    size_t size_r = 0, size_m = 0, ws;
    const uint8_t fmt = ref->bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
    ssda_register_config_t c = o->reg;
    int err;
    double t0 = now_s();
    c.offset_x = r->off_x;
    c.offset_y = r->off_y;
    ws = SSDA_REGISTER_WORK_SIZE(c.window ? c.window : 20, c.search ? c.search : 40, fmt);
    work = malloc(ws) /* malloc: aligned for any type */;
    if (o->have_mem) {
        /* the least arenas (register.h): a band of window rows of REF's
           widest cell, a row of MOV's search area; below them the library
           refuses, as its reads would not be bounded. Halves when both
           fit, else REF gets its least and MOV the rest. */
        const size_t need_r = SSDA_REGISTER_REF_SIZE(SSDA_LAYOUT_RASTER, ref->width, c.grid_x,
                                                     c.window, fmt, 1u, 0u);
        const size_t need_m = SSDA_REGISTER_MOV_SIZE(SSDA_LAYOUT_RASTER, r->img.width, c.search,
                                                     fmt, 1u, 0u);
        const size_t half = (size_t)(o->mem / 2) & ~(size_t)3;
        if (o->mem < (uint64_t)need_r + need_m) {
            cli_input_error(cmd, "'%s': control points: --mem %llu is below the least the search "
                            "needs: --mem %zu (REF: %u rows of a %zu px cell, %zu bytes; MOV: a "
                            "row of the search area, %zu bytes)", r->path,
                            (unsigned long long)o->mem, need_r + need_m,
                            c.window ? c.window : 20u,
                            (size_t)SSDA_REGISTER_CELL_W(ref->width, c.grid_x), need_r, need_m);
            r->secs_points = now_s() - t0;
            return -1;
        }
        size_r = half < need_r ? need_r
                               : ((size_t)o->mem - half < need_m ? ((size_t)o->mem - need_m) & ~(size_t)3
                                                                 : half);
        size_m = (size_t)o->mem - size_r;
        ar = malloc(size_r);
        am = malloc(size_m);
    }
    if (work == NULL || (o->have_mem && (ar == NULL || am == NULL))) {
        err = SSDA_ERR_BUFFER;
        goto done;
    }
    err = img_source_init(&sr, ref, &dr, ar, size_r);
    if (err == SSDA_OK) {
        err = img_source_init(&sm, &r->img, &dm, am, size_m);
    }
    if (err == SSDA_OK) {
        err = ssda_register_points(&sr, &sm, &c, r->pts, r->ncells, &r->accepted, work, ws);
    }
    if (o->have_mem && err == SSDA_OK) {
        r->bytes_read += sr.stats.bytes_read + sm.stats.bytes_read;
    }
done:
    if (err != SSDA_OK) {
        cli_input_error(cmd, "'%s': control points: %s%s", r->path, ssda_strerror(err),
                        err == SSDA_ERR_BUFFER && o->have_mem ? " (--mem too small)" : "");
    }
    free(work);
    free(ar);
    free(am);
    r->secs_points = now_s() - t0;
    return err == SSDA_OK ? 0 : -1;
}

static int fit_map(const char *cmd, const gray_image_t *ref, reg_one_t *r, const reg_opts_t *o)
{
    ssda_poly_pair_t *pairs = malloc(r->ncells * sizeof *pairs);
    uint32_t *res = malloc(r->ncells * sizeof *res);
    uint8_t *used = malloc(r->ncells), *work = malloc(r->ncells + 1);
    size_t *idx = malloc(r->ncells * sizeof *idx);
    ssda_poly_fit_config_t fc = {o->order, o->max_residual_q8};
    const uint32_t need = SSDA_POLY_TERMS(o->order);
    size_t k, n = 0;
    int err, rc = -1;
    double t0 = now_s();
    if (pairs == NULL || res == NULL || used == NULL || work == NULL || idx == NULL) {
        cli_input_error(cmd, "out of memory");
        goto done;
    }
    for (k = 0; k < r->ncells; k++) {
        r->residual[k] = UINT32_MAX;
        r->used[k] = 0;
        if (r->pts[k].status == SSDA_REGISTER_OK) {
            idx[n] = k;
            pairs[n++] = r->pts[k].pair;
        }
    }
    if (n < need) {
        cli_input_error(cmd, "'%s': found %zu control point%s of %zu cells; order %u needs at "
                        "least %u (try --offset, a larger --search, a finer --grid or a lower "
                        "--order)", r->path, n, n == 1 ? "" : "s", r->ncells, o->order, need);
        goto done;
    }
    err = ssda_poly_fit(pairs, n, (uint16_t)ref->width, (uint16_t)ref->height, &fc, &r->map, res,
                        used, &r->fit, work, n + 1);
    if (err != SSDA_OK) {
        cli_input_error(cmd, "'%s': the %zu control points do not fix an order-%u map (%s)",
                        r->path, n, o->order, ssda_strerror(err));
        goto done;
    }
    for (k = 0; k < n; k++) {
        r->residual[idx[k]] = res[k];
        r->used[idx[k]] = used[k];
    }
    /* residuals of the cells that matched but were not accepted */
    for (k = 0; k < r->ncells; k++) {
        const ssda_register_point_t *p = &r->pts[k];
        if (p->status == SSDA_REGISTER_BORDER || p->status == SSDA_REGISTER_LOW_RHO) {
            double x, y;
            poly_eval_double(&r->map, p->pair.ref_x_q8 / 256.0, p->pair.ref_y_q8 / 256.0, &x, &y);
            r->residual[k] = (uint32_t)fmin(4e9, 256.0 * hypot(x - p->pair.mov_x_q8 / 256.0,
                                                              y - p->pair.mov_y_q8 / 256.0));
        }
    }
    rc = 0;
done:
    free(pairs);
    free(res);
    free(used);
    free(work);
    free(idx);
    r->secs_fit = now_s() - t0;
    return rc;
}

static int warp_image(const char *cmd, reg_one_t *r, const reg_opts_t *o)
{
    ssda_source_t src;
    img_device_t dev;
    ssda_warp_config_t wc;
    ssda_warp_t job;
    ssda_warp_plan_t plan;
    out_sink_t sink = {&r->out};
    void *arena = NULL, *row = NULL;
    size_t arena_size = 0;
    int err;
    double t0 = now_s();
    memset(&wc, 0, sizeof wc);
    wc.map = &r->map;
    wc.sink = put_rows;
    wc.context = &sink;
    wc.resample = o->resample;
    wc.fill = r->img.bits == 8 && o->fill > 255 ? 255 : o->fill;
    if (o->have_mem) {
        /* the arena and the segment buffer within --mem: the plan's tile
           for an arena, shrunk until both fit */
        ssda_source_config_t g;
        memset(&g, 0, sizeof g);
        g.width = (uint16_t)r->img.width;
        g.height = (uint16_t)r->img.height;
        g.format = r->img.bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
        arena_size = (size_t)o->mem;
        for (int it = 0; it < 64; it++) {
            g.arena_size = arena_size;
            if (ssda_warp_plan(&r->map, o->resample, &g, 0, 0, &plan) != SSDA_OK) {
                break;
            }
            if (arena_size + plan.row_size <= o->mem || arena_size < 64) {
                break;
            }
            arena_size = o->mem - plan.row_size < arena_size - 16 ? (size_t)o->mem - plan.row_size
                                                                   : arena_size - 16;
        }
        arena_size &= ~(size_t)3;
        arena = malloc(arena_size > 0 ? arena_size : 4);
        wc.tile_w = plan.tile_w;
        wc.tile_h = plan.tile_h;
        wc.row_size = plan.row_size;
    } else {
        wc.row_size = (size_t)r->map.ref_w * (r->img.bits == 16 ? 2u : 1u);
    }
    row = malloc(wc.row_size > 0 ? wc.row_size : 1);
    wc.row = row;
    if (row == NULL || (o->have_mem && arena == NULL)) {
        err = SSDA_ERR_BUFFER;
    } else {
        err = img_source_init(&src, &r->img, &dev, arena, arena_size);
    }
    if (err == SSDA_OK) {
        err = ssda_warp_init(&job, &wc, &src);
    }
    if (err == SSDA_OK) {
        err = ssda_warp_run(&job, NULL);
    }
    if (err == SSDA_OK && o->have_mem) {
        r->bytes_read += src.stats.bytes_read;
        r->arena = arena_size + wc.row_size;
    }
    if (err != SSDA_OK) {
        cli_input_error(cmd, "'%s': resampling: %s%s", r->path, ssda_strerror(err),
                        err == SSDA_ERR_BUFFER && o->have_mem ? " (--mem too small)" : "");
    }
    free(arena);
    free(row);
    r->secs_warp = now_s() - t0;
    return err == SSDA_OK ? 0 : -1;
}

static int register_one(const char *cmd, const gray_image_t *ref, reg_one_t *r,
                        const reg_opts_t *o)
{
    const uint32_t gx = o->reg.grid_x ? o->reg.grid_x : 4, gy = o->reg.grid_y ? o->reg.grid_y : 4;
    double t0;
    r->ncells = (size_t)gx * gy;
    r->pts = calloc(r->ncells, sizeof *r->pts);
    r->residual = calloc(r->ncells, sizeof *r->residual);
    r->used = calloc(r->ncells, 1);
    if (r->pts == NULL || r->residual == NULL || r->used == NULL ||
        gray_image_alloc(&r->out, ref->width, ref->height, ref->bits) != 0) {
        cli_input_error(cmd, "out of memory");
        return -1;
    }
    r->off_x = o->reg.offset_x;
    r->off_y = o->reg.offset_y;
    t0 = now_s();
    if (o->auto_offset && auto_offset(ref, &r->img, &r->off_x, &r->off_y) != 0) {
        r->off_x = r->off_y = 0; /* too small to search: assume none */
    }
    r->secs_offset = now_s() - t0;
    if (find_points(cmd, ref, r, o) != 0 || fit_map(cmd, ref, r, o) != 0) {
        return -1;
    }
    return warp_image(cmd, r, o);
}

/* ---- outputs ---- */

static const char *status_name(uint8_t s)
{
    static const char *const names[] = {"ok", "flat", "low_rho", "border", "outside"};
    return s < 5 ? names[s] : "?";
}

static cJSON *json_of(const reg_one_t *r, const gray_image_t *ref, const reg_opts_t *o,
                      const char *ref_path)
{
    cJSON *j = cJSON_CreateObject(), *pts = cJSON_CreateArray(), *cx = cJSON_CreateArray(),
          *cy = cJSON_CreateArray();
    double px[10], py[10];
    size_t k;
    int t;
    cJSON_AddStringToObject(j, "ref", ref_path);
    cJSON_AddStringToObject(j, "mov", r->path);
    cJSON_AddNumberToObject(j, "width", ref->width);
    cJSON_AddNumberToObject(j, "height", ref->height);
    cJSON_AddNumberToObject(j, "order", o->order);
    cJSON_AddStringToObject(j, "metric", o->reg.metric == SSDA_REGISTER_SAD   ? "sad"
                                         : o->reg.metric == SSDA_REGISTER_NCC ? "ncc"
                                                                              : "absncc");
    cJSON_AddNumberToObject(j, "grid_x", o->reg.grid_x ? o->reg.grid_x : 4);
    cJSON_AddNumberToObject(j, "grid_y", o->reg.grid_y ? o->reg.grid_y : 4);
    cJSON_AddNumberToObject(j, "window", o->reg.window ? o->reg.window : 20);
    cJSON_AddNumberToObject(j, "search", o->reg.search ? o->reg.search : 40);
    cJSON_AddNumberToObject(j, "offset_x", r->off_x);
    cJSON_AddNumberToObject(j, "offset_y", r->off_y);
    for (k = 0; k < r->ncells; k++) {
        const ssda_register_point_t *p = &r->pts[k];
        const int matched = p->status == SSDA_REGISTER_OK || p->status == SSDA_REGISTER_BORDER ||
                            p->status == SSDA_REGISTER_LOW_RHO;
        cJSON *e = cJSON_CreateObject();
        cJSON_AddNumberToObject(e, "ref_x", p->pair.ref_x_q8 / 256.0);
        cJSON_AddNumberToObject(e, "ref_y", p->pair.ref_y_q8 / 256.0);
        if (matched) {
            cJSON_AddNumberToObject(e, "mov_x", p->pair.mov_x_q8 / 256.0);
            cJSON_AddNumberToObject(e, "mov_y", p->pair.mov_y_q8 / 256.0);
        } else {
            cJSON_AddNullToObject(e, "mov_x");
            cJSON_AddNullToObject(e, "mov_y");
        }
        if (matched) {
            cJSON_AddNumberToObject(e, "rho", p->rho_q30 / 1073741824.0);
        } else {
            cJSON_AddNullToObject(e, "rho");
        }
        if (r->residual[k] != UINT32_MAX) {
            cJSON_AddNumberToObject(e, "residual", r->residual[k] / 256.0);
        } else {
            cJSON_AddNullToObject(e, "residual");
        }
        cJSON_AddBoolToObject(e, "used", r->used[k] != 0);
        cJSON_AddStringToObject(e, "status", status_name(p->status));
        if (o->reg.metric == SSDA_REGISTER_SAD && matched) {
            cJSON_AddNumberToObject(e, "sad", (double)p->sad);
        } else { /* not measured: 0 would read as a perfect match */
            cJSON_AddNullToObject(e, "sad");
        }
        cJSON_AddNumberToObject(e, "texture", p->texture);
        cJSON_AddItemToArray(pts, e);
    }
    cJSON_AddItemToObject(j, "points", pts);
    cJSON_AddNumberToObject(j, "accepted", (double)r->accepted);
    cJSON_AddNumberToObject(j, "used", r->fit.used);
    cJSON_AddNumberToObject(j, "rejected", r->fit.rejected);
    cJSON_AddNumberToObject(j, "rms", r->fit.rms_q8 / 256.0);
    cJSON_AddNumberToObject(j, "max_residual", r->fit.max_q8 / 256.0);
    cJSON_AddNumberToObject(j, "cond", r->fit.cond);
    cJSON_AddNumberToObject(j, "max_leverage", r->fit.max_leverage_q15 / 32768.0);
    cJSON_AddBoolToObject(j, "weak", r->fit.weak);
    poly_to_pixel(&r->map, px, py);
    for (t = 0; t < (int)SSDA_POLY_TERMS(o->order); t++) {
        cJSON_AddItemToArray(cx, cJSON_CreateNumber(px[t]));
        cJSON_AddItemToArray(cy, cJSON_CreateNumber(py[t]));
    }
    cJSON_AddItemToObject(j, "coeffs_x", cx);
    cJSON_AddItemToObject(j, "coeffs_y", cy);
    cJSON_AddNumberToObject(j, "cpu_offset_s", r->secs_offset);
    cJSON_AddNumberToObject(j, "cpu_points_s", r->secs_points);
    cJSON_AddNumberToObject(j, "cpu_fit_s", r->secs_fit);
    cJSON_AddNumberToObject(j, "cpu_warp_s", r->secs_warp);
    if (o->have_mem) {
        cJSON_AddNumberToObject(j, "mem", (double)o->mem);
        cJSON_AddNumberToObject(j, "bytes_read", (double)r->bytes_read);
    }
    return j;
}

static int write_json(FILE *f, reg_one_t *r, int n, const gray_image_t *ref, const reg_opts_t *o,
                      const char *ref_path)
{
    cJSON *doc;
    char *text;
    int i, rc;
    if (n == 1) {
        doc = json_of(&r[0], ref, o, ref_path);
    } else {
        cJSON *arr = cJSON_CreateArray();
        doc = cJSON_CreateObject();
        for (i = 0; i < n; i++) {
            cJSON_AddItemToArray(arr, json_of(&r[i], ref, o, ref_path));
        }
        cJSON_AddStringToObject(doc, "ref", ref_path);
        cJSON_AddItemToObject(doc, "registrations", arr);
    }
    text = cJSON_PrintUnformatted(doc);
    rc = text != NULL && fputs(text, f) >= 0 && fputc('\n', f) != EOF ? 0 : -1;
    free(text);
    cJSON_Delete(doc);
    return rc;
}

static int write_outputs(const char *cmd, const gray_image_t *ref, reg_one_t *r, int n,
                         const reg_opts_t *o, const char *ref_path)
{
    cli_outputs_t outs;
    gray_image_t disp[MAX_MOV + 1];
    const gray_image_t *ch[MAX_MOV + 1];
    char err[256];
    int i, rc = CLI_INPUT, ndisp = 0;
    FILE *f;
    memset(disp, 0, sizeof disp);
    cli_outputs_begin(&outs, cmd);
    for (i = 0; i < o->nout; i++) {
        const gray_image_t *one[1] = {&r[i].out};
        if ((f = cli_outputs_open(&outs, o->out[i])) == NULL) {
            goto fail;
        }
        if (img_write_png(f, one, 1, err, sizeof err) != 0) {
            cli_input_error(cmd, "'%s': %s", o->out[i], err);
            goto fail;
        }
    }
    if (o->stack != NULL) {
        ch[0] = ref;
        for (i = 0; i < n; i++) {
            ch[i + 1] = &r[i].out;
        }
        if ((f = cli_outputs_open(&outs, o->stack)) == NULL) {
            goto fail;
        }
        if (img_write_png(f, ch, n + 1, err, sizeof err) != 0) {
            cli_input_error(cmd, "'%s': %s", o->stack, err);
            goto fail;
        }
    }
    if (o->flicker != NULL || o->checker != NULL || o->diff != NULL) {
        if (img_display8(ref, &disp[0]) != 0) {
            goto oom;
        }
        ndisp = 1;
        for (i = 0; i < n; i++) {
            if (img_display8(&r[i].out, &disp[i + 1]) != 0) {
                goto oom;
            }
            ndisp++;
        }
    }
    if (o->flicker != NULL) {
        for (i = 0; i < ndisp; i++) {
            ch[i] = &disp[i];
        }
        if ((f = cli_outputs_open(&outs, o->flicker)) == NULL) {
            goto fail;
        }
        if (img_write_flicker_gif(f, ch, ndisp, 7, err, sizeof err) != 0) {
            cli_input_error(cmd, "'%s': %s", o->flicker, err);
            goto fail;
        }
    }
    for (i = 0; i < 2; i++) {
        const char *path = i == 0 ? o->checker : o->diff;
        gray_image_t comp = {0};
        const gray_image_t *one[1] = {&comp};
        int bad;
        if (path == NULL) {
            continue;
        }
        if ((i == 0 ? img_checkerboard(&disp[0], &disp[1], 32, &comp)
                    : img_difference(&disp[0], &disp[1], &comp)) != 0) {
            goto oom;
        }
        f = cli_outputs_open(&outs, path);
        bad = f == NULL || img_write_png(f, one, 1, err, sizeof err) != 0;
        if (bad && f != NULL) {
            cli_input_error(cmd, "'%s': %s", path, err);
        }
        gray_image_free(&comp);
        if (bad) {
            goto fail;
        }
    }
    if (o->json != NULL) {
        if ((f = cli_outputs_open(&outs, o->json)) == NULL) {
            goto fail;
        }
        if (write_json(f, r, n, ref, o, ref_path) != 0) {
            cli_input_error(cmd, "'%s': cannot write the JSON", o->json);
            goto fail;
        }
    }
    rc = cli_outputs_commit(&outs);
    goto done;
oom:
    cli_input_error(cmd, "out of memory");
fail:
    cli_outputs_abort(&outs);
    rc = CLI_INPUT;
done:
    for (i = 0; i < ndisp; i++) {
        gray_image_free(&disp[i]);
    }
    return rc;
}

/* A map fixed by fewer than half the cells is often wrong without its
   residuals showing it: a large rotation, low texture or a repeated
   pattern leave a few chance matches, which fit a low-order map closely
   (measured in docs/registration.md). Said on stderr, also under -q. */
static void few_points_warning(const char *cmd, const reg_one_t *r)
{
    if ((size_t)r->fit.used * 2u < r->ncells) {
        fprintf(stderr,
                "ssda %s: warning: '%s': only %u of %zu cells gave the map's control points; "
                "it may be wrong (large rotation, low texture, repeated pattern): check "
                "--flicker or --checker\n",
                cmd, r->path, r->fit.used, r->ncells);
    }
}

/* A map the used points fix weakly: an outlier among them can pass the
   rejection (poly.h, result.weak). Said on stderr, also under -q. */
static void weak_fit_warning(const char *cmd, const reg_one_t *r, unsigned order)
{
    const unsigned terms = SSDA_POLY_TERMS(order);
    if (r->fit.weak) {
        fprintf(stderr,
                "ssda %s: warning: '%s': the order-%u map is weakly determined (%u points for "
                "%u terms, largest leverage %.2f; wanted >= %u points, <= %.2f): an outlier "
                "may pass unseen; try a lower --order or a finer --grid, and check --flicker "
                "or --checker\n",
                cmd, r->path, order, r->fit.used, terms, r->fit.max_leverage_q15 / 32768.0,
                SSDA_POLY_WEAK_PAIRS(terms), SSDA_POLY_WEAK_LEVERAGE_Q15 / 32768.0);
    }
}

static void summary(const reg_one_t *r, const reg_opts_t *o)
{
    double px[10], py[10];
    poly_to_pixel(&r->map, px, py);
    printf("%s: offset (%d, %d), %zu of %zu control points accepted, %u used (%u rejected as "
           "outliers), RMS residual %.3f px, max %.3f px\n",
           r->path, r->off_x, r->off_y, r->accepted, r->ncells, r->fit.used, r->fit.rejected,
           r->fit.rms_q8 / 256.0, r->fit.max_q8 / 256.0);
    printf("  x = %.6g + %.6g X + %.6g Y%s\n  y = %.6g + %.6g X + %.6g Y%s\n", px[0], px[1], px[2],
           o->order > 1 ? " + ..." : "", py[0], py[1], py[2], o->order > 1 ? " + ..." : "");
    if (o->have_mem) {
        printf("  streamed in %llu bytes of memory: read %llu bytes (%.2f x the image)\n",
               (unsigned long long)o->mem, (unsigned long long)r->bytes_read,
               (double)r->bytes_read / ((double)r->img.stride * r->img.height));
    }
    printf("  CPU time: offset %.3f s, points %.3f s, fit %.3f s, resampling %.3f s\n",
           r->secs_offset, r->secs_points, r->secs_fit,
           r->secs_warp);
}

int cmd_register(int argc, char **argv)
{
    cli_args_t a;
    reg_opts_t o;
    reg_one_t r[MAX_MOV];
    gray_image_t ref = {0};
    int i, n, rc = CLI_INPUT;
    memset(r, 0, sizeof r);
    cli_args_begin(&a, "register", argc, argv);
    rc = parse_opts(&a, &o);
    if (rc == 1) {
        return CLI_OK;
    }
    if (rc != 0) {
        return CLI_USAGE;
    }
    rc = CLI_INPUT;
    n = a.npos - 1;
    if (a.npos < 2) {
        return cli_usage_error(a.cmd, "need REF.png and at least one MOV.png");
    }
    if (n > MAX_MOV) {
        return cli_usage_error(a.cmd, "at most %d MOV images", MAX_MOV);
    }
    if (o.nout > n) {
        return cli_usage_error(a.cmd, "%d -o outputs for %d MOV image%s", o.nout, n,
                               n == 1 ? "" : "s");
    }
    if (o.nout == 0 && o.stack == NULL && o.json == NULL && o.flicker == NULL &&
        o.checker == NULL && o.diff == NULL) {
        return cli_usage_error(a.cmd, "no output: give -o OUT.png (or --stack, --json, "
                               "--flicker, --checker, --diff)");
    }
    if (o.stack != NULL && n + 1 > 4) {
        return cli_usage_error(a.cmd, "--stack holds REF and up to 3 MOVs (%d given)", n);
    }
    if (o.json != NULL && strcmp(o.json, "-") == 0) {
        o.quiet = 1;
    }
    /* fewer -o than MOVs: the MOVs after the last -o reach a file only
       through --stack, --json or --flicker (--checker and --diff show the
       first MOV alone); without them their registration is written nowhere */
    i = o.nout > 0 || (o.checker == NULL && o.diff == NULL) ? o.nout : 1;
    if (i < n && o.stack == NULL && o.json == NULL && o.flicker == NULL) {
        fprintf(stderr, "ssda %s: warning: %d MOV images and %d -o output%s: '%s'%s %s "
                "registered but written nowhere (give -o once per MOV, in order, or "
                "--stack, --json, --flicker)\n", a.cmd, n, o.nout, o.nout == 1 ? "" : "s",
                a.pos[1 + i], n - i > 1 ? " and the MOVs after it" : "",
                n - i > 1 ? "are" : "is");
    }
    for (i = 0; i < o.nout; i++) {
        cli_warn_png_name(a.cmd, "-o", o.out[i]);
    }
    cli_warn_png_name(a.cmd, "--stack", o.stack);
    cli_warn_png_name(a.cmd, "--checker", o.checker);
    cli_warn_png_name(a.cmd, "--diff", o.diff);
    if (cli_load_png(a.cmd, a.pos[0], PNG_GRAY_NATIVE, &ref) != 0) {
        return CLI_INPUT;
    }
    if ((i = check_cells(a.cmd, a.pos[0], &ref, &o)) != CLI_OK) {
        gray_image_free(&ref);
        return i;
    }
    for (i = 0; i < n; i++) {
        r[i].path = a.pos[i + 1];
        if (cli_load_png(a.cmd, r[i].path, ref.bits == 16 ? PNG_GRAY_16 : PNG_GRAY_NATIVE,
                         &r[i].img) != 0) {
            goto done;
        }
        if (r[i].img.bits == 16 && ref.bits == 8) { /* widen REF (and those before) */
            int k;
            gray_image_free(&ref);
            if (cli_load_png(a.cmd, a.pos[0], PNG_GRAY_16, &ref) != 0) {
                goto done;
            }
            for (k = 0; k < i; k++) {
                gray_image_free(&r[k].img);
                if (cli_load_png(a.cmd, r[k].path, PNG_GRAY_16, &r[k].img) != 0) {
                    goto done;
                }
            }
        }
    }
    if (o.shade) {
        if (remove_shading(&ref) != 0) {
            cli_input_error(a.cmd, "'%s': too small for --shade (3 x 3 at least)", a.pos[0]);
            goto done;
        }
        for (i = 0; i < n; i++) {
            if (remove_shading(&r[i].img) != 0) {
                cli_input_error(a.cmd, "'%s': too small for --shade", r[i].path);
                goto done;
            }
        }
    }
    for (i = 0; i < n; i++) {
        if (register_one(a.cmd, &ref, &r[i], &o) != 0) {
            goto done;
        }
    }
    rc = write_outputs(a.cmd, &ref, r, n, &o, a.pos[0]);
    for (i = 0; rc == CLI_OK && i < n; i++) {
        few_points_warning(a.cmd, &r[i]);
        weak_fit_warning(a.cmd, &r[i], o.order);
    }
    if (rc == CLI_OK && !o.quiet) {
        for (i = 0; i < n; i++) {
            summary(&r[i], &o);
        }
    }
done:
    gray_image_free(&ref);
    for (i = 0; i < n; i++) {
        gray_image_free(&r[i].img);
        gray_image_free(&r[i].out);
        free(r[i].pts);
        free(r[i].residual);
        free(r[i].used);
    }
    return rc;
}
