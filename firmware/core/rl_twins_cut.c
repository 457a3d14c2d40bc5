/* rl_twins_cut: a cut read's circle against its outer edge, how much of
 * its code zone 1 the frame shows, and a small cut global read's twins at
 * 9% (rl_twins_cut.h). */
#include "rl_twins_cut.h"

#include <math.h>

#include "rl_edge.h"
#include "rl_twins.h"
#include "rl_twins_lead.h"

/* Whether the local read d of a landmark the border cuts lies where its
 * outer edge is, by the landmark contract (RL_TWINS_CUT_BULGE), the edge
 * the circle fitted to its points along rays from d's circle (one whose
 * edge gives no circle passes). Judged only where d's radius is
 * RL_TWINS_CUT_SIZE or more over size, the frame's (the median of its
 * other whole reads, rl_twins.c's frame_size; 0: none known, always
 * judged): where the search climbed past the
 * landmark, and only there can it matter (the cut read it refuses was 1.2
 * times the frame's size; right cut reads sit at the border, which the
 * lens makes smaller, and the local pass's taken reads of cut landmarks on
 * seeds 41-44 were at most 1.05 of their true radius). An edge fit is
 * some 45,000 instructions: judged on every cut local read it cost 0.6% of
 * the recognizer's instructions on moving frames, judged here 0.05%. */
int rl_twins_cut_on_edge(const rl_image *img, const rl_tone *tone, int light, const rl_detection *d,
                         double size)
{
    double u = d->u, v = d->v, r = d->radius;
    if ((size > 0 && d->radius < (1.0 + RL_TWINS_CUT_SIZE) * size) ||
        !rl_edge_fit_rays(img, tone, light, &u, &v, &r))
        return 1;
    return hypot(u - d->u, v - d->v) + d->radius - r <= RL_TWINS_CUT_BULGE * d->radius;
}

/* Points round the circle through code zone 1's middle (every 2.8
 * degrees; one step a share of 1/128 of it) */
#define ZONE1_STEPS 128

double rl_twins_cut_zone1_shown(const rl_image *img, const rl_family *fam, const rl_detection *d)
{
    double r[RL_MAX_BITS + 2], rho, c, s, x = 1.0, y = 0.0, t;
    int k, in = 0;
    rl_family_radii(fam, r);
    rho = 0.5 * (r[1] + r[2]) * d->radius;
    c = cos(6.283185307179586 / ZONE1_STEPS);
    s = sin(6.283185307179586 / ZONE1_STEPS);
    for (k = 0; k < ZONE1_STEPS; k++) {
        double px = d->u + rho * x, py = d->v + rho * y;
        in += px >= -0.5 && py >= -0.5 && px <= img->width - 0.5 && py <= img->height - 0.5;
        t = x * c - y * s; /* the next point: (x, y) turned by one step */
        y = x * s + y * c;
        x = t;
    }
    return (double)in / ZONE1_STEPS;
}

/* Whether d, a small read, may keep its id where the border cuts a global
 * read of it in a frame read through a curve (curved): its twins at 0.91
 * .. 1.09 of its radius through the frame's own curve must not lead it. A
 * cut 2 behind a 2x scaler (19.3 px, the border 0.6 px into its disk) read
 * as 18 led its twin by 0.0243 through the other formation and 0.0219
 * through its curve at 3%, but the twin led by 0.0075 at 9%; the 72 right
 * reads so judged on the development scale sets led by 0.0048 or more
 * there, where through the other formation 13 let the twin lead, by up to
 * 0.0113 (docs/results.md, sixteenth session). */
int rl_twins_cut_global_fits(const rl_recog *rec, const rl_image *img, const rl_detection *d, const int *rv, int n,
                             int curved)
{
    double fit;
    if (d->complete || d->pass == RL_PASS_LOCAL || !curved)
        return 1;
    return rl_twins_lead(rec, img, rec->tone, d, rv, n, 1, -1, &fit) > 0;
}
