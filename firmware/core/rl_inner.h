/* rl_inner: is a candidate a code ring inside a larger landmark?
 * (internal)
 *
 * A code ring of a landmark can look like a whole landmark of half its
 * size (id 2's zone 4 ring reads as id 16). The paper drops inner rings by
 * containment in the binary image; when glare breaks the outer ring, the
 * border cuts it, or it merges with a dark wall or shadow next to its
 * sheet, that containment is lost, so it is checked on the grey levels
 * instead: rays from the candidate's centre, beyond its quiet zone, that
 * meet a dark ring (dark, then paper again) at one common radius in most
 * directions mean the candidate sits inside a larger landmark. A dark
 * ceiling around a sheet is dark that does not end: no ring.
 *
 * An enclosing landmark is at most a few times the candidate's size; where
 * the frame's landmark size is known, no larger than one of that size
 * (the lens's spread allowed for): `reach` bounds how far out its ring may
 * start, so that a striped or grated ceiling past a narrow margin (dark,
 * then light, at about one radius in many directions) is no ring around a
 * landmark of the frame's size.
 *
 *   if (rl_inner_enclosed(&img, light, d.u, d.v, d.radius, 0.0))
 *       d.id = -1;   // not a landmark
 */
#ifndef RL_INNER_H
#define RL_INNER_H

#include "rl_image.h"
#include "rl_recog.h"

/* Where the landmarks' size R is known (the frame's median, a map's
 * landmark predicted), a landmark enclosing a candidate is no larger than
 * 1.45 times it (the lens's spread of sizes): its outer ring starts within
 * RL_INNER_REACH R + RL_INNER_REACH_PX of the candidate's centre (0.8 of
 * that, blur and the rays' steps). Beyond, a grille or striped ceiling
 * past a narrow margin looked like a ring around landmarks of the frame's
 * size (next to lamps, on composited photos: 2-3% of them). */
#define RL_INNER_REACH 1.16
#define RL_INNER_REACH_PX 2.0

/* 1 if the candidate (cx, cy, r) is enclosed by a concentric dark ring
 * that starts within `reach` px of its centre (0: within 2.9 r, the ring
 * around the smallest mimic); rays are looked along from 1.3 r, past the
 * candidate's quiet zone, however small `reach` is. */
int rl_inner_enclosed(const rl_image *img, int light, double cx, double cy, double r, double reach);

#endif
