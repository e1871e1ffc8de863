/*
 * fuzz_wav.c - wav_read_mono_i16_ex (tools/common/wav_io.c, libsndfile) on
 * arbitrary bytes. Input: one byte choosing the error buffer's length and
 * whether info is asked for, then the file's bytes.
 *   Success: >= 1 samples (all readable), a rate >= 1, a consistent info.
 *   Failure: -1, every output untouched, a one-line message inside the
 *   error buffer. Either way nothing is leaked and no file is left.
 */
#include <stdlib.h>
#include <string.h>

#include "fuzz_files.h"
#include "fuzz_input.h"
#include "wav_io.h"

#define ERR_CANARY 0xC5u

static const char *const k_keep[] = {"in.wav", NULL};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in_t in = {data, size};
    uint32_t choice = fuzz_u8(&in);
    size_t errlen = choice % 4u == 0u ? (choice / 4u) % 8u : 256u, i;
    char err[264], path[4200];
    int16_t *samples = (int16_t *)(uintptr_t)0x1234u, *const poison_ptr = samples;
    size_t count = 777u;
    uint32_t rate = 888u;
    wav_info_t info, poison_info;
    int rc, want_info = (choice & 0x80u) == 0u;

    fuzz_write("in.wav", in.p, in.n, path, sizeof path);
    memset(err, ERR_CANARY, sizeof err);
    memset(&poison_info, 0x3C, sizeof poison_info);
    info = poison_info;
    rc = wav_read_mono_i16_ex(path, &samples, &count, &rate, want_info ? &info : NULL, err,
                              errlen);
    for (i = errlen; i < sizeof err; i++) {
        FUZZ_CHECK((uint8_t)err[i] == ERR_CANARY);
    }
    if (rc != 0) {
        FUZZ_CHECK(rc == -1);
        FUZZ_CHECK(samples == poison_ptr && count == 777u && rate == 888u);
        FUZZ_CHECK(memcmp(&info, &poison_info, sizeof info) == 0);
        if (errlen > 0) {
            FUZZ_CHECK(memchr(err, '\0', errlen) != NULL);
            FUZZ_CHECK(strlen(err) > 0 || errlen == 1);
            FUZZ_CHECK(strchr(err, '\n') == NULL);
        }
    } else {
        int64_t sum = 0;
        size_t k;
        FUZZ_CHECK(samples != NULL && samples != poison_ptr);
        FUZZ_CHECK(count >= 1u && rate >= 1u);
        for (k = 0; k < count; k++) { /* ASan checks the whole array */
            sum += samples[k];
        }
        (void)sum;
        if (want_info) {
            FUZZ_CHECK(info.channels >= 1u);
            FUZZ_CHECK(info.clipped <= count);
            FUZZ_CHECK(memchr(info.format_name, '\0', sizeof info.format_name) != NULL);
        }
        free(samples);
    }
    FUZZ_CHECK(fuzz_strays(k_keep) == 0);
    return 0;
}
