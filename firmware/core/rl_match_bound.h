/* rl_match_bound: a proved upper bound on every id's correlation with a
 * profile, from a few numbers a template (internal).
 *
 * Pearson's r of a profile with a template column t needs three sums over
 * the bins: S = <w, t>, Q = <w, t^2> and X = <q, t>, w the profile's
 * pixels per bin and q their darkness sums (rl_match.h). The numerator
 * n X - sx S is <a, t> with a = n q - sx w. These are plain inner
 * products of the fixed vectors t and t^2 with vectors of the profile, so
 * with an orthonormal basis B of a few vectors (chosen once from the
 * templates: pivoted Gram-Schmidt over every column and its square) each
 * is <B v, B t> + <v_perp, t_perp>, the last at most |v_perp| |t_perp|
 * (Cauchy-Schwarz). The profile is projected once (2 x 64 x dims
 * products) and each column bounded from its dims coordinates and its
 * residual's norm, so empty bins and uneven counts cost nothing in
 * exactness. The intervals also hold the rounding of the float
 * coordinates and of the matcher's own single-precision sums
 * (rl_match_kernel.h), so the bound holds for the score rl_match_all
 * computes, not only for the exact r.
 *
 *   static rl_match_bound mb;                      // in rl_recog, built at init
 *   rl_match m;
 *   if (rl_match_bound_init(&mb, &ws, &tt) == RL_OK)
 *       rl_match_all_bounded(&tt, &mb, &p, &m);    // rl_match_all's m (rl_match.h)
 */
#ifndef RL_MATCH_BOUND_H
#define RL_MATCH_BOUND_H

#include "rl_error.h"
#include "rl_match.h"
#include "rl_profile.h"
#include "rl_templates.h"
#include "rl_workspace.h"

/* Basis vectors the bound projects on (at most; fewer when the templates
 * span fewer). */
#ifndef RL_MATCH_BOUND_DIMS
#define RL_MATCH_BOUND_DIMS 28
#endif

typedef struct rl_match_bound_s {
    int dims;     /* basis vectors, 0 .. RL_MATCH_BOUND_DIMS */
    int n;        /* ids (the templates') */
    int stride;   /* the coordinates' row length: the templates' columns */
    double *gs;    /* the basis: dims x RL_PROFILE_BINS, orthonormal */
    double *basis; /* the same bin-major: bin k's coordinates at k * RL_MATCH_BOUND_DIMS */
    double ih[RL_PROFILE_BINS]; /* 1 / the reference weighting (rl_match_bound.c) */
    float *tau;    /* dims x stride: coordinate j of column c at j * stride + c */
    float *tau2;   /* the same for the column's squares */
    float *rho;    /* per column: |t_perp|, rounded up */
    float *rho2;   /* |(t^2)_perp|, rounded up */
    float *norm;   /* |t|, rounded up */
    float *norm2;  /* |t^2|, rounded up */
} rl_match_bound;

/* Build the bound for a template table (its columns, after
 * rl_templates_init on the same workspace); in a sizing workspace only
 * the memory is counted. RL_ENOMEM when ws is too small. */
RL_CHECK rl_err rl_match_bound_init(rl_match_bound *mb, rl_ws *ws, const rl_templates *tt);

/* Upper bounds on each id's best score over its RL_BLUR_LEVELS columns,
 * as rl_match_all would compute it for profile p (n its pixels, sx its
 * darkness sum, ivx 1 / sqrt of its variance term: rl_match's terms),
 * into upper[i] for id tt->ids[i]: 0 when no column can score above 0,
 * HUGE_VAL when nothing is proved. */
void rl_match_bound_ids(const rl_match_bound *mb, const rl_profile *p, double n, double sx, double ivx,
                        double *upper);

#endif
