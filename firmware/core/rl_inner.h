/* rl_inner: is a candidate a code ring inside a larger landmark?
 * (internal)
 *
 * A code ring of a landmark can look like a whole landmark of half its
 * size (id 2's zone 4 ring reads as id 16). The paper drops inner rings by
 * containment in the binary image; when glare breaks the outer ring, or
 * the border cuts it, that containment is lost, so it is checked on the
 * grey levels instead: rays from the candidate's centre, beyond its quiet
 * zone, that meet a dark ring at one common radius in most directions
 * mean the candidate sits inside a larger landmark.
 *
 *   if (rl_inner_possible(&res, &d) && rl_inner_enclosed(&img, light, d.u, d.v, d.radius))
 *       d.id = -1;   // not a landmark
 */
#ifndef RL_INNER_H
#define RL_INNER_H

#include "rl_image.h"
#include "rl_recog.h"

/* 1 if the candidate (cx, cy, r) is enclosed by a concentric dark ring. */
int rl_inner_enclosed(const rl_image *img, int light, double cx, double cy, double r);

/* 1 if a light or the border is near enough to d to have broken a larger
 * ring around it (only then is rl_inner_enclosed needed in the global
 * pass, where containment of boxes finds the rest). */
int rl_inner_possible(const rl_result *res, const rl_detection *d);

#endif
