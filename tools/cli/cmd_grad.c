/* cmd_grad.c - `ssda grad IN.png OUT.png`: the seed's Fig. 8 operator. */
#include "cli.h"
#include "ssda/grad.h"

#include <string.h>

static const char help[] =
    "usage: ssda grad IN.png OUT.png [options]\n"
    "\n"
    "The seed's differential pre-processing (Fig. 8) on each 3 x 3 neighbourhood\n"
    "      A B C\n"
    "      D E F      E' = |A+B+C-G-H-I| + |A+D+G-C-F-I|\n"
    "      G H I\n"
    "written as a gray PNG, scaled by a power of two (see --shift).\n"
    "E' <= 4 x M, M = the largest pixel value in IN.\n"
    "\n"
    "options:\n"
    "  --bits 8|16   output depth (default: the input's)\n"
    "  --shift N     store E' >> N, 0..31; values above the output maximum are\n"
    "                stored as the maximum (counted). Default: scale by the power\n"
    "                of two that brings 4 x M closest to the output maximum without\n"
    "                exceeding it, so nothing saturates and data using only part\n"
    "                of its depth is not left dark: E' >> N with the smallest such\n"
    "                N (full-range 8->8: 2, 16->16: 2, 16->8: 10, 8->16: 0), or\n"
    "                E' x 2^U when the depth is kept and even N = 0 leaves room\n"
    "                (12-bit counts, M 4095, in a 16-bit PNG -> 16-bit: E' x 4;\n"
    "                -> 8-bit: E' >> 6)\n"
    "  --crop        write only the (W-2) x (H-2) pixels that have a full\n"
    "                neighbourhood (default: same size as IN, 1-pixel border 0,\n"
    "                so coordinates match IN)\n"
    "  -h, --help    this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input, 2 usage.\n";

/* The largest pixel value actually present. */
static uint32_t data_max(const gray_image_t *img)
{
    uint32_t x, y, m = 0;
    for (y = 0; y < img->height; y++) {
        for (x = 0; x < img->width; x++) {
            uint32_t v = gray_image_get(img, x, y);
            m = v > m ? v : m;
        }
    }
    return m;
}

typedef struct {
    const char *in_path, *out_path;
    uint32_t bits;  /* 0: the input's */
    uint32_t shift;
    int have_shift, crop;
} grad_opts_t;

/* Parse argv. Returns CLI_OK, CLI_USAGE, or -1 after --help. */
static int parse_args(int argc, char **argv, grad_opts_t *o)
{
    cli_args_t a;
    const char *v;
    memset(o, 0, sizeof *o);
    cli_args_begin(&a, "grad", argc, argv);
    while (cli_next(&a) && !a.bad) {
        if (cli_flag(&a, "--help") || cli_flag(&a, "-h")) {
            fputs(help, stdout);
            return -1;
        } else if (cli_opt(&a, "--bits", &v)) {
            if (v != NULL &&
                (cli_parse_u32(v, 8, 16, &o->bits) != 0 || (o->bits != 8 && o->bits != 16))) {
                return cli_usage_error(a.cmd, "bad --bits '%s' (8 or 16)", v);
            }
        } else if (cli_opt(&a, "--shift", &v)) {
            if (v != NULL && cli_parse_u32(v, 0, 31, &o->shift) != 0) {
                return cli_usage_error(a.cmd, "bad --shift '%s' (0..31)", v);
            }
            o->have_shift = 1;
        } else if (cli_flag(&a, "--crop")) {
            o->crop = 1;
        } else if (cli_flag(&a, "--quiet") || cli_flag(&a, "-q")) {
            /* nothing long-running */
        } else {
            return cli_unknown(&a);
        }
    }
    if (a.bad || cli_positionals(&a, 2, "need IN.png and OUT.png") != CLI_OK) {
        return CLI_USAGE;
    }
    o->in_path = a.pos[0];
    o->out_path = a.pos[1];
    return CLI_OK;
}

/* The default scale (no --shift): from the data's own maximum, not its
   depth, so that 12-bit counts in a 16-bit PNG are not shifted as if they
   reached 65535 (near black): E' >> shift with the smallest shift that fits,
   or E' << *up when the depth is kept and even shift 0 leaves room. */
static void default_scale(uint32_t in_max, uint32_t bits, uint32_t in_bits, uint32_t *shift,
                          uint32_t *up)
{
    uint32_t out_max = bits == 16 ? 65535u : 255u;
    uint64_t top = 4u * (uint64_t)in_max;
    while ((top >> *shift) > out_max) {
        (*shift)++;
    }
    /* scale up only data that uses part of its own depth; 8 -> 16 keeps E' as is */
    while (*shift == 0 && bits == in_bits && top > 0 && (top << (*up + 1u)) <= out_max) {
        (*up)++;
    }
}

/* The operator of in into out (allocated here, same size with a border of
   0, or cropped), scaled by >> shift or << up. *sat: saturated pixels. */
static int apply(const grad_opts_t *o, const gray_image_t *in, uint32_t bits, uint32_t shift,
                 uint32_t up, gray_image_t *out, uint32_t *sat)
{
    ssda_view_t src;
    ssda_grad_out_t go;
    uint32_t x, y;
    size_t off;
    int e;
    if (gray_image_alloc(out, o->crop ? in->width - 2 : in->width,
                         o->crop ? in->height - 2 : in->height, (int)bits) != 0) {
        return cli_input_error("grad", "out of memory");
    }
    off = o->crop ? 0u : out->stride + bits / 8u; /* pixel (1, 1) of a same-size image */
    go.format = bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
    go.shift = (uint8_t)shift;
    go.stride = out->stride;
    go.data = (uint8_t *)out->pixels + off;
    go.size = (size_t)out->stride * out->height - off;
    gray_image_view(in, &src);
    e = ssda_grad(&src, &go, sat);
    if (e != SSDA_OK) {
        return cli_input_error("grad", "operator failed: %s", ssda_strerror(e));
    }
    for (y = 0; up > 0 && y < out->height; y++) { /* E' x 2^up: cannot overflow (above) */
        uint8_t *row = (uint8_t *)out->pixels + (size_t)y * out->stride;
        for (x = 0; x < out->width; x++) {
            if (bits == 16) {
                ((uint16_t *)(void *)row)[x] = (uint16_t)(((uint16_t *)(void *)row)[x] << up);
            } else {
                row[x] = (uint8_t)(row[x] << up);
            }
        }
    }
    return CLI_OK;
}

int cmd_grad(int argc, char **argv)
{
    grad_opts_t o;
    uint32_t bits, shift, sat = 0, in_max, up = 0;
    gray_image_t in = {0}, out = {0};
    char err[512];
    int rc = parse_args(argc, argv, &o);
    if (rc != CLI_OK) {
        return rc < 0 ? CLI_OK : rc; /* -1: --help */
    }
    cli_warn_png_name("grad", "output", o.out_path);
    if (cli_output_check("grad", o.out_path) != 0 ||
        cli_load_png("grad", o.in_path, PNG_GRAY_NATIVE, &in) != 0) {
        return CLI_INPUT;
    }
    if (in.width < 3 || in.height < 3) {
        rc = cli_input_error("grad", "'%s' is %u x %u; the operator needs at least 3 x 3",
                             o.in_path, in.width, in.height);
        goto done;
    }
    bits = o.bits != 0 ? o.bits : in.bits;
    in_max = data_max(&in);
    shift = o.shift;
    if (!o.have_shift) {
        default_scale(in_max, bits, in.bits, &shift, &up);
    }
    if ((rc = apply(&o, &in, bits, shift, up, &out, &sat)) != CLI_OK) {
        goto done;
    }
    if (png_write_gray(o.out_path, &out, err, sizeof err) != 0) {
        rc = cli_input_error("grad", "%s", err);
        goto done;
    }
    if (sat > 0) {
        fprintf(stderr, "ssda grad: note: %u pixels saturated at %u (E' >> %u); use a larger "
                        "--shift or --bits 16 to keep them\n",
                sat, gray_image_max(&out), shift);
    }
    if (!cli_is_stdout(o.out_path)) {
        printf("wrote %s: %u x %u, %u-bit, E' %s %u (input maximum %u)%s\n", o.out_path,
               out.width, out.height, bits, up ? "x" : ">>", up ? 1u << up : shift, in_max,
               o.crop ? " (cropped)" : ", 1-pixel border 0");
    }
done:
    gray_image_free(&in);
    gray_image_free(&out);
    return rc;
}
