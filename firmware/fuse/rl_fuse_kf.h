/* rl_fuse_kf: the filter's arithmetic, for rl_fuse.c (internal): the
 * state (x, y, yaw, distance scale, turn scale) with its covariance, an
 * odometry increment, moving the state by one, and a pose measurement.
 *
 *   rl_fuse_kf_state s;
 *   double a[3] = {0, 0, 0}, b[3] = {0.1, 0, 0.01}, z[3] = {0.1, 0, 0}, R[3][3] = {{1e-6, 0, 0}, {0, 1e-6, 0}, {0, 0, 1e-6}};
 *   rl_fuse_config cfg;
 *   rl_fuse_defaults(&cfg);
 *   rl_fuse_kf_start(&s, z, R, 1.0, 1e-4, 1.0, 1e-4);
 *   rl_fuse_kf_propagate(&s, rl_fuse_kf_increment(a, b), &cfg);
 *   if (rl_fuse_kf_distance(&s, z, R) < cfg.gate)
 *       rl_fuse_kf_update(&s, z, R);
 */
#ifndef RL_FUSE_KF_H
#define RL_FUSE_KF_H

#include "rl_fuse.h"

typedef struct {
    double m[RL_FUSE_N];
    double P[RL_FUSE_N][RL_FUSE_N];
} rl_fuse_kf_state;

/* an odometry increment: forward and sideways (m) in the frame of its mid
 * heading, and the turn (rad) */
typedef struct {
    double fwd, lat, turn;
} rl_fuse_kf_incr;

double rl_fuse_kf_wrap(double a);

/* the increment from odometry pose a to pose b (x, y, yaw) */
rl_fuse_kf_incr rl_fuse_kf_increment(const double *a, const double *b);

/* pose o moved by the fraction q of increment d, into out */
void rl_fuse_kf_advance(const double *o, rl_fuse_kf_incr d, double q, double *out);

/* a state at pose z with pose covariance R, the scales and their variances
 * given, nothing correlated */
void rl_fuse_kf_start(rl_fuse_kf_state *s, const double *z, double R[3][3], double scale,
                      double scale_var, double turn, double turn_var);

/* s moved by the odometry increment d (the fraction q of it) */
void rl_fuse_kf_propagate_part(rl_fuse_kf_state *s, rl_fuse_kf_incr d, double q,
                               const rl_fuse_config *cfg);
void rl_fuse_kf_propagate(rl_fuse_kf_state *s, rl_fuse_kf_incr d, const rl_fuse_config *cfg);

/* the squared Mahalanobis distance of pose z (covariance R) from the state */
double rl_fuse_kf_distance(const rl_fuse_kf_state *s, const double *z, double R[3][3]);

/* the state corrected by pose z (covariance R); Joseph form, so the
 * covariance stays symmetric and positive */
void rl_fuse_kf_update(rl_fuse_kf_state *s, const double *z, double R[3][3]);

#endif
