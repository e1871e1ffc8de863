/*
 * config_file.c - the library built with a settings file of the user's
 * (-DSSDA_CONFIG_FILE=my_ssda_config.h, which defines SSDA_CFG_NO_RAMP):
 * the switch reaches the headers and the library, which then refuses the
 * ramp thresholds and still answers the exact search. Exit 0 on success.
 */
#include <stdio.h>

#include "ssda/match.h"

#ifndef SSDA_CFG_NO_RAMP
#error "SSDA_CONFIG_FILE was not included by ssda/config.h"
#endif

int main(void)
{
    static uint8_t img[16 * 16], win[4 * 4];
    ssda_view_t a, w;
    ssda_match_config_t cfg = {0};
    ssda_match_result_t r = {0};
    int x, y, err;
    for (y = 0; y < 16; y++) {
        for (x = 0; x < 16; x++) {
            img[y * 16 + x] = (uint8_t)(x * 7 + y * y * 3);
        }
    }
    for (y = 0; y < 4; y++) {
        for (x = 0; x < 4; x++) {
            win[y * 4 + x] = img[(5 + y) * 16 + 9 + x];
        }
    }
    (void)ssda_view_init(&a, img, 16, 16, 16, SSDA_PIX_U8);
    (void)ssda_view_init(&w, win, 4, 4, 4, SSDA_PIX_U8);
    cfg.threshold = SSDA_THRESHOLD_AUTO_RAMP;
    err = ssda_match(&a, &w, &cfg, &r);
    if (err != SSDA_ERR_UNSUPPORTED || r.pixel_ops != 0u) {
        printf("ramp: %d, want SSDA_ERR_UNSUPPORTED and no output\n", err);
        return 1;
    }
    cfg.threshold = SSDA_THRESHOLD_AUTO;
    err = ssda_match(&a, &w, &cfg, &r);
    if (err != SSDA_OK || r.x != 9u || r.y != 5u || r.sad != 0u) {
        printf("auto: %d at (%u, %u), want (9, 5)\n", err, r.x, r.y);
        return 1;
    }
    return 0;
}
