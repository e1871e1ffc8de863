/* cli_args.c - option scanning, value parsing and messages for `ssda`. */
#define _POSIX_C_SOURCE 200809L /* fcntl, O_ACCMODE */
#include "cli.h"
#include "parallel.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void cli_args_begin(cli_args_t *a, const char *cmd, int argc, char **argv)
{
    memset(a, 0, sizeof *a);
    a->cmd = cmd;
    a->argc = argc;
    a->argv = argv;
    a->i = 1; /* argv[0] is the subcommand */
}

int cli_next(cli_args_t *a)
{
    while (a->i < a->argc) {
        const char *s = a->argv[a->i++];
        const char *eq;
        if (!a->options_done && strcmp(s, "--") == 0) {
            a->options_done = 1;
            a->dashdash_argi = a->i - 1;
            continue;
        }
        /* "-" alone is a positional (stdout/stdin); "-5" is not an option either */
        if (a->options_done || s[0] != '-' || s[1] == '\0' || (s[1] >= '0' && s[1] <= '9')) {
            if (a->npos >= CLI_MAX_POSITIONAL) {
                cli_usage_error(a->cmd, "too many arguments ('%s')", s);
                a->bad = 1;
                return 0;
            }
            a->pos_argi[a->npos] = a->i - 1;
            a->pos[a->npos++] = s;
            continue;
        }
        a->name = s;
        eq = strchr(s, '=');
        a->name_len = eq != NULL ? (size_t)(eq - s) : strlen(s);
        a->inline_value = eq != NULL ? eq + 1 : NULL;
        return 1;
    }
    return 0;
}

static int name_is(const cli_args_t *a, const char *name)
{
    return strlen(name) == a->name_len && strncmp(a->name, name, a->name_len) == 0;
}

int cli_flag(cli_args_t *a, const char *name)
{
    if (!name_is(a, name)) {
        return 0;
    }
    if (a->inline_value != NULL) {
        cli_usage_error(a->cmd, "option %s takes no value", name);
        a->bad = 1;
    }
    return 1;
}

int cli_opt(cli_args_t *a, const char *name, const char **value)
{
    if (!name_is(a, name)) {
        return 0;
    }
    if (a->inline_value != NULL) {
        *value = a->inline_value;
    } else if (a->i < a->argc) {
        *value = a->argv[a->i++];
    } else {
        cli_usage_error(a->cmd, "option %s needs a value", name);
        a->bad = 1;
        *value = NULL;
    }
    return 1;
}

int cli_unknown(cli_args_t *a)
{
    return cli_usage_error(a->cmd, "unknown option '%.*s'", (int)a->name_len, a->name);
}

int cli_scan_options(cli_args_t *a, void (*help)(void), int (*take)(cli_args_t *a, void *opts),
                     void *opts)
{
    while (cli_next(a)) {
        if (cli_flag(a, "--help") || cli_flag(a, "-h")) {
            help();
            return -1;
        }
        if (!take(a, opts)) {
            return cli_unknown(a);
        }
        if (a->bad) {
            return CLI_USAGE;
        }
    }
    return a->bad ? CLI_USAGE : CLI_OK;
}

int cli_positionals(const cli_args_t *a, int n, const char *need)
{
    if (a->npos > n) {
        const char *x = a->pos[n];
        int after = a->dashdash_argi != 0 && a->pos_argi[n] > a->dashdash_argi && x[0] == '-';
        return cli_usage_error(a->cmd, "unexpected argument '%s'%s", x,
                               after ? " (after '--' every argument is a file name)" : "");
    }
    if (a->npos < n) {
        return cli_usage_error(a->cmd, "%s", need);
    }
    return CLI_OK;
}

int cli_usage_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "ssda %s: ", cmd);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\nTry 'ssda %s --help'.\n", cmd);
    return CLI_USAGE;
}

int cli_input_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "ssda %s: ", cmd);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return CLI_INPUT;
}

/* ---- values ---- */

int cli_parse_i32(const char *s, int32_t lo, int32_t hi, int32_t *out)
{
    char *end;
    long long v;
    if (s == NULL || *s == '\0') {
        return -1;
    }
    errno = 0;
    v = strtoll(s, &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) {
        return -1;
    }
    *out = (int32_t)v;
    return 0;
}

int cli_parse_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out)
{
    char *end;
    unsigned long long v;
    if (s == NULL || *s < '0' || *s > '9') { /* no sign, no space */
        return -1;
    }
    errno = 0;
    v = strtoull(s, &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) {
        return -1;
    }
    *out = (uint32_t)v;
    return 0;
}

int cli_parse_double(const char *s, double lo, double hi, double *out)
{
    char *end;
    double v;
    if (s == NULL || *s == '\0') {
        return -1;
    }
    errno = 0;
    v = strtod(s, &end);
    if (errno != 0 || *end != '\0' || !(v >= lo && v <= hi)) {
        return -1;
    }
    *out = v;
    return 0;
}

int cli_parse_pair(const char *s, int32_t lo, int32_t hi, int32_t *x, int32_t *y)
{
    char buf[64];
    char *comma;
    int32_t a, b;
    if (s == NULL || strlen(s) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    comma = strchr(buf, ',');
    if (comma == NULL) {
        return -1;
    }
    *comma = '\0';
    if (cli_parse_i32(buf, lo, hi, &a) != 0 || cli_parse_i32(comma + 1, lo, hi, &b) != 0) {
        return -1;
    }
    *x = a;
    *y = b;
    return 0;
}

int cli_parse_list_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out, int n)
{
    char buf[128];
    char *p, *next;
    uint32_t tmp[8];
    int k;
    if (s == NULL || n > 8 || strlen(s) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    p = buf;
    for (k = 0; k < n; k++) {
        next = strchr(p, ',');
        if ((next == NULL) != (k == n - 1)) {
            return -1;
        }
        if (next != NULL) {
            *next = '\0';
        }
        if (cli_parse_u32(p, lo, hi, &tmp[k]) != 0) {
            return -1;
        }
        p = next != NULL ? next + 1 : p;
    }
    memcpy(out, tmp, (size_t)n * sizeof *out);
    return 0;
}

/* K (safety factor) in Q8.8, 0 < K < 256. */
static int parse_k_q8(const char *s, uint16_t *k_q8)
{
    double k;
    if (cli_parse_double(s, 1.0 / 256.0, 255.99, &k) != 0) {
        return -1;
    }
    *k_q8 = (uint16_t)lround(k * 256.0);
    return 0;
}

int cli_parse_threshold(const char *s, ssda_match_config_t *cfg)
{
    ssda_match_config_t c = *cfg;
    char buf[96];
    char *arg, *arg2;
    if (s == NULL || strlen(s) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    arg = strchr(buf, ':');
    if (arg != NULL) {
        *arg++ = '\0';
    }
    arg2 = arg != NULL ? strchr(arg, ':') : NULL;
    if (arg2 != NULL) {
        *arg2++ = '\0';
    }
    c.k_q8 = 0;
    if (strcmp(buf, "auto") == 0 && arg == NULL) {
        c.threshold = SSDA_THRESHOLD_AUTO;
    } else if (strcmp(buf, "none") == 0 && arg == NULL) {
        c.threshold = SSDA_THRESHOLD_NONE;
    } else if (strcmp(buf, "fixed") == 0 && arg != NULL && arg2 == NULL) {
        char *end;
        unsigned long long t;
        if (*arg < '0' || *arg > '9') {
            return -1;
        }
        errno = 0;
        t = strtoull(arg, &end, 10);
        if (errno != 0 || *end != '\0') {
            return -1;
        }
        c.threshold = SSDA_THRESHOLD_FIXED;
        c.fixed_threshold = (uint64_t)t;
    } else if (strcmp(buf, "ramp") == 0 && arg != NULL) {
        double lambda;
        /* lambda in SAD units per pixel, Q24.8 */
        if (cli_parse_double(arg, 1.0 / 256.0, 16777215.0, &lambda) != 0) {
            return -1;
        }
        c.threshold = SSDA_THRESHOLD_RAMP;
        c.lambda_q8 = (uint32_t)llround(lambda * 256.0);
        if (arg2 != NULL && parse_k_q8(arg2, &c.k_q8) != 0) {
            return -1;
        }
    } else if (strcmp(buf, "auto-ramp") == 0 && arg2 == NULL) {
        c.threshold = SSDA_THRESHOLD_AUTO_RAMP;
        if (arg != NULL && parse_k_q8(arg, &c.k_q8) != 0) {
            return -1;
        }
    } else {
        return -1;
    }
    *cfg = c;
    return 0;
}

int cli_parse_scan(const char *s, ssda_match_config_t *cfg)
{
    if (strcmp(s, "raster") == 0) {
        cfg->scan = SSDA_SCAN_RASTER;
    } else if (strcmp(s, "predict") == 0) {
        cfg->scan = SSDA_SCAN_PREDICT;
    } else if (strcmp(s, "coarse") == 0) {
        cfg->scan = SSDA_SCAN_COARSE;
    } else {
        return -1;
    }
    return 0;
}

int cli_parse_order(const char *s, ssda_match_config_t *cfg)
{
    if (strcmp(s, "rows") == 0) {
        cfg->order = SSDA_ORDER_ROWS;
    } else if (strcmp(s, "spread") == 0) {
        cfg->order = SSDA_ORDER_SPREAD;
    } else {
        return -1;
    }
    return 0;
}

void cli_threshold_name(const ssda_match_config_t *cfg, char *buf, size_t len)
{
    double k = (cfg->k_q8 != 0 ? cfg->k_q8 : SSDA_DEFAULT_K_Q8) / 256.0;
    switch (cfg->threshold) {
    case SSDA_THRESHOLD_NONE: snprintf(buf, len, "none"); break;
    case SSDA_THRESHOLD_FIXED:
        snprintf(buf, len, "fixed:%llu", (unsigned long long)cfg->fixed_threshold);
        break;
    case SSDA_THRESHOLD_RAMP:
        snprintf(buf, len, "ramp:%g:%g", cfg->lambda_q8 / 256.0, k);
        break;
    case SSDA_THRESHOLD_AUTO_RAMP: snprintf(buf, len, "auto-ramp:%g", k); break;
    default: snprintf(buf, len, "auto"); break;
    }
}

const char *cli_scan_name(const ssda_match_config_t *cfg)
{
    return cfg->scan == SSDA_SCAN_PREDICT  ? "predict"
           : cfg->scan == SSDA_SCAN_COARSE ? "coarse"
                                           : "raster";
}

/* ---- outputs ---- */

void cli_outputs_begin(cli_outputs_t *o, const char *cmd)
{
    memset(o, 0, sizeof *o);
    o->cmd = cmd;
}

static const char *shown_name(const char *path)
{
    return strcmp(path, "-") == 0 ? "standard output" : path;
}

FILE *cli_outputs_open(cli_outputs_t *o, const char *path)
{
    if (o->n >= CLI_MAX_OUTPUTS) {
        cli_input_error(o->cmd, "internal error: too many outputs");
        return NULL;
    }
    if (atomic_file_open(&o->f[o->n], path) != 0) {
        cli_input_error(o->cmd, "cannot create '%s': %s", shown_name(path),
                        atomic_file_strerror(errno));
        return NULL;
    }
    o->path[o->n] = path;
    return o->f[o->n++].fp;
}

int cli_outputs_commit(cli_outputs_t *o)
{
    int failed = -1, n = o->n;
    o->n = 0;
    if (atomic_file_commit_all(o->f, n, &failed) != 0) {
        int e = errno;
        return cli_input_error(o->cmd, "cannot write '%s': %s",
                               failed >= 0 ? shown_name(o->path[failed]) : "?",
                               atomic_file_strerror(e));
    }
    return CLI_OK;
}

void cli_outputs_abort(cli_outputs_t *o)
{
    int i;
    for (i = 0; i < o->n; i++) {
        atomic_file_abort(&o->f[i]);
    }
    o->n = 0;
}

int cli_output_check(const char *cmd, const char *path)
{
    if (path != NULL && atomic_file_check(path) != 0) {
        cli_input_error(cmd, "cannot write '%s': %s", shown_name(path),
                        atomic_file_strerror(errno));
        return -1;
    }
    return 0;
}

int cli_is_stdout(const char *path)
{
    return path != NULL && (strcmp(path, "-") == 0 || strcmp(path, "/dev/stdout") == 0 ||
                            strcmp(path, "/dev/fd/1") == 0 ||
                            strcmp(path, "/proc/self/fd/1") == 0);
}

/* ---- standard streams ---- */

void cli_guard_std_fds(void)
{
    int fd;
    for (fd = 0; fd <= 2; fd++) { /* open() takes the lowest free number */
        if (fcntl(fd, F_GETFD) == -1 && errno == EBADF) {
            int n = open("/dev/null", O_RDONLY);
            if (n >= 0 && n != fd) {
                close(n);
            }
        }
    }
}

int cli_finish_stdout(const char *cmd, int rc)
{
    int e;
    errno = 0;
    if ((fflush(stdout) == 0 && !ferror(stdout)) || errno == EPIPE ||
        atomic_file_stdout_gone()) {
        return rc;
    }
    e = errno != 0 ? errno : atomic_file_stdout_errno();
    if (rc == CLI_OK) {
        cli_input_error(cmd, "cannot write standard output: %s", strerror(e));
        rc = CLI_INPUT;
    }
    return rc;
}

void cli_warn_png_name(const char *cmd, const char *what, const char *path)
{
    static const char ext[] = ".png";
    size_t n = path != NULL ? strlen(path) : 0, i;
    int match = n >= 4;
    if (path == NULL || strcmp(path, "-") == 0) {
        return;
    }
    for (i = 0; match && i < 4; i++) {
        match = tolower((unsigned char)path[n - 4 + i]) == ext[i];
    }
    if (!match) { /* a viewer going by the name would misread the file */
        fprintf(stderr, "ssda %s: warning: %s '%s' does not end in .png; it is written as "
                "PNG data all the same\n", cmd, what, path);
    }
}

const char *cli_basename(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash != NULL && slash[1] != '\0' ? slash + 1 : path;
}

/* ---- inputs ---- */

int cli_load_png(const char *cmd, const char *path, png_gray_depth_t depth, gray_image_t *img)
{
    char err[512];
    if (png_read_gray(path, depth, img, NULL, err, sizeof err) != 0) {
        cli_input_error(cmd, "%s", err);
        return -1;
    }
    return 0;
}

/* The threads a command may use (--threads; 0 until set: every core). */
static unsigned g_threads;

void cli_set_threads(unsigned threads)
{
    g_threads = threads;
}

unsigned cli_threads(void)
{
    return g_threads != 0u ? g_threads : parallel_cores();
}

/* One PNG read at its native depth, on its own thread. */
typedef struct {
    const char *path;
    gray_image_t img;
    int rc;
    char err[512];
} png_job_t;

static void *png_job(void *arg)
{
    png_job_t *j = arg;
    j->rc = png_read_gray(j->path, PNG_GRAY_NATIVE, &j->img, NULL, j->err, sizeof j->err);
    return NULL;
}

/* The largest sample of a 16-bit image. */
static uint32_t largest_sample(const gray_image_t *img)
{
    uint32_t x, y, top = 0;
    for (y = 0; y < img->height; y++) {
        for (x = 0; x < img->width; x++) {
            const uint32_t v = gray_image_get(img, x, y);
            top = v > top ? v : top;
        }
    }
    return top;
}

/* *img (8-bit) replaced by its 16-bit copy, v * 257: what png_read_gray
   gives for PNG_GRAY_16 from any source it decodes to 8 bits. */
static int widen_to_16(gray_image_t *img)
{
    gray_image_t w;
    uint32_t x, y;
    if (gray_image_alloc(&w, img->width, img->height, 16) != 0) {
        return -1;
    }
    for (y = 0; y < img->height; y++) {
        const uint8_t *in = (const uint8_t *)img->pixels + (size_t)y * img->stride;
        uint16_t *out = (uint16_t *)(void *)((uint8_t *)w.pixels + (size_t)y * w.stride);
        for (x = 0; x < img->width; x++) {
            out[x] = (uint16_t)(in[x] * 257u);
        }
    }
    gray_image_free(img);
    *img = w;
    return 0;
}

int cli_load_png_pair(const char *cmd, const char *p1, const char *p2, gray_image_t *a,
                      gray_image_t *b)
{
    png_job_t j[2];
    pthread_t tid;
    int threaded;
    memset(j, 0, sizeof j);
    j[0].path = p1;
    j[1].path = p2;
    /* decoding is most of a tracking run's time outside the search: the
       two files at once when a second core may be used */
    threaded = cli_threads() > 1u && pthread_create(&tid, NULL, png_job, &j[1]) == 0;
    (void)png_job(&j[0]);
    if (threaded) {
        pthread_join(tid, NULL);
    } else {
        (void)png_job(&j[1]);
    }
    if (j[0].rc != 0 || j[1].rc != 0) { /* FIRST's error first, as read in order */
        cli_input_error(cmd, "%s", j[0].rc != 0 ? j[0].err : j[1].err);
        if (j[0].rc == 0) {
            gray_image_free(&j[0].img);
        }
        if (j[1].rc == 0) {
            gray_image_free(&j[1].img);
        }
        return -1;
    }
    if (j[0].img.bits != j[1].img.bits) {
        /* v x 257 matches a 16-bit image of the full range; raw counts of
           fewer bits (12-bit satellite data) then sit far below it */
        const gray_image_t *wide = j[0].img.bits == 16 ? &j[0].img : &j[1].img;
        const uint32_t top = largest_sample(wide);
        if (top < 32768u) {
            fprintf(stderr, "ssda %s: note: '%s' is 8-bit, widened to 16 (v x 257), but the "
                    "16-bit '%s' reaches only %u: their levels differ (SAD compares levels; "
                    "the correlation, --metric ncc, does not mind)\n", cmd,
                    wide == &j[0].img ? p2 : p1, wide == &j[0].img ? p1 : p2, top);
        }
    }
    if ((j[0].img.bits != j[1].img.bits) &&
        widen_to_16(j[0].img.bits == 8 ? &j[0].img : &j[1].img) != 0) {
        gray_image_free(&j[0].img);
        gray_image_free(&j[1].img);
        cli_input_error(cmd, "out of memory");
        return -1;
    }
    *a = j[0].img;
    *b = j[1].img;
    return 0;
}
