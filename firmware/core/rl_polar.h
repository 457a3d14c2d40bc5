/* rl_polar: a candidate gathered once into polar cells, for the local
 * pass (internal).
 *
 * Near a light, glare adds a smooth light field that varies with
 * direction, so each angular sector is normalized by its own black and
 * white levels. The cells keep raw sums per sector and radial bin, so the
 * local search can derive the profile for a shifted centre or a scaled
 * radius without touching the image again.
 *
 *   static rl_polar pol;                        // large: not on a small stack
 *   rl_polar_gather(&img, &tone, cx, cy, r, light, 20.0, &pol);
 *   rl_profile p;
 *   rl_polar_profile(&pol, 0.5, 0.0, 1.02, &p); // centre 0.5 px right, radius +2%
 */
#ifndef RL_POLAR_H
#define RL_POLAR_H

#include <stdint.h>
#include "rl_image.h"
#include "rl_profile.h"

/* Angular sectors for glare normalization: glare adds a smooth light
 * field that varies with direction, so each sector is rescaled by its own
 * black and white levels. */
#define RL_SECTORS 16

/* Polar cells reach beyond the profile (1.2 R) so that a larger radius or
 * a shifted centre still finds its outermost pixels: 68 bins reach
 * 1.275 R. Further out, a search's outermost quiet-zone bins are only
 * partly filled, which Pearson's r takes as pixels not seen. */
#define RL_POLAR_BINS 68
/* Zero cells before and after a sector's bins (whole vectors of 4). */
#define RL_POLAR_PAD 4
#define RL_POLAR_CELLS (RL_POLAR_BINS + 2 * RL_POLAR_PAD)

/* A candidate gathered once into RL_SECTORS x RL_POLAR_BINS polar cells
 * (raw count, sum, sum of squares), from which the sector-normalized
 * profile for any small shift of the centre, or change of radius, is
 * derived without touching the image again: a shift d moves the pixels
 * of sector s (direction u_s) to radius rho - d . u_s, and a radius scale
 * f divides every radius by f. */
typedef struct {
    double cx, cy, r;
    /* bin k of a sector at [RL_POLAR_PAD + k]; the pads are zero */
    float n[RL_SECTORS][RL_POLAR_CELLS]; /* pixels */
    float s[RL_SECTORS][RL_POLAR_CELLS]; /* sum of darkness */
    float q[RL_SECTORS][RL_POLAR_CELLS]; /* sum of squared darkness */
    /* while gathering: count, sum and sum of squares of grey levels packed
     * in one integer per cell (one add per pixel), from a table per level;
     * the float cells above then hold raw sums until normalized */
    uint64_t acc[RL_SECTORS][RL_POLAR_CELLS];
    uint64_t lut[256];
    double ux[RL_SECTORS], uy[RL_SECTORS]; /* sector directions */
    double lo[RL_SECTORS], hi[RL_SECTORS]; /* sector black and white */
    int usable[RL_SECTORS];                /* sector has enough contrast */
    int merged_usable[RL_SECTORS / 2];     /* after the octants' sectors are summed
                                              into the first half of the arrays */
} rl_polar;

/* Gather a candidate into polar cells, as light (tone->lin), and
 * normalize each sector by its own black and white; sectors with less
 * than min_contrast levels of light between them (washed out) are left
 * out. After this the first
 * RL_SECTORS / 2 rows of cells hold the normalized darkness (count, sum,
 * sum of squares) of each octant, its two sectors summed, and ux, uy the
 * octants' middle directions. */
void rl_polar_gather(const rl_image *img, const rl_tone *tone, double cx, double cy, double r,
                     int light, double min_contrast, rl_polar *pol);

/* The profile of pol with the centre moved by (dx, dy) px and the radius
 * multiplied by scale (1 = as gathered). */
void rl_polar_profile(const rl_polar *pol, double dx, double dy, double scale,
                            rl_profile *p);

/* The axes a profile can be read along: an octant and its opposite. */
#define RL_POLAR_AXES (RL_SECTORS / 4)

/* The octant opposite octant o (0 .. 7: 4 for x < 0, 2 for y < 0, 1 for
 * |x| > |y|): both signs flipped. Axis a (0 .. RL_POLAR_AXES - 1) is
 * octant a and its opposite, a line through the centre. */
int rl_polar_opposite(int o);

/* Octants, the merged sectors a profile reads (RL_SECTORS / 2). */
#define RL_POLAR_OCTANTS (RL_SECTORS / 2)

/* Octant o's mirror image across the vertical (x's sign flipped): the
 * pair lies on one side of the horizontal. */
int rl_polar_mirror(int o);

/* Every octant, as a mask (bit o: octant o). */
#define RL_POLAR_ALL ((1u << RL_POLAR_OCTANTS) - 1)

/* As rl_polar_profile, from the octants of the mask alone (an axis: the
 * directions across a motion, where it smears the rings least). */
void rl_polar_profile_octants(const rl_polar *pol, double dx, double dy, double scale,
                              unsigned octants, rl_profile *p);

/* A profile's first step, the one its scale does not enter: the octants
 * of the mask moved to a centre shifted by (dx, dy) and summed into mid
 * bins (RL_POLAR_SHIFT_GUARD bins either side of the cells' span). Made
 * once, read at several scales: rl_polar_shift_profile(sh, scale) is
 * rl_polar_profile_octants(pol, dx, dy, scale, octants), bit for bit. */
#define RL_POLAR_SHIFT_GUARD 8
#define RL_POLAR_MID_BINS (RL_POLAR_BINS + RL_POLAR_PAD + 2 * RL_POLAR_SHIFT_GUARD)
typedef struct {
    float n[RL_POLAR_MID_BINS], s[RL_POLAR_MID_BINS], q[RL_POLAR_MID_BINS];
} rl_polar_shift;

void rl_polar_shift_make(const rl_polar *pol, double dx, double dy, unsigned octants, rl_polar_shift *sh);

/* The profile of the shifted octants sh at the radius `scale` times the
 * gather's. */
void rl_polar_shift_profile(const rl_polar_shift *sh, double scale, rl_profile *p);

#endif
