/* rl_motion: how a landmark moved during the exposure, from its rings'
 * own edges (internal).
 *
 * Every edge of a landmark is a circle, so its pixels' radial gradients
 * are alike in every direction, whatever focus or processing blurred it
 * (a blur the same every way). A straight motion smears the edges whose
 * normal runs along it and leaves those across it sharp: the radial
 * gradients' energy, summed per axis (an octant and its opposite,
 * rl_polar's), is largest across the motion and smallest along it. The
 * measure is chosen for no id. Axes are compared with the one at right
 * angles to them: the pixel grid's central differences read the diagonals
 * otherwise than rows and columns.
 *
 *   rl_motion m;
 *   if (rl_motion_measure(&img, cx, cy, r, &m) && m.ratio < 0.5)
 *       use(m.axis);   // the sharpest axis: across the motion
 */
#ifndef RL_MOTION_H
#define RL_MOTION_H

#include "rl_image.h"

/* Axes measured: four, 45 degrees apart (0: along x, 1: 45 degrees
 * towards +y, 2: along y, 3: 135 degrees). */
#define RL_MOTION_AXES 4

typedef struct {
    int axis;     /* the sharpest axis (0 .. RL_MOTION_AXES - 1): across the motion */
    double ratio; /* of two axes at right angles, the smoother's mean energy over
                     the sharper's, the least of both pairs: 1 where nothing
                     moved, towards 0 the longer the motion */
    double energy[RL_MOTION_AXES]; /* mean squared radial gradient per axis, grey levels */
} rl_motion;

/* The radial gradients of img's grey levels over 0.25 .. 1.15 r of
 * (cx, cy) (the code zones' and the outer ring's edges), per axis, into
 * *m. 0 (m unset) when an axis has too few pixels in the frame (a landmark
 * the border cuts to less than half along it) or no edge at all. */
int rl_motion_measure(const rl_image *img, double cx, double cy, double r, rl_motion *m);

/* Whether a pixel at (dx, dy) from a centre lies within 22.5 degrees of
 * axis a (either side of the centre; a pixel on a wedge's edge in one of
 * the two): the wedge rl_motion_measure sums into a, and
 * rl_profile_gather_axis gathers. */
int rl_motion_on_axis(double dx, double dy, int a);

#endif
