/* rl_twins_rank: the rank read of the twins check (rl_twins_rank.h). */
#include "rl_twins_rank.h"

#include <math.h>

#include "rl_edge.h"
#include "rl_profile.h"
#include "rl_rank.h"
#include "rl_twins.h"

/* Radii the rank read gathers for: RANK_SCALES from RANK_FROM of the
 * landmark's, RANK_STEP apart (0.88 .. 1.12), from one gather at the
 * largest: through the wrong formation the outer edge moves too, and a
 * twin read there fits at a radius 5% off the id's (the ISP frames:
 * 22.7 px for a 7 at gamma 1, 23.9 px for the 23 it is at 2.2), so every
 * id must have every radius near to try. The id is scored at 0.97 .. 1.03
 * (where it peaked on all 399 reads of the development sets), its rivals
 * at all but the outermost (0.91 .. 1.09: 0.94 .. 1.06 let 4 of those
 * reads keep an id a rival led at 0.91 or 1.09; 0.88 and 1.12 decided
 * none). */
#define RANK_SCALES 9
#define RANK_FROM 0.88
#define RANK_STEP 0.03
#define RANK_TOP (RANK_FROM + (RANK_SCALES - 1) * RANK_STEP)
/* Rivals of the rank read: ids this many code zones away or fewer. */
#define RANK_ZONES 2

/* A radius's bins in order of darkness (scale k of RANK_SCALES). */
static void rank_order(const rl_profile *wide, int k, rl_rank_order *o)
{
    rl_profile p;
    rl_profile_rescale(wide, (RANK_FROM + k * RANK_STEP) / RANK_TOP, &p);
    rl_rank_sort(&p, o);
}

/* The ids at most RANK_ZONES zones from id (indices into the table), their
 * count: the rivals the rank read can lose to (2 zones away decided 31 of
 * the development sets' 399 reads, 3 zones away none). */
static int rank_rivals(const rl_templates *tt, int id, int *out)
{
    int n = 0, i;
    for (i = 0; i < tt->n; i++) {
        int x = tt->ids[i] ^ id, z = 0;
        for (; x; x &= x - 1)
            z++;
        if (z > 0 && z <= RANK_ZONES)
            out[n++] = i;
    }
    return n;
}

/* Whether d's id leads every id near it read through any monotone curve
 * (rl_rank) by RL_TWINS_RANK_LEAD about (cx, cy), from one gather of every
 * row through tone (the ranks do not depend on it; every other row left
 * wrong reads up to 0.008, every row 0.003). The id's best over its blurs
 * at its own radius and 3% either side, each rival's over its blurs at
 * 0.91 .. 1.09 (a rival through the wrong formation fits elsewhere).
 * Costs a fraction of scoring every id: the id's scores leave as soon as
 * they cannot pass its best so far, a rival's blurs as soon as their
 * error says they cannot come within the lead (rl_rank_any_over), and the
 * first rival that does ends the read. */
static int rank_keeps_at(const rl_recog *rec, const rl_image *img, const rl_tone *tone, const rl_detection *d,
                         double cx, double cy)
{
    const rl_templates *tt = &rec->templates;
    double own = -1, bar;
    int self = rl_templates_find(tt, d->id), rv[RL_MAX_IDS], n, k, b, i;
    rl_profile wide;
    rl_rank_order o[3];
    if (self < 0 || (n = rank_rivals(tt, d->id, rv)) == 0)
        return 0;
    rl_profile_gather_rows(img, tone, cx, cy, d->radius * RANK_TOP, 1, &wide);
    /* its own radius first (where it peaks most often), each score
     * left as soon as it cannot pass the best so far */
    for (k = 0; k < 3; k++) {
        int at = (k + 1) % 3;
        rank_order(&wide, RANK_SCALES / 2 - 1 + at, &o[at]);
        for (b = 0; b < RL_BLUR_LEVELS; b++) {
            double sc = rl_rank_score_over(tt, &o[at], self, b, own);
            own = sc > own ? sc : own;
        }
    }
    bar = own - RL_TWINS_RANK_LEAD;
    for (k = 1; k < RANK_SCALES - 1; k++) {
        int mid = k - (RANK_SCALES / 2 - 1);
        rl_rank_order far;
        const rl_rank_order *p = mid >= 0 && mid < 3 ? &o[mid] : &far;
        if (p == &far)
            rank_order(&wide, k, &far);
        for (i = 0; i < n; i++)
            if (rl_rank_any_over(tt, p, rv[i], bar))
                return 0;
    }
    return 1;
}

/* The centre of d's outer edge (rl_edge_fit_arc from d's circle, through
 * tone; light: the frame's light level) into (*cx, *cy): taken where its
 * radius is within RL_TWINS_EDGE_RADIUS of d's (the search reads 0.88 .. 1.06 of
 * a fitted one) and the centre within RL_TWINS_EDGE_REACH radii of d's (the same
 * landmark, not a neighbour's ring). 0 otherwise. Not rl_verify.c's
 * edge_centre: that one refits the visible part of the edge twice from a
 * prediction next to the border (rl_edge_fit_rays, the radius within a
 * tenth of the predicted); this one takes a whole read's own circle once
 * and only where enough of the edge lies on it (rl_edge_fit_arc). */
static int edge_centre(const rl_image *img, const rl_tone *tone, int light, const rl_detection *d, double *cx,
                       double *cy)
{
    double u = d->u, v = d->v, r = d->radius;
    if (!rl_edge_fit_arc(img, tone, light, &u, &v, &r) || !(fabs(r - d->radius) <= RL_TWINS_EDGE_RADIUS * d->radius) ||
        !(hypot(u - d->u, v - d->v) <= RL_TWINS_EDGE_REACH * d->radius))
        return 0;
    *cx = u;
    *cy = v;
    return 1;
}

/* Whether the rank read keeps d (rank_keeps_at) about its centre and,
 * for a whole local read whose outer edge gives a centre (edge_centre),
 * about that centre too; where the edge gives none, about its own alone
 * (as before the edge's centre was read).
 *
 * The read is blind to the formation only where each bin of the profile
 * holds pixels of one printed radius, so only about the landmark's true
 * centre. About a centre off by a pixel a bin averages pixels of radii a
 * pixel apart (more than half a zone's width next to the outer ring), and
 * averaging grey levels is a mixing after the curve, which no monotone
 * curve undoes: a thin black zone reads as grey, and the code with it
 * white can lead. A local read's centre is where its search found the id
 * fitting best (up to 1.5 px each way from where it started): for a
 * misread, where the wrong id fits. The centre of its outer edge is
 * chosen for no id, and a symmetric blur of either formation moves the
 * edge alike along every ray; but motion and a lamp's halo can move it too
 * (3 px off on a moving frame of another seed, where the edge's centre
 * alone kept a wrong read the search's refused). Neither is sure to be
 * the landmark's centre, so the id must lead about both (the case that
 * made the rule: docs/results.md, "Frames nobody tuned on"). A global
 * read's centre is its darkness centroid, chosen for no id
 * (rl_refine_centre), and a cut one has only the read's (a circle through
 * an arc fixes its centre loosely). */
int rl_twins_rank_keeps(const rl_recog *rec, const rl_image *img, const rl_tone *tone, int light,
                        const rl_detection *d)
{
    double cx, cy;
    if (!rank_keeps_at(rec, img, tone, d, d->u, d->v))
        return 0;
    if (d->pass != RL_PASS_LOCAL || !d->complete || !edge_centre(img, tone, light, d, &cx, &cy))
        return 1;
    return rank_keeps_at(rec, img, tone, d, cx, cy);
}
