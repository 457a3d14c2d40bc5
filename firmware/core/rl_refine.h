/* rl_refine: a CLR's centre and outer radius from the grey levels, before
 * global identification (internal).
 *
 *   rl_refine_centre(&img, &res.levels, &d.u, &d.v, d.radius);   // d: a CLR
 *   rl_refine_radius(&img, &tone, d.u, d.v, &d.radius);
 */
#ifndef RL_REFINE_H
#define RL_REFINE_H

#include "rl_family.h"
#include "rl_image.h"
#include "rl_profile.h"
#include "rl_recog.h"

/* Darkness-weighted centroid of the disk (*cx, *cy, r): code rings are
 * concentric, so every ROI pixel, weighted by how dark it is, pulls
 * towards the true centre with sub-pixel precision (the paper takes the
 * binary centroid of all ROI pixels). Only for a disk wholly inside the
 * image; unchanged otherwise. */
void rl_refine_centre(const rl_image *img, const rl_levels *lv, double *cx, double *cy, double r);

/* The same from every ystep-th row of the disk only (a coarse step over a
 * wide disk: ystep 3, a third of the pixels). Returns the weight it saw
 * (the pixels' darkness past the background, summed): 0 when the disk
 * held no ink (the centre is kept) or was not read. */
double rl_refine_centre_rows(const rl_image *img, const rl_levels *lv, double *cx, double *cy, double r,
                             int ystep);

/* Outer radius: the mean light (the tone curve undone, rl_tone.h) on
 * circles of growing radius drops to the outer ring's black and rises to
 * the paper's white; where it crosses halfway is the printed edge,
 * whatever the blur (a symmetric blur of light moves a threshold
 * crossing, not the 50% one; in grey levels the tone curve would move it
 * inwards). Only rays that stay inside the image are used; *r is kept
 * when there is no clear edge. */
void rl_refine_radius(const rl_image *img, const rl_tone *tone, double cx, double cy, double *r);

/* The outer radius of an identified landmark from both edges of its
 * outermost black band (the outer ring and the black code zones just
 * inside it), each at the halfway crossing: a tone curve or a blur that
 * moves one edge's crossing moves the other's the opposite way, so the
 * band's mid radius, rescaled, is the printed radius unbiased. Only when
 * the band's inner edge is clear (rl_family_band_inner); *r is kept
 * otherwise. */
void rl_refine_radius_band(const rl_image *img, const rl_tone *tone, const rl_family *fam, int id,
                           double cx, double cy, double *r);

/* The same with radii in the shape's metric (rl_profile.h). */
void rl_refine_radius_shaped(const rl_image *img, const rl_tone *tone, double cx, double cy,
                             const rl_shape *sh, double *r);

#endif
