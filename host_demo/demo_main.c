/* demo_main.c - ssda-demo: arguments, the output folder, the two parts. */
#define _XOPEN_SOURCE 700 /* realpath, mkdir, access */
#include "demo.h"
#include "wav_io.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char usage[] =
    "usage: ssda-demo [--out DIR] [--quiet] [FIRST.png SECOND.png] [SOUND.wav [--ref F0.csv]]\n"
    "                 [--mask-value V] [--step N]\n"
    "\n"
    "With no files: makes a synthetic cloud pair moved by a known wind, a synthetic\n"
    "voice with a known f0 and an aerial pair turned, scaled and darkened by a known\n"
    "amount; tracks, pitches and registers them with the library, and reports the\n"
    "accuracy against the truth and the work the early exit saved. With files: the same\n"
    "on your image pair and/or sound (any PNG; WAV, FLAC, OGG, ...).\n"
    "\n"
    "  --out DIR        output folder (default ./ssda-demo-out), created if missing\n"
    "  --mask-value V   fill value in your images (e.g. 4095 for GOES)\n"
    "  --step N         grid step for your images, px (default 16)\n"
    "  --ref F0.csv     reference f0 for your sound (time_s,f0_hz rows)\n"
    "  --quiet          print only the pictures written\n";

void demo_heading(const demo_ctx_t *c, const char *fmt, ...)
{
    va_list ap;
    printf("\n%s", c->color ? "\033[1m" : "");
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("%s\n", c->color ? "\033[0m" : "");
}

const char *demo_path(const demo_ctx_t *c, const char *name, char *buf, size_t len)
{
    snprintf(buf, len, "%s/%s", c->out_dir, name);
    return buf;
}

static int is_png(const char *path)
{
    static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    unsigned char b[8];
    FILE *f = fopen(path, "rb");
    size_t n = f != NULL ? fread(b, 1, 8, f) : 0;
    if (f != NULL) {
        fclose(f);
    }
    return n == 8 && memcmp(b, sig, 8) == 0;
}

/* The `ssda` tool next to this program in a build tree, for the hints:
   relative to the current folder when it is below it. */
static void tool_path(const char *argv0, char *buf, size_t len)
{
    const char *slash = strrchr(argv0, '/');
    char guess[2048], *real, cwd[2048];
    snprintf(buf, len, "ssda");
    if (slash == NULL) {
        return;
    }
    /* in a build tree: ../tools/cli/ssda; installed: ssda beside ssda-demo */
    snprintf(guess, sizeof guess, "%.*s/../tools/cli/ssda", (int)(slash - argv0), argv0);
    real = realpath(guess, NULL);
    if (real == NULL || access(real, X_OK) != 0) {
        free(real);
        snprintf(guess, sizeof guess, "%.*s/ssda", (int)(slash - argv0), argv0);
        real = realpath(guess, NULL);
        if (real == NULL || access(real, X_OK) != 0) {
            free(real);
            return;
        }
    }
    if (getcwd(cwd, sizeof cwd) != NULL && strncmp(real, cwd, strlen(cwd)) == 0 &&
        real[strlen(cwd)] == '/') {
        snprintf(buf, len, "./%s", real + strlen(cwd) + 1);
    } else {
        snprintf(buf, len, "%s", real);
    }
    free(real);
}

static int run_synthetic(const demo_ctx_t *c, const char *argv0)
{
    /* 384 x 256 px; drift (2.5, -1.0) px/frame plus a vortex of 3.2 px/frame at
       48 px from its centre: motion up to about 6 px, inside the 32 x 32 areas' +-8 */
    const demo_wind_t wind = {2.5, -1.0, 0.62 * 384, 0.5 * 256, 3.2, 48.0};
    gray_image_t a = {0}, b = {0};
    demo_signal_t voice = {NULL, 0, 0};
    char p1[1024], p2[1024], pw[1024], pc[1024], tool[1024], label[4096];
    char e[512];
    int rc = 1;

    if (demo_make_clouds(384, 256, &wind, 2.0, &a, &b) != 0 ||
        demo_make_voice(16000, &voice) != 0) {
        fprintf(stderr, "ssda-demo: out of memory\n");
        goto done;
    }
    demo_path(c, "clouds_1.png", p1, sizeof p1);
    demo_path(c, "clouds_2.png", p2, sizeof p2);
    demo_path(c, "voice.wav", pw, sizeof pw);
    demo_path(c, "voice_f0.csv", pc, sizeof pc);
    if (png_write_gray(p1, &a, e, sizeof e) != 0 || png_write_gray(p2, &b, e, sizeof e) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", e);
        goto done;
    }
    if (demo_write_wav(pw, &voice) != 0 || demo_write_truth_csv(pc, 3.0) != 0) {
        goto done;
    }

    demo_heading(c, "1. Cloud tracking with SSDA (the seed's section 3)");
    snprintf(label, sizeof label,
             "%s and %s: 384 x 256 synthetic clouds, 8-bit;\n"
             "            the second is the first moved by a known wind: a drift of (2.5, -1.0) "
             "px\n            plus a vortex of 3.2 px, so the clouds also turn and shear; they "
             "brighten 4 %%;\n            noise sigma 2",
             p1, p2);
    if (demo_track(c, &a, &b, &wind, -1, 16, 1, "clouds_overlay.png", label) != 0) {
        goto done;
    }
    demo_heading(c, "2. Pitch with the AMDF and SSDA early exit (the seed's appendix)");
    snprintf(label, sizeof label,
             "%s: a 3 s synthetic voice at 16 kHz, glides 110 -> 180 Hz and\n"
             "            240 -> 160 Hz with vibrato, an unvoiced hiss and silences between",
             pw);
    if (demo_pitch(c, &voice, 1, NULL, "pitch_plot.png", label) != 0) {
        goto done;
    }
    demo_heading(c, "3. Registration by closed loops and Fourier descriptors (seed 001)");
    if (demo_symreg(c, "") != 0) {
        goto done;
    }
    demo_heading(c, "4. Colour segmentation: K-L transform and Gaussian mixtures (seed 004)");
    if (demo_segment(c) != 0) {
        goto done;
    }
    tool_path(argv0, tool, sizeof tool);
    demo_heading(c, "Next: the same on your own files");
    printf("   %s track FIRST.png SECOND.png --overlay vectors.png --json vectors.json\n", tool);
    printf("   %s pitch SOUND.wav --plot pitch.png --csv f0.csv\n", tool);
    printf("   %s segment PHOTO.png -o labels.png --plot hist.png --picture labels_colour.png\n",
           tool);
    printf("   for example on the files above:\n");
    printf("   %s track %s %s --exclude --overlay %s/my_vectors.png\n", tool, p1, p2, c->out_dir);
    printf("   %s pitch %s --ref %s --plot %s/my_pitch.png\n", tool, pw, pc, c->out_dir);
    printf("   %s symreg %s/aerial_1.png %s/aerial_2.png --overlay %s/my_loops.png -o "
           "%s/registered.png\n", tool, c->out_dir, c->out_dir, c->out_dir, c->out_dir);
    printf("   %s segment %s/scene.png --picture %s/my_labels.png\n", tool, c->out_dir,
           c->out_dir);
    printf("   (docs/cli.md lists every option)\n");
    rc = 0;
done:
    gray_image_free(&a);
    gray_image_free(&b);
    free(voice.samples);
    return rc;
}

static int run_files(const demo_ctx_t *c, const char *img1, const char *img2, const char *snd,
                     const char *ref, long mask, uint32_t step)
{
    char e[512], label[4096];
    int part = 0;
    if (img1 != NULL) {
        gray_image_t a = {0}, b = {0};
        png_source_info_t ia, ib;
        int rc;
        if (png_read_gray(img1, PNG_GRAY_NATIVE, &a, &ia, e, sizeof e) != 0 ||
            png_read_gray(img2, a.bits == 16 ? PNG_GRAY_16 : PNG_GRAY_NATIVE, &b, &ib, e,
                          sizeof e) != 0) {
            fprintf(stderr, "ssda-demo: %s\n", e);
            gray_image_free(&a);
            return 1;
        }
        if (b.bits == 16 && a.bits == 8) {
            gray_image_free(&a);
            if (png_read_gray(img1, PNG_GRAY_16, &a, &ia, e, sizeof e) != 0) {
                fprintf(stderr, "ssda-demo: %s\n", e);
                gray_image_free(&b);
                return 1;
            }
        }
        if (mask > (long)gray_image_max(&a)) {
            fprintf(stderr, "ssda-demo: --mask-value %ld is beyond these %u-bit images\n", mask,
                    a.bits);
            gray_image_free(&a);
            gray_image_free(&b);
            return 2;
        }
        demo_heading(c, "%d. Tracking your image pair", ++part);
        snprintf(label, sizeof label,
                 "%s (%u x %u, %s)\n         -> %s (%u x %u, %s),\n            read as "
                 "%u-bit gray; every window searched (no texture exclusion:\n            add "
                 "it with ssda track --exclude)",
                 img1, a.width, a.height, ia.description, img2, b.width, b.height,
                 ib.description, a.bits);
        rc = demo_track(c, &a, &b, NULL, mask, step, 0, "overlay.png", label);
        gray_image_free(&a);
        gray_image_free(&b);
        if (rc != 0) {
            return 1;
        }
    }
    if (snd != NULL) {
        demo_signal_t s = {NULL, 0, 0};
        wav_info_t wi;
        int rc;
        if (wav_read_mono_i16_ex(snd, &s.samples, &s.count, &s.rate, &wi, e, sizeof e) != 0) {
            fprintf(stderr, "ssda-demo: %s\n", e);
            return 1;
        }
        demo_heading(c, "%d. Pitch of your sound", ++part);
        snprintf(label, sizeof label, "%s:\n            %.2f s at %u Hz, %u channel%s (%s)", snd,
                 (double)s.count / s.rate, s.rate, wi.channels, wi.channels > 1 ? "s mixed" : "",
                 wi.format_name);
        rc = demo_pitch(c, &s, 0, ref, "pitch_plot.png", label);
        free(s.samples);
        if (rc != 0) {
            return 1;
        }
    }
    return 0;
}

/* What the command line names. */
typedef struct {
    const char *imgs[2], *snd, *ref;
    int nimg;
    long mask;
    uint32_t step;
} demo_args_t;

/* A number option's value in lo..hi into *v. Returns 0, or 2 (printed). */
static int number_arg(const char *name, const char *s, long lo, long hi, long *v)
{
    char *end;
    *v = strtol(s, &end, 10);
    if (*end != '\0' || *v < lo || *v > hi) {
        fprintf(stderr, "ssda-demo: bad %s '%s' (%ld..%ld)\n", name, s, lo, hi);
        return 2;
    }
    return 0;
}

/* A file argument: two PNGs and one sound at most. Returns 0 or the exit
   code (printed). */
static int file_arg(const char *a, demo_args_t *d)
{
    if (access(a, R_OK) != 0) {
        fprintf(stderr, "ssda-demo: cannot open '%s': %s\n", a, strerror(errno));
        return 1;
    }
    if (is_png(a)) {
        if (d->nimg == 2) {
            fprintf(stderr, "ssda-demo: give two images (FIRST and SECOND), not more\n");
            return 2;
        }
        d->imgs[d->nimg++] = a;
    } else {
        if (d->snd != NULL) {
            fprintf(stderr, "ssda-demo: give one sound file, not more\n");
            return 2;
        }
        d->snd = a; /* anything else is tried as a sound file */
    }
    return 0;
}

/* The command line into c and d. Returns -1 to go on, else the exit code
   (--help: 0). */
static int parse_args(int argc, char **argv, demo_ctx_t *c, demo_args_t *d)
{
    int i, rc = 0;
    long v;
    for (i = 1; i < argc && rc == 0; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            fputs(usage, stdout);
            return 0;
        } else if (strcmp(a, "--out") == 0 && i + 1 < argc) {
            c->out_dir = argv[++i];
        } else if (strcmp(a, "--quiet") == 0) {
            c->quiet = 1;
        } else if (strcmp(a, "--ref") == 0 && i + 1 < argc) {
            d->ref = argv[++i];
        } else if (strcmp(a, "--mask-value") == 0 && i + 1 < argc) {
            rc = number_arg("--mask-value", argv[++i], 0, 65535, &d->mask);
        } else if (strcmp(a, "--step") == 0 && i + 1 < argc) {
            rc = number_arg("--step", argv[++i], 1, 65535, &v);
            d->step = (uint32_t)v;
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "ssda-demo: unknown option '%s'\n\n%s", a, usage);
            return 2;
        } else {
            rc = file_arg(a, d);
        }
    }
    if (rc != 0) {
        return rc;
    }
    if (d->nimg == 1) {
        fprintf(stderr, "ssda-demo: give two images (FIRST and SECOND) to track\n");
        return 2;
    }
    return -1;
}

int main(int argc, char **argv)
{
    demo_ctx_t c = {0, 0, "ssda-demo-out"};
    demo_args_t d = {{NULL, NULL}, NULL, NULL, 0, -1, 16};
    int rc = parse_args(argc, argv, &c, &d);
    if (rc >= 0) {
        return rc;
    }
    if (mkdir(c.out_dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "ssda-demo: cannot create the output folder '%s': %s\n", c.out_dir,
                strerror(errno));
        return 1;
    }
    c.color = isatty(STDOUT_FILENO) && !c.quiet;
    if (c.quiet && freopen("/dev/null", "w", stdout) == NULL) {
        return 1;
    }
    printf("%sssda-demo %u.%u.%u%s: exact SSDA template matching and AMDF pitch, in integers\n",
           c.color ? "\033[1m" : "", (unsigned)SSDA_VERSION_MAJOR, (unsigned)SSDA_VERSION_MINOR,
           (unsigned)SSDA_VERSION_PATCH, c.color ? "\033[0m" : "");
    printf("output folder: %s/\n", c.out_dir);
    if (d.nimg == 0 && d.snd == NULL) {
        rc = run_synthetic(&c, argv[0]);
    } else {
        rc = run_files(&c, d.imgs[0], d.imgs[1], d.snd, d.ref, d.mask, d.step);
    }
    printf("\n");
    if (c.quiet && rc == 0) {
        fprintf(stderr, "ssda-demo: pictures written to %s/\n", c.out_dir);
    }
    return rc;
}
