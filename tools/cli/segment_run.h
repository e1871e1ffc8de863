/*
 * segment_run.h - the work of `ssda segment` (cmd_segment.c writes its
 * outputs): read a PNG, K-L transform a colour image (or take a gray one
 * as its own feature), a histogram and a Gaussian mixture per feature,
 * labels through the look-up table, isolated-point removal, contours,
 * counts. All through the library (kl.h, mixture.h, region.h).
 */
#ifndef SSDA_SEGMENT_RUN_H
#define SSDA_SEGMENT_RUN_H

#include <stdint.h>
#include "ssda/kl.h"
#include "ssda/mixture.h"

typedef struct {
    int band;             /* 0 = every feature, 1..3 = Z1..Z3 only */
    uint8_t comps[3];     /* components per feature, 0 = by BIC */
    uint8_t max_comps;    /* automatic K up to this (0 = library default) */
    uint8_t fit;          /* ssda_mix_fit_t */
    uint8_t init;         /* ssda_mix_init_t */
    uint8_t seed_steps;   /* search: stop where the seed stops */
    uint8_t rule;         /* ssda_mix_rule_t */
    uint32_t band_q8;     /* band rule width, sigmas Q8 (0 = 2) */
    uint8_t matrix;       /* ssda_kl_matrix_t */
    uint8_t nsigma;       /* K-L range: mean +- nsigma sd (0 = 4) */
    double gain_max;      /* K-L: feature steps per sample step at most (0: 1 for
                             8-bit input, 4096 for 16-bit) */
    uint32_t bins;        /* histogram bins: K-L out_max + 1; 16-bit gray at most */
    int have_nodata;
    uint32_t nodata;      /* masked value (every band) */
    int clean;            /* 3 x 3 isolated-point removal */
    int contours;         /* keep contour images */
} seg_opts_t;

typedef struct {
    int index;            /* 0..2: Z1..Z3 (gray: 0) */
    uint16_t *values;     /* width x height feature values, SSDA_KL_NODATA masked */
    uint32_t *hist;       /* bins counts */
    uint32_t bins, shift; /* bin = value >> shift */
    ssda_mix_model_t model;
    uint8_t *labels;      /* width x height, 0..count (cleaned if asked) */
    uint8_t *contour;     /* width x height, or NULL */
    uint32_t counts[256]; /* pixels per label in labels (label 0: none or nodata) */
    uint32_t band_pixels[SSDA_MIX_MAX_COMPONENTS];
    double gain, offset;  /* feature units per bin: Z = (bin - offset) / gain */
    double fit_secs;      /* histogram + fit + table, seconds */
} seg_feature_t;

typedef struct {
    uint32_t width, height;
    int color;            /* 1: RGB through the K-L transform; 0: gray */
    uint32_t bits;        /* input sample bits, 8 or 16 */
    ssda_kl_t kl;         /* color only */
    uint32_t masked;      /* nodata pixels */
    uint32_t clamped;     /* K-L values clamped into 0..out_max */
    int nfeat;
    seg_feature_t feat[3];
    double secs;          /* everything after reading, seconds */
} seg_result_t;

/* Run everything; prints its own errors. Returns CLI_OK or CLI_INPUT. */
int seg_run(const char *cmd, const char *path, const seg_opts_t *o, seg_result_t *r);
void seg_result_free(seg_result_t *r);

#endif /* SSDA_SEGMENT_RUN_H */
