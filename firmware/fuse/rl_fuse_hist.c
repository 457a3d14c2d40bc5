/* rl_fuse_hist: see rl_fuse_hist.h.
 *
 * Invariants:
 * - h[] holds the odometry samples, newest at head; an entry's state is
 *   the filter's just after its sample (valid once a frame gave a pose).
 * - The anchor is the state just after the last fused frame, at its
 *   capture time, with the odometry's pose interpolated to that time.
 *   Every entry later than the anchor was propagated from it through the
 *   odometry since; fusing a frame sets a new anchor and recomputes them
 *   (the replay). Entries before the anchor keep what they had.
 * - A state at any time is its base (the anchor, or the newest valid entry
 *   after it, at or before that time) moved by the odometry from the
 *   base's time to that time: interpolation and prediction are one path
 *   (and a time before the anchor is the anchor moved back). */
#include <math.h>
#include <string.h>
#include "rl_fuse_hist.h"
#include "rl_fuse_kf.h"

#define RATE_SPAN 0.15 /* s of odometry a prediction's speed and turn rate are taken over */

/* the sample `age` back from the newest (0: newest) */
static const rl_fuse_entry *at_age(const rl_fuse *f, int age)
{
    return &f->h[(f->head - age + f->cap) % f->cap];
}

/* the age of the newest sample at or before t; -1 if t is before all */
int rl_fuse_hist_find(const rl_fuse *f, double t)
{
    int k;
    for (k = 0; k < f->count; k++)
        if (at_age(f, k)->t <= t)
            return k;
    return -1;
}

/* The odometry's pose at time t: a fraction of the increment between two
 * samples; past the newest, the last increment's rate (at most
 * max_extrapolate, else 1). -1 when t is before the history. */
int rl_fuse_hist_odo_at(const rl_fuse *f, double t, double *o)
{
    int k = rl_fuse_hist_find(f, t), clamped = 0;
    const rl_fuse_entry *a, *b;
    if (k < 0)
        return -1;
    a = at_age(f, k);
    if (k > 0) {
        b = at_age(f, k - 1);
        rl_fuse_kf_advance(a->o, rl_fuse_kf_increment(a->o, b->o), (t - a->t) / (b->t - a->t), o);
        return 0;
    }
    if (t > a->t + f->cfg.max_extrapolate) {
        t = a->t + f->cfg.max_extrapolate;
        clamped = 1;
    }
    if (f->count < 2 || t == a->t) { /* one sample: the robot taken as standing */
        memcpy(o, a->o, sizeof a->o);
        return clamped;
    }
    /* the rate over the last RATE_SPAN s or more: a single short increment's
     * wheel noise would tilt the whole prediction */
    for (k = 1; k < f->count - 1 && a->t - at_age(f, k)->t < RATE_SPAN; k++)
        ;
    b = at_age(f, k);
    rl_fuse_kf_advance(a->o, rl_fuse_kf_increment(b->o, a->o), (t - a->t) / (a->t - b->t), o);
    return clamped;
}

/* the odometry's speed (m/s) and turn rate (rad/s) around time t */
void rl_fuse_hist_rate(const rl_fuse *f, double t, double *v, double *w)
{
    int k = rl_fuse_hist_find(f, t);
    const rl_fuse_entry *a, *b;
    rl_fuse_kf_incr d;
    *v = *w = 0;
    if (f->count < 2)
        return;
    if (k < 1)
        k = 1;
    a = at_age(f, k);
    b = at_age(f, k - 1);
    d = rl_fuse_kf_increment(a->o, b->o);
    *v = d.fwd / (b->t - a->t);
    *w = d.turn / (b->t - a->t);
}

/* the state at time t (0), 1 past the extrapolation limit, -1 outside */
int rl_fuse_hist_state_at(const rl_fuse *f, double t, rl_fuse_kf_state *s)
{
    const rl_fuse_entry *base = &f->anchor;
    double o[3];
    int k = rl_fuse_hist_find(f, t), r;
    if (k >= 0 && at_age(f, k)->valid && at_age(f, k)->t >= f->anchor.t)
        base = at_age(f, k);
    /* before the anchor (a time earlier than the last fused frame) the
     * anchor is still the best base: moved back through the odometry, its
     * covariance grows as forward (conservative), its mean keeps the frame */
    if (!base->valid || (r = rl_fuse_hist_odo_at(f, t, o)) < 0)
        return -1;
    memcpy(s->m, base->m, sizeof s->m);
    memcpy(s->P, base->P, sizeof s->P);
    rl_fuse_kf_propagate(s, rl_fuse_kf_increment(base->o, o), &f->cfg);
    return r;
}

/* Every entry after the anchor, again from it. */
static void replay(rl_fuse *f)
{
    const rl_fuse_entry *prev = &f->anchor;
    int k;
    for (k = f->count - 1; k >= 0; k--) {
        rl_fuse_entry *e = &f->h[(f->head - k + f->cap) % f->cap];
        rl_fuse_kf_state s;
        if (e->t <= f->anchor.t)
            continue;
        memcpy(s.m, prev->m, sizeof s.m);
        memcpy(s.P, prev->P, sizeof s.P);
        rl_fuse_kf_propagate(&s, rl_fuse_kf_increment(prev->o, e->o), &f->cfg);
        memcpy(e->m, s.m, sizeof s.m);
        memcpy(e->P, s.P, sizeof s.P);
        e->valid = 1;
        prev = e;
    }
}

/* s becomes the anchor at time t (the last fused frame's); the rest replayed */
void rl_fuse_hist_anchor(rl_fuse *f, double t, const rl_fuse_kf_state *s)
{
    if (rl_fuse_hist_odo_at(f, t, f->anchor.o) != 0)
        return; /* callers checked t is inside the history */
    f->anchor.t = t;
    memcpy(f->anchor.m, s->m, sizeof s->m);
    memcpy(f->anchor.P, s->P, sizeof s->P);
    f->anchor.valid = 1;
    f->has_pose = 1;
    f->last_frame_t = t;
    replay(f);
}

/* A frame's covariance: its sigmas (or the config's), the floor, and the
 * capture time's error carried by the motion (speed and turn rate at yaw). */
void rl_fuse_hist_frame_cov(const rl_fuse *f, const rl_fuse_frame *fr, double yaw, double R[3][3])
{
    const rl_fuse_config *c = &f->cfg;
    double sx = fr->sx > 0 ? fr->sx : c->sigma_xy, sy = fr->sy > 0 ? fr->sy : c->sigma_xy;
    double sa = fr->syaw > 0 ? fr->syaw : c->sigma_yaw, v, w, u[3];
    double t2 = c->time_sigma * c->time_sigma + fr->st * fr->st;
    int i, j;
    rl_fuse_hist_rate(f, fr->t, &v, &w);
    u[0] = v * cos(yaw);
    u[1] = v * sin(yaw);
    u[2] = w;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            R[i][j] = t2 * u[i] * u[j];
    R[0][0] += sx * sx + c->floor_xy * c->floor_xy;
    R[1][1] += sy * sy + c->floor_xy * c->floor_xy;
    R[2][2] += sa * sa + c->floor_yaw * c->floor_yaw;
}


void rl_fuse_hist_push(rl_fuse *f, double t, const double *o)
{
    const rl_fuse_entry *prev = f->count > 0 ? at_age(f, 0) : NULL;
    rl_fuse_entry *e;
    rl_fuse_kf_state s;
    f->head = (f->head + 1) % f->cap;
    if (f->count < f->cap)
        f->count++;
    e = &f->h[f->head];
    e->t = t;
    memcpy(e->o, o, sizeof e->o);
    e->valid = 0;
    if (!f->has_pose)
        return;
    if (prev == NULL || !prev->valid || prev->t < f->anchor.t)
        prev = &f->anchor;
    memcpy(s.m, prev->m, sizeof s.m);
    memcpy(s.P, prev->P, sizeof s.P);
    rl_fuse_kf_propagate(&s, rl_fuse_kf_increment(prev->o, o), &f->cfg);
    memcpy(e->m, s.m, sizeof s.m);
    memcpy(e->P, s.P, sizeof s.P);
    e->valid = 1;
}
