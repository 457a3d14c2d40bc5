/* rl_fuse_hist: the filter's past, for rl_fuse.c (internal): the ring of
 * odometry samples with the state after each, the anchor (the state just
 * after the last fused frame), and the state or odometry pose at any time
 * inside it.
 *
 *   rl_fuse_kf_state s;
 *   double o[3] = {0, 0, 0}, R[3][3];
 *   rl_fuse_frame fr = {1.0, 0, 0, 0, 0.001, 0.001, 0.001, 0};
 *   static rl_fuse f;
 *   static rl_fuse_entry hist[64];
 *   rl_fuse_config cfg;
 *   rl_fuse_defaults(&cfg);
 *   if (rl_fuse_init(&f, &cfg, hist, 64) != RL_OK)
 *       return;
 *   rl_fuse_hist_push(&f, 1.0, o);                 // an odometry sample
 *   if (rl_fuse_hist_state_at(&f, fr.t, &s) >= 0) {
 *       rl_fuse_hist_frame_cov(&f, &fr, s.m[2], R);
 *       double z[3] = {fr.x, fr.y, fr.yaw};
 *       rl_fuse_kf_update(&s, z, R);
 *       rl_fuse_hist_anchor(&f, fr.t, &s);         // later samples replayed
 *   }
 */
#ifndef RL_FUSE_HIST_H
#define RL_FUSE_HIST_H

#include "rl_fuse.h"
#include "rl_fuse_kf.h"

/* the age (0: newest) of the newest sample at or before t; -1 if none */
int rl_fuse_hist_find(const rl_fuse *f, double t);

/* A new newest sample (time t, odometry pose o), its state propagated
 * from the one before (or the anchor) once there is a pose. */
void rl_fuse_hist_push(rl_fuse *f, double t, const double *o);

/* The odometry's pose at t into o: 0, 1 when t was past the extrapolation
 * limit (o at the limit), -1 before the history. */
int rl_fuse_hist_odo_at(const rl_fuse *f, double t, double *o);

/* The filter's state at t: 0, 1 (past the limit, as above), -1 when
 * there is none (no pose yet, or t before the anchor's base). */
int rl_fuse_hist_state_at(const rl_fuse *f, double t, rl_fuse_kf_state *s);

/* s, the state just after a frame captured at t (inside the history),
 * becomes the anchor; every later sample's state is recomputed from it. */
void rl_fuse_hist_anchor(rl_fuse *f, double t, const rl_fuse_kf_state *s);

/* the odometry's speed (m/s) and turn rate (rad/s) over the samples
 * around t (the newest two past them; 0 with fewer than two) */
void rl_fuse_hist_rate(const rl_fuse *f, double t, double *v, double *w);

/* a frame's covariance R: its sigmas (or the config's), the floor, and
 * the capture time's error carried by the motion at heading yaw */
void rl_fuse_hist_frame_cov(const rl_fuse *f, const rl_fuse_frame *fr, double yaw, double R[3][3]);

#endif
