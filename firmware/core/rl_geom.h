/* rl_geom: boxes and disks in the image (internal).
 *
 *   double v = rl_geom_visible_in(640, 480, 10.0, 240.0, 30.0);  // 0.61: cut on the left
 *   rl_box b;
 *   rl_geom_square_in(640, 480, 10.0, 240.0, 34.5, 1, &b);        // (1, 206)-(44, 274)
 */
#ifndef RL_GEOM_H
#define RL_GEOM_H

#include "rl_recog.h"

/* 1 if the point (x, y) lies in box b (its edges included). */
int rl_geom_box_has(const rl_box *b, double x, double y);

/* 1 if box `in` lies within box `out`. */
int rl_geom_box_inside(const rl_box *in, const rl_box *out);

/* Gap in pixels between two boxes (0 when they touch or overlap). */
double rl_geom_box_gap(const rl_box *a, const rl_box *b);

/* Into b the pixels of the square of half-side `half` about (cx, cy)
 * (its edges included) that lie in a W x H image `border` px or more in
 * from its edges (1 for a central difference's neighbours); empty (x1 <
 * x0 or y1 < y0) where there are none. */
void rl_geom_square_in(int W, int H, double cx, double cy, double half, int border, rl_box *b);

/* Into box the pixels a circle (cx, cy, r) touches, its box rounded
 * outwards, within the W x H frame. */
void rl_geom_circle_box(int W, int H, double cx, double cy, double r, rl_box *box);

/* Fraction of a disk of radius r left visible when a straight edge passes
 * at signed distance d from its centre (d > 0: centre on the visible side). */
double rl_geom_disk_visible(double r, double d);

/* Fraction of a disk of radius r at (cx, cy) inside a W x H image, from
 * the side that cuts most (a corner cut counts as its larger cut). */
double rl_geom_visible_in(int W, int H, double cx, double cy, double r);

/* 1 if the disk (cx, cy, r) lies wholly inside a W x H image. */
int rl_geom_disk_complete(int W, int H, double cx, double cy, double r);

#endif
