/*
 * demo_register.c - the demo's band registration (seed 002, section 3): a
 * synthetic "second band" made from the first through a known 2nd-order
 * map (shift, rotation, scale, a bow) with a gain and offset change, the
 * control points, the least-squares map, and the resampling from a
 * streamed source in 4 KB; the map's error against the truth, and the
 * flicker view and checkerboard to look at.
 */
#include "demo.h"
#include "img_out.h"
#include "poly_float.h"
#include "ssda/register.h"
#include "ssda/warp.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RW 480
#define RH 360
#define GAIN 0.85 /* the second band's gain and offset */
#define OFFS 20.0

/* The known map REF -> MOV, pixel units (terms 1, X, Y, X^2, XY, Y^2). */
static const double k_cx[6] = {11.4, 1.006, -0.0131, 1.8e-5, -0.9e-5, 1.2e-5};
static const double k_cy[6] = {-7.2, 0.0131, 1.006, -1.1e-5, 1.6e-5, 0.4e-5};

static void truth(double X, double Y, double *x, double *y)
{
    *x = k_cx[0] + k_cx[1] * X + k_cx[2] * Y + k_cx[3] * X * X + k_cx[4] * X * Y + k_cx[5] * Y * Y;
    *y = k_cy[0] + k_cy[1] * X + k_cy[2] * Y + k_cy[3] * X * X + k_cy[4] * X * Y + k_cy[5] * Y * Y;
}

/* A smooth procedural scene: value noise (random values on lattices of
   5 and 17 px, hashed from the lattice point, bicubic between them), so
   every window is textured and has one match. */
static double lattice(int i, int j, unsigned salt)
{
    unsigned h = (unsigned)i * 73856093u ^ (unsigned)j * 19349663u ^ salt;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return (h & 0xFFFFu) / 65535.0;
}

static double cubic(double p0, double p1, double p2, double p3, double t)
{
    return p1 + 0.5 * t * (p2 - p0 + t * (2 * p0 - 5 * p1 + 4 * p2 - p3 + t * (3 * (p1 - p2) + p3 - p0)));
}

static double noise(double x, double y, double cell, unsigned salt)
{
    const double u = x / cell + 100.0, v = y / cell + 100.0;
    const int i = (int)floor(u), j = (int)floor(v);
    double col[4];
    int k;
    for (k = 0; k < 4; k++) {
        col[k] = cubic(lattice(i - 1, j - 1 + k, salt), lattice(i, j - 1 + k, salt),
                       lattice(i + 1, j - 1 + k, salt), lattice(i + 2, j - 1 + k, salt), u - i);
    }
    return cubic(col[0], col[1], col[2], col[3], v - j);
}

static double land(double x, double y)
{
    const double v = 128.0 + 90.0 * (noise(x, y, 5.0, 1u) - 0.5) + 70.0 * (noise(x, y, 17.0, 2u) - 0.5);
    return v < 0 ? 0 : (v > 255 ? 255 : v);
}

static int sink(void *ctx, uint32_t x, uint32_t y, uint32_t n, const void *px)
{
    gray_image_t *o = (gray_image_t *)ctx;
    memcpy((uint8_t *)o->pixels + (size_t)y * o->stride + x, px, n);
    return 0;
}

typedef struct {
    const gray_image_t *img;
} dev_t_;

static int dev_read(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    const dev_t_ *d = (const dev_t_ *)ctx;
    if ((size_t)off + size > (size_t)d->img->stride * d->img->height) {
        return SSDA_ERR_IO;
    }
    memcpy(buf, (const uint8_t *)d->img->pixels + off, size);
    return 0;
}

int demo_register(const demo_ctx_t *c)
{
    gray_image_t ref = {0}, mov = {0}, out = {0}, d_ref = {0}, d_out = {0}, comp = {0};
    ssda_register_point_t pts[16];
    ssda_poly_pair_t pairs[16];
    uint32_t res[16];
    uint8_t used[16], work_fit[16];
    static uint64_t work[(SSDA_REGISTER_WORK_SIZE(20, 64, 1) + 7) / 8];
    static uint32_t arena[3000 / 4];
    uint8_t rowbuf[RW];
    ssda_register_config_t rc_cfg;
    ssda_poly_fit_config_t fc = {2, 0};
    ssda_poly_fit_result_t fit;
    ssda_poly_t map;
    ssda_source_t sref, smov, sstr;
    ssda_source_config_t scfg;
    ssda_warp_config_t wc;
    ssda_warp_t job;
    ssda_view_t vr, vm;
    dev_t_ dev;
    size_t accepted = 0, n = 0, k;
    double worst = 0, sum2 = 0, cnt = 0;
    int x, y, rc = -1, i, j;
    char path[1024], e[256];

    if (gray_image_alloc(&ref, RW, RH, 8) != 0 || gray_image_alloc(&mov, RW, RH, 8) != 0 ||
        gray_image_alloc(&out, RW, RH, 8) != 0) {
        goto done;
    }
    for (y = 0; y < RH; y++) {
        for (x = 0; x < RW; x++) {
            /* MOV(x, y) = 0.85 REF(X, Y) + 20 where truth(X, Y) = (x, y) */
            double X = x, Y = y, u, v;
            int it;
            for (it = 0; it < 30; it++) {
                truth(X, Y, &u, &v);
                X -= u - x;
                Y -= v - y;
            }
            ((uint8_t *)ref.pixels)[(size_t)y * ref.stride + x] = (uint8_t)lround(land(x, y));
            ((uint8_t *)mov.pixels)[(size_t)y * mov.stride + x] =
                (uint8_t)lround(GAIN * land(X, Y) + OFFS);
        }
    }
    (void)gray_image_view(&ref, &vr);
    (void)gray_image_view(&mov, &vm);
    (void)ssda_source_init_view(&sref, &vr);
    (void)ssda_source_init_view(&smov, &vm);
    memset(&rc_cfg, 0, sizeof rc_cfg);
    rc_cfg.search = 64; /* +-22 px around each window: the shift is unknown */
    if (ssda_register_points(&sref, &smov, &rc_cfg, pts, 16, &accepted, work, sizeof work) !=
        SSDA_OK) {
        goto done;
    }
    for (k = 0; k < 16; k++) {
        if (pts[k].status == SSDA_REGISTER_OK) {
            pairs[n++] = pts[k].pair;
        }
    }
    if (ssda_poly_fit(pairs, n, RW, RH, &fc, &map, res, used, &fit, work_fit, sizeof work_fit) !=
        SSDA_OK) {
        printf("   too few control points (%zu)\n", n);
        goto done;
    }
    /* the moving band streamed in 3 000 bytes of plate + a 480-byte row */
    memset(&scfg, 0, sizeof scfg);
    dev.img = &mov;
    scfg.read = dev_read;
    scfg.context = &dev;
    scfg.width = RW;
    scfg.height = RH;
    scfg.format = SSDA_PIX_U8;
    scfg.arena = arena;
    scfg.arena_size = sizeof arena;
    memset(&wc, 0, sizeof wc);
    wc.map = &map;
    wc.sink = sink;
    wc.context = &out;
    wc.row = rowbuf;
    wc.row_size = sizeof rowbuf;
    wc.resample = SSDA_WARP_BILINEAR;
    if (ssda_source_init(&sstr, &scfg) != SSDA_OK || ssda_warp_init(&job, &wc, &sstr) != SSDA_OK ||
        ssda_warp_run(&job, NULL) != SSDA_OK) {
        goto done;
    }
    for (j = 0; j <= 10; j++) {
        for (i = 0; i <= 10; i++) {
            const double X = 20 + (RW - 40) * i / 10.0, Y = 20 + (RH - 40) * j / 10.0;
            double tx, ty, fx, fy, d;
            truth(X, Y, &tx, &ty);
            poly_eval_double(&map, X, Y, &fx, &fy);
            d = hypot(fx - tx, fy - ty);
            worst = d > worst ? d : worst;
            sum2 += d * d;
            cnt++;
        }
    }
    if (!c->quiet) {
        printf("   input: a %d x %d 8-bit scene; the second band is it seen through a known\n"
               "   2nd-order map (shift (11.4, -7.2) px, rotation 0.75 deg, scale 1.006, a bow)\n"
               "   with gain 0.85 and offset +20\n",
               RW, RH);
        printf("   control points: %zu of 16 cells accepted (|rho| > 0.65, 20 x 20 in 64 x 64, sub-pixel)\n",
               accepted);
        printf("   fit (order 2, exact integer normal equations, Cholesky + refinement):\n"
               "     %u pairs used, %u rejected, RMS residual %.3f px, max %.3f px\n",
               fit.used, fit.rejected, fit.rms_q8 / 256.0, fit.max_q8 / 256.0);
        printf("   the map against the truth on an 11 x 11 grid: RMS %.3f px, max %.3f px\n",
               sqrt(sum2 / cnt), worst);
        printf("   resampled (bilinear) from a streamed source: %zu bytes of plate, read %llu bytes "
               "(%.2f x the image)\n",
               sizeof arena, (unsigned long long)sstr.stats.bytes_read,
               (double)sstr.stats.bytes_read / (RW * RH));
    }
    /* the pictures: flicker (the seed's 15 Hz view) and a checkerboard */
    if (img_display8(&ref, &d_ref) != 0 || img_display8(&out, &d_out) != 0) {
        goto done;
    }
    {
        const gray_image_t *frames[2] = {&d_ref, &d_out};
        FILE *f = fopen(demo_path(c, "bands_flicker.gif", path, sizeof path), "wb");
        if (f == NULL || img_write_flicker_gif(f, frames, 2, 7, e, sizeof e) != 0) {
            fprintf(stderr, "ssda-demo: cannot write %s\n", path);
            if (f != NULL) {
                fclose(f);
            }
            goto done;
        }
        fclose(f);
        printf("   %s: the two bands alternating at about 15 Hz\n", path);
    }
    if (img_checkerboard(&d_ref, &d_out, 32, &comp) != 0 ||
        png_write_gray(demo_path(c, "bands_checker.png", path, sizeof path), &comp, e, sizeof e) !=
            0) {
        goto done;
    }
    printf("   %s: 32 px squares of each band\n", path);
    rc = 0;
done:
    gray_image_free(&ref);
    gray_image_free(&mov);
    gray_image_free(&out);
    gray_image_free(&d_ref);
    gray_image_free(&d_out);
    gray_image_free(&comp);
    return rc;
}
