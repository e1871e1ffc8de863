/* kl_jacobi.c - eigenvectors of a symmetric 3 x 3 Q30 matrix by cyclic
   Jacobi rotations in fixed point (kl_internal.h). */
#include "kl_internal.h"

#include "fixmath.h"

static uint64_t mag64(int64_t v)
{
    return v < 0 ? (uint64_t)(-(v + 1)) + 1u : (uint64_t)v;
}

/* round(a * b / 2^30) for |a| < 2^32, |b| <= 2^30: the product < 2^62 */
static int64_t mulq(int64_t a, int64_t b)
{
    return ssda__round_shift(a * b, 30u);
}

/* The rotation that zeroes a_pq (given a_pp, a_qq, a_pq): tangent t, cosine c and sine s, Q30
   (Numerical Recipes' choice: |t| <= 1, the smaller rotation angle). */
typedef struct {
    int64_t t, c, s;
} rot_t;

static rot_t rotation(int64_t app, int64_t aqq, int64_t apq)
{
    const int64_t d = aqq - app; /* |d| < 2^33 */
    const int64_t e = 2 * apq;   /* |e| < 2^33 */
    uint64_t ad = mag64(d), ae = mag64(e);
    const uint32_t bits = ssda__bitlen64(ad > ae ? ad : ae);
    uint64_t hyp, den, r, t2;
    uint32_t sh;
    rot_t rot;
    /* scale |d| and |e| alike so the larger lies in [2^29, 2^30) */
    if (bits > 30u) {
        sh = bits - 30u;
        ad >>= sh;
        ae >>= sh;
    } else {
        sh = 30u - bits;
        ad <<= sh;
        ae <<= sh;
    }
    hyp = ssda__isqrt64(ad * ad + ae * ae); /* sum < 2^61 */
    den = ad + hyp;                        /* >= hyp >= ae, < 2^32 */
    /* t = sign(d) sign(e) |e| / (|d| + sqrt(d^2 + e^2)), sign(0) = +1 */
    rot.t = (int64_t)SSDA_DIV64_32((ae << 30) + (den >> 1), (uint32_t)den); /* <= 2^30 */
    if ((d < 0) != (e < 0)) {
        rot.t = -rot.t;
    }
    /* c = 1 / sqrt(1 + t^2): r = sqrt(2^60 + t^2) in [2^30, 2^30.5] */
    t2 = mag64(rot.t);
    r = ssda__isqrt64(((uint64_t)1u << 60) + (t2 * t2));
    rot.c = (int64_t)SSDA_DIV64_32(((uint64_t)1u << 60) + (r >> 1), (uint32_t)r);
    rot.s = mulq(rot.t, rot.c);
    return rot;
}

/* Apply the rotation in the (p, q) plane to a and v; r is the third index. */
static void rotate(int64_t a[3][3], int64_t v[3][3], uint32_t p, uint32_t q)
{
    const uint32_t r = 3u - p - q;
    const rot_t rot = rotation(a[p][p], a[q][q], a[p][q]);
    const int64_t apq = a[p][q];
    const int64_t arp = a[r][p], arq = a[r][q];
    uint32_t i;
    a[p][p] -= mulq(rot.t, apq);
    a[q][q] += mulq(rot.t, apq);
    a[p][q] = 0;
    a[q][p] = 0;
    a[r][p] = mulq(rot.c, arp) - mulq(rot.s, arq);
    a[r][q] = mulq(rot.s, arp) + mulq(rot.c, arq);
    a[p][r] = a[r][p];
    a[q][r] = a[r][q];
    for (i = 0u; i < 3u; i++) {
        const int64_t vp = v[i][p], vq = v[i][q];
        v[i][p] = mulq(rot.c, vp) - mulq(rot.s, vq);
        v[i][q] = mulq(rot.s, vp) + mulq(rot.c, vq);
    }
}

uint32_t ssda__kl_jacobi(int64_t a[3][3], int64_t v[3][3])
{
    static const uint8_t pairs[3][2] = {{0u, 1u}, {0u, 2u}, {1u, 2u}};
    uint32_t sweep, i, j;
    for (i = 0u; i < 3u; i++) {
        for (j = 0u; j < 3u; j++) {
            v[i][j] = 0;
        }
        v[i][i] = SSDA__ONE_Q30_KL;
    }
    for (sweep = 1u; sweep <= SSDA__KL_MAX_SWEEPS; sweep++) {
        for (i = 0u; i < 3u; i++) {
            if (a[pairs[i][0]][pairs[i][1]] != 0) {
                rotate(a, v, pairs[i][0], pairs[i][1]);
            }
        }
        /* the sweep's last rotation left a12 = 0 */
        if (a[0][1] == 0 && a[0][2] == 0) {
            break;
        }
    }
    return sweep > SSDA__KL_MAX_SWEEPS ? SSDA__KL_MAX_SWEEPS : sweep;
}
