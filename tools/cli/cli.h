/*
 * cli.h - shared parts of the `ssda` command-line tool: exit codes, option
 * scanning, value parsers, input loading. One file per subcommand (cmd_*.c).
 */
#ifndef SSDA_CLI_H
#define SSDA_CLI_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "atomic_file.h"
#include "png_io.h"
#include "ssda/match.h"

/* Exit codes (docs/cli.md). */
enum {
    CLI_OK = 0,    /* success */
    CLI_INPUT = 1, /* bad input file or a failure while running; no output file left */
    CLI_USAGE = 2  /* bad command line */
};

/* ---- option scanning ----
 * Options are "--name VALUE" or "--name=VALUE"; everything else is a
 * positional argument; "--" ends the options. Typical loop:
 *     cli_args_t a;
 *     cli_args_begin(&a, "match", argc, argv);
 *     while (cli_next(&a)) {
 *         if (cli_flag(&a, "--json")) json = 1;
 *         else if (cli_opt(&a, "--scan", &v)) ...;
 *         else return cli_unknown(&a);
 *     }
 */
#define CLI_MAX_POSITIONAL 8

typedef struct {
    const char *cmd;   /* subcommand name, for messages */
    int argc;
    char **argv;
    int i;             /* next argv index */
    const char *name;  /* current option name (without "=value") */
    size_t name_len;
    const char *inline_value; /* value after '=' or NULL */
    int bad;           /* a usage error was already reported */
    const char *pos[CLI_MAX_POSITIONAL];
    int pos_argi[CLI_MAX_POSITIONAL]; /* argv index of each positional */
    int npos;
    int options_done;
    int dashdash_argi; /* argv index of "--", 0 if none */
} cli_args_t;

void cli_args_begin(cli_args_t *a, const char *cmd, int argc, char **argv);
/* Advance to the next option; positionals are collected on the way.
   Returns 0 at the end of argv or after a usage error (check a->bad). */
int cli_next(cli_args_t *a);
/* The current option is a flag called name (a value is a usage error). */
int cli_flag(cli_args_t *a, const char *name);
/* The current option is name, taking a value (next argument or "=VALUE"). */
int cli_opt(cli_args_t *a, const char *name, const char **value);
/* Report the current option as unknown; returns CLI_USAGE. */
int cli_unknown(cli_args_t *a);
/* The whole option loop of a subcommand whose options one function
   takes (after cli_args_begin): --help and -h call help() and return -1;
   every other option goes to take(a, opts), which returns 1 when it took
   it (a->bad set on a bad value, already said) and 0 when it does not
   know it (then said as unknown). Returns CLI_OK (the positionals
   collected in *a), CLI_USAGE, or -1 after the help. */
int cli_scan_options(cli_args_t *a, void (*help)(void), int (*take)(cli_args_t *a, void *opts),
                     void *opts);
/* After the loop: exactly n positionals? More: "unexpected argument 'X'"
   naming the first extra one (after "--" every argument is a file: said
   when X looks like an option); fewer: need (e.g. "need FIRST.png and
   SECOND.png"). Returns CLI_OK or CLI_USAGE (printed). */
int cli_positionals(const cli_args_t *a, int n, const char *need);

/* Print "ssda CMD: message" and a hint to stderr; returns CLI_USAGE. */
int cli_usage_error(const char *cmd, const char *fmt, ...);
/* Print "ssda CMD: message" to stderr; returns CLI_INPUT. */
int cli_input_error(const char *cmd, const char *fmt, ...);

/* ---- value parsers: 0 on success, -1 (nothing written) otherwise ---- */
int cli_parse_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out);
int cli_parse_i32(const char *s, int32_t lo, int32_t hi, int32_t *out);
int cli_parse_double(const char *s, double lo, double hi, double *out);
/* "X,Y" of integers in [lo, hi]. */
int cli_parse_pair(const char *s, int32_t lo, int32_t hi, int32_t *x, int32_t *y);
/* n comma-separated unsigned integers in [lo, hi]. */
int cli_parse_list_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out, int n);

/* --threshold none|fixed:T|ramp:LAMBDA[:K]|auto|auto-ramp[:K] into cfg. */
int cli_parse_threshold(const char *s, ssda_match_config_t *cfg);
/* --scan raster|predict|coarse. */
int cli_parse_scan(const char *s, ssda_match_config_t *cfg);
/* --order rows|spread. */
int cli_parse_order(const char *s, ssda_match_config_t *cfg);
/* Name of cfg's threshold and scan, for output ("auto", "ramp:2:2", ...). */
void cli_threshold_name(const ssda_match_config_t *cfg, char *buf, size_t len);
const char *cli_scan_name(const ssda_match_config_t *cfg);

/* Warn on stderr when path (an output written as PNG; what names it, e.g.
   "--overlay") does not end in .png, any case. "-" and NULL are fine. */
void cli_warn_png_name(const char *cmd, const char *what, const char *path);

/* The file name of a path, without its folders (for picture titles). */
const char *cli_basename(const char *path);

/* ---- threads ---- */
/* The thread count a command's --threads set (0: every core, the default);
   cli_threads() is that count, at least 1. */
void cli_set_threads(unsigned threads);
unsigned cli_threads(void);

/* ---- inputs ---- */
/* Read a PNG as gray (depth as png_io). Prints the error; returns 0 or -1. */
int cli_load_png(const char *cmd, const char *path, png_gray_depth_t depth, gray_image_t *img);
/* Read two PNGs of a common depth (an 8-bit one is widened to 16 if the
   other is 16-bit, v * 257), on two threads when cli_threads() > 1 (the
   same images either way). Prints errors (FIRST's if both fail); returns
   0 or -1. */
int cli_load_png_pair(const char *cmd, const char *p1, const char *p2, gray_image_t *a,
                      gray_image_t *b);

/* ---- output files: all or nothing ----
 * Each output is written to a temp file beside its final name; only when
 * every output is complete are they renamed into place (atomic_file.h: a
 * rename that still fails puts back what the others replaced). On any
 * failure, cli_outputs_abort deletes the temp files: no output is created or
 * changed. FIFOs, character devices and /dev/std* are written directly. */
#define CLI_MAX_OUTPUTS 16

typedef struct {
    const char *cmd;
    atomic_file_t f[CLI_MAX_OUTPUTS];
    const char *path[CLI_MAX_OUTPUTS]; /* as given, for messages */
    int n;
} cli_outputs_t;

void cli_outputs_begin(cli_outputs_t *o, const char *cmd);
/* Open one more output ("-" = stdout). Prints the error; NULL on failure. */
FILE *cli_outputs_open(cli_outputs_t *o, const char *path);
/* Rename every output into place. Returns CLI_OK or CLI_INPUT (printed). */
int cli_outputs_commit(cli_outputs_t *o);
/* Delete every temp file. */
void cli_outputs_abort(cli_outputs_t *o);

/* Can path (may be NULL: nothing to check) be written as an output? Run
   before the work, so that a directory or a missing folder is said at once.
   Prints the error; returns 0 or -1. */
int cli_output_check(const char *cmd, const char *path);
/* Does path name standard output ("-", /dev/stdout, /dev/fd/1)? Then the
   text summary is not printed. NULL is not. */
int cli_is_stdout(const char *path);

/* ---- standard streams ---- */
/* At start: a closed descriptor 0, 1 or 2 is opened read-only on /dev/null,
   so that no output file gets its number and a write to a closed stdout
   fails (EBADF) instead of landing in that file. */
void cli_guard_std_fds(void);
/* At exit: flush stdout; if anything written to it was lost (a full disk,
   a closed stdout; not a reader that has gone, EPIPE), say so and turn a
   success into CLI_INPUT. Returns the exit code. */
int cli_finish_stdout(const char *cmd, int rc);

/* ---- subcommands: (argc, argv) after the subcommand name; return an exit code ---- */
int cmd_match(int argc, char **argv);
int cmd_flow(int argc, char **argv);
int cmd_track(int argc, char **argv);
int cmd_compare(int argc, char **argv);
int cmd_grad(int argc, char **argv);
int cmd_pitch(int argc, char **argv);
int cmd_segment(int argc, char **argv);
int cmd_symreg(int argc, char **argv);
int cmd_shape(int argc, char **argv);
int cmd_register(int argc, char **argv);

#endif /* SSDA_CLI_H */
