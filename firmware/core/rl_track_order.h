/* rl_track_order: the order a frame's windows are read in, and how the
 * reads so far moved them (rl_track.c's helpers; not a public API).
 *
 *   static rl_track trk;                     // its windows predicted (rl_track_plan)
 *   rl_track_shift fs = {0};
 *   rl_detection d = {0};                    // window 0's read
 *   fs.cu = 319.5;                           // the turn's centre: the image's
 *   fs.cv = 239.5;
 *   rl_track_order_spread(&trk, fs.cu, fs.cv); // trk.win spread over the frame
 *   rl_track_shift_add(&fs, &trk.win[0], &d);
 *   rl_track_shift_apply(&fs, &trk.win[1]);  // window 1 moved as the reads say
 */
#ifndef RL_TRACK_ORDER_H
#define RL_TRACK_ORDER_H

#include "rl_result.h"
#include "rl_track.h"

/* How the reads so far moved from their predictions: a shift and a small
 * turn about the image centre (the robot's rocking shifts every landmark
 * alike, a heading error turns them), least squares over the reads. */
typedef struct {
    double cu, cv;               /* the turn's centre */
    double n, x, y, q, du, dv, w; /* sums */
} rl_track_shift;

void rl_track_shift_add(rl_track_shift *f, const rl_track_window *w, const rl_detection *d);

/* w moved as the reads so far say. */
void rl_track_shift_apply(const rl_track_shift *f, rl_track_window *w);

/* t's predictions reordered so that each next one lies farthest from
 * those before it, the one nearest (cu, cv) first. */
void rl_track_order_spread(rl_track *t, double cu, double cv);

#endif
