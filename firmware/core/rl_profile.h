/* rl_profile: a candidate's pixels gathered into radial bins (internal).
 *
 * Landmarks are rotationally symmetric, so what identification needs of a
 * candidate is, per radial bin, how many pixels fall in it and the sum of
 * their darkness (RL_TONE_MAX less their light, rl_tone.h), plus the sum of squared darkness over every
 * pixel. Because that last sum is taken per pixel, anything that varies
 * around a ring (asymmetric clutter, a wrong centre) still lowers Pearson's
 * r exactly as a 2-D correlation would; all but a plane, which light
 * falling across a landmark adds and no ring explains. Pixels outside the image are not
 * gathered: a landmark cut by the border meets templates cut the same way.
 *
 *   rl_profile p;
 *   rl_profile_gather(&img, &tone, cx, cy, r, &p);   // p.total pixels within 1.2 r
 */
#ifndef RL_PROFILE_H
#define RL_PROFILE_H

#include "rl_image.h"
#include "rl_shape.h"
#include "rl_tone.h"

/* Radial bins of a profile: at R = 24 px a bin is 0.45 px wide, so bin
 * quantization costs under 0.01 of correlation. */
#define RL_PROFILE_BINS 64
/* A profile covers radii 0 .. RL_PROFILE_EXTENT * R (the quiet zone's start). */
#define RL_PROFILE_EXTENT 1.2

typedef struct {
    double n[RL_PROFILE_BINS];  /* pixels per bin */
    double sx[RL_PROFILE_BINS]; /* sum of darkness per bin (0 .. RL_TONE_MAX a pixel) */
    double sxx;                 /* sum of squared darkness over all pixels */
    double plane;               /* the part of the spread about the mean that a plane
                                   explains (light falling across the candidate: a lamp's
                                   glare, vignetting), left out of the correlation; 0 for
                                   a disk the border cuts */
    double total;               /* pixels in all bins */
} rl_profile;

/* Gather the pixels of img within RL_PROFILE_EXTENT * r of (cx, cy), their
 * darkness in light (tone->packed's low words). */
void rl_profile_gather(const rl_image *img, const rl_tone *tone, double cx, double cy, double r,
                       rl_profile *p);

/* The same with radii measured in the shape's metric (an ellipse's
 * pixels binned by their normalized radius). */
void rl_profile_gather_shaped(const rl_image *img, const rl_tone *tone, double cx, double cy,
                              double r, const rl_shape *sh, rl_profile *p);

/* rl_profile_gather from every step-th row only (step 2: half the
 * pixels, for a second opinion on a read). */
void rl_profile_gather_rows(const rl_image *img, const rl_tone *tone, double cx, double cy, double r,
                            int step, rl_profile *p);

/* rl_profile_gather from the pixels within 22.5 degrees of axis a alone
 * (rl_motion_on_axis: either side of the centre), no plane left out: a
 * moving landmark read across its motion (rl_motion), where the rings are
 * sharp. Plain per-pixel code: for the few reads that need it. */
void rl_profile_gather_axis(const rl_image *img, const rl_tone *tone, double cx, double cy, double r, int a,
                            rl_profile *p);

/* Profile src, gathered at radius r, as one gathered at s * r would be
 * (s <= 1): each bin's pixels moved to the bin its middle falls in, those
 * past the extent into the last bin (as gathering puts the rim's). Three
 * radii read from one gather, for 64 additions each. */
void rl_profile_rescale(const rl_profile *src, double s, rl_profile *dst);

/* Where rl_profile_rescale moves each bin at one scale, worked out once
 * for a scale that many profiles are read at (the division a bin left
 * out). made 0 (a zeroed one): not worked out. */
typedef struct {
    double s;
    int made;
    unsigned char to[RL_PROFILE_BINS];
} rl_profile_scale;

/* The bins' moves at scale s (0 < s <= 1) into *sc. */
void rl_profile_scale_make(double s, rl_profile_scale *sc);

/* rl_profile_rescale(src, sc->s, dst), the same bits, by sc's moves. */
void rl_profile_rescale_by(const rl_profile *src, const rl_profile_scale *sc, rl_profile *dst);

#endif
