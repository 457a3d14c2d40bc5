/* rl_twins_cut: reads of partly hidden landmarks, a cut read's circle
 * against its outer edge and a lamp over a disk (rl_twins_cut.h). */
#include "rl_twins_cut.h"

#include <math.h>

#include "rl_edge.h"
#include "rl_twins.h"

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

/* The disk's pixels in the frame, every other row (a lamp is a large
 * blob: half the rows see as much of it), counted at or above light. */
double rl_twins_lamp_share(const rl_image *img, int light, const rl_detection *d)
{
    int x, y, n = 0, lit = 0;
    int y0 = (int)ceil(d->v - d->radius), y1 = (int)floor(d->v + d->radius);
    if (light > 255)
        return 0.0; /* no light level: no lamp in the frame */
    for (y = y0 < 0 ? 0 : y0; y <= y1 && y < img->height; y += 2) {
        double h = sqrt(fmax(0.0, d->radius * d->radius - (y - d->v) * (y - d->v)));
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        int x0 = (int)ceil(d->u - h), x1 = (int)floor(d->u + h);
        for (x = x0 < 0 ? 0 : x0; x <= x1 && x < img->width; x++) {
            n++;
            lit += row[x] >= light;
        }
    }
    return n > 0 ? (double)lit / n : 0.0;
}
