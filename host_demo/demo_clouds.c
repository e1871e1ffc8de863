/* demo_clouds.c - a procedural cloud field and its exact advection by a known
   wind, for a tracking test with a known answer. */
#include "demo.h"

#include <math.h>
#include <stdlib.h>

/* Deterministic lattice values in 0..1. */
static double lattice(int32_t x, int32_t y, uint32_t seed)
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return (h & 0xffffu) / 65535.0;
}

static double fade(double t)
{
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); /* C2-smooth interpolation */
}

/* Value noise at real coordinates, cell size `cell`. */
static double vnoise(double x, double y, double cell, uint32_t seed)
{
    double gx = floor(x / cell), gy = floor(y / cell);
    double fx = fade(x / cell - gx), fy = fade(y / cell - gy);
    int32_t ix = (int32_t)gx, iy = (int32_t)gy;
    double a = lattice(ix, iy, seed), b = lattice(ix + 1, iy, seed);
    double c = lattice(ix, iy + 1, seed), d = lattice(ix + 1, iy + 1, seed);
    return (a + (b - a) * fx) + ((c + (d - c) * fx) - (a + (b - a) * fx)) * fy;
}

/* Fractal sum of five octaves, 0..1. */
static double fbm(double x, double y, uint32_t seed)
{
    static const double cell[5] = {48, 24, 12, 6, 3};
    static const double amp[5] = {1.0, 0.5, 0.25, 0.13, 0.07};
    double s = 0.0, n = 0.0;
    int o;
    for (o = 0; o < 5; o++) {
        s += amp[o] * vnoise(x, y, cell[o], seed + (uint32_t)o * 101u);
        n += amp[o];
    }
    return s / n;
}

static double smoothstep(double a, double b, double x)
{
    double t = (x - a) / (b - a);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return t * t * (3 - 2 * t);
}

/* Brightness of the field at real coordinates: flat clear sky (35), clouds
   up to 255 with inner texture. gain > 1 brightens the clouds (development). */
static double field(double x, double y, double gain)
{
    double cover = smoothstep(0.40, 0.62, fbm(x, y, 11u));
    double detail = fbm(x * 2.0, y * 2.0, 29u); /* finer: clouds have inner texture */
    double v = 35.0 + cover * (60.0 + 170.0 * detail) * gain;
    return v > 255.0 ? 255.0 : v;
}

void demo_wind_at(const demo_wind_t *w, double x, double y, double *u, double *v)
{
    double dx = x - w->cx, dy = y - w->cy, r = sqrt(dx * dx + dy * dy), speed;
    /* Rankine vortex: solid rotation inside the radius, 1/r outside */
    speed = r < w->radius ? w->vmax * r / w->radius : w->vmax * w->radius / r;
    *u = w->u0;
    *v = w->v0;
    if (r > 1e-9) { /* anticlockwise on screen (y down): (dy, -dx) / r */
        *u += speed * dy / r;
        *v += speed * -dx / r;
    }
}

/* Deterministic Gaussian noise (xorshift + Box-Muller). */
typedef struct {
    uint32_t s;
    int have;
    double spare;
} rng_t;

static double uniform01(rng_t *r)
{
    r->s ^= r->s << 13;
    r->s ^= r->s >> 17;
    r->s ^= r->s << 5;
    return (r->s + 0.5) / 4294967296.0;
}

static double gauss(rng_t *r)
{
    double a, b;
    if (r->have) {
        r->have = 0;
        return r->spare;
    }
    a = sqrt(-2.0 * log(uniform01(r)));
    b = 6.283185307179586 * uniform01(r);
    r->spare = a * sin(b);
    r->have = 1;
    return a * cos(b);
}

static uint8_t to_u8(double v)
{
    return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : lround(v));
}

int demo_make_clouds(uint32_t width, uint32_t height, const demo_wind_t *wind,
                     double noise_sigma, gray_image_t *first, gray_image_t *second)
{
    rng_t rng = {0x9e3779b9u, 0, 0.0};
    uint32_t x, y;
    if (gray_image_alloc(first, width, height, 8) != 0) {
        return -1;
    }
    if (gray_image_alloc(second, width, height, 8) != 0) {
        gray_image_free(first);
        return -1;
    }
    for (y = 0; y < height; y++) {
        for (x = 0; x < width; x++) {
            double u, v;
            demo_wind_at(wind, x, y, &u, &v);
            /* pixel (x, y) of SECOND came from (x - u, y - v) of FIRST */
            ((uint8_t *)first->pixels)[(size_t)y * width + x] =
                to_u8(field(x, y, 1.0) + noise_sigma * gauss(&rng));
            ((uint8_t *)second->pixels)[(size_t)y * width + x] =
                to_u8(field(x - u, y - v, 1.04) + noise_sigma * gauss(&rng));
        }
    }
    return 0;
}
