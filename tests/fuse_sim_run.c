/* fuse_sim: one drive under a scenario (see fuse_sim.h). */
#define _DEFAULT_SOURCE 1
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_outfile.h"
#include "fuse_sim.h"

#define STEP 0.001 /* the robot integrates its odometry at 1 kHz */
#define MAX_ODO 4096
#define MAX_FR 1024
#define TICK 0.01
#define BAUD 115200
#define RATE_SPAN 0.15

typedef struct {
    double t, o[3];
    double read; /* when the controller read it (stamped then) */
    int lost;    /* never read */
} odo_sample;

typedef struct {
    double capture, arrival;
    rl_msg msg;
    fs_pose meas;
} sim_frame;

static unsigned long long rng;

static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return ((rng >> 11) + 0.5) / 9007199254740992.0;
}

static double gauss(void)
{
    return sqrt(-2 * log(uniform())) * cos(2 * M_PI * uniform());
}

static double wrap(double a)
{
    return atan2(sin(a), cos(a));
}

/* the truth at time t: the path, and 3 m further in x once carried */
static void truth(const fs_drive *d, const fs_scenario *sc, double t, fs_pose *p)
{
    fs_truth_at(d, sc->v * t, p);
    if (sc->kidnap_at >= 0 && sc->v * t >= sc->kidnap_at)
        p->x += 3.0;
}

/* The wheels over the drive: the truth's increments split into the two
 * wheels of the true track, each noisy, read through the wrong scale and
 * put together with the nominal track, as the robot's controller does. */
static int odometry(const fs_drive *d, const fs_scenario *sc, double T, odo_sample *out)
{
    fs_pose prev, p;
    double o[3] = {0, 0, 0}, next = 0, bt = sc->track * sc->track_err;
    int n = 0;
    long i, steps = (long)(T / STEP + 0.5);
    fs_truth_at(d, 0, &prev);
    for (i = 0; i <= steps && n < MAX_ODO; i++) {
        double t = i * STEP;
        if (i > 0) {
            double a, dist, dr, dl, dro, dlo, dd, da;
            fs_truth_at(d, sc->v * t, &p);
            a = wrap(p.yaw - prev.yaw);
            dist = hypot(p.x - prev.x, p.y - prev.y);
            dr = dist + a * bt / 2;
            dl = dist - a * bt / 2;
            dro = (dr + sc->wheel_noise * sqrt(fabs(dr)) * gauss()) / sc->scale_err;
            dlo = (dl + sc->wheel_noise * sqrt(fabs(dl)) * gauss()) / sc->scale_err;
            dd = (dro + dlo) / 2;
            da = (dro - dlo) / sc->track;
            o[0] += dd * cos(o[2] + da / 2);
            o[1] += dd * sin(o[2] + da / 2);
            o[2] = wrap(o[2] + da);
            prev = p;
        }
        if (t >= next - 1e-9) {
            out[n].t = out[n].read = t;
            out[n].lost = 0;
            memcpy(out[n].o, o, sizeof o);
            n++;
            next += 1.0 / sc->odo_hz;
        }
    }
    return n;
}

#define CLOCK0 1234.5678 /* the board's clock at the drive's start, s */
#define BOOT 0.5         /* s a restarted firmware sends nothing */

/* the board's clock at capture time t (s), and the frame's sequence number */
static void board_clock(const fs_scenario *sc, double t, int order, int order_at_restart, rl_msg *m)
{
    double rate = 1 + sc->drift_ppm * 1e-6;
    int after = sc->restart_at >= 0 && t >= sc->restart_at;
    double c = after ? (t - sc->restart_at) * rate : CLOCK0 + t * rate;
    if (sc->from_clock == 0 && !after)
        c = t; /* the capture on the controller's clock (ringloc fuse without --arrivals) */
    m->time_ms = (uint32_t)floor(c * 1e3); /* as the firmware does (rl_packet_sink) */
    m->seq = (uint16_t)(after ? order - order_at_restart : order);
}

/* when frame f, sent at `sent`, is read by the controller, the frame
 * before it read at `prev` (a line keeps the order) */
static double arrive(const fs_scenario *sc, double sent, double prev)
{
    double a = sent + sc->extra_fixed + (sc->extra_max > 0 ? sc->extra_max * uniform() : 0), line = (RL_POSE_PAYLOAD + 5) * 10.0 / BAUD;
    if (sc->ftdi_tick > 0) /* a free-running timer, its phase 3 ms */
        a = 0.003 + ceil((a - 0.003) / sc->ftdi_tick) * sc->ftdi_tick;
    if (a < prev + line)
        a = prev + line;
    return a;
}

/* the controller's reads of the odometry: late, some stalled (the
 * samples behind a stalled one read right after it) */
static void reads(const fs_scenario *sc, odo_sample *odo, int no)
{
    int i;
    if (sc->read_late <= 0 && sc->stall_p <= 0 && sc->lose_p <= 0)
        return;
    for (i = 0; i < no; i++) {
        double r = odo[i].t + sc->read_late * uniform();
        if (uniform() < sc->stall_p)
            r += sc->stall_max * uniform();
        odo[i].lost = i > 0 && uniform() < sc->lose_p;
        odo[i].read = i > 0 && r <= odo[i - 1].read ? odo[i - 1].read + 1e-5 : r;
    }
}

/* the frames of the drive, lap after lap, in order of arrival */
static int frames(const fs_drive *d, const fs_scenario *sc, double T, sim_frame *out)
{
    int lap, k, n = 0, order = 0, order_at_restart = -1;
    double line = (RL_POSE_PAYLOAD + 5) * 10.0 / BAUD, prev = -1;
    for (lap = 0; lap < (d->closed ? (int)ceil(sc->laps) : 1); lap++)
        for (k = 0; k < d->n && n < MAX_FR; k++) {
            double s = lap * d->length + (d->closed ? k * d->length / d->n : d->length * k / (d->n - 1));
            sim_frame *f = &out[n];
            fs_pose tr;
            if (s / sc->v > T - sc->delay - TICK)
                return n;
            if (s >= sc->gap_from && s < sc->gap_to)
                continue;
            if (sc->restart_at >= 0 && s / sc->v >= sc->restart_at && s / sc->v < sc->restart_at + BOOT)
                continue;
            if (sc->restart_at >= 0 && s / sc->v >= sc->restart_at && order_at_restart < 0)
                order_at_restart = order;
            f->capture = s / sc->v;
            truth(d, sc, f->capture, &tr);
            if (sc->simulated) {
                f->meas.x = tr.x + d->sx[k] * gauss();
                f->meas.y = tr.y + d->sy[k] * gauss();
                f->meas.yaw = tr.yaw + d->syaw[k] * gauss();
            } else {
                f->meas = d->meas[k];
                f->meas.x += tr.x - d->truth[k].x; /* carried: the same error, elsewhere */
            }
            memset(&f->msg, 0, sizeof f->msg);
            board_clock(sc, f->capture, order, order_at_restart, &f->msg);
            if (order++ == sc->outlier)
                f->meas.x += 0.5;
            f->arrival = arrive(sc, f->capture + sc->delay, prev) + sc->jitter * (2 * uniform() - 1);
            prev = f->arrival;
            f->msg.type = RL_PACKET_POSE;
            f->msg.version = 2;
            f->msg.x_mm = (int32_t)lround(f->meas.x * 1e3);
            f->msg.y_mm = (int32_t)lround(f->meas.y * 1e3);
            f->msg.yaw_e4 = (int16_t)lround(wrap(f->meas.yaw) * 1e4);
            /* what the firmware reports: its whole capture -> send delay */
            f->msg.latency_e4 = (uint16_t)lround((sc->delay - line) * 1e4);
            f->msg.sigma_x_e4 = (uint16_t)lround(d->sx[k] * 1e4);
            f->msg.sigma_y_e4 = (uint16_t)lround(d->sy[k] * 1e4);
            f->msg.sigma_yaw_e4 = (uint16_t)lround(d->syaw[k] * 1e4);
            n++;
        }
    return n;
}

/* b o (a^-1 o c): pose b moved by the odometry from a to c */
static void moved(const fs_pose *b, const double *a, const double *c, fs_pose *out)
{
    double dx = c[0] - a[0], dy = c[1] - a[1], ca = cos(a[2]), sa = sin(a[2]);
    double lx = ca * dx + sa * dy, ly = -sa * dx + ca * dy, cb = cos(b->yaw), sb = sin(b->yaw);
    out->x = b->x + cb * lx - sb * ly;
    out->y = b->y + sb * lx + cb * ly;
    out->yaw = wrap(b->yaw + c[2] - a[2]);
}

/* a tick shortly after a corner of the rect drive, whose heading turns in
 * no time: the odometry tells of the turn up to a period later, and the
 * pose past the newest sample is predicted at the rate of the last
 * 0.15 s or more (rl_fuse_hist.c), the corner's turn in it until then */
static int near_corner(const fs_drive *d, const fs_scenario *sc, double t)
{
    static const double corners[] = {0, 1.8, 3.0, 4.8};
    double s = fmod(sc->v * t, d->length);
    int i;
    if (strcmp(d->kind, "rect") != 0)
        return 0;
    for (i = 0; i < 4; i++) {
        double after = s - corners[i];
        if (after < 0)
            after += d->length;
        if (after <= sc->v * (RATE_SPAN + 2.0 / sc->odo_hz + TICK) && sc->v * t > 0.01)
            return 1;
    }
    return 0;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void metrics(const fs_drive *d, const fs_scenario *sc, fs_result *r)
{
    static double errs[FS_MAX_TICKS];
    double s2 = 0, s2r = 0, sy2 = 0, prev_ex = 0, prev_ey = 0;
    int i, m = 0, first = 1;
    r->max_err_fused = r->max_step = r->max_yaw = r->gap_max_err = 0;
    r->warm_max_err = r->warm_max_step = r->warm_max_yaw = 0;
    for (i = 0; i < r->n; i++) {
        double ex = r->fused[i].x - r->truth[i].x, ey = r->fused[i].y - r->truth[i].y;
        double e = hypot(ex, ey), ey_aw = fabs(wrap(r->fused[i].yaw - r->truth[i].yaw));
        if (r->in_gap[i] && !r->corner[i] && e > r->gap_max_err)
            r->gap_max_err = e;
        if (r->t[i] < sc->warmup) {
            r->warm_max_err = fmax(r->warm_max_err, e);
            r->warm_max_yaw = fmax(r->warm_max_yaw, ey_aw);
            if (!first)
                r->warm_max_step = fmax(r->warm_max_step, hypot(ex - prev_ex, ey - prev_ey));
            prev_ex = ex;
            prev_ey = ey;
            first = 0;
            continue;
        }
        if (r->in_gap[i] || r->corner[i] || (sc->kidnap_at >= 0 && sc->v * r->t[i] >= sc->kidnap_at)) {
            first = 1;
            continue;
        }
        errs[m] = e;
        s2 += e * e;
        s2r += pow(r->reset[i].x - r->truth[i].x, 2) + pow(r->reset[i].y - r->truth[i].y, 2);
        sy2 += ey_aw * ey_aw;
        m++;
        if (e > r->max_err_fused)
            r->max_err_fused = e;
        if (ey_aw > r->max_yaw) {
            r->max_yaw = ey_aw;
            r->t_max_yaw = r->t[i];
        }
        if (!first && hypot(ex - prev_ex, ey - prev_ey) > r->max_step) {
            r->max_step = hypot(ex - prev_ex, ey - prev_ey);
            r->t_max_step = r->t[i];
        }
        prev_ex = ex;
        prev_ey = ey;
        first = 0;
    }
    r->rms_fused = m ? sqrt(s2 / m) : NAN;
    qsort(errs, (size_t)m, sizeof errs[0], by_value);
    r->p95_fused = m ? errs[(int)ceil(0.95 * m) - 1] : NAN;
    r->rms_reset = m ? sqrt(s2r / m) : NAN;
    r->rms_yaw = m ? sqrt(sy2 / m) : NAN;
    r->gap_dist = sc->gap_to > sc->gap_from ? sc->gap_to - sc->gap_from : 0;
    (void)d;
}

/* the controller's 10 ms ticks: events up to the tick, then both poses */
static int ticks(const fs_drive *d, const fs_scenario *sc, double T, const odo_sample *odo, int no,
                 const sim_frame *fr, int nf, rl_fuse *f, fs_result *r)
{
    int io = 0, jf = 0, have_reset = 0, kid_frames = 0;
    double t, reset_odo[3];
    rl_fuse_cycle cy;
    fs_pose reset_base = {0, 0, 0};
    r->n = 0;
    r->kidnap_err = NAN;
    r->kidnap_err_2s = 0;
    if (rl_fuse_cycle_init(&cy, 1.0 / sc->odo_hz) != RL_OK)
        return -1;
    for (t = 0; t <= T + 1e-9; t += TICK) {
        rl_fuse_pose p;
        while ((io < no && odo[io].read <= t) || (jf < nf && fr[jf].arrival <= t)) {
            if (jf >= nf || (io < no && odo[io].read <= fr[jf].arrival)) {
                double stamp;
                if (odo[io].lost) {
                    io++;
                    continue;
                }
                stamp = sc->cycled ? rl_fuse_cycle_stamp(&cy, odo[io].read) : odo[io].read;
                if (rl_fuse_odometry(f, stamp, odo[io].o[0], odo[io].o[1], odo[io].o[2]) != RL_OK)
                    return -1;
                io++;
            } else {
                rl_fuse_frame ff;
                rl_fuse_frame_from_msg(&fr[jf].msg, fr[jf].arrival, BAUD, &ff);
                if (sc->from_clock)
                    (void)!rl_fuse_msg_add(f, &fr[jf].msg, fr[jf].arrival, BAUD); /* in the stats */
                else
                    (void)!rl_fuse_frame_add(f, &ff); /* outcomes are counted in the stats */
                reset_base = fr[jf].meas; /* today's snippet: moveTo(frame) */
                memcpy(reset_odo, odo[io > 0 ? io - 1 : 0].o, sizeof reset_odo);
                have_reset = 1;
                if (sc->kidnap_at >= 0 && fr[jf].capture * sc->v >= sc->kidnap_at)
                    kid_frames++;
                jf++;
            }
        }
        if (!have_reset || rl_fuse_pose_at(f, t, &p) != RL_OK)
            continue;
        if (r->n >= FS_MAX_TICKS)
            return -1;
        r->t[r->n] = t;
        truth(d, sc, t, &r->truth[r->n]);
        r->fused[r->n].x = p.x;
        r->fused[r->n].y = p.y;
        r->fused[r->n].yaw = p.yaw;
        r->cov[r->n][0] = p.cov[0][0];
        r->cov[r->n][1] = p.cov[0][1];
        r->cov[r->n][2] = p.cov[1][1];
        moved(&reset_base, reset_odo, odo[io - 1].o, &r->reset[r->n]);
        r->in_gap[r->n] = sc->gap_to > sc->gap_from && sc->v * t >= sc->gap_from &&
                          t < sc->gap_to / sc->v + sc->delay;
        r->corner[r->n] = near_corner(d, sc, t);
        if (kid_frames == 2 && isnan(r->kidnap_err))
            r->kidnap_err = hypot(p.x - r->truth[r->n].x, p.y - r->truth[r->n].y);
        if (sc->kidnap_at >= 0 && sc->v * t >= sc->kidnap_at + 2.0 * sc->v)
            r->kidnap_err_2s = fmax(r->kidnap_err_2s, hypot(p.x - r->truth[r->n].x, p.y - r->truth[r->n].y));
        r->scale = p.scale;
        r->turn = p.turn;
        r->n++;
    }
    return 0;
}

/* The drive as `ringloc fuse` takes it: the odometry log, the frames
 * recorded as sent (time_ms: the board's clock; without from_clock the
 * capture on the controller's clock), their arrivals (seq, s) and the
 * truth at every 10 ms. */
static int export_drive(const fs_drive *d, const fs_scenario *sc, double T, const odo_sample *odo, int no,
                        const sim_frame *fr, int nf)
{
    static const char *names[4] = {"odometry.txt", "frames.bin", "truth.txt", "arrivals.txt"};
    char path[1024], err[1200];
    rl_outfile o[4];
    int i, j, ok = 1;
    long k;
    for (j = 0; j < 4; j++) { /* written whole or not at all (rl_outfile) */
        snprintf(path, sizeof path, "%s/%s", sc->export_dir, names[j]);
        if (rl_outfile_open(&o[j], path, err, sizeof err) != RL_OK) {
            while (j-- > 0)
                rl_outfile_abort(&o[j]);
            fprintf(stderr, "%s\n", err);
            return -1;
        }
    }
    for (i = 0; i < no; i++)
        fprintf(o[0].f, "%.4f %.6f %.6f %.6f\n", odo[i].t, odo[i].o[0], odo[i].o[1], odo[i].o[2]);
    for (i = 0; i < nf; i++) {
        uint8_t buf[RL_PACKET_MAX];
        fwrite(buf, 1, rl_packet_encode(&fr[i].msg, buf), o[1].f);
        fprintf(o[3].f, "%u %.6f\n", (unsigned)fr[i].msg.seq, fr[i].arrival);
    }
    for (k = 0; k * TICK <= T + 1e-9; k++) {
        fs_pose p;
        truth(d, sc, k * TICK, &p);
        fprintf(o[2].f, "%.3f %.6f %.6f %.6f\n", k * TICK, p.x, p.y, p.yaw);
    }
    for (j = 0; j < 4; j++)
        if (rl_outfile_commit(&o[j], err, sizeof err) != RL_OK) {
            fprintf(stderr, "%s\n", err);
            ok = 0;
        }
    return ok ? 0 : -1;
}

int fs_run(const fs_drive *d, const fs_scenario *sc, fs_result *r)
{
    static odo_sample odo[MAX_ODO];
    static sim_frame fr[MAX_FR];
    static rl_fuse f;
    static rl_fuse_entry hist[1024];
    rl_fuse_config cfg;
    double T = (d->closed ? sc->laps : 1.0) * d->length / sc->v;
    int no, nf, k;
    rng = 0x9E3779B97F4A7C15ULL ^ (sc->seed * 0x2545F4914F6CDD1DULL);
    no = odometry(d, sc, T, odo);
    nf = frames(d, sc, T, fr);
    reads(sc, odo, no);
    if (sc->export_dir && export_drive(d, sc, T, odo, no, fr, nf) != 0)
        return -1;
    rl_fuse_defaults(&cfg);
    cfg.track = sc->track;
    /* the wheel noise is the library's default: the stretch without
     * landmarks judges it (the simulated wheels are ordinary ones) */
    cfg.time_sigma = sc->jitter / sqrt(3.0);
    /* the renderer's map is exact and the frames' yaw errors are as their
     * sigmas say (0.09 mrad RMS on the circle); their positions are 0.5 mm
     * RMS off for sigmas of 0.1 mm: the default floor_xy stays */
    cfg.floor_yaw = 0;
    if (rl_fuse_history_count(2.5, sc->odo_hz) > 1024 ||
        rl_fuse_init(&f, &cfg, hist, rl_fuse_history_count(2.5, sc->odo_hz)) != RL_OK || ticks(d, sc, T, odo, no, fr, nf, &f, r) != 0)
        return -1;
    r->stats = f.stats;
    r->mean_latency = 0;
    for (k = 0; k < d->n; k++)
        r->mean_latency += d->latency[k] / d->n;
    metrics(d, sc, r);
    return 0;
}
