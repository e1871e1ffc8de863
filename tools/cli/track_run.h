/*
 * track_run.h - the grid tracking shared by `ssda track` and `ssda compare`:
 * the track options, loading and pre-processing the pair, running
 * ssda_track, and writing the JSON and the overlay picture.
 */
#ifndef SSDA_TRACK_RUN_H
#define SSDA_TRACK_RUN_H

#include "cli.h"
#include "ssda/relax.h"
#include "draw.h"
#include "json_out.h"
#include "ssda/track.h"

typedef struct {
    ssda_track_config_t cfg;  /* library options as parsed */
    int grad;                 /* --grad: Fig. 8 operator on both images first */
    int exclude;              /* --exclude given */
    int exclude_argi;         /* argv index of --exclude (its value is optional) */
    int scan_given;           /* --scan given */
    int unique_given;         /* --unique RATIO given (not off) */
    int exclude_level_given;  /* LEVEL given (else the mean of SECOND) */
    uint32_t exclude_level;
    uint32_t exclude_count;   /* COUNT, 0 = window pixels / 16 */
    int have_mem;             /* --mem BYTES given */
    uint64_t mem;
    int have_roi;
    uint32_t roi[4];          /* X, Y, W, H */
    const char *json_path;    /* --json FILE|- or NULL */
    const char *overlay_path; /* --overlay OUT.png or NULL */
    double arrow_scale;       /* --arrow-scale, 0 = automatic */
    int quiet;
    uint32_t relax;           /* --relax N: relaxation labelling iterations, 0 = none */
    int relax_median;         /* --relax-median: the normalised median test */
    int relax_keep;           /* --relax-keep: SSDA_RELAX_KEEP */
    int metric;               /* --metric: TRACK_METRIC_* (track_metric.h), 0 = not given */
} track_opts_t;

/* Defaults: 16 px windows, 32 px areas, step 16, auto threshold, prediction
   from neighbours (median), no exclusion, no mask. */
void track_opts_init(track_opts_t *o);

/* If the current option of a is a track option, take it into opts (a
   track_opts_t) and return 1 (a->bad set on a usage error, already
   reported); else return 0. For cli_scan_options. */
int track_opts_take(cli_args_t *a, void *opts);

/* After the loop: FIRST.png and SECOND.png, and nothing more (an extra
   argument is named; right after --exclude, its value syntax is said).
   Returns CLI_OK or CLI_USAGE (printed). */
int track_check_positionals(const cli_args_t *a, const track_opts_t *o);

/* Everything track and compare do with argv: the options, FIRST and
   SECOND (*first, *second), --json and --overlay not both on stdout, the
   outputs writable. Returns CLI_OK, CLI_USAGE or CLI_INPUT (said), or -1
   after help() for --help. */
int track_parse_args(const char *cmd, int argc, char **argv, void (*help)(void),
                     track_opts_t *o, const char **first, const char **second);

/* The help text lines of the track options (for --help). */
extern const char track_opts_help[];

/* A finished run. */
typedef struct {
    gray_image_t first, second;   /* as tracked (after --grad) */
    gray_image_t second_orig;     /* SECOND as read, for the overlay */
    ssda_track_config_t cfg;      /* as run (mask value moved by --grad) */
    uint32_t texture_level;       /* --exclude level used (0 when not excluding) */
    uint32_t texture_min_count;   /* --exclude count used */
    ssda_track_grid_t grid;
    ssda_track_vector_t *vec;     /* grid.count entries */
    ssda_track_stats_t stats;
    uint64_t bytes_read;          /* image bytes the tracker's sources read */
    uint64_t reads;               /* --mem: read() calls of both sources */
    size_t arena_first;           /* --mem: plate memory of FIRST and SECOND, bytes */
    size_t arena_second;
    double secs;                  /* tracking time only */
    ssda_relax_vector_t *clean;   /* --relax / --relax-median: grid.count entries */
    uint32_t changed;             /* vectors the cleaning changed */
    int32_t *rho_q30;             /* --metric: rho per window (Q2.30), INT32_MIN if not searched */
    uint64_t metric_ops;          /* --metric: pixel ops of the correlation part */
    double metric_secs;           /* --metric: its time */
} track_result_t;

/* --relax N (iterations, SSDA_RELAX_KEEP with keep) or --relax-median on
   the field g into out (count entries): an ssda error code (SSDA_ERR_NULL
   when the work buffer cannot be had). */
int relax_field(const ssda_relax_grid_t *g, uint32_t iterations, int median, int keep,
                ssda_relax_vector_t *out, size_t count);

/*
 * Load FIRST and SECOND, apply --grad, track. Prints errors.
 * Returns CLI_OK, CLI_INPUT or CLI_USAGE (an option that does not fit the
 * images, e.g. a --roi outside them, or --mem in a build without streaming).
 */
int track_run(const char *cmd, const char *first_path, const char *second_path,
              const track_opts_t *o, track_result_t *r);
void track_result_free(track_result_t *r);

/* "ok", "flat", "ambiguous", "at_limit", "excluded", "masked", "edge". */
const char *track_status_name(int status);

/* Brute-force pixel operations over every window that is neither edge nor
   masked (each area searched in full, as without any texture test). */
uint64_t track_brute_ops(const track_result_t *r);

/* The work the run did, comparable with track_brute_ops: the searches'
   pixel_ops plus the pixels the window tests read (check_pixels). */
uint64_t track_work_ops(const track_result_t *r);

/* Median of the ok windows' sub-pixel dx (axis 0) or dy (axis 1), px; 0
   without ok windows. */
double track_median_motion(const track_result_t *r, int axis);

/* Write the JSON document (see docs/cli.md) to f (an output of the
   command's cli_outputs_t). ref (grid.count entries, may be NULL) adds
   "ref_dx", "ref_dy" to each OK window; extra (may be NULL; taken over and
   deleted) is an object whose members are added to the top level before
   "windows", e.g. {"compare":{...}}. Returns 0, or -1 (out of memory; said
   on stderr for cmd). */
int track_write_json(const char *cmd, FILE *f, const track_result_t *r, const track_opts_t *o,
                     const int32_t (*ref)[2], cJSON *extra);

/* Draw the vectors over SECOND into f (name for messages). truth
   (grid.count entries, may be NULL) is drawn as the reference arrows.
   Returns 0 or -1 (message printed). */
int track_write_overlay(const char *cmd, FILE *f, const char *name, const track_result_t *r,
                        const track_opts_t *o, const double (*truth)[2],
                        const char *truth_label, const char *title, const char *subtitle);

#endif /* SSDA_TRACK_RUN_H */
