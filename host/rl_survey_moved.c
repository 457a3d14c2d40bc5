#include "rl_survey_moved.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int k, j;     /* survey landmark, old map landmark */
    double ox, oy; /* the old place in the survey's frame */
    double d;     /* distance from it */
    int in;       /* in the fit */
} pair;

/* Similarity taking the old places onto the new of the pairs in the fit:
 * new = s R old + t, as (a, b, tx, ty) with s R = [a -b; b a]. */
static void fit(const rl_survey *sv, const rl_map *old, const pair *p, int n, double *T)
{
    double pcx = 0, pcy = 0, mcx = 0, mcy = 0, sa = 0, sb = 0, pp = 0;
    int i, m = 0;
    for (i = 0; i < n; i++)
        if (p[i].in) {
            pcx += old->lm[p[i].j].x;
            pcy += old->lm[p[i].j].y;
            mcx += sv->lm[p[i].k].x;
            mcy += sv->lm[p[i].k].y;
            m++;
        }
    T[0] = 1;
    T[1] = T[2] = T[3] = 0;
    if (m < 2)
        return;
    pcx /= m, pcy /= m, mcx /= m, mcy /= m;
    for (i = 0; i < n; i++)
        if (p[i].in) {
            double ax = old->lm[p[i].j].x - pcx, ay = old->lm[p[i].j].y - pcy;
            double bx = sv->lm[p[i].k].x - mcx, by = sv->lm[p[i].k].y - mcy;
            sa += ax * bx + ay * by;
            sb += ax * by - ay * bx;
            pp += ax * ax + ay * ay;
        }
    if (!(pp > 0))
        return;
    T[0] = sa / pp;
    T[1] = sb / pp;
    T[2] = mcx - (T[0] * pcx - T[1] * pcy);
    T[3] = mcy - (T[1] * pcx + T[0] * pcy);
}

static void apply(const rl_survey *sv, const rl_map *old, const double *T, pair *p, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        const rl_map_landmark *o = &old->lm[p[i].j];
        p[i].ox = T[0] * o->x - T[1] * o->y + T[2];
        p[i].oy = T[1] * o->x + T[0] * o->y + T[3];
        p[i].d = hypot(sv->lm[p[i].k].x - p[i].ox, sv->lm[p[i].k].y - p[i].oy);
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int cmp_move(const void *a, const void *b)
{
    double x = ((const rl_survey_move *)a)->sigmas, y = ((const rl_survey_move *)b)->sigmas;
    return (x < y) - (x > y);
}

/* The variance of pair p's distance along direction (ux, uy) from both
 * maps' covariances. */
static double own_var(const rl_survey *sv, const rl_map *old, const double *T, const pair *p, double ux, double uy)
{
    const rl_survey_landmark *l = &sv->lm[p->k];
    const rl_map_landmark *o = &old->lm[p->j];
    return ux * ux * l->cov[0] + 2 * ux * uy * l->cov[1] + uy * uy * l->cov[2] +
           (T[0] * T[0] + T[1] * T[1]) * (ux * ux * o->sigma_x * o->sigma_x + uy * uy * o->sigma_y * o->sigma_y);
}

/* The standard deviation of pair p's distance along its direction: both
 * maps' own, at least the typical landmark's (`floor`: the origin and the
 * axis have none in their maps, yet are as uncertain as the rest against
 * the others), and the spread of the fit (what the covariances do not
 * hold: systematic differences between two drives). */
static double sigma_along(const rl_survey *sv, const rl_map *old, const double *T, const pair *p, double floor,
                          double spread)
{
    const rl_survey_landmark *l = &sv->lm[p->k];
    double ux = l->x - p->ox, uy = l->y - p->oy, n = hypot(ux, uy), v;
    if (!(n > 0))
        ux = 1, uy = 0, n = 1;
    v = own_var(sv, old, T, p, ux / n, uy / n);
    return sqrt(fmax(v, floor * floor) + spread * spread);
}

/* The median over the pairs of their own standard deviation (the mean of
 * the two axes). */
static double typical_sigma(const rl_survey *sv, const rl_map *old, const double *T, const pair *p, int n, double *tmp)
{
    int i;
    if (n == 0)
        return 0;
    for (i = 0; i < n; i++)
        tmp[i] = sqrt(0.5 * (own_var(sv, old, T, &p[i], 1, 0) + own_var(sv, old, T, &p[i], 0, 1)));
    qsort(tmp, (size_t)n, sizeof *tmp, cmp_double);
    return tmp[n / 2];
}

int rl_survey_moved(const rl_survey *sv, const rl_map *old, double sigmas, rl_survey_move *mv, int max)
{
    pair *p = malloc((size_t)(sv->n_lm + 1) * sizeof *p);
    double *d = malloc((size_t)(sv->n_lm + 1) * sizeof *d), T[4];
    rl_survey_move *all = malloc((size_t)(sv->n_lm + 1) * sizeof *all);
    int n = 0, k, j, it, moved = 0, i;
    double spread = 0, floor = 0;
    if (p == NULL || d == NULL || all == NULL) {
        free(p), free(d), free(all);
        return -1;
    }
    for (k = 0; k < sv->n_lm; k++) {
        int best = -1;
        double bd = 1e30;
        if (sv->lm[k].status != RL_SURVEY_PLACED)
            continue;
        for (j = 0; j < old->count; j++) {
            double dd = hypot(old->lm[j].x - sv->lm[k].x, old->lm[j].y - sv->lm[k].y);
            if (old->lm[j].id == sv->lm[k].id && dd < bd) {
                bd = dd;
                best = j;
            }
        }
        if (best >= 0) {
            p[n].k = k;
            p[n].j = best;
            p[n].in = 1;
            n++;
        }
    }
    /* fit, then leave out what lies far beyond the typical disagreement */
    for (it = 0; it < 4; it++) {
        double med;
        fit(sv, old, p, n, T);
        apply(sv, old, T, p, n);
        for (i = 0; i < n; i++)
            d[i] = p[i].d;
        if (n == 0)
            break;
        qsort(d, (size_t)n, sizeof *d, cmp_double);
        med = d[n / 2];
        /* the median distance of a 2-D normal is 1.177 sigma */
        spread = med / 1.177;
        floor = typical_sigma(sv, old, T, p, n, d);
        for (i = 0; i < n; i++)
            p[i].in = p[i].d <= 4 * med + 1e-4 || p[i].d <= sigmas * sigma_along(sv, old, T, &p[i], floor, spread);
    }
    for (i = 0; i < n; i++) {
        double s = sigma_along(sv, old, T, &p[i], floor, spread);
        if (p[i].d > sigmas * s) {
            rl_survey_move *m = &all[moved++];
            m->id = sv->lm[p[i].k].id;
            m->x = sv->lm[p[i].k].x;
            m->y = sv->lm[p[i].k].y;
            m->old_x = p[i].ox;
            m->old_y = p[i].oy;
            m->distance = p[i].d;
            m->sigmas = s > 0 ? p[i].d / s : 1e9;
        }
    }
    qsort(all, (size_t)moved, sizeof *all, cmp_move);
    if (moved > max)
        moved = max;
    memcpy(mv, all, (size_t)moved * sizeof *mv);
    free(p), free(d), free(all);
    return moved;
}
