/* main.c - `ssda`: exact SSDA template matching, grid tracking and AMDF pitch
   on PNG and WAV files. Dispatches to one file per subcommand (cmd_*.c). */
#define _POSIX_C_SOURCE 200809L /* SIGPIPE */
#include "cli.h"

#include <signal.h>
#include <string.h>

static const struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} commands[] = {
    {"match", cmd_match, "find where WINDOW.png fits best in SEARCH.png"},
    {"track", cmd_track, "motion vectors on a grid between two images (cloud tracking)"},
    {"compare", cmd_compare, "SSDA vectors vs exhaustive normalised cross-correlation"},
    {"grad", cmd_grad, "the seed's Fig. 8 differential operator on an image"},
    {"pitch", cmd_pitch, "f0 track of a WAV (or any libsndfile format) by AMDF"},
    {"segment", cmd_segment, "colour segmentation: K-L transform + Gaussian-mixture histograms"},
    {"symreg", cmd_symreg, "register two images by their closed loops (rotation, scale, gain)"},
    {"shape", cmd_shape, "Fourier-descriptor match of two silhouettes: scale, rotation, E2"},
};
#define NCOMMANDS (sizeof commands / sizeof commands[0])

static void usage(FILE *f)
{
    size_t i;
    fprintf(f, "usage: ssda <command> [options]   (ssda <command> --help for details)\n\n");
    for (i = 0; i < NCOMMANDS; i++) {
        fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].summary);
    }
    fprintf(f, "\nExit codes: 0 ok, 1 bad input or failure (no output file left), 2 usage.\n"
               "Images: any PNG (gray, RGB, palette, alpha ignored; 1-16 bit), read as 8- or\n"
               "16-bit gray. Documentation: docs/cli.md.\n");
}

int main(int argc, char **argv)
{
    size_t i;
    /* A reader that stops early (ssda ... --csv - | head) must not kill the
       tool before its file outputs are renamed into place: writes to the
       closed pipe fail with EPIPE instead, which the output code treats as
       the quiet end of standard output. */
    signal(SIGPIPE, SIG_IGN);
    cli_guard_std_fds();
    if (argc < 2) {
        usage(stderr);
        return CLI_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        if (argc >= 3) { /* ssda help CMD */
            for (i = 0; i < NCOMMANDS; i++) {
                if (strcmp(argv[2], commands[i].name) == 0) {
                    char *sub[] = {argv[2], (char *)"--help", NULL};
                    return cli_finish_stdout(commands[i].name, commands[i].run(2, sub));
                }
            }
        }
        usage(stdout);
        return cli_finish_stdout("--help", CLI_OK);
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("ssda %u.%u.%u\n", (unsigned)SSDA_VERSION_MAJOR, (unsigned)SSDA_VERSION_MINOR,
               (unsigned)SSDA_VERSION_PATCH);
        return cli_finish_stdout("--version", CLI_OK);
    }
    for (i = 0; i < NCOMMANDS; i++) {
        if (strcmp(argv[1], commands[i].name) == 0) {
            /* every command: output lost on stdout is a failure */
            return cli_finish_stdout(commands[i].name, commands[i].run(argc - 1, argv + 1));
        }
    }
    fprintf(stderr, "ssda: unknown command '%s'\n\n", argv[1]);
    usage(stderr);
    return CLI_USAGE;
}
