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
    "written as a gray PNG. E' <= 4 x the input maximum; E' >> SHIFT is stored.\n"
    "\n"
    "options:\n"
    "  --bits 8|16   output depth (default: the input's)\n"
    "  --shift N     store E' >> N, 0..31 (default: the smallest that never\n"
    "                saturates: 8->8 2, 8->16 0, 16->16 2, 16->8 10); values\n"
    "                above the output maximum are stored as the maximum (counted)\n"
    "  --crop        write only the (W-2) x (H-2) pixels that have a full\n"
    "                neighbourhood (default: same size as IN, 1-pixel border 0,\n"
    "                so coordinates match IN)\n"
    "  -h, --help    this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input, 2 usage.\n";

int cmd_grad(int argc, char **argv)
{
    cli_args_t a;
    const char *v;
    uint32_t bits = 0, shift = 0, sat = 0;
    int have_shift = 0, crop = 0, rc = CLI_INPUT, e;
    gray_image_t in = {0}, out = {0};
    ssda_view_t src;
    ssda_grad_out_t go;
    char err[512];

    cli_args_begin(&a, "grad", argc, argv);
    while (cli_next(&a)) {
        if (cli_flag(&a, "--help") || cli_flag(&a, "-h")) {
            fputs(help, stdout);
            return CLI_OK;
        } else if (cli_opt(&a, "--bits", &v)) {
            if (v != NULL && (cli_parse_u32(v, 8, 16, &bits) != 0 || (bits != 8 && bits != 16))) {
                return cli_usage_error(a.cmd, "bad --bits '%s' (8 or 16)", v);
            }
        } else if (cli_opt(&a, "--shift", &v)) {
            if (v != NULL && cli_parse_u32(v, 0, 31, &shift) != 0) {
                return cli_usage_error(a.cmd, "bad --shift '%s' (0..31)", v);
            }
            have_shift = 1;
        } else if (cli_flag(&a, "--crop")) {
            crop = 1;
        } else if (cli_flag(&a, "--quiet") || cli_flag(&a, "-q")) {
            /* nothing long-running */
        } else {
            return cli_unknown(&a);
        }
        if (a.bad) {
            return CLI_USAGE;
        }
    }
    if (a.bad) {
        return CLI_USAGE;
    }
    if (a.npos != 2) {
        return cli_usage_error(a.cmd, "need IN.png and OUT.png");
    }
    if (cli_load_png(a.cmd, a.pos[0], PNG_GRAY_NATIVE, &in) != 0) {
        return CLI_INPUT;
    }
    if (in.width < 3 || in.height < 3) {
        cli_input_error(a.cmd, "'%s' is %u x %u; the operator needs at least 3 x 3", a.pos[0],
                        in.width, in.height);
        goto done;
    }
    if (bits == 0) {
        bits = in.bits;
    }
    go.format = bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
    go.shift = (uint8_t)(have_shift ? shift
                                    : SSDA_GRAD_SAFE_SHIFT(in.bits == 16 ? SSDA_PIX_U16
                                                                          : SSDA_PIX_U8,
                                                           go.format));
    if (gray_image_alloc(&out, crop ? in.width - 2 : in.width, crop ? in.height - 2 : in.height,
                         (int)bits) != 0) {
        cli_input_error(a.cmd, "out of memory");
        goto done;
    }
    go.stride = out.stride;
    if (crop) {
        go.data = out.pixels;
        go.size = (size_t)out.stride * out.height;
    } else { /* pixel (1, 1) of a same-size image */
        size_t off = out.stride + bits / 8u;
        go.data = (uint8_t *)out.pixels + off;
        go.size = (size_t)out.stride * out.height - off;
    }
    gray_image_view(&in, &src);
    e = ssda_grad(&src, &go, &sat);
    if (e != SSDA_OK) {
        cli_input_error(a.cmd, "operator failed: %s", ssda_strerror(e));
        goto done;
    }
    if (png_write_gray(a.pos[1], &out, err, sizeof err) != 0) {
        cli_input_error(a.cmd, "%s", err);
        goto done;
    }
    if (sat > 0) {
        fprintf(stderr, "ssda grad: note: %u pixels saturated at %u (E' >> %u); use a larger "
                        "--shift or --bits 16 to keep them\n",
                sat, gray_image_max(&out), (unsigned)go.shift);
    }
    if (strcmp(a.pos[1], "-") != 0) {
        printf("wrote %s: %u x %u, %u-bit, E' >> %u%s\n", a.pos[1], out.width, out.height,
               bits, (unsigned)go.shift, crop ? " (cropped)" : ", 1-pixel border 0");
    }
    rc = CLI_OK;
done:
    gray_image_free(&in);
    gray_image_free(&out);
    return rc;
}
