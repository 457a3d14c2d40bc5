/* rl_rivals: the ids a known window's read is held against (rl_rivals.h). */
#include "rl_rivals.h"

#include <math.h>
#include <string.h>
#include "rl_family.h"
#include "rl_match.h"

/* The landmark's tone as read: darkness t (0 white .. 1 black) through a
 * curve the recognizer may not know (0: linear, 1: a 2.2 camera read as
 * linear, 2: the inverse). */
#define TONES 3
static double toned(double t, int f)
{
    if (f == 0)
        return t;
    return f == 1 ? 1.0 - pow(1.0 - t, 1.0 / 2.2) : 1.0 - pow(1.0 - t, 2.2);
}

/* Radii the landmark is read at, relative to its own: 0.9 to 1.1. A
 * verification searches 0.95 to 1.05 of the predicted radius, and the
 * prediction may itself be a few percent off (at 0.95 to 1.05 alone a
 * window predicted at 0.94 R took a 20 as 8, at 1.12 R a 21 as 29:
 * test_rivals' off_radius). */
#define RADII 5
#define RADIUS_STEP 0.05

/* Column (i, b) of tt as the profile of a uniform disk of pixels (bin k
 * holds 2k + 1) read at radius (1 + e) R through curve f. */
static void modelled(const rl_templates *tt, int i, int b, double e, int f, rl_profile *p)
{
    int k;
    memset(p, 0, sizeof *p);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        double x = (k + 0.5) / (1.0 + e) - 0.5, a, t, g;
        int k0 = (int)floor(x);
        a = x - k0;
        if (k0 < 0) {
            k0 = 0;
            a = 0;
        }
        if (k0 >= RL_PROFILE_BINS - 1) {
            k0 = RL_PROFILE_BINS - 1;
            a = 0;
        }
        t = (1 - a) * rl_templates_bin(tt, i, b, k0) + (a > 0 ? a * rl_templates_bin(tt, i, b, k0 + 1) : 0);
        g = 20.0 + 200.0 * toned(t, f); /* darkness, grey levels */
        p->n[k] = 2.0 * k + 1;
        p->sx[k] = p->n[k] * g;
        p->sxx += p->n[k] * g * g;
        p->total += p->n[k];
    }
}

rl_err rl_rivals_init(rl_rivals *rv, rl_ws *ws, const rl_templates *tt)
{
    int n = tt->n, i, j, b, f, e, twins[RL_MAX_BITS];
    double best[RL_RIVALS_MAX_IDS];
    rl_err err;
    rv->n = 0;
    rv->near = NULL;
    if (n > RL_RIVALS_MAX_IDS)
        return RL_OK;
    if ((err = rl_ws_alloc(ws, (size_t)n * (size_t)n, RL_WS_ALIGN, (void **)&rv->near)) != RL_OK)
        return err;
    if (rl_ws_is_sizing(ws))
        return RL_OK;
    memset(rv->near, 0, (size_t)n * (size_t)n);
    for (i = 0; i < n; i++) {
        int nt = rl_family_zone_twins(&tt->fam, tt->ids[i], twins), k;
        for (k = 0; k < nt; k++)
            if ((j = rl_templates_find(tt, twins[k])) >= 0)
                rv->near[i * n + j] = 1;
    }
    /* landmark j modelled, every id's templates scored on it */
    for (j = 0; j < n; j++)
        for (b = 0; b < RL_BLUR_LEVELS; b++)
            for (f = 0; f < TONES; f++)
                for (e = -(RADII / 2); e <= RADII / 2; e++) {
                    rl_profile p;
                    modelled(tt, j, b, e * RADIUS_STEP, f, &p);
                    rl_match_ids_each(tt, &p, tt->ids, n, best);
                    for (i = 0; i < n; i++)
                        if (i != j && tt->ids[i] != tt->ids[j] && best[i] >= RL_RIVALS_MIN)
                            rv->near[i * n + j] = 1;
                }
    rv->n = n;
    return RL_OK;
}

rl_err rl_rivals_none(rl_rivals *rv)
{
    rv->n = 0;
    rv->near = NULL;
    return RL_OK;
}

int rl_rivals_ready(const rl_rivals *rv)
{
    return rv->n > 0;
}

int rl_rivals_of(const rl_rivals *rv, const rl_templates *tt, int id, int *out)
{
    int i = rl_templates_find(tt, id), j, c = 0;
    if (rv->n == 0 || rv->n != tt->n || i < 0)
        return -1;
    for (j = 0; j < rv->n; j++)
        if (rv->near[i * rv->n + j])
            out[c++] = tt->ids[j];
    return c;
}
