/*
 * peers_match_main.c - ssda-peers-match: ssda against OpenCV's
 * matchTemplate on the same inputs in one process run (tools/bench-peers.sh
 * runs it; docs/benchmarks.md explains the figures). Prints Markdown.
 *
 * usage: ssda-peers-match [--reps N] [--search-reps N] [--ratios FILE]
 *            [--pair FIRST.png SECOND.png] [--pair-name NAME] [--mask V]
 *            [--image PNG]... [--size N] [--quick] [--searches-only]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cv_peer.h"
#include "peers_search.h"
#include "peers_track.h"
#include "png_io.h"
#include "ssda/ssda.h"
#include "synth_texture.h"

typedef struct {
    int reps, search_reps, size, quick, use_mask, searches_only;
    uint16_t mask;
    const char *ratios, *pair[2], *pair_name, *image[4];
    int nimage;
} options_t;

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

static int usage(void)
{
    fprintf(stderr,
            "usage: ssda-peers-match [options]\n"
            "  --reps N            repetitions of each grid-tracking run (7)\n"
            "  --search-reps N     repetitions of each single search (5)\n"
            "  --ratios FILE       write the speed ratios for the chart (TSV)\n"
            "  --pair A.png B.png  a real pair (earlier, later) to track\n"
            "  --pair-name NAME    its label (\"real pair\")\n"
            "  --mask V            fill value of the pair: windows touching it are left out\n"
            "  --image PNG         an image for single searches (e.g. camera.png), as 8-bit\n"
            "                      gray, its centre 640x480 when larger; up to 4\n"
            "  --size N            side of the synthetic tracking pair (1024)\n"
            "  --quick             3 repetitions, fewer template sizes (a smoke run)\n"
            "  --searches-only     single searches only, no grid tracking\n");
    return 2;
}

/* A synthetic pair, w x h: value noise and its smoothly moved copy. */
static int make_pair(int w, int h, unsigned seed, uint8_t **a, uint8_t **b)
{
    *a = malloc((size_t)w * (size_t)h);
    *b = malloc((size_t)w * (size_t)h);
    if (*a == NULL || *b == NULL || synth_texture(*a, w, h, seed) != 0) {
        return -1;
    }
    synth_moved(*a, *b, w, h, seed + 1u);
    return 0;
}

/* Track one pair at both geometries. */
static int track_both(peers_pair_t *p, const options_t *o, FILE *ratios)
{
    int rc = 0;
    if (o->searches_only) {
        return 0;
    }
    p->cv_first = cv_peer_image_new(&p->first);
    p->cv_second = cv_peer_image_new(&p->second);
    if (p->cv_first == NULL || p->cv_second == NULL) {
        return -1;
    }
    rc |= peers_track(p, 16, o->reps, ratios);
    rc |= peers_track(p, 32, o->reps, ratios);
    cv_peer_image_free(p->cv_first);
    cv_peer_image_free(p->cv_second);
    return rc;
}

static int search_scene(peers_scene_t *s, const options_t *o, FILE *ratios)
{
    static const unsigned full[] = {8, 16, 32, 64, 128};
    static const unsigned quick[] = {16, 64};
    int rc;
    s->cv_image = cv_peer_image_new(&s->image);
    s->cv_moved = cv_peer_image_new(&s->moved);
    if (s->cv_image == NULL || s->cv_moved == NULL) {
        return -1;
    }
    rc = o->quick ? peers_search(s, quick, 2, o->search_reps, ratios)
                  : peers_search(s, full, sizeof full / sizeof full[0], o->search_reps, ratios);
    cv_peer_image_free(s->cv_image);
    cv_peer_image_free(s->cv_moved);
    return rc;
}

/* Does the w x h rectangle at (x, y) of a 16-bit image hold the value v? */
static int holds_value(const gray_image_t *img, uint32_t x, uint32_t y, uint32_t w, uint32_t h,
                       uint32_t v)
{
    for (uint32_t j = y; j < y + h; j++) {
        for (uint32_t i = x; i < x + w; i++) {
            if (gray_image_get(img, i, j) == v) {
                return 1;
            }
        }
    }
    return 0;
}

/* Returns 0, or 2 after a message. */
static int parse_options(int argc, char **argv, options_t *o)
{
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--reps") && i + 1 < argc) o->reps = atoi(argv[++i]);
        else if (!strcmp(a, "--search-reps") && i + 1 < argc) o->search_reps = atoi(argv[++i]);
        else if (!strcmp(a, "--ratios") && i + 1 < argc) o->ratios = argv[++i];
        else if (!strcmp(a, "--pair") && i + 2 < argc) { o->pair[0] = argv[++i]; o->pair[1] = argv[++i]; }
        else if (!strcmp(a, "--pair-name") && i + 1 < argc) o->pair_name = argv[++i];
        else if (!strcmp(a, "--mask") && i + 1 < argc) { o->use_mask = 1; o->mask = (uint16_t)atoi(argv[++i]); }
        else if (!strcmp(a, "--image") && i + 1 < argc && o->nimage < 4) o->image[o->nimage++] = argv[++i];
        else if (!strcmp(a, "--size") && i + 1 < argc) o->size = atoi(argv[++i]);
        else if (!strcmp(a, "--quick")) o->quick = 1;
        else if (!strcmp(a, "--searches-only")) o->searches_only = 1;
        else return usage();
    }
    if (o->quick) {
        o->reps = o->reps > 3 ? 3 : o->reps;
        o->search_reps = o->search_reps > 3 ? 3 : o->search_reps;
    }
    if (o->reps < 1 || o->search_reps < 1 || o->size < 128 || o->size > 8192) {
        fprintf(stderr, "ssda-peers-match: --reps and --search-reps >= 1, 128 <= --size <= 8192\n");
        return 2;
    }
    return 0;
}

/* Single searches in a 640 x 480 crop of the real pair's centre, if it
   holds no fill value. */
static int search_pair_centre(const options_t *o, const gray_image_t *a, const peers_pair_t *p,
                              FILE *ratios)
{
    peers_scene_t s;
    char sdesc[512];
    uint32_t x0 = (a->width - 640) / 2, y0 = (a->height - 480) / 2;
    memset(&s, 0, sizeof s);
    s.name = o->pair_name;
    snprintf(sdesc, sizeof sdesc,
             "The 640x480 centre (from %u, %u) of the pair, %d-bit: templates from "
             "`%s`, searched in `%s`%s",
             x0, y0, a->bits, base_name(o->pair[1]), base_name(o->pair[0]),
             a->bits == 16 ? " (float32 for OpenCV, converted once)" : "");
    s.description = sdesc;
    ssda_view_roi(&s.image, &p->first, (uint16_t)x0, (uint16_t)y0, 640, 480);
    ssda_view_roi(&s.moved, &p->second, (uint16_t)x0, (uint16_t)y0, 640, 480);
    return search_scene(&s, o, ratios);
}

/* Grid tracking on the real pair (--pair), then single searches in its
   centre. Returns 0, 1 (a peer failed) or -1 (unreadable input). */
static int run_real_pair(const options_t *o, FILE *ratios, int *fatal)
{
    gray_image_t a, b;
    peers_pair_t p;
    char err[512], desc[512];
    int rc = 0;
    if (png_read_gray(o->pair[0], PNG_GRAY_NATIVE, &a, NULL, err, sizeof err) != 0 ||
        png_read_gray(o->pair[1], PNG_GRAY_NATIVE, &b, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-peers-match: %s\n", err);
        *fatal = 1;
        return 1;
    }
    if (a.bits != b.bits) {
        fprintf(stderr, "ssda-peers-match: the pair's images differ in depth\n");
        *fatal = 1;
        return 1;
    }
    memset(&p, 0, sizeof p);
    p.name = o->pair_name;
    snprintf(desc, sizeof desc,
             "`%s` -> `%s`, %ux%u, %d-bit%s%s", base_name(o->pair[0]), base_name(o->pair[1]),
             b.width, b.height, b.bits, b.bits == 16 ? " (converted to float32 once for "
             "OpenCV, outside the timed region: matchTemplate takes 8-bit or float32 only)" : "",
             o->use_mask ? "; windows whose window or area holds the fill value are left "
             "out for every method" : "");
    p.description = desc;
    gray_image_view(&a, &p.first);
    gray_image_view(&b, &p.second);
    p.use_mask = o->use_mask;
    p.mask_value = o->mask;
    rc |= track_both(&p, o, ratios);
    if (a.width >= 640 && a.height >= 480 &&
        (!o->use_mask ||
         (!holds_value(&a, (a.width - 640) / 2, (a.height - 480) / 2, 640, 480, o->mask) &&
          !holds_value(&b, (a.width - 640) / 2, (a.height - 480) / 2, 640, 480, o->mask)))) {
        rc |= search_pair_centre(o, &a, &p, ratios);
    }
    gray_image_free(&a);
    gray_image_free(&b);
    return rc;
}

/* Grid tracking on the synthetic pair (--size). */
static int run_synthetic_pair(const options_t *o, FILE *ratios, int *fatal)
{
    uint8_t *a, *b;
    peers_pair_t p;
    char desc[512];
    int rc;
    if (make_pair(o->size, o->size, 1u, &a, &b) != 0) {
        fprintf(stderr, "ssda-peers-match: out of memory\n");
        *fatal = 1;
        return 1;
    }
    memset(&p, 0, sizeof p);
    p.name = "synthetic";
    snprintf(desc, sizeof desc,
             "Synthetic %dx%d 8-bit value-noise texture and a copy moved by a smooth known "
             "field of up to 5 px plus noise +-2 (the pair of `ssda-bench-track`)",
             o->size, o->size);
    p.description = desc;
    ssda_view_init(&p.first, a, (uint16_t)o->size, (uint16_t)o->size, (uint32_t)o->size, SSDA_PIX_U8);
    ssda_view_init(&p.second, b, (uint16_t)o->size, (uint16_t)o->size, (uint32_t)o->size, SSDA_PIX_U8);
    p.synthetic_truth = 1;
    rc = track_both(&p, o, ratios);
    free(a);
    free(b);
    return rc;
}

/* Single searches in synthetic 640 x 480 value noise. */
static int run_synthetic_scene(const options_t *o, FILE *ratios, int *fatal)
{
    uint8_t *a, *b;
    peers_scene_t s;
    int rc;
    if (make_pair(640, 480, 5u, &a, &b) != 0) {
        fprintf(stderr, "ssda-peers-match: out of memory\n");
        *fatal = 1;
        return 1;
    }
    memset(&s, 0, sizeof s);
    s.name = "synthetic";
    s.description = "Synthetic 640x480 8-bit value noise; templates from its copy moved by "
                    "the smooth known field plus noise +-2";
    ssda_view_init(&s.image, a, 640, 480, 640, SSDA_PIX_U8);
    ssda_view_init(&s.moved, b, 640, 480, 640, SSDA_PIX_U8);
    s.synthetic_truth = 1;
    rc = search_scene(&s, o, ratios);
    free(a);
    free(b);
    return rc;
}

/* Single searches in the given image (--image; its centre 640 x 480 when
   larger), against its moved copy. */
static int run_image_scene(const options_t *o, const char *path, FILE *ratios, int *fatal)
{
    ssda_view_t whole, moved;
    uint32_t cw, ch;
    gray_image_t img;
    peers_scene_t s;
    uint8_t *b;
    char err[512], desc[512];
    int rc;
    if (png_read_gray(path, PNG_GRAY_8, &img, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-peers-match: %s\n", err);
        *fatal = 1;
        return 1;
    }
    b = malloc((size_t)img.width * img.height);
    if (b == NULL || img.stride != img.width) {
        fprintf(stderr, "ssda-peers-match: out of memory\n");
        *fatal = 1;
        return 1;
    }
    synth_moved(img.pixels, b, (int)img.width, (int)img.height, 7u);
    memset(&s, 0, sizeof s);
    s.name = base_name(path);
    cw = img.width > 640 ? 640 : img.width;
    ch = img.height > 480 ? 480 : img.height;
    snprintf(desc, sizeof desc,
             "`%s`, %ux%u 8-bit%s; templates from its copy moved by the smooth known field "
             "of the synthetic pair plus noise +-2",
             base_name(path), img.width, img.height,
             cw < img.width || ch < img.height ? ", its centre 640x480" : "");
    s.description = desc;
    gray_image_view(&img, &whole);
    ssda_view_init(&moved, b, (uint16_t)img.width, (uint16_t)img.height, img.width, SSDA_PIX_U8);
    ssda_view_roi(&s.image, &whole, (uint16_t)((img.width - cw) / 2), (uint16_t)((img.height - ch) / 2),
                  (uint16_t)cw, (uint16_t)ch);
    ssda_view_roi(&s.moved, &moved, (uint16_t)((img.width - cw) / 2), (uint16_t)((img.height - ch) / 2),
                  (uint16_t)cw, (uint16_t)ch);
    s.synthetic_truth = 1;
    rc = search_scene(&s, o, ratios);
    free(b);
    gray_image_free(&img);
    return rc;
}

int main(int argc, char **argv)
{
    options_t o = {7, 5, 1024, 0, 0, 0, 0, NULL, {NULL, NULL}, "real pair", {NULL}, 0};
    FILE *ratios = NULL;
    char info[256];
    int rc = parse_options(argc, argv, &o), fatal = 0;
    if (rc != 0) {
        return rc;
    }
    if (o.ratios != NULL && (ratios = fopen(o.ratios, "w")) == NULL) {
        perror(o.ratios);
        return 1;
    }
    cv_peer_init(info, sizeof info);
    printf("## Template matching: ssda %d.%d.%d vs %s\n", SSDA_VERSION_MAJOR, SSDA_VERSION_MINOR,
           SSDA_VERSION_PATCH, info);
    /* Grid tracking: the real pair, then the synthetic one; single searches:
       synthetic 640 x 480, then the given image. */
    if (o.pair[0] != NULL) {
        rc |= run_real_pair(&o, ratios, &fatal);
    }
    rc |= fatal || o.searches_only ? 0 : run_synthetic_pair(&o, ratios, &fatal);
    rc |= fatal ? 0 : run_synthetic_scene(&o, ratios, &fatal);
    for (int k = 0; k < o.nimage && !fatal; k++) {
        rc |= run_image_scene(&o, o.image[k], ratios, &fatal);
    }
    if (fatal) {
        return 1;
    }
    if (ratios != NULL && fclose(ratios) != 0) {
        perror(o.ratios);
        rc = 1;
    }
    return rc ? 1 : 0;
}
