/* rl_twins_steep: a frame read as linear doubted against the steepest
 * camera curve (rl_twins_steep.h). */
#include "rl_twins_steep.h"

#include "rl_median.h"
#include "rl_result.h"
#include "rl_twins_lead.h"
#include <math.h>

int rl_twins_steep_doubts(const rl_recog *rec, const rl_image *img, const rl_tone *steep, const rl_detection *d,
                          const int *rv, int n)
{
    return rl_twins_lead_reached(rec, img, steep, d, rv, n);
}

/* The frame's evidence for a curve (RL_TWINS_STEEP_FRAME) from res's
 * landmarks: the ids' fits alone are wanted, so no rival is scored; the
 * fit through the other formation taken where rl_twins_check read it
 * (far_fit[from[k]], NAN where it did not: the same gather, scales and
 * id's columns). */
static double curve_evidence(const rl_recog *rec, const rl_image *img, const rl_result *res, const int *from,
                             const double *far_fit)
{
    double v[RL_MAX_LANDMARKS], curved, linear;
    const rl_tone *other = rl_tones_other(&rec->tones, rec->tone);
    int k;
    for (k = 0; k < res->n_landmarks; k++) {
        rl_detection d = res->landmarks[k];
        d.pass = RL_PASS_GLOBAL; /* the id alone: no rival scored (rl_twins_lead's every_rival) */
        curved = far_fit[from[k]];
        if (isnan(curved))
            rl_twins_lead(rec, img, other, &d, NULL, 0, 1, -1, &curved);
        rl_twins_lead(rec, img, rec->tone, &d, NULL, 0, 1, -1, &linear);
        v[k] = curved - linear;
    }
    return rl_median(v, res->n_landmarks);
}

/* Whether res's landmark k (asked: rl_twins_steep_asks) is doubted; the
 * steep curve made into *steep at the first read asked (*made). */
static int doubted(const rl_recog *rec, const rl_image *img, const rl_result *res, int k, rl_tone *steep,
                   int *made)
{
    int rv[RL_MAX_IDS], n = rl_twins_rivals(rec, &res->landmarks[k], rv);
    if (!*made)
        rl_tones_steep(&rec->tones, steep);
    *made = 1;
    return rl_twins_steep_doubts(rec, img, steep, &res->landmarks[k], rv, n);
}

void rl_twins_steep_settle(const rl_recog *rec, const rl_image *img, rl_result *res, const unsigned char *ask,
                           const int *from, const double *far_fit, unsigned char *kept)
{
    unsigned char doubt[RL_MAX_LANDMARKS];
    rl_tone steep;
    int k, m = 0, any = 0, made = 0;
    /* the asked reads in turn, the frame's evidence at the first doubted
     * one: where it says linear light, no doubt changes anything, and the
     * reads left are not asked (the landmarks a read asks of are the
     * kept ones as they stand, so the order changes no read) */
    for (k = 0; k < res->n_landmarks; k++) {
        doubt[k] = (unsigned char)(ask[k] && doubted(rec, img, res, k, &steep, &made));
        if (doubt[k] && !any) {
            if (!(curve_evidence(rec, img, res, from, far_fit) > RL_TWINS_STEEP_FRAME))
                return;
            any = 1;
        }
    }
    if (!any)
        return;
    for (k = 0; k < res->n_landmarks; k++) {
        if (!doubt[k]) {
            res->landmarks[m++] = res->landmarks[k];
            continue;
        }
        rl_result_add_unidentified(res, &res->landmarks[k]);
        if (kept != NULL)
            kept[from[k]] = 0;
    }
    res->n_landmarks = m;
}
