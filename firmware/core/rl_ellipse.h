/* rl_ellipse: an ellipse fitted to edge points, as a landmark's shape
 * (internal).
 *
 * A landmark seen off the optical axis (perspective, lens distortion) is an
 * ellipse; cut by the border or next to a light, only part of its outline
 * is seen, which its region's moments cannot tell but an arc of edge
 * points can: a general conic through them, centre free.
 *
 *   double x[6] = {12, 0, -12, 0, 8.5, -8.5}, y[6] = {0, 10, 0, -10, 7.07, -7.07};
 *   rl_ellipse e;
 *   if (rl_ellipse_fit(x, y, 6, 0, 0, 11, &e))   // centre (0, 0), axes 12 and 10
 *       use(e.cx, e.cy, e.r, e.shape);            // r = sqrt(12 * 10)
 */
#ifndef RL_ELLIPSE_H
#define RL_ELLIPSE_H

#include "rl_profile.h"

/* An ellipse as the profiles read it: centre, the radius of the circle of
 * the same area, and the shape (normalized radii). */
typedef struct {
    double cx, cy, r;
    rl_shape shape;
} rl_ellipse;

/* Least-squares conic through the n edge points (algebraic: rows
 * [x^2 xy y^2 x y] . q = 1 about the guess (gx, gy), scaled by the guess
 * radius gr); 1 when it is an ellipse whose centre lies inside it, else 0
 * (fewer than 6 points, a singular system, a hyperbola). */
int rl_ellipse_fit(const double *x, const double *y, int n, double gx, double gy, double gr,
                   rl_ellipse *e);

/* Minor over major axis of a shape (1 for the circle). */
double rl_ellipse_aspect(const rl_shape *sh);

#endif
