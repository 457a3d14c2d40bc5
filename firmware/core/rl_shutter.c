/* rl_shutter: a rolling shutter's frame brought to one instant (rl_shutter.h). */
#include "rl_shutter.h"

#include <math.h>

int rl_motion_between(const rl_pose *a, double ta, const rl_pose *b, double tb, double t, double max_gap,
                      rl_motion *m)
{
    double dt = tb - ta, dx, dy, c, s, dyaw, mid, arc;
    if (!(dt > 0 && dt <= max_gap) || !(t - tb >= 0 && t - tb <= max_gap) ||
        !isfinite(a->x + a->y + a->yaw + b->x + b->y + b->yaw))
        return 0;
    dyaw = atan2(sin(b->yaw - a->yaw), cos(b->yaw - a->yaw));
    /* on an arc the chord from a to b points along the mid-heading and is
     * shorter than the arc by sin(h) / h, h half the turn */
    mid = a->yaw + 0.5 * dyaw;
    arc = fabs(dyaw) > 1e-9 ? (0.5 * dyaw) / sin(0.5 * dyaw) : 1.0;
    dx = arc * (b->x - a->x) / dt;
    dy = arc * (b->y - a->y) / dt;
    c = cos(mid);
    s = sin(mid);
    m->forward = c * dx + s * dy;
    m->left = -s * dx + c * dy;
    m->turn = dyaw / dt;
    return 1;
}

/* The ceiling point (fwd, left) of the level camera at `distance` back
 * to pixels. */
static void ceiling_to_pixel(const rl_calib *cam, double distance, double fwd, double left, double *u, double *v)
{
    rl_calib_project(cam, left / distance, -fwd / distance, u, v);
}

void rl_shutter_move(const rl_mount *mount, double dt, const rl_motion *m, double *fwd, double *left)
{
    /* the camera's velocity in its own frame (image top forward, left):
     * the robot's, the turn carrying the mount's offset round, turned by
     * the mount's yaw; the camera then was turned by turn dt and moved by
     * v dt from where it is at the middle row: seen from there, the point
     * lies turned back by that turn and moved by the travel */
    double vf = m->forward - m->turn * mount->y, vl = m->left + m->turn * mount->x;
    double cf = cos(mount->yaw), sf = sin(mount->yaw), a = m->turn * dt;
    double cvf = cf * vf + sf * vl, cvl = -sf * vf + cf * vl, f = *fwd, l = *left;
    *fwd = cos(a) * f - sin(a) * l + cvf * dt;
    *left = sin(a) * f + cos(a) * l + cvl * dt;
}

/* Move the centre of d, seen `distance` below its landmark, to the middle
 * row's instant. */
static void correct_one(const rl_calib *cam, const rl_mount *mount, double distance, double readout_s,
                        const rl_motion *m, rl_detection *d)
{
    /* the row's time from the middle row's */
    double dt = ((d->v + 0.5) / cam->height - 0.5) * readout_s;
    double fwd, left, f, l, u0, v0, u1, v1;
    if (!(distance > 0))
        return;
    rl_pose_ceiling_point(cam, NULL, distance, d->u, d->v, &fwd, &left);
    f = fwd;
    l = left;
    rl_shutter_move(mount, dt, m, &f, &l);
    /* the shift between the two points' pixels (the round trip's own
     * error cancels) */
    ceiling_to_pixel(cam, distance, fwd, left, &u0, &v0);
    ceiling_to_pixel(cam, distance, f, l, &u1, &v1);
    if (isfinite(u1 - u0) && isfinite(v1 - v0)) {
        d->u += u1 - u0;
        d->v += v1 - v0;
    }
}

void rl_shutter_correct(const rl_calib *cam, const rl_mount *mount, double distance, double readout_s,
                        const rl_motion *m, rl_detection *lm, int n)
{
    int i;
    if (!(readout_s > 0) || m == NULL || cam->height <= 0)
        return;
    for (i = 0; i < n; i++)
        correct_one(cam, mount, distance, readout_s, m, &lm[i]);
}

void rl_shutter_correct_each(const rl_calib *cam, const rl_mount *mount, const double *distance, double readout_s,
                             const rl_motion *m, rl_detection *lm, int n)
{
    int i;
    if (!(readout_s > 0) || m == NULL || distance == NULL || cam->height <= 0)
        return;
    for (i = 0; i < n; i++)
        correct_one(cam, mount, distance[i], readout_s, m, &lm[i]);
}
