/* rl_edge: a landmark's outer edge, fitted as a circle, for the local
 * pass, where glare or the border hides part of it (internal).
 *
 *   rl_image win;
 *   rl_edge_window w;
 *   if (rl_image_sub(&img, 100, 80, 60, 60, &win) == RL_OK) {
 *       w.img = &win;
 *       w.x0 = 100;
 *       w.y0 = 80;
 *       w.frame_w = img.width;
 *       w.frame_h = img.height;
 *       // lb has labelled win at threshold 90; its region 0 is the ring
 *       if (rl_edge_fit_outline(&lb, 0, &w, 90, light, &cx, &cy, &r) &&
 *           rl_edge_fit_rays(&img, &tone, light, &cx, &cy, &r))
 *           use(cx, cy, r);
 *   }
 */
#ifndef RL_EDGE_H
#define RL_EDGE_H

#include "rl_image.h"
#include "rl_tone.h"
#include "rl_label.h"

/* A window of a W x H frame: its view and where it sits in the frame. */
typedef struct {
    const rl_image *img;
    int x0, y0;             /* the window's top left corner in the frame */
    int frame_w, frame_h;
} rl_edge_window;

/* Circle through the visible outer edge of region `reg` of the window's
 * labelling lb (algebraic least squares): edge points at sub-pixel
 * positions where the grey level crosses the window's threshold thr, at
 * the left end of each row's first run and the right end of its last run.
 * Points on the frame border, or next to light, are not the landmark's
 * edge and are skipped. 1 on success with (*cx, *cy, *r) in window
 * coordinates. */
int rl_edge_fit_outline(const rl_label *lb, int reg, const rl_edge_window *w, int thr,
                        int light, double *cx, double *cy, double *r);

/* Rays along which the outer edge is sought. */
#define RL_EDGE_RAYS 24

/* The outer edge's points along RL_EDGE_RAYS rays from (cx, cy), each the
 * steepest rise after the ring's black within about a fifth of r of r;
 * rays that leave the image, run into light or show no clear edge give
 * none. The count is returned, the points in ex, ey (RL_EDGE_RAYS each). */
int rl_edge_points(const rl_image *img, const rl_tone *tone, int light, double cx, double cy,
                   double r, double *ex, double *ey);

/* Refine a landmark's centre and radius from its outer edge seen along
 * rays from (*cx, *cy): on each ray the edge is the steepest rise after
 * the ring's black (a smooth glare gradient adds a constant slope, which
 * moves a level crossing but hardly the gradient's peak). Rays that leave
 * the image or run into light are skipped; then rl_edge_fit_points, with
 * a few outliers left out where the rays that found the edge go round it
 * (no gap of 105 degrees or more between two of them). On success
 * (frame coordinates) the number of edge points within 1 px of the
 * circle first fitted, before the refit (rl_edge_fit_points' count, at
 * least 5), 0 when none. */
int rl_edge_fit_rays(const rl_image *img, const rl_tone *tone, int light, double *cx, double *cy,
                     double *r);

/* The circle through n edge points (RL_EDGE_RAYS / 4 .. RL_EDGE_RAYS): a
 * least-squares circle (few_outliers: with up to a sixth of the points
 * left out, one at a time the farthest while over 3 px off the circle
 * through the points kept, itself included), the points over 1 px off it
 * dropped, fitted again and finished geometrically. The number of
 * points kept (those within the pixel, at least 5), 0 when none. */
int rl_edge_fit_points(const double *ex, const double *ey, int n, int few_outliers, double *cx, double *cy,
                       double *r);

/* rl_edge_fit_rays from (*cx, *cy, *r), the circle taken only where at
 * least RL_EDGE_ARC_MIN_POINTS of the rays' edge points lie within 1 px,
 * or a 25th of its radius where that is more, of the circle returned: the
 * local pass's fallback from a candidate's centre (rl_locate.c). 1 when
 * taken. */
#define RL_EDGE_ARC_MIN_POINTS 9
int rl_edge_fit_arc(const rl_image *img, const rl_tone *tone, int light, double *cx, double *cy, double *r);

#endif
