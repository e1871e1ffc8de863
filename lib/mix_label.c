/* mix_label.c - histograms, label look-up tables and labelling
   (mixture.h). */
#include "mix_internal.h"

int ssda_mix_hist_add(uint32_t *hist, uint32_t bins, const uint16_t *values, uint32_t n,
                      uint32_t shift, uint32_t *skipped)
{
    uint32_t i, out = 0u;
    if (hist == NULL || values == NULL) {
        return SSDA_ERR_NULL;
    }
    if (bins == 0u || bins > SSDA_MIX_MAX_BINS) {
        return SSDA_ERR_SIZE;
    }
    if (shift > 15u) {
        return SSDA_ERR_ARG;
    }
    for (i = 0u; i < n; i++) {
        const uint32_t b = (uint32_t)values[i] >> shift;
        if (b < bins) {
            hist[b]++;
        } else {
            out++;
        }
    }
    if (skipped != NULL) {
        *skipped = *skipped > UINT32_MAX - out ? UINT32_MAX : *skipped + out;
    }
    return SSDA_OK;
}

static int check_model(const ssda_mix_model_t *m, uint32_t band_q8)
{
    uint32_t k;
    if (m->count == 0u || m->count > SSDA__MIX_K || m->bins < SSDA_MIX_MIN_BINS ||
        m->bins > SSDA_MIX_MAX_BINS || band_q8 > 4096u) {
        return SSDA_ERR_ARG;
    }
    for (k = 0u; k < m->count; k++) {
        if (m->comp[k].sigma_q16 == 0u) {
            return SSDA_ERR_ARG; /* no density: ssda__mix_prepare needs sigma > 0 */
        }
    }
    return SSDA_OK;
}

/* Is z within band sigmas of the component? |z - mean| <= band sigma,
   compared exactly in Q24 (band Q8 x sigma Q16). */
static bool in_band(const ssda_mix_component_t *c, uint32_t z, uint32_t band_q8)
{
    const uint64_t zq = (uint64_t)z << 16;
    const uint64_t d = zq > c->mean_q16 ? zq - c->mean_q16 : c->mean_q16 - zq; /* < 2^28 */
    return (d << 8) <= (uint64_t)band_q8 * c->sigma_q16;
}

int ssda_mix_lut(const ssda_mix_model_t *model, uint8_t rule, uint32_t band_q8, uint8_t *lut)
{
    ssda__mix_gauss_t g[SSDA__MIX_K];
    uint32_t z, k;
    int err;
    if (model == NULL || lut == NULL) {
        return SSDA_ERR_NULL;
    }
    band_q8 = band_q8 == 0u ? SSDA_MIX_DEFAULT_BAND_Q8 : band_q8;
    err = check_model(model, band_q8);
    if (err != SSDA_OK) {
        return err;
    }
    if (rule > (uint8_t)SSDA_MIX_LABEL_LIKELY) {
        return SSDA_ERR_ARG;
    }
    for (k = 0u; k < model->count; k++) {
        ssda__mix_prepare(&g[k], model->comp[k].weight_q16, 65536u, model->comp[k].mean_q16,
                          model->comp[k].sigma_q16);
    }
    for (z = 0u; z < model->bins; z++) {
        uint8_t label = 0u;
        int32_t best = 0;
        for (k = 0u; k < model->count; k++) {
            const int32_t s = g[k].lw_q16 - (int32_t)ssda__mix_q(&g[k], z);
            const bool eligible = g[k].active &&
                                  (rule == (uint8_t)SSDA_MIX_LABEL_LIKELY ||
                                   in_band(&model->comp[k], z, band_q8));
            if (eligible && (label == 0u || s > best)) {
                best = s;
                label = (uint8_t)(k + 1u);
            }
        }
        lut[z] = label;
    }
    return SSDA_OK;
}

int ssda_mix_label_row(const uint8_t *lut, uint32_t bins, const uint16_t *values, uint32_t n,
                       uint32_t shift, uint8_t *labels)
{
    uint32_t i;
    if (lut == NULL || values == NULL || labels == NULL) {
        return SSDA_ERR_NULL;
    }
    if (bins == 0u || bins > SSDA_MIX_MAX_BINS) {
        return SSDA_ERR_SIZE;
    }
    if (shift > 15u) {
        return SSDA_ERR_ARG;
    }
    for (i = 0u; i < n; i++) {
        const uint32_t b = (uint32_t)values[i] >> shift;
        labels[i] = b < bins ? lut[b] : 0u;
    }
    return SSDA_OK;
}

int ssda_mix_band_pixels(const ssda_mix_model_t *model, const uint32_t *hist, uint32_t band_q8,
                         uint32_t *pixels)
{
    uint32_t k, z;
    int err;
    if (model == NULL || hist == NULL || pixels == NULL) {
        return SSDA_ERR_NULL;
    }
    band_q8 = band_q8 == 0u ? SSDA_MIX_DEFAULT_BAND_Q8 : band_q8;
    err = check_model(model, band_q8);
    if (err != SSDA_OK) {
        return err;
    }
    for (k = 0u; k < model->count; k++) {
        uint32_t n = 0u; /* <= the histogram's total < 2^32 */
        for (z = 0u; z < model->bins; z++) {
            if (in_band(&model->comp[k], z, band_q8)) {
                n += hist[z];
            }
        }
        pixels[k] = n;
    }
    return SSDA_OK;
}
