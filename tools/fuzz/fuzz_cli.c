/*
 * fuzz_cli.c - the `ssda` tool's subcommands (tools/cli/cmd_*.c, called
 * without main) on fuzzed command lines and input files.
 * Input layout (every field cut short is 0, see fuzz_input.h):
 *   subcommand byte; up to 12 option tokens (option byte, value bytes);
 *   positional-argument shape byte; then the files: each a kind byte (raw
 *   bytes, or a small valid PNG/WAV generated here from the next bytes) and
 *   its contents. Raw PNGs claiming more than 64 x 64 pixels are skipped
 *   (the PNG reader's own target takes any size; here the searches behind
 *   would only be slow).
 * Checked: the exit code is 0, 1 or 2; a failed run (1 or 2) leaves no
 * output and no temp file; a successful one no temp file; nothing leaks or
 * crashes (ASan, UBSan, LeakSanitizer). The tool runs inside the target's
 * private folder, so whatever it writes is found there.
 */
#define _POSIX_C_SOURCE 200809L
#include <sndfile.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "fuzz_files.h"
#include "fuzz_input.h"

#define MAX_ARGS 48
#define MAX_IMG 48u
#define MAX_RAW_DIM 64u

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char g_argbuf[MAX_ARGS][4200];
static const char *const k_inputs[] = {"a.png", "b.png", "in.wav", "ref.csv", NULL};

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    FUZZ_CHECK(freopen("/dev/null", "w", stdout) != NULL); /* results and "-" outputs */
    FUZZ_CHECK(chdir(fuzz_dir()) == 0); /* any relative path lands in the folder */
    return 0;
}

static uint32_t next_rand(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* ---- values ---- */
enum { V_NONE, V_NUM, V_BIG, V_WXH, V_PAIR, V_QUAD, V_THRESH, V_SCAN, V_ORDER, V_PREDICT,
       V_EXCLUDE, V_FLOAT, V_BITS, V_OUT_JSON, V_OUT_PNG, V_OUT_CSV, V_REF };

static const char *const k_odd[] = {"",   "0",  "-1",  "65535", "65536", "4294967296", "1e9",
                                    "nan", "inf", "-0", "0x10", " 5",    "5 ",  "1,",
                                    ",1",  "x",  "1x",  "-",     "99999999999999999999"};

static const char *pick(fuzz_in_t *in, const char *const *list, size_t n)
{
    return list[fuzz_range(in, 0, (uint32_t)n - 1u)];
}
#define PICK(in, list) pick(in, list, sizeof list / sizeof list[0])

/* Text of a value of the given type into buf (or an odd string). */
static void value(fuzz_in_t *in, int type, char *buf, size_t len)
{
    static const char *const thr[] = {"auto", "none", "fixed:%u", "ramp:%u", "ramp:%u:%u",
                                      "auto-ramp", "auto-ramp:%u", "fixed", "ramp:0"};
    static const char *const scan[] = {"raster", "predict", "coarse"};
    static const char *const order[] = {"rows", "spread"};
    static const char *const pred[] = {"neighbour", "neighbor", "median", "left", "none"};
    uint32_t a = fuzz_u16(in) % 70u, b = fuzz_u16(in) % 70u;
    char p[4200];
    /* odd strings, except as --mem ("4294967296" is 4 GB) and output names */
    if (type != V_BIG && type < V_OUT_JSON && fuzz_one_in(in, 12)) {
        snprintf(buf, len, "%s", PICK(in, k_odd));
        return;
    }
    switch (type) {
    case V_NUM: snprintf(buf, len, "%u", fuzz_u16(in) % 300u); break;
    case V_BIG: /* --mem: the tool allocates what it is given, so at most 100 MB here */
        snprintf(buf, len, "%u%s", fuzz_u32(in) % 100000u, fuzz_u8(in) & 1u ? "" : "K");
        break;
    case V_WXH:
        if (fuzz_u8(in) & 1u) snprintf(buf, len, "%u", a);
        else snprintf(buf, len, "%ux%u", a, b);
        break;
    case V_PAIR: snprintf(buf, len, "%d,%d", (int)a - 10, (int)b - 10); break;
    case V_QUAD: snprintf(buf, len, "%u,%u,%u,%u", a, b, fuzz_u8(in) % 70u, fuzz_u8(in) % 70u); break;
    case V_THRESH: snprintf(buf, len, PICK(in, thr), fuzz_u16(in), fuzz_u8(in) % 8u); break;
    case V_SCAN: snprintf(buf, len, "%s", PICK(in, scan)); break;
    case V_ORDER: snprintf(buf, len, "%s", PICK(in, order)); break;
    case V_PREDICT: snprintf(buf, len, "%s", PICK(in, pred)); break;
    case V_EXCLUDE:
        if (fuzz_u8(in) & 1u) snprintf(buf, len, "%u", a * 4u);
        else snprintf(buf, len, "%s:%u", fuzz_u8(in) & 1u ? "mean" : "100", b);
        break;
    case V_FLOAT: snprintf(buf, len, "%.3g", (double)fuzz_u16(in) / (double)(1u + fuzz_u8(in))); break;
    case V_BITS: snprintf(buf, len, "%u", fuzz_u8(in) & 1u ? 8u : 16u); break;
    case V_OUT_JSON: snprintf(buf, len, "%s", fuzz_u8(in) % 4u ? fuzz_path("o1.json", p, sizeof p) : "-"); break;
    case V_OUT_PNG: snprintf(buf, len, "%s", fuzz_path(fuzz_u8(in) & 1u ? "o2.png" : "o4.png", p, sizeof p)); break;
    case V_OUT_CSV: snprintf(buf, len, "%s", fuzz_u8(in) % 4u ? fuzz_path("o3.csv", p, sizeof p) : "-"); break;
    case V_REF: snprintf(buf, len, "%s", fuzz_path("ref.csv", p, sizeof p)); break;
    default: buf[0] = '\0'; break;
    }
}

typedef struct {
    const char *name;
    int type;
} opt_t;

static const opt_t k_match_opts[] = {
    {"--threshold", V_THRESH}, {"--scan", V_SCAN}, {"--order", V_ORDER}, {"--predict", V_PAIR},
    {"--coarse-step", V_NUM},  {"--bounds", V_NONE}, {"--json", V_NONE}, {"--quiet", V_NONE}};
static const opt_t k_track_opts[] = {
    {"--window", V_WXH},     {"--search", V_WXH},      {"--step", V_WXH},
    {"--roi", V_QUAD},       {"--threshold", V_THRESH}, {"--predict", V_PREDICT},
    {"--scan", V_SCAN},      {"--order", V_ORDER},     {"--no-bounds", V_NONE},
    {"--bounds", V_NONE},    {"--exclude", V_EXCLUDE}, {"--exclude", V_NONE},
    {"--mask-value", V_NUM}, {"--grad", V_NONE},       {"--mem", V_BIG},
    {"--json", V_OUT_JSON},  {"--overlay", V_OUT_PNG}, {"--arrow-scale", V_FLOAT},
    {"--quiet", V_NONE}};
static const opt_t k_grad_opts[] = {
    {"--bits", V_BITS}, {"--shift", V_NUM}, {"--crop", V_NONE}, {"--quiet", V_NONE}};
static const opt_t k_pitch_opts[] = {
    {"--fmin", V_FLOAT},     {"--fmax", V_FLOAT},    {"--hop-ms", V_FLOAT},
    {"--frame-ms", V_FLOAT}, {"--threshold", V_FLOAT}, {"--voicing", V_FLOAT},
    {"--full", V_NONE},      {"--csv", V_OUT_CSV},   {"--plot", V_OUT_PNG},
    {"--ref", V_REF},        {"--quiet", V_NONE},    {"--silence", V_FLOAT},
    {"--ref-hop", V_FLOAT}};

/* ---- files ---- */

/* Bytes as given; a PNG whose header claims a large image is skipped. */
static int write_raw(const char *name, fuzz_in_t *in)
{
    size_t n;
    const uint8_t *p = fuzz_bytes(in, fuzz_u16(in) % 4096u, &n);
    char path[4200];
    if (n >= 24 && memcmp(p + 12, "IHDR", 4) == 0) {
        uint32_t w = (uint32_t)p[16] << 24 | (uint32_t)p[17] << 16 | (uint32_t)p[18] << 8 | p[19];
        uint32_t h = (uint32_t)p[20] << 24 | (uint32_t)p[21] << 16 | (uint32_t)p[22] << 8 | p[23];
        if (w > MAX_RAW_DIM || h > MAX_RAW_DIM) {
            return -1;
        }
    }
    fuzz_write(name, p, n, path, sizeof path);
    return 0;
}

/* A valid gray PNG of up to 48 x 48, 8 or 16 bits, written by png_io. */
static void write_png(const char *name, fuzz_in_t *in, uint32_t *seed)
{
    gray_image_t img;
    char path[4200], err[256];
    uint32_t w = fuzz_range(in, 1, MAX_IMG), h = fuzz_range(in, 1, MAX_IMG);
    uint32_t bits = fuzz_u8(in) & 1u ? 16u : 8u, levels = fuzz_range(in, 1, 256), x, y;
    FUZZ_CHECK(gray_image_alloc(&img, w, h, (int)bits) == 0);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint32_t v = next_rand(seed) % levels * (bits == 16u ? 257u : 1u);
            if (bits == 16u) ((uint16_t *)img.pixels)[y * w + x] = (uint16_t)(v * (65535u / 257u / levels + 1u));
            else ((uint8_t *)img.pixels)[y * w + x] = (uint8_t)(v * (255u / levels));
        }
    }
    FUZZ_CHECK(png_write_gray(fuzz_path(name, path, sizeof path), &img, err, sizeof err) == 0);
    gray_image_free(&img);
}

/* A valid WAV: a fuzzed period repeated, 8..48 kHz, 16-bit PCM, 1-2 channels. */
static void write_wav(const char *name, fuzz_in_t *in)
{
    static const int rates[] = {8000, 11025, 16000, 22050, 44100, 48000, 4000};
    SF_INFO info;
    SNDFILE *sf;
    char path[4200];
    int16_t buf[2 * 4800];
    uint32_t period = fuzz_range(in, 1, 200), frames = fuzz_range(in, 1, 4800), i;
    int16_t pat[200];
    memset(&info, 0, sizeof info);
    info.samplerate = rates[fuzz_range(in, 0, 6)];
    info.channels = (int)fuzz_range(in, 1, 2);
    info.format = SF_FORMAT_WAV | (fuzz_u8(in) & 1u ? SF_FORMAT_PCM_16 : SF_FORMAT_FLOAT);
    for (i = 0; i < period; i++) {
        pat[i] = (int16_t)fuzz_u16(in);
    }
    for (i = 0; i < frames * (uint32_t)info.channels; i++) {
        buf[i] = pat[(i / (uint32_t)info.channels) % period];
    }
    sf = sf_open(fuzz_path(name, path, sizeof path), SFM_WRITE, &info);
    FUZZ_CHECK(sf != NULL);
    FUZZ_CHECK(sf_writef_short(sf, buf, frames) == (sf_count_t)frames);
    FUZZ_CHECK(sf_close(sf) == 0);
}

static int write_input(const char *name, fuzz_in_t *in, uint32_t *seed, int wav)
{
    uint32_t kind = fuzz_u8(in) % 4u;
    if (kind == 0u) {
        return write_raw(name, in);
    }
    if (wav) {
        write_wav(name, in);
    } else {
        write_png(name, in, seed);
    }
    return 0;
}

/* Up to 12 option tokens of the subcommand's into g_argbuf from argc on
   (valid, bad, "=VALUE", a value missing, unknown, "--"). Returns argc. */
static int add_options(fuzz_in_t *in, const opt_t *opts, size_t nopts, int argc)
{
    uint32_t ntok = fuzz_range(in, 0, 12), i;
    for (i = 0; i < ntok && argc + 2 < MAX_ARGS - 4; i++) {
        uint32_t which = fuzz_u8(in);
        const opt_t *o;
        char v[4200];
        if (which >= 250u) { /* an unknown option, or a bare "--" */
            snprintf(g_argbuf[argc++], sizeof g_argbuf[0], "%s", which == 255u ? "--" : "--bogus");
            continue;
        }
        o = &opts[which % nopts];
        value(in, o->type, v, sizeof v);
        if (o->type == V_NONE) {
            snprintf(g_argbuf[argc++], sizeof g_argbuf[0], "%s", o->name);
        } else if (fuzz_u8(in) % 4u == 0u) {
            snprintf(g_argbuf[argc++], sizeof g_argbuf[0], "%s=%s", o->name, v);
        } else if (fuzz_one_in(in, 16)) { /* missing value at the end */
            snprintf(g_argbuf[argc++], sizeof g_argbuf[0], "%s", o->name);
        } else {
            snprintf(g_argbuf[argc++], sizeof g_argbuf[0], "%s", o->name);
            snprintf(g_argbuf[argc++], sizeof g_argbuf[0], "%s", v);
        }
    }
    return argc;
}

/* Positionals: usually what subcommand cmd wants, sometimes not (one
   missing, one too many, a file that does not exist, a folder). */
static int add_positionals(fuzz_in_t *in, uint32_t cmd, int argc)
{
    uint32_t shape = fuzz_u8(in) % 16u, n = 0, k;
    const char *want[3];
    char path[4200];
    if (cmd <= 2u) {
        want[n++] = "a.png";
        want[n++] = "b.png";
    } else if (cmd == 3u) {
        want[n++] = "a.png";
        want[n++] = "o2.png";
    } else {
        want[n++] = "in.wav";
    }
    if (shape == 1u && n > 0u) n--;                /* one missing */
    if (shape == 2u) want[n++] = "a.png";          /* one too many */
    for (k = 0; k < n; k++) {
        const char *name = want[k];
        if (shape == 3u && k == 0u) name = "missing.png"; /* does not exist */
        if (shape == 4u && k == 0u) {                      /* a folder */
            snprintf(g_argbuf[argc++], sizeof g_argbuf[0], "%s", fuzz_dir());
            continue;
        }
        snprintf(g_argbuf[argc++], sizeof g_argbuf[0], "%s", fuzz_path(name, path, sizeof path));
    }
    return argc;
}

/* The subcommand's input files. Returns 0, or -1 when the input is skipped. */
static int write_inputs(fuzz_in_t *in, uint32_t cmd)
{
    uint32_t seed = fuzz_u32(in) | 1u;
    char path[4200];
    if (cmd == 4u) {
        size_t n;
        const uint8_t *p;
        if (write_input("in.wav", in, &seed, 1) != 0) {
            return -1;
        }
        p = fuzz_bytes(in, fuzz_u16(in) % 1024u, &n);
        fuzz_write("ref.csv", p, n, path, sizeof path);
        return 0;
    }
    if (write_input("a.png", in, &seed, 0) != 0 ||
        (cmd != 3u && write_input("b.png", in, &seed, 0) != 0)) {
        fuzz_clean(NULL);
        return -1;
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char *argv[MAX_ARGS + 1];
    static const char *const names[] = {"match", "track", "compare", "grad", "pitch"};
    static const struct {
        const opt_t *opts;
        size_t n;
        int (*run)(int, char **);
    } cmds[] = {
        {k_match_opts, sizeof k_match_opts / sizeof k_match_opts[0], cmd_match},
        {k_track_opts, sizeof k_track_opts / sizeof k_track_opts[0], cmd_track},
        {k_track_opts, sizeof k_track_opts / sizeof k_track_opts[0], cmd_compare},
        {k_grad_opts, sizeof k_grad_opts / sizeof k_grad_opts[0], cmd_grad},
        {k_pitch_opts, sizeof k_pitch_opts / sizeof k_pitch_opts[0], cmd_pitch}};
    fuzz_in_t in = {data, size};
    uint32_t cmd = fuzz_u8(&in) % 5u, i;
    int argc = 1, rc;

    snprintf(g_argbuf[0], sizeof g_argbuf[0], "%s", names[cmd]);
    argc = add_options(&in, cmds[cmd].opts, cmds[cmd].n, argc);
    argc = add_positionals(&in, cmd, argc);
    for (i = 0; i < (uint32_t)argc; i++) {
        argv[i] = g_argbuf[i];
    }
    argv[argc] = NULL;
    if (write_inputs(&in, cmd) != 0) {
        return 0;
    }
    rc = cmds[cmd].run(argc, argv); /* its messages: -close_fd_mask=2 (tools/fuzz.sh) */
    fflush(stdout);
    clearerr(stdout);

    FUZZ_CHECK(rc == CLI_OK || rc == CLI_INPUT || rc == CLI_USAGE);
    if (rc != CLI_OK) {
        FUZZ_CHECK(fuzz_strays(k_inputs) == 0); /* no output, no temp file */
    } else {
        /* outputs, named as asked: "--json --grad" writes a file called
           "--grad", as getopt would; but never a temp file */
        FUZZ_CHECK(fuzz_strays_named(".tmp.") == 0);
    }
    fuzz_clean(NULL);
    return 0;
}
