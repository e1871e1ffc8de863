/* cref.c - the C side of the Python binding's tests: runs one library call
   on raw input files and prints every field of its result as text, so that
   the tests compare the binding's results with the C library's, field for
   field. Options are name=value pairs naming config struct fields.

   cref match  AREA W H WIN W H BPP [opts]   one line: x y sad exact pixel_ops positions completed
   cref sad_at AREA W H WIN W H BPP X Y      one line: sad
   cref track  FIRST SECOND W H BPP [opts]   grid line, stats line, then one line per window:
                                             sad dx dy x y status exact
   cref grad   IN W H BPP OUT_BPP SHIFT OUT  writes OUT (packed samples); prints saturated
   cref ncc    AREA W H WIN W H BPP [opts]   one line: x y rho_q30 flags pixel_ops positions
                                             completed [9 around_q30 values with AROUND]
   cref ncc_at AREA W H WIN W H BPP X Y      one line: rho_q30
   cref pitch  SAMPLES N RATE [opts]         one line per estimate: frame center lag
                                             period_q16 f0_q16 diffs confidence_q15 voiced dip silent
   cref kl     IMG W H BPP CH [opts]         (opts: kl config fields, nodata=N) lines: matrix_q30 (9),
                                             vec_q30 (9), lambda_q16, zvar_q16, mean_q8 (3 each),
                                             count masked sweeps clamped; then Z1, Z2, Z3 (h w each)
   cref mix    HIST BINS RULE BAND [opts]    line: count loglik bic bins total iterations fit;
                                             one line per component: weight mean sigma (Q16);
                                             then the lut (bins) and the band pixels (count)
   cref region LABELS W H OP                 the output labels (h w), then 256 counts
   cref composite REF W H NEXT W H BPP [opts] totals line: cols rows count ok origin
                                             mean_rho_q30 pixel_ops; then per template:
                                             var dx dy rho_q30 x y status origin
   cref relax  DX DY ST COLS ROWS FRAC [opts] (ST "-": all valid) one line per node:
                                             dx_q8 dy_q8 p_q15 cls flags
   cref median DX DY ST COLS ROWS FRAC [opts] the same for ssda_relax_median
   cref polyfit PAIRS N W H ORDER MAXRES     line: rms max cond used rejected refinements within leverage weak;
                                             line: u_q24 (10) v_q24 (10) cx cy kx ky order;
                                             then per pair: residual used; then u v at (W/3, H/4)
   cref shade  IMGS N W H BPP MODE [CX CY]   line: k_q8 (9) centre_x centre_y centre_q8 images;
                                             then the corrected images (N H rows of W)
   Files are raw native-order samples, rows packed. Exit 0, or 1 with the
   library's error code printed ("error N"). */
#include "ssda/composite.h"
#include "ssda/grad.h"
#include "ssda/kl.h"
#include "ssda/mixture.h"
#include "ssda/region.h"
#include "ssda/match.h"
#include "ssda/ncc.h"
#include "ssda/pitch.h"
#include "ssda/poly.h"
#include "ssda/relax.h"
#include "ssda/shade.h"
#include "ssda/track.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *name;
    size_t offset;
    int size; /* bytes; negative: signed */
} field_t;

#define F(type, member, size) {#member, offsetof(type, member), size}

static const field_t match_fields[] = {
    F(ssda_match_config_t, threshold, 1), F(ssda_match_config_t, scan, 1),
    F(ssda_match_config_t, order, 1),     F(ssda_match_config_t, flags, 1),
    F(ssda_match_config_t, k_q8, 2),      F(ssda_match_config_t, coarse_step, 2),
    F(ssda_match_config_t, lambda_q8, 4), F(ssda_match_config_t, fixed_threshold, 8),
    F(ssda_match_config_t, predict_x, -4), F(ssda_match_config_t, predict_y, -4),
    {NULL, 0, 0}};

static const field_t ncc_fields[] = {
    F(ssda_ncc_config_t, metric, 1), F(ssda_ncc_config_t, flags, 1),
    F(ssda_ncc_config_t, radius, 2), F(ssda_ncc_config_t, predict_x, -4),
    F(ssda_ncc_config_t, predict_y, -4), {NULL, 0, 0}};

static const field_t track_fields[] = {
    F(ssda_track_config_t, win_w, 2),   F(ssda_track_config_t, win_h, 2),
    F(ssda_track_config_t, search_w, 2), F(ssda_track_config_t, search_h, 2),
    F(ssda_track_config_t, step_x, 2),  F(ssda_track_config_t, step_y, 2),
    F(ssda_track_config_t, roi_x, 2),   F(ssda_track_config_t, roi_y, 2),
    F(ssda_track_config_t, roi_w, 2),   F(ssda_track_config_t, roi_h, 2),
    F(ssda_track_config_t, predict, 1), F(ssda_track_config_t, flags, 1),
    F(ssda_track_config_t, mask_value, 2), F(ssda_track_config_t, texture_threshold, 2),
    F(ssda_track_config_t, texture_min_count, 4), F(ssda_track_config_t, flat_q8, 4),
    F(ssda_track_config_t, unique_q8, 2), F(ssda_track_config_t, unique_radius, 1),
    {NULL, 0, 0}};

static const field_t pitch_fields[] = {
    F(ssda_pitch_config_t, f0_min_hz, 2),  F(ssda_pitch_config_t, f0_max_hz, 2),
    F(ssda_pitch_config_t, frame_len, 2),  F(ssda_pitch_config_t, hop, 2),
    F(ssda_pitch_config_t, threshold_q15, 2), F(ssda_pitch_config_t, voicing_q15, 2),
    F(ssda_pitch_config_t, silence_mad, 2), F(ssda_pitch_config_t, chunk, 2),
    F(ssda_pitch_config_t, lowpass_hz, 2), F(ssda_pitch_config_t, flags, 1),
    {NULL, 0, 0}};

static const field_t kl_fields[] = {
    F(ssda_kl_config_t, matrix, 1), F(ssda_kl_config_t, range, 1),
    F(ssda_kl_config_t, nsigma, 1), F(ssda_kl_config_t, out_max, 2),
    F(ssda_kl_config_t, gain_max_q16, 4), {NULL, 0, 0}};

static const field_t mix_fields[] = {
    F(ssda_mix_config_t, components, 1), F(ssda_mix_config_t, max_components, 1),
    F(ssda_mix_config_t, fit, 1), F(ssda_mix_config_t, init, 1),
    F(ssda_mix_config_t, flags, 1), F(ssda_mix_config_t, max_iter, 2),
    F(ssda_mix_config_t, sigma_min_q16, 4), F(ssda_mix_config_t, tol_q24, 4), {NULL, 0, 0}};

static const field_t composite_fields[] = {
    F(ssda_composite_config_t, tp, 2), F(ssda_composite_config_t, step, 2),
    F(ssda_composite_config_t, roi_x, 2), F(ssda_composite_config_t, roi_y, 2),
    F(ssda_composite_config_t, roi_w, 2), F(ssda_composite_config_t, roi_h, 2),
    F(ssda_composite_config_t, radius_q8, 2), F(ssda_composite_config_t, min_radius, 2),
    F(ssda_composite_config_t, min_std_q8, 2), F(ssda_composite_config_t, metric, 1),
    F(ssda_composite_config_t, flags, 1), {NULL, 0, 0}};

static const field_t relax_fields[] = {
    F(ssda_relax_config_t, iterations, 2), F(ssda_relax_config_t, len_step_q8, 2),
    F(ssda_relax_config_t, flags, 1), {NULL, 0, 0}};

static const field_t median_fields[] = {
    F(ssda_relax_median_config_t, threshold_q8, 2), F(ssda_relax_median_config_t, eps_q8, 2),
    {NULL, 0, 0}};

/* name=value into the struct at base; prefix "m." addresses the match
   options inside a track config. Returns 0, or -1 for an unknown name. */
static int set_field(void *base, const field_t *fields, const char *arg)
{
    const char *eq = strchr(arg, '=');
    const field_t *f;
    long long v;
    if (eq == NULL) {
        return -1;
    }
    v = strtoll(eq + 1, NULL, 0);
    for (f = fields; f->name != NULL; f++) {
        if (strlen(f->name) == (size_t)(eq - arg) && strncmp(f->name, arg, (size_t)(eq - arg)) == 0) {
            char *p = (char *)base + f->offset;
            switch (f->size) {
            case 1: *(uint8_t *)p = (uint8_t)v; break;
            case 2: *(uint16_t *)p = (uint16_t)v; break;
            case 4: *(uint32_t *)p = (uint32_t)v; break;
            case -4: *(int32_t *)p = (int32_t)v; break;
            default: *(uint64_t *)p = (uint64_t)strtoull(eq + 1, NULL, 0); break;
            }
            return 0;
        }
    }
    return -1;
}

static void *load(const char *path, size_t bytes)
{
    FILE *f = fopen(path, "rb");
    void *p = malloc(bytes > 0 ? bytes : 1);
    if (f == NULL || p == NULL || fread(p, 1, bytes, f) != bytes) {
        fprintf(stderr, "cref: cannot read %zu bytes of %s\n", bytes, path);
        exit(2);
    }
    fclose(f);
    return p;
}

static int fail(int e)
{
    printf("error %d\n", e);
    return 1;
}

static int view(ssda_view_t *v, const void *data, const char *w, const char *h, int bpp)
{
    unsigned long width = strtoul(w, NULL, 0), height = strtoul(h, NULL, 0);
    return ssda_view_init(v, data, (uint16_t)width, (uint16_t)height,
                          (uint32_t)(width * (unsigned long)bpp),
                          bpp == 1 ? SSDA_PIX_U8 : SSDA_PIX_U16);
}

static size_t bytes_of(const char *w, const char *h, int bpp)
{
    return (size_t)strtoul(w, NULL, 0) * strtoul(h, NULL, 0) * (size_t)bpp;
}

static int run_match(int argc, char **argv)
{
    int bpp = atoi(argv[8]), i, e;
    void *a = load(argv[2], bytes_of(argv[3], argv[4], bpp));
    void *w = load(argv[5], bytes_of(argv[6], argv[7], bpp));
    ssda_view_t va, vw;
    ssda_match_config_t cfg;
    ssda_match_result_t r;
    if ((e = view(&va, a, argv[3], argv[4], bpp)) != SSDA_OK ||
        (e = view(&vw, w, argv[6], argv[7], bpp)) != SSDA_OK) {
        return fail(e);
    }
    if (strcmp(argv[1], "sad_at") == 0) {
        uint64_t sad;
        e = ssda_sad_at(&va, &vw, (uint16_t)atoi(argv[9]), (uint16_t)atoi(argv[10]), &sad);
        if (e != SSDA_OK) {
            return fail(e);
        }
        printf("%llu\n", (unsigned long long)sad);
        return 0;
    }
    memset(&cfg, 0, sizeof cfg);
    for (i = 9; i < argc; i++) {
        if (set_field(&cfg, match_fields, argv[i]) != 0) {
            fprintf(stderr, "cref: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if (cfg.flags & SSDA_MATCH_BLOCKS) {
        cfg.work_size = SSDA_MATCH_WORK_SIZE_BLOCKS(va.width, va.height, vw.width, vw.height);
        cfg.work = malloc(cfg.work_size);
    } else if (cfg.flags & SSDA_MATCH_BOUNDS) {
        cfg.work_size = SSDA_MATCH_WORK_SIZE(va.width, va.height, vw.width, vw.height);
        cfg.work = malloc(cfg.work_size);
    }
    if ((e = ssda_match(&va, &vw, &cfg, &r)) != SSDA_OK) {
        return fail(e);
    }
    printf("%u %u %llu %d %llu %u %u\n", r.x, r.y, (unsigned long long)r.sad, r.exact ? 1 : 0,
           (unsigned long long)r.pixel_ops, r.positions, r.completed);
    return 0;
}

static int run_ncc(int argc, char **argv)
{
    int bpp = atoi(argv[8]), i, e;
    void *a = load(argv[2], bytes_of(argv[3], argv[4], bpp));
    void *w = load(argv[5], bytes_of(argv[6], argv[7], bpp));
    ssda_view_t va, vw;
    ssda_ncc_config_t cfg;
    ssda_ncc_result_t r;
    if ((e = view(&va, a, argv[3], argv[4], bpp)) != SSDA_OK ||
        (e = view(&vw, w, argv[6], argv[7], bpp)) != SSDA_OK) {
        return fail(e);
    }
    if (strcmp(argv[1], "ncc_at") == 0) {
        int32_t rho;
        e = ssda_ncc_at(&va, &vw, (uint16_t)atoi(argv[9]), (uint16_t)atoi(argv[10]), &rho);
        if (e != SSDA_OK) {
            return fail(e);
        }
        printf("%d\n", (int)rho);
        return 0;
    }
    memset(&cfg, 0, sizeof cfg);
    for (i = 9; i < argc; i++) {
        if (set_field(&cfg, ncc_fields, argv[i]) != 0) {
            fprintf(stderr, "cref: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    cfg.work_size = SSDA_NCC_WORK_SIZE(va.width, vw.width, vw.height);
    cfg.work = malloc(cfg.work_size); /* malloc: aligned for any type */
    if ((e = ssda_ncc_match(&va, &vw, &cfg, &r)) != SSDA_OK) {
        return fail(e);
    }
    printf("%u %u %d %u %llu %u %u", r.x, r.y, (int)r.rho_q30, r.flags,
           (unsigned long long)r.pixel_ops, r.positions, r.completed);
    for (i = 0; (cfg.flags & SSDA_NCC_AROUND) != 0u && i < 9; i++) {
        printf(" %d", (int)r.around_q30[i]);
    }
    printf("\n");
    return 0;
}

static int run_track(int argc, char **argv)
{
    int bpp = atoi(argv[6]), i, e;
    size_t bytes = bytes_of(argv[4], argv[5], bpp);
    void *a = load(argv[2], bytes), *b = load(argv[3], bytes);
    ssda_view_t va, vb;
    ssda_track_config_t cfg;
    ssda_track_grid_t g;
    ssda_track_stats_t s;
    ssda_track_vector_t *v;
    if ((e = view(&va, a, argv[4], argv[5], bpp)) != SSDA_OK ||
        (e = view(&vb, b, argv[4], argv[5], bpp)) != SSDA_OK) {
        return fail(e);
    }
    memset(&cfg, 0, sizeof cfg);
    for (i = 7; i < argc; i++) {
        int rc = strncmp(argv[i], "m.", 2) == 0 ? set_field(&cfg.match, match_fields, argv[i] + 2)
                                                : set_field(&cfg, track_fields, argv[i]);
        if (rc != 0) {
            fprintf(stderr, "cref: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if ((e = ssda_track_grid(&cfg, vb.width, vb.height, &g)) != SSDA_OK) {
        return fail(e);
    }
    if ((cfg.match.flags & SSDA_MATCH_BOUNDS) || (cfg.flags & SSDA_TRACK_UNIQUE)) {
        cfg.match.work_size = SSDA_TRACK_WORK_SIZE(g.search_w, g.search_h, g.win_w, g.win_h);
        cfg.match.work = malloc(cfg.match.work_size); /* malloc: 8-byte aligned */
    }
    v = calloc(g.count, sizeof *v);
    if ((e = ssda_track(&va, &vb, &cfg, v, g.count, &s)) != SSDA_OK) {
        return fail(e);
    }
    printf("%u %u %u\n", g.count, g.cols, g.rows);
    printf("%llu %llu %llu %llu %u %u %u %u %u %u %u %u\n", (unsigned long long)s.pixel_ops,
           (unsigned long long)s.positions, (unsigned long long)s.completed,
           (unsigned long long)s.check_pixels, s.windows, s.ok, s.excluded, s.masked, s.edge,
           s.flat, s.ambiguous, s.at_limit);
    for (i = 0; i < (int)g.count; i++) {
        printf("%llu %d %d %d %d %u %u %u %u %u %d\n", (unsigned long long)v[i].sad,
               (int)v[i].dx, (int)v[i].dy, (int)v[i].sub_dx_q8, (int)v[i].sub_dy_q8,
               (unsigned)v[i].texture_q8, v[i].x, v[i].y, v[i].unique_q8, v[i].status,
               v[i].exact ? 1 : 0);
    }
    return 0;
}

static int run_grad(char **argv)
{
    int bpp = atoi(argv[5]), obpp = atoi(argv[6]), e;
    void *in = load(argv[2], bytes_of(argv[3], argv[4], bpp));
    ssda_view_t v;
    ssda_grad_out_t go;
    uint32_t sat = 0;
    FILE *f;
    if ((e = view(&v, in, argv[3], argv[4], bpp)) != SSDA_OK) {
        return fail(e);
    }
    memset(&go, 0, sizeof go);
    go.format = (uint8_t)obpp;
    go.shift = (uint8_t)atoi(argv[7]);
    go.size = SSDA_GRAD_SIZE(v.width, v.height, go.format);
    go.data = malloc(go.size);
    if ((e = ssda_grad(&v, &go, &sat)) != SSDA_OK) {
        return fail(e);
    }
    f = fopen(argv[8], "wb");
    if (f == NULL || fwrite(go.data, 1, go.size, f) != go.size || fclose(f) != 0) {
        return 2;
    }
    printf("%u\n", sat);
    return 0;
}

static int run_pitch(int argc, char **argv)
{
    size_t n = strtoul(argv[3], NULL, 0), pos = 0, used, bytes;
    int16_t *x = load(argv[2], n * sizeof *x);
    ssda_pitch_config_t cfg;
    ssda_pitch_t p;
    ssda_pitch_estimate_t est;
    int i, e;
    void *buf;
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = (uint32_t)strtoul(argv[4], NULL, 0);
    for (i = 5; i < argc; i++) {
        if (set_field(&cfg, pitch_fields, argv[i]) != 0) {
            fprintf(stderr, "cref: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if ((e = ssda_pitch_buffer_size(&cfg, &bytes)) != SSDA_OK) {
        return fail(e);
    }
    buf = malloc(bytes);
    if ((e = ssda_pitch_init(&p, &cfg, buf, bytes)) != SSDA_OK) {
        return fail(e);
    }
    while (pos < n) {
        e = ssda_pitch_push(&p, x + pos, n - pos, &used, &est);
        if (e < 0) {
            return fail(e);
        }
        pos += used;
        if (e == 1) {
            printf("%u %u %u %u %u %u %u %d %d %d\n", est.frame, est.center, est.lag,
                   est.period_q16, est.f0_q16, est.diffs, est.confidence_q15,
                   est.voiced ? 1 : 0, est.dip ? 1 : 0, est.silent ? 1 : 0);
        }
    }
    return 0;
}

static int run_kl(int argc, char **argv)
{
    const size_t w = strtoul(argv[3], NULL, 0), h = strtoul(argv[4], NULL, 0);
    const int bpp = atoi(argv[5]), ch = atoi(argv[6]);
    const uint8_t *img = load(argv[2], w * h * (size_t)bpp * (size_t)ch);
    uint16_t *z = malloc(3u * (w * h > 0 ? w * h : 1u) * sizeof *z);
    ssda_kl_acc_config_t ac;
    ssda_kl_config_t kc;
    ssda_kl_acc_t acc;
    ssda_kl_t kl;
    uint32_t clamped = 0;
    size_t y, k;
    int i, e;
    memset(&ac, 0, sizeof ac);
    memset(&kc, 0, sizeof kc);
    ac.format = bpp == 1 ? SSDA_PIX_U8 : SSDA_PIX_U16;
    for (i = 7; i < argc; i++) {
        if (strncmp(argv[i], "nodata=", 7) == 0) {
            ac.flags = SSDA_KL_MASK_NODATA;
            ac.nodata = (uint16_t)strtoul(argv[i] + 7, NULL, 0);
        } else if (set_field(&kc, kl_fields, argv[i]) != 0) {
            fprintf(stderr, "cref: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if ((e = ssda_kl_acc_init(&acc, &ac)) != SSDA_OK) {
        return fail(e);
    }
    for (y = 0; y < h; y++) { /* planar rows through band pointers, step ch */
        const uint8_t *p = img + y * w * (size_t)ch * (size_t)bpp;
        const ssda_kl_row_t row = {{p, p + bpp, p + 2 * bpp}, (uint32_t)ch};
        if ((e = ssda_kl_acc_add_row(&acc, &row, (uint32_t)w)) != SSDA_OK) {
            return fail(e);
        }
    }
    if ((e = ssda_kl_solve(&acc, &kc, &kl)) != SSDA_OK) {
        return fail(e);
    }
    for (y = 0; y < h; y++) {
        const uint8_t *p = img + y * w * (size_t)ch * (size_t)bpp;
        const ssda_kl_row_t row = {{p, p + bpp, p + 2 * bpp}, (uint32_t)ch};
        uint16_t *const out[3] = {z + y * w, z + (h + y) * w, z + (2u * h + y) * w};
        if ((e = ssda_kl_transform_row(&kl, &row, (uint32_t)w, out, &clamped)) != SSDA_OK) {
            return fail(e);
        }
    }
    for (i = 0; i < 9; i++) {
        printf("%d%c", (int)kl.matrix_q30[i / 3][i % 3], i == 8 ? '\n' : ' ');
    }
    for (i = 0; i < 9; i++) {
        printf("%d%c", (int)kl.vec_q30[i / 3][i % 3], i == 8 ? '\n' : ' ');
    }
    printf("%llu %llu %llu\n", (unsigned long long)kl.lambda_q16[0],
           (unsigned long long)kl.lambda_q16[1], (unsigned long long)kl.lambda_q16[2]);
    printf("%llu %llu %llu\n", (unsigned long long)kl.zvar_q16[0],
           (unsigned long long)kl.zvar_q16[1], (unsigned long long)kl.zvar_q16[2]);
    printf("%u %u %u\n", kl.mean_q8[0], kl.mean_q8[1], kl.mean_q8[2]);
    printf("%u %u %u %u\n", kl.count, acc.masked, kl.sweeps, clamped);
    for (k = 0; k < 3u * h; k++) {
        for (y = 0; y < w; y++) {
            printf("%u%c", z[k * w + y], y + 1 == w ? '\n' : ' ');
        }
    }
    return 0;
}

static int run_mix(int argc, char **argv)
{
    const uint32_t bins = (uint32_t)strtoul(argv[3], NULL, 0);
    const uint32_t *hist = load(argv[2], (size_t)bins * 4u);
    const uint8_t rule = (uint8_t)atoi(argv[4]);
    const uint32_t band = (uint32_t)strtoul(argv[5], NULL, 0);
    ssda_mix_config_t cfg;
    ssda_mix_model_t m;
    uint8_t *lut = malloc(bins > 0 ? bins : 1u);
    uint32_t px[SSDA_MIX_MAX_COMPONENTS], j;
    void *work = malloc(SSDA_MIX_WORK_SIZE(bins));
    int i, e;
    memset(&cfg, 0, sizeof cfg);
    for (i = 6; i < argc; i++) {
        if (set_field(&cfg, mix_fields, argv[i]) != 0) {
            fprintf(stderr, "cref: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    if ((e = ssda_mix_fit(hist, bins, &cfg, work, SSDA_MIX_WORK_SIZE(bins), &m)) != SSDA_OK ||
        (e = ssda_mix_lut(&m, rule, band, lut)) != SSDA_OK ||
        (e = ssda_mix_band_pixels(&m, hist, band, px)) != SSDA_OK) {
        return fail(e);
    }
    printf("%u %lld %lld %u %u %u %u\n", m.count, (long long)m.loglik_q16, (long long)m.bic_q16,
           m.bins, m.total, m.iterations, m.fit);
    for (j = 0; j < m.count; j++) {
        printf("%u %u %u\n", m.comp[j].weight_q16, m.comp[j].mean_q16, m.comp[j].sigma_q16);
    }
    for (j = 0; j < bins; j++) {
        printf("%u%c", lut[j], j + 1 == bins ? '\n' : ' ');
    }
    for (j = 0; j < m.count; j++) {
        printf("%u%c", px[j], j + 1 == m.count ? '\n' : ' ');
    }
    return 0;
}

static int run_region(char **argv)
{
    const uint32_t w = (uint32_t)strtoul(argv[3], NULL, 0), h = (uint32_t)strtoul(argv[4], NULL, 0);
    const uint8_t *in = load(argv[2], (size_t)w * h);
    uint8_t *out = malloc((size_t)w * h + 1u), *ring = malloc(SSDA_REGION_RING_SIZE(w) + 1u);
    uint32_t counts[256] = {0}, y, done = 0;
    ssda_region_config_t rc;
    ssda_region_t job;
    int e;
    rc.width = (uint16_t)w;
    rc.height = (uint16_t)h;
    rc.op = (uint8_t)atoi(argv[5]);
    rc.counts = counts;
    if ((e = ssda_region_init(&job, &rc, ring, SSDA_REGION_RING_SIZE(w))) != SSDA_OK) {
        return fail(e);
    }
    for (y = 0; y < h; y++) {
        if ((e = ssda_region_push(&job, in + (size_t)y * w, out + (size_t)done * w)) < 0) {
            return fail(e);
        }
        done += (uint32_t)e;
    }
    if ((e = ssda_region_flush(&job, out + (size_t)done * w)) < 0) {
        return fail(e);
    }
    for (y = 0; y < w * h; y++) {
        printf("%u%c", out[y], (y + 1) % w == 0 ? '\n' : ' ');
    }
    for (y = 0; y < 256; y++) {
        printf("%u%c", counts[y], y == 255 ? '\n' : ' ');
    }
    return 0;
}

static int run_composite(int argc, char **argv)
{
    int bpp = atoi(argv[8]), i, e;
    void *a = load(argv[2], bytes_of(argv[3], argv[4], bpp));
    void *b = load(argv[5], bytes_of(argv[6], argv[7], bpp));
    ssda_view_t vr, vn;
    ssda_composite_config_t cfg;
    ssda_composite_result_t r;
    ssda_composite_tp_t *tp;
    size_t n;
    uint32_t k;
    if ((e = view(&vr, a, argv[3], argv[4], bpp)) != SSDA_OK ||
        (e = view(&vn, b, argv[6], argv[7], bpp)) != SSDA_OK) {
        return fail(e);
    }
    memset(&cfg, 0, sizeof cfg);
    for (i = 9; i < argc; i++) {
        if (set_field(&cfg, composite_fields, argv[i]) != 0) {
            fprintf(stderr, "cref: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    n = (size_t)vr.width * vr.height; /* more than any grid */
    tp = malloc(n * sizeof *tp);
    cfg.work_size = SSDA_COMPOSITE_WORK_SIZE(vn.width, cfg.tp != 0u ? cfg.tp : 20u);
    cfg.work = malloc(cfg.work_size); /* malloc: aligned for any type */
    if ((e = ssda_composite_match(&vr, &vn, &cfg, tp, n, &r)) != SSDA_OK) {
        return fail(e);
    }
    printf("%u %u %u %u %u %d %llu\n", r.cols, r.rows, r.count, r.ok, r.origin,
           (int)r.mean_rho_q30, (unsigned long long)r.pixel_ops);
    for (k = 0; k < r.count; k++) {
        printf("%llu %d %d %d %u %u %u %u\n", (unsigned long long)tp[k].var, (int)tp[k].dx,
               (int)tp[k].dy, (int)tp[k].rho_q30, tp[k].x, tp[k].y, tp[k].status, tp[k].origin);
    }
    return 0;
}

/* A node in another layout than the binding's (status between the two). */
typedef struct {
    int32_t dx;
    uint8_t status;
    int32_t dy;
} cref_node_t;

static int run_relax(int argc, char **argv)
{
    const size_t cols = strtoul(argv[5], NULL, 0), rows = strtoul(argv[6], NULL, 0);
    const size_t n = cols * rows;
    int32_t *dx = load(argv[2], n * 4u), *dy = load(argv[3], n * 4u);
    uint8_t *st = strcmp(argv[4], "-") == 0 ? NULL : load(argv[4], n);
    cref_node_t *node = malloc((n > 0 ? n : 1) * sizeof *node);
    ssda_relax_vector_t *out = malloc((n > 0 ? n : 1) * sizeof *out);
    ssda_relax_grid_t g;
    size_t k;
    int i, e;
    for (k = 0; k < n; k++) {
        node[k].dx = dx[k];
        node[k].dy = dy[k];
        node[k].status = st != NULL ? st[k] : 0u;
    }
    g.dx = &node[0].dx;
    g.dy = &node[0].dy;
    g.status = st != NULL ? &node[0].status : NULL;
    g.stride = sizeof *node;
    g.cols = (uint16_t)cols;
    g.rows = (uint16_t)rows;
    g.frac_bits = (uint8_t)atoi(argv[7]);
    if (strcmp(argv[1], "relax") == 0) {
        ssda_relax_config_t cfg;
        memset(&cfg, 0, sizeof cfg);
        for (i = 8; i < argc; i++) {
            if (set_field(&cfg, relax_fields, argv[i]) != 0) {
                fprintf(stderr, "cref: unknown option %s\n", argv[i]);
                return 2;
            }
        }
        cfg.work_size = SSDA_RELAX_WORK_SIZE(cols, rows);
        cfg.work = malloc(cfg.work_size);
        e = ssda_relax_labels(&g, &cfg, out, n);
    } else {
        ssda_relax_median_config_t cfg;
        memset(&cfg, 0, sizeof cfg);
        for (i = 8; i < argc; i++) {
            if (set_field(&cfg, median_fields, argv[i]) != 0) {
                fprintf(stderr, "cref: unknown option %s\n", argv[i]);
                return 2;
            }
        }
        e = ssda_relax_median(&g, &cfg, out, n);
    }
    if (e != SSDA_OK) {
        return fail(e);
    }
    for (k = 0; k < n; k++) {
        printf("%d %d %u %u %u\n", (int)out[k].dx_q8, (int)out[k].dy_q8, out[k].p_q15,
               out[k].cls, out[k].flags);
    }
    return 0;
}

static int run_polyfit(char **argv)
{
    const size_t n = strtoul(argv[3], NULL, 0);
    const ssda_poly_pair_t *pairs = load(argv[2], n * sizeof *pairs);
    const uint16_t w = (uint16_t)strtoul(argv[4], NULL, 0), h = (uint16_t)strtoul(argv[5], NULL, 0);
    ssda_poly_fit_config_t cfg = {(uint8_t)atoi(argv[6]), (uint32_t)strtoul(argv[7], NULL, 0)};
    ssda_poly_t p;
    ssda_poly_fit_result_t r;
    uint32_t *res = malloc((n + 1u) * 4u);
    uint8_t *used = malloc(n + 1u), *work = malloc(n + 1u);
    int32_t u, v;
    size_t k;
    int e;
    if ((e = ssda_poly_fit(pairs, n, w, h, &cfg, &p, res, used, &r, work, n)) != SSDA_OK) {
        return fail(e);
    }
    printf("%u %u %u %u %u %u %d %u %d\n", r.rms_q8, r.max_q8, r.cond, r.used, r.rejected,
           r.refinements, r.within_bound ? 1 : 0, r.max_leverage_q15, r.weak ? 1 : 0);
    for (k = 0; k < 10; k++) {
        printf("%lld ", (long long)p.u_q24[k]);
    }
    for (k = 0; k < 10; k++) {
        printf("%lld ", (long long)p.v_q24[k]);
    }
    printf("%d %d %u %u %u\n", (int)p.cx, (int)p.cy, p.kx, p.ky, p.order);
    for (k = 0; k < n; k++) {
        printf("%u %u\n", res[k], used[k]);
    }
    if ((e = ssda_poly_eval(&p, w / 3, h / 4, &u, &v)) != SSDA_OK) {
        return fail(e);
    }
    printf("%d %d\n", (int)u, (int)v);
    return 0;
}

static int run_shade(int argc, char **argv)
{
    const size_t n = strtoul(argv[3], NULL, 0), w = strtoul(argv[4], NULL, 0);
    const size_t h = strtoul(argv[5], NULL, 0), bpp = strtoul(argv[6], NULL, 0);
    const uint8_t *in = load(argv[2], n * w * h * bpp);
    uint8_t *out = malloc(n * w * h * bpp + 1u);
    ssda_shade_t sh;
    size_t i, y, x;
    int e, k;
    if ((e = ssda_shade_init(&sh, (uint16_t)w, (uint16_t)h,
                             bpp == 1 ? SSDA_PIX_U8 : SSDA_PIX_U16)) != SSDA_OK) {
        return fail(e);
    }
    for (i = 0; i < n * h; i++) {
        if ((e = ssda_shade_add_row(&sh, in + i * w * bpp)) != SSDA_OK) {
            return fail(e);
        }
    }
    if ((e = ssda_shade_finish(&sh, (uint8_t)atoi(argv[7]))) != SSDA_OK ||
        (argc == 10 && (e = ssda_shade_set_centre(&sh, (uint16_t)atoi(argv[8]),
                                                  (uint16_t)atoi(argv[9]))) != SSDA_OK)) {
        return fail(e);
    }
    for (i = 0; i < n; i++) {
        for (y = 0; y < h; y++) {
            const size_t at = (i * h + y) * w * bpp;
            if ((e = ssda_shade_apply_row(&sh, (uint32_t)y, in + at, out + at)) != SSDA_OK) {
                return fail(e);
            }
        }
    }
    for (k = 0; k < 9; k++) {
        printf("%d ", (int)sh.k_q8[k]);
    }
    printf("%u %u %d %u\n", sh.centre_x, sh.centre_y, (int)sh.centre_q8, sh.images);
    for (i = 0; i < n * h; i++) {
        for (x = 0; x < w; x++) {
            const uint8_t *p = out + (i * w + x) * bpp;
            printf("%u%c", bpp == 1 ? *p : (unsigned)(*(const uint16_t *)(const void *)p),
                   x + 1 == w ? '\n' : ' ');
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 8 && strcmp(argv[1], "polyfit") == 0) {
        return run_polyfit(argv);
    }
    if ((argc == 8 || argc == 10) && strcmp(argv[1], "shade") == 0) {
        return run_shade(argc, argv);
    }
    if (argc >= 9 && strcmp(argv[1], "composite") == 0) {
        return run_composite(argc, argv);
    }
    if (argc >= 8 && (strcmp(argv[1], "relax") == 0 || strcmp(argv[1], "median") == 0)) {
        return run_relax(argc, argv);
    }
    if (argc >= 7 && strcmp(argv[1], "kl") == 0) {
        return run_kl(argc, argv);
    }
    if (argc >= 6 && strcmp(argv[1], "mix") == 0) {
        return run_mix(argc, argv);
    }
    if (argc == 6 && strcmp(argv[1], "region") == 0) {
        return run_region(argv);
    }
    if (argc >= 9 && (strcmp(argv[1], "match") == 0 ||
                      (strcmp(argv[1], "sad_at") == 0 && argc == 11))) {
        return run_match(argc, argv);
    }
    if (argc >= 9 && (strcmp(argv[1], "ncc") == 0 ||
                      (strcmp(argv[1], "ncc_at") == 0 && argc == 11))) {
        return run_ncc(argc, argv);
    }
    if (argc >= 7 && strcmp(argv[1], "track") == 0) {
        return run_track(argc, argv);
    }
    if (argc == 9 && strcmp(argv[1], "grad") == 0) {
        return run_grad(argv);
    }
    if (argc >= 5 && strcmp(argv[1], "pitch") == 0) {
        return run_pitch(argc, argv);
    }
    fprintf(stderr, "usage: see cref.c\n");
    return 2;
}
