/* rl_fuse: see rl_fuse.h. The frames' road: waiting for the odometry,
 * the gate, the restart after the robot was carried; the arithmetic is
 * rl_fuse_kf.c, the past rl_fuse_hist.c. */
#include <limits.h>
#include <math.h>
#include <string.h>
#include "rl_fuse.h"
#include "rl_fuse_clock.h"
#include "rl_fuse_hist.h"
#include "rl_fuse_kf.h"

#define UNTIMED 0.01 /* s: frames whose capture time is less certain are not fused */

void rl_fuse_defaults(rl_fuse_config *cfg)
{
    cfg->track = 0.33;
    cfg->wheel_noise = 0.0002;
    cfg->scale = cfg->turn = 1;
    cfg->scale_sigma = 0.03;
    cfg->turn_sigma = 0.05;
    cfg->scale_drift = 1e-4;
    cfg->time_sigma = 0.002;
    cfg->sigma_xy = 0.005;
    cfg->sigma_yaw = 0.005;
    cfg->floor_xy = 0.0005;
    cfg->floor_yaw = 0.0005;
    cfg->gate = 16.27;
    cfg->recover_frames = 2;
    cfg->max_extrapolate = 0.5;
}

size_t rl_fuse_history_count(double seconds, double odo_hz)
{
    double n = ceil(seconds * odo_hz) + 2; /* a sample before the oldest frame, the newest */
    if (!(seconds >= 0) || !(odo_hz > 0) || !(n <= INT_MAX))
        return 0;
    return (size_t)n;
}

rl_err rl_fuse_init(rl_fuse *f, const rl_fuse_config *cfg, rl_fuse_entry *hist, size_t n)
{
    if (!(cfg->track > 0) || !(cfg->wheel_noise >= 0) || !(cfg->scale_sigma >= 0) ||
        !(cfg->turn_sigma >= 0) || !(cfg->scale_drift >= 0) || !(cfg->time_sigma >= 0) ||
        !(cfg->sigma_xy > 0) || !(cfg->sigma_yaw > 0) || !(cfg->floor_xy >= 0) ||
        !(cfg->floor_yaw >= 0) || !(cfg->gate > 0) || cfg->recover_frames < 0 ||
        !(cfg->max_extrapolate >= 0) || !(cfg->scale > 0) || !(cfg->turn > 0) || hist == NULL || n < 2 || n > INT_MAX)
        return RL_EINVAL;
    memset(f, 0, sizeof *f);
    memset(hist, 0, n * sizeof *hist);
    f->h = hist;
    f->cap = (int)n;
    f->cfg = *cfg;
    f->head = -1;
    f->last_frame_t = -HUGE_VAL;
    rl_fuse_clock_init(&f->clock);
    return RL_OK;
}

static rl_err add(rl_fuse *f, const rl_fuse_frame *fr);

rl_err rl_fuse_odometry(rl_fuse *f, double t, double x, double y, double yaw)
{
    double o[3];
    if (!isfinite(t) || !isfinite(x) || !isfinite(y) || !isfinite(yaw))
        return RL_EINVAL;
    if (f->count > 0 && !(t > f->h[f->head].t))
        return RL_EINVAL;
    o[0] = x;
    o[1] = y;
    o[2] = rl_fuse_kf_wrap(yaw);
    rl_fuse_hist_push(f, t, o);
    if (f->has_waiting && f->waiting.t <= t) {
        rl_fuse_frame w = f->waiting;
        f->has_waiting = 0;
        f->pending_seq = f->waiting_seq;
        f->pending_reset = f->waiting_reset;
        (void)!add(f, &w); /* the frame's fate is in stats and the event */
    }
    return RL_OK;
}

static void frame_pose(const rl_fuse_frame *fr, double *z)
{
    z[0] = fr->x;
    z[1] = fr->y;
    z[2] = fr->yaw;
}

/* the fate of the frame being added (captured at t) is decided: r back */
static rl_err decide(rl_fuse *f, double t, rl_fuse_fate fate, double d2, rl_err r)
{
    f->event.n++;
    f->event.fate = fate;
    f->event.t = t;
    f->event.d2 = d2;
    f->event.seq = f->pending_seq;
    f->event.clock_reset = f->pending_reset;
    return r;
}

/* (Re)start the filter from frame fr alone: its pose and covariance, the
 * scales as learned so far (or as configured, the first time). */
static void start_from(rl_fuse *f, const rl_fuse_frame *fr)
{
    rl_fuse_kf_state cur, s;
    double z[3], R[3][3];
    double sc = f->cfg.scale, sv = f->cfg.scale_sigma * f->cfg.scale_sigma;
    double tu = f->cfg.turn, tv = f->cfg.turn_sigma * f->cfg.turn_sigma;
    if (f->has_pose && rl_fuse_hist_state_at(f, fr->t, &cur) == 0) {
        sc = cur.m[3];
        sv = cur.P[3][3];
        tu = cur.m[4];
        tv = cur.P[4][4];
    }
    frame_pose(fr, z);
    rl_fuse_hist_frame_cov(f, fr, fr->yaw, R);
    rl_fuse_kf_start(&s, z, R, sc, sv, tu, tv);
    rl_fuse_hist_anchor(f, fr->t, &s);
}

/* Do the rejected frame c and frame fr tell one story through the
 * odometry between them (the robot carried, not a bad frame)? */
static int agree(const rl_fuse *f, const rl_fuse_frame *c, const rl_fuse_frame *fr)
{
    rl_fuse_kf_state s, cur;
    double oc[3], of[3], z[3], R[3][3];
    if (rl_fuse_hist_odo_at(f, c->t, oc) != 0 || rl_fuse_hist_odo_at(f, fr->t, of) != 0 ||
        rl_fuse_hist_state_at(f, fr->t, &cur) != 0)
        return 0;
    frame_pose(c, z);
    rl_fuse_hist_frame_cov(f, c, c->yaw, R);
    rl_fuse_kf_start(&s, z, R, cur.m[3], cur.P[3][3], cur.m[4], cur.P[4][4]);
    rl_fuse_kf_propagate(&s, rl_fuse_kf_increment(oc, of), &f->cfg);
    frame_pose(fr, z);
    rl_fuse_hist_frame_cov(f, fr, fr->yaw, R);
    return rl_fuse_kf_distance(&s, z, R) <= f->cfg.gate;
}

/* A rejected frame (distance d2): counted; the start of a run of frames
 * that agree, or the end of one long enough to restart from (RL_OK). */
static rl_err rejected(rl_fuse *f, const rl_fuse_frame *fr, double d2)
{
    f->stats.rejected++;
    if (f->n_cand > 0 && agree(f, &f->cand, fr))
        f->n_cand++;
    else
        f->n_cand = 1;
    f->cand = *fr;
    if (f->cfg.recover_frames == 0 || f->n_cand < f->cfg.recover_frames)
        return decide(f, fr->t, RL_FUSE_REJECTED, d2, RL_ERANGE);
    f->n_cand = 0;
    f->stats.recoveries++;
    start_from(f, fr);
    return decide(f, fr->t, RL_FUSE_RESTARTED, d2, RL_OK);
}

/* Fuse frame fr at its capture time (inside the history, a pose known). */
static rl_err fuse(rl_fuse *f, const rl_fuse_frame *fr)
{
    rl_fuse_kf_state s;
    double z[3], R[3][3], d2;
    if (rl_fuse_hist_state_at(f, fr->t, &s) != 0) {
        f->stats.too_old++;
        return decide(f, fr->t, RL_FUSE_TOO_OLD, 0, RL_ERANGE);
    }
    frame_pose(fr, z);
    rl_fuse_hist_frame_cov(f, fr, s.m[2], R);
    d2 = rl_fuse_kf_distance(&s, z, R);
    if (d2 > f->cfg.gate)
        return rejected(f, fr, d2);
    rl_fuse_kf_update(&s, z, R);
    rl_fuse_hist_anchor(f, fr->t, &s);
    f->n_cand = 0;
    f->stats.applied++;
    return decide(f, fr->t, RL_FUSE_APPLIED, d2, RL_OK);
}

/* frame fr, whose sequence number and clock reset are pending_* */
static rl_err add(rl_fuse *f, const rl_fuse_frame *fr)
{
    if (!isfinite(fr->t) || !isfinite(fr->x) || !isfinite(fr->y) || !isfinite(fr->yaw) ||
        !isfinite(fr->sx) || !isfinite(fr->sy) || !isfinite(fr->syaw) || !isfinite(fr->st))
        return RL_EINVAL;
    if (fr->t <= f->last_frame_t) {
        f->stats.out_of_order++;
        return decide(f, fr->t, RL_FUSE_OUT_OF_ORDER, 0, RL_ERANGE);
    }
    if (f->count == 0 || fr->t > f->h[f->head].t) {
        if (f->has_waiting) { /* the event is the lost frame's */
            unsigned seq = f->pending_seq;
            int reset = f->pending_reset;
            f->stats.waiting_lost++;
            f->pending_seq = f->waiting_seq;
            f->pending_reset = f->waiting_reset;
            (void)decide(f, f->waiting.t, RL_FUSE_LOST, 0, RL_OK);
            f->pending_seq = seq;
            f->pending_reset = reset;
        }
        f->waiting = *fr;
        f->waiting_seq = f->pending_seq;
        f->waiting_reset = f->pending_reset;
        f->has_waiting = 1;
        return RL_OK;
    }
    if (rl_fuse_hist_find(f, fr->t) < 0) {
        f->stats.too_old++;
        return decide(f, fr->t, RL_FUSE_TOO_OLD, 0, RL_ERANGE);
    }
    if (!f->has_pose) {
        start_from(f, fr);
        f->stats.applied++;
        return decide(f, fr->t, RL_FUSE_APPLIED, 0, RL_OK);
    }
    return fuse(f, fr);
}

rl_err rl_fuse_frame_add(rl_fuse *f, const rl_fuse_frame *fr)
{
    f->pending_seq = 0;
    f->pending_reset = 0;
    return add(f, fr);
}

static size_t frame_bytes(const rl_msg *m)
{
    return (m->version == 1 ? RL_POSE_V1_PAYLOAD : RL_POSE_PAYLOAD) + 5;
}

rl_err rl_fuse_msg_add(rl_fuse *f, const rl_msg *m, double arrival, int baud)
{
    rl_fuse_frame fr;
    double known;
    if (m->type != RL_PACKET_POSE || !isfinite(arrival))
        return RL_EINVAL;
    rl_fuse_frame_from_msg(m, 0, 0, &fr);
    known = m->latency_e4 * 1e-4 + (baud > 0 ? frame_bytes(m) * 10.0 / baud : 0);
    f->pending_seq = m->seq;
    f->pending_reset = rl_fuse_clock_stamp(&f->clock, m->time_ms, m->seq, known, arrival, &fr.t, &fr.st);
    if (f->pending_reset)
        f->stats.clock_resets++;
    /* a time this uncertain is wrong beyond the filter's linear model (a
     * turn's chord): the frame waits for the clock to be known */
    if (!(fr.st <= UNTIMED)) {
        f->stats.untimed++;
        return decide(f, fr.t, RL_FUSE_UNTIMED, 0, RL_ERANGE);
    }
    return add(f, &fr);
}

void rl_fuse_last_event(const rl_fuse *f, rl_fuse_event *ev)
{
    *ev = f->event;
}

rl_err rl_fuse_pose_at(const rl_fuse *f, double t, rl_fuse_pose *p)
{
    rl_fuse_kf_state s;
    int r, i, j;
    if (!f->has_pose)
        return RL_ENOTFOUND;
    r = rl_fuse_hist_state_at(f, t, &s);
    if (r < 0)
        return RL_ERANGE;
    p->t = t;
    p->x = s.m[0];
    p->y = s.m[1];
    p->yaw = s.m[2];
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            p->cov[i][j] = s.P[i][j];
    p->scale = s.m[3];
    p->turn = s.m[4];
    p->scale_sd = sqrt(s.P[3][3]);
    p->turn_sd = sqrt(s.P[4][4]);
    rl_fuse_hist_rate(f, t, &p->v, &p->w);
    p->v *= p->scale;
    p->w *= p->turn;
    return r == 0 ? RL_OK : RL_ERANGE;
}

void rl_fuse_frame_from_msg(const rl_msg *m, double arrival, int baud, rl_fuse_frame *fr)
{
    fr->t = arrival - m->latency_e4 * 1e-4 - (baud > 0 ? frame_bytes(m) * 10.0 / baud : 0);
    fr->x = m->x_mm * 1e-3;
    fr->y = m->y_mm * 1e-3;
    fr->yaw = m->yaw_e4 * 1e-4;
    fr->sx = m->version == 1 ? 0 : m->sigma_x_e4 * 1e-4;
    fr->sy = m->version == 1 ? 0 : m->sigma_y_e4 * 1e-4;
    fr->syaw = m->version == 1 ? 0 : m->sigma_yaw_e4 * 1e-4;
    fr->st = 0;
}
