/* rl_match_bound: proved upper bounds on every id's correlation with a
 * profile (rl_match_bound.h). */
#include "rl_match_bound.h"

#include <float.h>
#include <math.h>
#include <string.h>
#include "rl_clones.h"

/* A basis vector is only added while some column keeps this much of its
 * squared norm off the basis (relative to the largest column's). */
#define BASIS_FLOOR 1e-12
/* Slack for the basis not being exactly orthonormal (double rounding of
 * Gram-Schmidt, some 1e-15): added to |v_perp|^2 relative to |v|^2, and
 * to each inner product relative to |v| |t|. */
#define ORTHO_SLACK 1e-10
#define CROSS_SLACK 1e-9
/* The matcher's single-precision sums (rl_match_kernel.h: nonnegative
 * terms, 64 bins, each product rounded) are within 66 float epsilons
 * (4e-6) of the exact sums; its double arithmetic after that adds 1e-15.
 * The bound takes 1e-5. */
#define KERNEL_REL 1e-5
/* Columns bounded together (the coordinates' loops run over them). */
#define CHUNK 64

/* A float at least x (x >= 0). */
static float up(double x)
{
    float f = (float)x;
    return (double)f >= x ? f : nextafterf(f, FLT_MAX);
}

static double dot(const double *a, const double *b)
{
    double s = 0;
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        s += a[k] * b[k];
    return s;
}

static double href(int k)
{
    return sqrt(k + 0.5);
}

/* Column c of the table (v == 0) or its square (v == 1) into x, weighted
 * by href; c == -1: href itself, c == -2: the last bin. */
static void column(const rl_templates *tt, int c, int v, double *x)
{
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        double t = c == -1 ? 1.0 : c == -2 ? (k == RL_PROFILE_BINS - 1) : tt->table[(size_t)k * (size_t)tt->stride + (size_t)c];
        x[k] = (v ? t * t : t) * (c == -2 ? 1.0 : href(k));
    }
}

/* Squared norm of x off the first dims basis vectors (by its coordinates:
 * only to choose the next pivot). */
static double off_basis(const rl_match_bound *mb, const double *x)
{
    double r = dot(x, x);
    int j;
    for (j = 0; j < mb->dims; j++) {
        double c = dot(x, mb->gs + (size_t)j * RL_PROFILE_BINS);
        r -= c * c;
    }
    return r;
}

/* x less its part along the basis, twice (the second pass takes what
 * rounding left of the first). */
static void orthogonalize(const rl_match_bound *mb, double *x)
{
    int pass, j, k;
    for (pass = 0; pass < 2; pass++)
        for (j = 0; j < mb->dims; j++) {
            const double *b = mb->gs + (size_t)j * RL_PROFILE_BINS;
            double c = dot(x, b);
            for (k = 0; k < RL_PROFILE_BINS; k++)
                x[k] -= c * b[k];
        }
}

/* Pivoted Gram-Schmidt: each new basis vector is the column (or square)
 * farthest off the basis so far, so the largest residual shrinks first. */
static void build_basis(rl_match_bound *mb, const rl_templates *tt, int ncol)
{
    double x[RL_PROFILE_BINS], largest = 0;
    int c, v, k;
    for (c = 0; c < ncol; c++)
        for (v = 0; v < 2; v++) {
            column(tt, c, v, x);
            largest = fmax(largest, dot(x, x));
        }
    mb->dims = 0;
    {
        int seed;
        for (seed = -1; seed >= -2; seed--) {
            double nn;
            column(tt, seed, 0, x);
            orthogonalize(mb, x);
            nn = sqrt(dot(x, x));
            for (k = 0; k < RL_PROFILE_BINS; k++)
                mb->gs[(size_t)mb->dims * RL_PROFILE_BINS + k] = x[k] / nn;
            mb->dims++;
        }
    }
    while (mb->dims < RL_MATCH_BOUND_DIMS) {
        double best = BASIS_FLOOR * largest, norm;
        int bc = -1, bv = 0;
        for (c = 0; c < ncol; c++)
            for (v = 0; v < 2; v++) {
                double r;
                column(tt, c, v, x);
                r = off_basis(mb, x);
                if (r > best) {
                    best = r;
                    bc = c;
                    bv = v;
                }
            }
        if (bc < 0)
            break;
        column(tt, bc, bv, x);
        orthogonalize(mb, x);
        norm = sqrt(dot(x, x));
        if (!(norm > 0))
            break;
        for (k = 0; k < RL_PROFILE_BINS; k++)
            mb->gs[(size_t)mb->dims * RL_PROFILE_BINS + k] = x[k] / norm;
        mb->dims++;
    }
}

/* Each column's coordinates, its residual's norm and its norm, for the
 * column (v == 0) or its square (v == 1). */
static void coordinates(rl_match_bound *mb, const rl_templates *tt, int ncol, int v)
{
    float *tau = v ? mb->tau2 : mb->tau, *rho = v ? mb->rho2 : mb->rho, *nrm = v ? mb->norm2 : mb->norm;
    double x[RL_PROFILE_BINS], res[RL_PROFILE_BINS];
    int c, j, k;
    for (c = 0; c < ncol; c++) {
        column(tt, c, v, x);
        memcpy(res, x, sizeof res);
        for (j = 0; j < mb->dims; j++) {
            const double *b = mb->gs + (size_t)j * RL_PROFILE_BINS;
            double cj = dot(x, b);
            tau[(size_t)j * (size_t)mb->stride + (size_t)c] = (float)cj;
            for (k = 0; k < RL_PROFILE_BINS; k++)
                res[k] -= cj * b[k];
        }
        rho[c] = up(sqrt(dot(res, res)) * (1 + 1e-9));
        nrm[c] = up(sqrt(dot(x, x)) * (1 + 1e-9));
    }
}

rl_err rl_match_bound_init(rl_match_bound *mb, rl_ws *ws, const rl_templates *tt)
{
    size_t nc = (size_t)tt->stride, coords = (size_t)RL_MATCH_BOUND_DIMS * nc * sizeof(float);
    rl_err e;
    int j, k;
    memset(mb, 0, sizeof *mb);
    if ((e = rl_ws_alloc(ws, (size_t)RL_MATCH_BOUND_DIMS * RL_PROFILE_BINS * sizeof(double), RL_WS_ALIGN,
                         (void **)&mb->basis)) != RL_OK ||
        (e = rl_ws_alloc(ws, coords, RL_WS_ALIGN, (void **)&mb->tau)) != RL_OK ||
        (e = rl_ws_alloc(ws, coords, RL_WS_ALIGN, (void **)&mb->tau2)) != RL_OK ||
        (e = rl_ws_alloc(ws, 4 * nc * sizeof(float), RL_WS_ALIGN, (void **)&mb->rho)) != RL_OK ||
        (e = rl_ws_alloc(ws, (size_t)RL_MATCH_BOUND_DIMS * RL_PROFILE_BINS * sizeof(double), RL_WS_ALIGN,
                         (void **)&mb->gs)) != RL_OK)
        return e;
    if (rl_ws_is_sizing(ws))
        return RL_OK;
    mb->rho2 = mb->rho + nc;
    mb->norm = mb->rho2 + nc;
    mb->norm2 = mb->norm + nc;
    mb->n = tt->n;
    mb->stride = tt->stride;
    memset(mb->tau, 0, coords);
    memset(mb->tau2, 0, coords);
    memset(mb->rho, 0, 4 * nc * sizeof(float));
    build_basis(mb, tt, tt->n * RL_BLUR_LEVELS);
    coordinates(mb, tt, tt->n * RL_BLUR_LEVELS, 0);
    coordinates(mb, tt, tt->n * RL_BLUR_LEVELS, 1);
    /* bin-major for the profile's projection, unused coordinates 0 */
    memset(mb->basis, 0, (size_t)RL_MATCH_BOUND_DIMS * RL_PROFILE_BINS * sizeof(double));
    for (j = 0; j < mb->dims; j++)
        for (k = 0; k < RL_PROFILE_BINS; k++)
            mb->basis[(size_t)k * RL_MATCH_BOUND_DIMS + j] = mb->gs[(size_t)j * RL_PROFILE_BINS + k];
    for (k = 0; k < RL_PROFILE_BINS; k++)
        mb->ih[k] = 1.0 / href(k);
    return RL_OK;
}

/* The profile's vectors divided by the reference (w / h: its pixels per
 * bin; a / h: the numerator's vector, a = n q - sx w) projected on the
 * basis (bin by bin, each coordinate a running sum: the loops over the
 * coordinates vectorize), their norms and bounds on their norms off the
 * basis. */
RL_CLONES_AVX2
static void project(const rl_match_bound *mb, const rl_profile *p, double n, double sx, float *wc,
                    float *ac, double *norms)
{
    double cw[RL_MATCH_BOUND_DIMS] = {0}, ca[RL_MATCH_BOUND_DIMS] = {0}, w2 = 0, a2 = 0, iw = 0, ia = 0;
    int j, k;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        const double *b = mb->basis + (size_t)k * RL_MATCH_BOUND_DIMS;
        double w = p->n[k] * mb->ih[k], a = (n * p->sx[k] - sx * p->n[k]) * mb->ih[k];
        w2 += w * w;
        a2 += a * a;
        for (j = 0; j < RL_MATCH_BOUND_DIMS; j++) {
            cw[j] += w * b[j];
            ca[j] += a * b[j];
        }
    }
    for (j = 0; j < RL_MATCH_BOUND_DIMS; j++) {
        wc[j] = (float)cw[j];
        ac[j] = (float)ca[j];
        iw += cw[j] * cw[j];
        ia += ca[j] * ca[j];
    }
    norms[0] = sqrt(w2) * (1 + 1e-12);
    norms[1] = sqrt(fmax(0.0, w2 - iw) + ORTHO_SLACK * w2) * (1 + 1e-12);
    norms[2] = sqrt(a2) * (1 + 1e-12);
    norms[3] = sqrt(fmax(0.0, a2 - ia) + ORTHO_SLACK * a2) * (1 + 1e-12);
}

/* Each column's S, Q and numerator on the basis: nc columns from c0 (a
 * multiple of LANES; the coordinates' rows are padded with 0 to whole
 * blocks), LANES columns at a time, their sums kept over the
 * coordinates. */
#define LANES 8
#if defined(__GNUC__) && !defined(RL_NO_VECTOR_EXT)
typedef float lanes_f __attribute__((vector_size(LANES * sizeof(float))));
#endif
RL_CLONES_AVX2
static void on_basis(const rl_match_bound *mb, const float *wc, const float *ac, int c0, int nc,
                     float *restrict s, float *restrict q2, float *restrict nm)
{
    const int dims = mb->dims;
    const size_t stride = (size_t)mb->stride;
    int j, c;
    for (c = 0; c < nc; c += LANES) {
#if defined(__GNUC__) && !defined(RL_NO_VECTOR_EXT)
        const float *restrict tp = mb->tau + c0 + c, *restrict tq = mb->tau2 + c0 + c;
        lanes_f vs = {0}, vq = {0}, vn = {0};
        for (j = 0; j < dims; j++) {
            lanes_f t, t2;
            memcpy(&t, tp + (size_t)j * stride, sizeof t);
            memcpy(&t2, tq + (size_t)j * stride, sizeof t2);
            vs += wc[j] * t;
            vq += wc[j] * t2;
            vn += ac[j] * t;
        }
        memcpy(s + c, &vs, sizeof vs);
        memcpy(q2 + c, &vq, sizeof vq);
        memcpy(nm + c, &vn, sizeof vn);
#else
        int l;
        for (l = 0; l < LANES; l++)
            s[c + l] = q2[c + l] = nm[c + l] = 0;
        for (j = 0; j < mb->dims; j++)
            for (l = 0; l < LANES; l++) {
                size_t at = (size_t)j * (size_t)mb->stride + (size_t)(c0 + c + l);
                s[c + l] += wc[j] * mb->tau[at];
                q2[c + l] += wc[j] * mb->tau2[at];
                nm[c + l] += ac[j] * mb->tau[at];
            }
#endif
    }
}

/* What a profile's column bounds share. */
typedef struct {
    double n, sx, in, ivx2, wp, ap, ew, ea, grow;
} profile_errs;

/* Each column's bound, squared with its sign (not above 0 where
 * negative), and the lower bound of its variance term vts (nothing is
 * proved where it is not positive), from its S, Q and numerator on the
 * basis: their intervals (the residuals' Cauchy-Schwarz terms, the float
 * rounding), then the kernel's own rounding. */
RL_CLONES_AVX2
static void squared_bounds(const rl_match_bound *mb, const profile_errs *e, int c0, int nc,
                           const float *restrict s, const float *restrict q2, const float *restrict nm,
                           double *restrict b2, double *restrict vts)
{
    const float *restrict rho = mb->rho + c0, *restrict rho2 = mb->rho2 + c0, *restrict nrm = mb->norm + c0,
                          *restrict nrm2 = mb->norm2 + c0;
    const double wp = e->wp, ew = e->ew, ap = e->ap, ea = e->ea, n1 = e->n * (1 - KERNEL_REL),
                 sx2 = 2 * e->sx, grow = e->grow, ivx2 = e->ivx2;
    int c;
    for (c = 0; c < nc; c++) {
        double s_hi = s[c] + (wp * rho[c] + ew * nrm[c]);
        double q_lo = q2[c] - (wp * rho2[c] + ew * nrm2[c]);
        double a_hi = nm[c] + (ap * rho[c] + ea * nrm[c]);
        /* the kernel's rounding: num_f <= num + eps (n X + sx S), where
         * n X + sx S = num + 2 sx S */
        double num = a_hi + KERNEL_REL * (fabs(a_hi) + sx2 * s_hi);
        double vt = n1 * q_lo - s_hi * s_hi * grow;
        /* num's sign kept; where vt is not positive the caller reads
         * only that sign (no branch here: the loop vectorizes) */
        b2[c] = num * fabs(num) * ivx2 / fabs(vt);
        vts[c] = vt;
    }
}

void rl_match_bound_ids(const rl_match_bound *mb, const rl_profile *p, double n, double sx, double ivx,
                        double *upper)
{
    float wc[RL_MATCH_BOUND_DIMS], ac[RL_MATCH_BOUND_DIMS];
    double norms[4];
    profile_errs e;
    int ncol = mb->n * RL_BLUR_LEVELS, c0, i;
    /* the float coordinates' rounding and their sums' (dims products,
     * signed: gamma_dims times the sum of their sizes, at most |v| |t|),
     * with room to spare, and the basis's orthogonality */
    double eta = 2.0 * (mb->dims + 8) * FLT_EPSILON + CROSS_SLACK;
    project(mb, p, n, sx, wc, ac, norms);
    e.n = n;
    e.sx = sx;
    e.in = 1.0 / n;
    e.ivx2 = ivx * ivx;
    e.wp = norms[1];
    e.ap = norms[3];
    e.ew = eta * norms[0];
    e.ea = eta * norms[2];
    e.grow = (1 + KERNEL_REL) * (1 + KERNEL_REL);
    for (i = 0; i < mb->n; i++)
        upper[i] = 0;
    for (c0 = 0; c0 < ncol; c0 += CHUNK) {
        float s[CHUNK], q2[CHUNK], nm[CHUNK];
        double b2[CHUNK], vt[CHUNK];
        int nc = ncol - c0 < CHUNK ? ncol - c0 : CHUNK, c;
        on_basis(mb, wc, ac, c0, (nc + LANES - 1) / LANES * LANES, s, q2, nm);
        squared_bounds(mb, &e, c0, nc, s, q2, nm, b2, vt);
        for (c = 0; c < nc; c++) {
            double b = vt[c] > 0 ? b2[c] : b2[c] > 0 ? HUGE_VAL : 0;
            i = (c0 + c) / RL_BLUR_LEVELS;
            upper[i] = b > upper[i] ? b : upper[i];
        }
    }
    for (i = 0; i < mb->n; i++)
        if (upper[i] > 0 && upper[i] < HUGE_VAL)
            upper[i] = sqrt(upper[i]) * (1 + 1e-9);
}
