/* rl_pose_fit: the robot's pose and tilt against the ceiling plane, the
 * inside of rl_pose_solve. q = (x, y, yaw, roll, pitch) of the robot: it
 * stands at (x, y) on the floor, rotated Rz(yaw) Ry(pitch) Rx(roll)
 * about that point; the camera sits on it as the mount says. A robust
 * Gauss-Newton fit of q to the landmarks' ideal image positions, with a
 * prior on the tilt, and its covariance. Internal to the core.
 *
 *   rl_pose_model md;             // mount, its rotation, ceiling, noise, prior
 *   rl_pose_pt pt[3];             // observed and map positions
 *   double q[RL_POSE_NQ] = {0}, cov[RL_POSE_NQ * RL_POSE_NQ], chi2;
 *   memset(&md, 0, sizeof md);
 *   memset(pt, 0, sizeof pt);
 *   if (rl_pose_fit_solve(&md, pt, 3, RL_POSE_NQ, q, cov, &chi2))
 *       use(q[3], q[4], sqrt(cov[0]));
 */
#ifndef RL_POSE_FIT_H
#define RL_POSE_FIT_H

#include "rl_pose.h"

typedef struct {
    int id;
    double xn, yn; /* observed, normalized ideal image coordinates (pinhole) */
    double px, py; /* the ceiling point in the level robot frame */
    double mx, my; /* map */
    double mz;     /* the landmark's height above the floor, m */
    double noise;  /* the centre's expected noise, in units of the model's */
    double w;      /* robust weight of the current fit (1: full) */
} rl_pose_pt;

#define RL_POSE_NQ 5
typedef struct {
    const rl_mount *mount;
    double Rm[9];  /* camera axes in the robot frame */
    double height; /* ceiling above the floor (the map's plane; a landmark may hang lower) */
    double sn;     /* centre noise in normalized units */
    double prior[2]; /* sigma of the tilt prior: roll, pitch, rad */
    double radius; /* the landmarks' outer radius on the ceiling, m (0: centres as points) */
} rl_pose_model;

/* 3 x 3 row-major: c = a b; R = Rz(yaw) Ry(pitch) Rx(roll). */
void rl_pose_fit_mul(const double *a, const double *b, double *c);
void rl_pose_fit_rotation(double yaw, double pitch, double roll, double *R);

/* The mount's rotation Rm, the ceiling's height and the landmarks'
 * radius into md (sn and prior 1: the caller's to set). */
void rl_pose_fit_model(rl_pose_model *md, const rl_mount *mount, double height, double radius);

/* Where the ray of normalized image point (xn, yn) meets the ceiling Z
 * above the camera of a level robot, in the robot frame; 0 if it misses. */
int rl_pose_fit_level_point(const rl_pose_model *md, double Z, double xn, double yn, double *px, double *py);

/* Least-squares rotation and translation taking the points p onto m
 * (2-D Procrustes without scale). */
void rl_pose_fit_rigid(const rl_pose_pt *pt, int n, double *tx, double *ty, double *yaw);

/* The camera's rotation (its axes in the map) and centre for robot pose q. */
void rl_pose_fit_camera(const rl_pose_model *md, const double *q, double *Rc, double *C);

/* Where the recognizer sees the centre of the landmark at map (X, Y),
 * height Z above the floor, from the camera Rc, C (normalized, the tilted
 * view's edge-centre offset included); 0 if behind the camera. */
int rl_pose_fit_predict(const rl_pose_model *md, const double *Rc, const double *C, double X, double Y, double Z,
                        double *xn, double *yn);

/* The camera of q (as rl_pose_fit_camera) and its derivatives by each of
 * q's five parameters, for rl_pose_fit_predict_d. */
typedef struct {
    double Rc[9], C[3];
    double dRc[RL_POSE_NQ][9]; /* dRc / dq[a] (0 for x and y) */
    double dc[RL_POSE_NQ][3];  /* -Rc' dC / dq[a]: a fixed point's move in the camera's axes */
} rl_pose_fit_view;

void rl_pose_fit_view_of(const rl_pose_model *md, const double *q, rl_pose_fit_view *v);

/* rl_pose_fit_predict from the view v (the same value, bit for bit) and
 * its derivatives by the first nq parameters of q into dxn, dyn (exact:
 * the fit's Jacobian); 0 if behind the camera. */
int rl_pose_fit_predict_d(const rl_pose_model *md, const rl_pose_fit_view *v, double X, double Y, double Z,
                          int nq, double *xn, double *yn, double *dxn, double *dyn);

/* Fit the first nf (3: a level robot, 5: tilted too) parameters of q from
 * its start; the covariance of all five into cov (the held ones as unsure
 * as the prior, and the free ones as unsure as that makes them: a level
 * fit is off by as much as the robot leans), the centres' noise pooled
 * with what their residuals show; chi2 of the image residuals.
 * 0 if it failed (a landmark behind the camera, a tilt past 0.5 rad). */
int rl_pose_fit_solve(const rl_pose_model *md, rl_pose_pt *pt, int m, int nf, double *q, double *cov,
                      double *chi2);

#endif
