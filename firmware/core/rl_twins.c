#include "rl_twins.h"

#include "rl_match.h"
#include "rl_profile.h"
#include "rl_result.h"

/* Radius scales a landmark and its twins are scored at (the radius was
 * read through one formation and the edge falls elsewhere through the
 * other): 0.97, 1 and 1.03 of it, from one gather at the largest. */
#define SCALE_STEP 0.03
/* Every other row: the leads compared are differences between templates
 * on the same pixels, and half of a landmark's pixels give the same
 * decisions on every set measured (docs/design.md). */
#define ROW_STEP 2

/* How far d's id leads its best rival (rivals()) through tone: its best score
 * over the three radii (into *fit) less the rival's. */
static double twin_lead(const rl_recog *rec, const rl_image *img, const rl_tone *tone, const rl_detection *d,
                        const int *rv, int n, double *fit)
{
    static const double scales[3] = {1.0, 1.0 / (1.0 + SCALE_STEP), (1.0 - SCALE_STEP) / (1.0 + SCALE_STEP)};
    double own = -1, twin = -1;
    rl_profile wide;
    int k;
    rl_profile_gather_rows(img, tone, d->u, d->v, d->radius * (1.0 + SCALE_STEP), ROW_STEP, &wide);
    for (k = 0; k < 3; k++) {
        rl_profile p;
        rl_match m;
        rl_profile_rescale(&wide, scales[k], &p);
        rl_match_ids(&rec->templates, &p, &d->id, 1, -1, &m);
        if (m.id >= 0 && m.score > own)
            own = m.score;
        /* the rivals at every blur: through the other formation a rival
         * may fit another than the id does */
        rl_match_ids(&rec->templates, &p, rv, n, -1, &m);
        if (m.id >= 0 && m.score > twin)
            twin = m.score;
    }
    *fit = own;
    return own - twin;
}

/* The valid codes one zone away from id (every zone: a wrong formation
 * moves every edge, the outer ones most); their count. */
static int neighbours(const rl_recog *rec, int id, int *out)
{
    int n = 0, z;
    for (z = 0; z < rec->templates.fam.bits; z++)
        if (rl_family_valid(&rec->templates.fam, id ^ (1 << z)))
            out[n++] = id ^ (1 << z);
    return n;
}

/* The ids d is judged against: its zone twins; for a local read (sector
 * by sector, the centre searched) every other id of the table. */
static int rivals(const rl_recog *rec, const rl_detection *d, int *out)
{
    int n = 0, i;
    if (d->pass != RL_PASS_LOCAL)
        return neighbours(rec, d->id, out);
    for (i = 0; i < rec->templates.n; i++)
        if (rec->templates.ids[i] != d->id)
            out[n++] = rec->templates.ids[i];
    return n;
}

/* Whether d keeps its id, from its lead over its best rival through
 * the other formation (other) and through the frame's curve (own): while
 * the twin leads by less than RL_TWINS_TOLERANCE through the other, and
 * the sum is positive (a global read: the whole ring at the frame's
 * levels) or over RL_TWINS_LOCAL_MARGIN (a local one, read sector by
 * sector, whose own lead says less). */
static int keeps(const rl_detection *d, double other, double own)
{
    return other > -RL_TWINS_TOLERANCE && other + own > (d->pass == RL_PASS_LOCAL ? RL_TWINS_LOCAL_MARGIN : 0.0);
}

void rl_twins_check(const rl_recog *rec, const rl_image *img, const rl_tone *other, rl_result *res)
{
    int i, kept = 0, rv[RL_MAX_IDS], n;
    for (i = 0; i < res->n_landmarks; i++) {
        rl_detection d = res->landmarks[i];
        double lead, own = 0, fit;
        /* a global read clear of every other id through its curve is
         * clear of its twins; a local read's runner-up (sector-normalized)
         * does not say so */
        if ((d.pass == RL_PASS_GLOBAL && d.score - d.runner_up >= RL_TWINS_CLEAR) ||
            (n = rivals(rec, &d, rv)) == 0) {
            res->landmarks[kept++] = d;
            continue;
        }
        lead = twin_lead(rec, img, other, &d, rv, n, &fit);
        /* a circle far from what was read (an ellipse the local pass read
         * in its own shape, at a wide-angle lens's border) says nothing */
        if (fit < d.score - RL_TWINS_UNFIT) {
            res->landmarks[kept++] = d;
            continue;
        }
        if (d.score - lead > d.runner_up)
            d.runner_up = d.score - lead;
        /* through the frame's own curve only where the other's lead
         * alone does not keep it (own: 0, the id's lead where it was read) */
        if (!keeps(&d, lead, 0.0))
            own = twin_lead(rec, img, rec->tone, &d, rv, n, &fit);
        if (keeps(&d, lead, own))
            res->landmarks[kept++] = d;
        else
            rl_result_add_unidentified(res, &d);
    }
    res->n_landmarks = kept;
}
