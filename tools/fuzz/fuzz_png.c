/*
 * fuzz_png.c - png_read_gray (tools/common/png_io.c) on arbitrary bytes.
 * Input: one byte choosing the depth asked for and the error buffer's
 * length, then the file's bytes.
 *   Success: a consistent image (every pixel readable, within the depth),
 *   which png_write_gray writes and png_read_gray reads back unchanged.
 *   Failure: -1, *img and *info untouched, a one-line message that stays
 *   inside the error buffer.
 *   Either way: no file left behind, nothing leaked (LeakSanitizer).
 */
#include <string.h>

#include "fuzz_files.h"
#include "fuzz_input.h"
#include "png_io.h"

#define ERR_CANARY 0xC5u

static const char *const k_keep[] = {"in.png", NULL};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in_t in = {data, size};
    uint32_t choice = fuzz_u8(&in);
    png_gray_depth_t depth = choice % 3u == 0u ? PNG_GRAY_NATIVE
                           : choice % 3u == 1u ? PNG_GRAY_8 : PNG_GRAY_16;
    size_t errlen = (choice / 3u) % 4u == 0u ? (choice / 12u) % 8u : 256u, i;
    char err[264], path[4200], out[4200];
    gray_image_t img, poison_img;
    png_source_info_t info, poison_info;
    int rc;

    fuzz_write("in.png", in.p, in.n, path, sizeof path);
    memset(err, ERR_CANARY, sizeof err);
    memset(&poison_img, 0x3C, sizeof poison_img);
    memset(&poison_info, 0x3C, sizeof poison_info);
    img = poison_img;
    info = poison_info;
    rc = png_read_gray(path, depth, &img, (choice & 0x80u) ? NULL : &info, err, errlen);
    for (i = errlen; i < sizeof err; i++) {
        FUZZ_CHECK((uint8_t)err[i] == ERR_CANARY);
    }
    if (rc != 0) {
        FUZZ_CHECK(rc == -1);
        FUZZ_CHECK(memcmp(&img, &poison_img, sizeof img) == 0);
        FUZZ_CHECK(memcmp(&info, &poison_info, sizeof info) == 0);
        if (errlen > 0) {
            FUZZ_CHECK(memchr(err, '\0', errlen) != NULL);
            FUZZ_CHECK(strlen(err) > 0 || errlen == 1);
            FUZZ_CHECK(strchr(err, '\n') == NULL);
        }
    } else {
        uint64_t sum = 0;
        uint32_t x, y, maxv;
        ssda_view_t v;
        FUZZ_CHECK(img.pixels != NULL);
        FUZZ_CHECK(img.width >= 1 && img.width <= 65535u && img.height >= 1 &&
                   img.height <= 65535u);
        FUZZ_CHECK(img.bits == 8 || img.bits == 16);
        FUZZ_CHECK(depth == PNG_GRAY_NATIVE || img.bits == (uint8_t)depth);
        FUZZ_CHECK(img.stride == img.width * (img.bits / 8u));
        FUZZ_CHECK(gray_image_view(&img, &v) == SSDA_OK);
        if (!(choice & 0x80u)) {
            FUZZ_CHECK(memchr(info.description, '\0', sizeof info.description) != NULL);
            FUZZ_CHECK(info.source_bits == 1 || info.source_bits == 2 || info.source_bits == 4 ||
                       info.source_bits == 8 || info.source_bits == 16);
        }
        maxv = gray_image_max(&img);
        for (y = 0; y < img.height; y++) { /* ASan checks the whole buffer */
            for (x = 0; x < img.width; x++) {
                uint32_t p = gray_image_get(&img, x, y);
                FUZZ_CHECK(p <= maxv);
                sum += p;
            }
        }
        (void)sum;
        /* write and read back: the same pixels */
        if ((uint64_t)img.width * img.height <= 65536u) {
            gray_image_t back = {0};
            FUZZ_CHECK(png_write_gray(fuzz_path("out.png", out, sizeof out), &img, err,
                                      sizeof err) == 0);
            FUZZ_CHECK(png_read_gray(out, PNG_GRAY_NATIVE, &back, NULL, err, sizeof err) == 0);
            FUZZ_CHECK(back.width == img.width && back.height == img.height &&
                       back.bits == img.bits);
            FUZZ_CHECK(memcmp(back.pixels, img.pixels, (size_t)img.stride * img.height) == 0);
            gray_image_free(&back);
            fuzz_clean(k_keep);
        }
        gray_image_free(&img);
    }
    FUZZ_CHECK(fuzz_strays(k_keep) == 0);
    return 0;
}
