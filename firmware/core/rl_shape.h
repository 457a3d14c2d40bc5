/* rl_shape: the ellipse a round landmark projects to (internal).
 *
 * Perspective and lens distortion show a circle as an ellipse; radii are
 * then measured in the ellipse's metric, so that radial bins and rays
 * follow the rings as seen.
 *
 *   rl_shape s = rl_shape_from_moments(4.0, 0.5, 2.0);  // a region's covariance
 *   double step = rl_shape_step(&s, 0.6, 0.8);          // px per unit radius along (0.6, 0.8)
 */
#ifndef RL_SHAPE_H
#define RL_SHAPE_H

/* A landmark seen as an ellipse (perspective, lens distortion): the
 * normalized radius of an offset (dx, dy) from the centre is
 * sqrt(a dx^2 + 2 b dx dy + c dy^2), with a c - b^2 = 1 (areas kept): the
 * ellipse of normalized radius r has the area of a circle of radius r.
 * A circle is (1, 0, 1). */
typedef struct {
    double a, b, c;
} rl_shape;

/* The circle. */
rl_shape rl_shape_circle(void);

/* The shape of a region from its central second moments (covariance);
 * a circle when its axes differ by less than 3% or the moments are
 * degenerate. */
rl_shape rl_shape_from_moments(double cxx, double cxy, double cyy);

/* 1 for the circle. */
int rl_shape_is_circle(const rl_shape *s);

/* Image offset per unit of normalized radius in direction (c, s). */
double rl_shape_step(const rl_shape *sh, double c, double s);

#endif
