#include "rl_run.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static rl_err solve(rl_runner *r, uint64_t t_us, rl_pose *pose);

void rl_run_init(rl_runner *r, const rl_run_io *io, rl_recog *rec, const rl_calib *calib,
                 const rl_map *map, const rl_mount *mount, rl_result *res)
{
    memset(r, 0, sizeof *r);
    r->io = *io;
    r->rec = rec;
    r->calib = calib;
    r->map = map;
    r->mount = mount;
    r->res = res;
    r->timeout_ms = 500;
    r->reopen_after_timeouts = 3;
    r->backoff_min_us = 100000;
    r->backoff_max_us = 2000000;
    r->status_period_us = 200000;
    r->log_interval_us = 5000000;
    r->cam_backoff = r->out_backoff = r->backoff_min_us;
}

/* Logs are rate-limited per kind: the first line of a kind goes out, then
 * at most one per interval with a count of the ones held back. */
static void logf_(rl_runner *r, int kind, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* 1 the first time a bad-frame line is seen (its hash kept while there
 * is room): it is logged then, whatever the interval. */
static int new_frame_line(rl_runner *r, const char *line)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    int i;
    for (; *line; line++)
        h = (h ^ (uint8_t)*line) * 16777619u;
    for (i = 0; i < r->n_frame_lines; i++)
        if (r->frame_lines[i] == h)
            return 0;
    if (r->n_frame_lines == RL_RUN_FRAME_LINES)
        return 0;
    r->frame_lines[r->n_frame_lines++] = h;
    return 1;
}

static void logf_(rl_runner *r, int kind, const char *fmt, ...)
{
    char line[512], full[600];
    uint64_t now = r->io.clock.now_us(r->io.clock.ctx);
    va_list ap;
    if (r->io.log == NULL)
        return;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (r->last_log[kind] != 0 && now - r->last_log[kind] < r->log_interval_us &&
        !(kind == RL_LOG_FRAME && new_frame_line(r, line))) {
        r->suppressed[kind]++;
        return;
    }
    if (kind == RL_LOG_FRAME)
        (void)new_frame_line(r, line); /* the first such line is kept too */
    if (r->suppressed[kind] > 0)
        snprintf(full, sizeof full, "%s (%ld more like it)", line, r->suppressed[kind]);
    else
        snprintf(full, sizeof full, "%s", line);
    r->io.log(r->io.log_ctx, full);
    r->last_log[kind] = now ? now : 1;
    r->suppressed[kind] = 0;
}

static uint64_t next_backoff(const rl_runner *r, uint64_t b)
{
    return 2 * b > r->backoff_max_us ? r->backoff_max_us : 2 * b;
}

/* Send one message; a failed line is closed and reopened later, and the
 * message is counted as dropped (the controller sees a gap in seq). */
static void send_msg(rl_runner *r, rl_msg *m)
{
    uint8_t buf[RL_PACKET_MAX];
    size_t n;
    char err[256];
    uint64_t now = r->io.clock.now_us(r->io.clock.ctx);
    rl_err e;
    m->seq = r->seq++;
    if (!r->out_up) {
        if (now < r->out_retry_at) {
            r->dropped++;
            return;
        }
        if ((e = r->io.out.open(r->io.out.ctx, err, sizeof err)) != RL_OK) {
            logf_(r, RL_LOG_SERIAL, "serial: %s; retrying", err);
            r->out_retry_at = now + r->out_backoff;
            r->out_backoff = next_backoff(r, r->out_backoff);
            r->serial_errors++;
            r->dropped++;
            return;
        }
        r->out_up = 1;
        r->out_backoff = r->backoff_min_us;
    }
    n = rl_packet_encode(m, buf);
    if ((e = r->io.out.write(r->io.out.ctx, buf, n)) != RL_OK) {
        const char *why = r->io.out.why ? r->io.out.why(r->io.out.ctx) : NULL;
        logf_(r, RL_LOG_SERIAL, "serial: write failed (%s); reopening", why ? why : rl_strerror(e));
        r->io.out.close(r->io.out.ctx);
        r->out_up = 0;
        r->out_retry_at = now + r->out_backoff;
        r->out_backoff = next_backoff(r, r->out_backoff);
        r->serial_errors++;
        r->dropped++;
        return;
    }
    /* sent: the summary counts what reached the line */
    if (m->type == RL_PACKET_POSE)
        r->poses++;
    else
        r->statuses++;
}

static void send_status(rl_runner *r, int reason, int identified, int candidates, uint64_t t_us)
{
    rl_msg m;
    memset(&m, 0, sizeof m);
    m.type = RL_PACKET_STATUS;
    m.time_ms = (uint32_t)(t_us / 1000u);
    m.reason = (uint8_t)reason;
    m.identified = (uint8_t)(identified > 255 ? 255 : identified);
    m.candidates = (uint8_t)(candidates > 255 ? 255 : candidates);
    send_msg(r, &m);
}

static int32_t clamp32(double v)
{
    return v > 2147483647.0 ? 2147483647 : v < -2147483647.0 ? -2147483647 : (int32_t)lround(v);
}

static uint16_t clampu16(double v)
{
    return v > 65535.0 ? 65535 : v < 0 ? 0 : (uint16_t)lround(v);
}

static int16_t clamp16(double v)
{
    return v > 32767.0 ? 32767 : v < -32767.0 ? -32767 : (int16_t)lround(v);
}

static void camera_down(rl_runner *r, uint64_t now)
{
    rl_cam_close(&r->cam);
    r->cam_up = 0;
    r->cam_retry_at = now + r->cam_backoff;
    r->cam_backoff = next_backoff(r, r->cam_backoff);
}

rl_err rl_run_step(rl_runner *r)
{
    uint64_t now = r->io.clock.now_us(r->io.clock.ctx);
    rl_cam_frame f;
    rl_pose pose;
    rl_err e;
    char err[256];
    int i, w, h, local = 0;

    if (!r->cam_up) {
        if (now >= r->cam_retry_at) {
            if ((e = rl_cam_open(&r->cam, r->io.cam, err, sizeof err)) == RL_OK) {
                r->cam_up = 1;
                r->timeouts = 0;
                r->cam_backoff = r->backoff_min_us;
                logf_(r, RL_LOG_INFO, "camera: open%s%s", r->cam.info[0] ? ": " : "", r->cam.info);
                return RL_OK;
            }
            r->camera_errors++;
            logf_(r, RL_LOG_CAMERA, "camera: %s; retrying", err);
            r->cam_retry_at = now + r->cam_backoff;
            r->cam_backoff = next_backoff(r, r->cam_backoff);
        }
        /* while the camera is down, the controller still hears from us */
        send_status(r, RL_STATUS_CAMERA_ERROR, 0, 0, now);
        {
            uint64_t wait = r->cam_retry_at > now ? r->cam_retry_at - now : 0;
            r->io.clock.sleep_us(r->io.clock.ctx, wait < r->status_period_us ? wait : r->status_period_us);
        }
        return RL_OK;
    }

    e = rl_cam_grab(&r->cam, r->timeout_ms, &f);
    if (e == RL_ENOTFOUND)
        return RL_ENOTFOUND;
    if (e == RL_ETIMEOUT) {
        r->camera_timeouts++;
        logf_(r, RL_LOG_TIMEOUT, "camera: no frame in %d ms", r->timeout_ms);
        send_status(r, RL_STATUS_CAMERA_TIMEOUT, 0, 0, r->io.clock.now_us(r->io.clock.ctx));
        if (++r->timeouts >= r->reopen_after_timeouts) {
            logf_(r, RL_LOG_CAMERA, "camera: %d timeouts in a row; reopening", r->timeouts);
            camera_down(r, r->io.clock.now_us(r->io.clock.ctx));
            r->cam_retry_at = 0; /* reopen at once */
        }
        return RL_OK;
    }
    if (e == RL_EFORMAT) {
        /* a frame that could not be read: reported and skipped */
        r->bad_frames++;
        logf_(r, RL_LOG_FRAME, "camera: %s; frame skipped", r->cam.error[0] ? r->cam.error : "bad frame");
        send_status(r, RL_STATUS_CAMERA_ERROR, 0, 0, now);
        return RL_OK;
    }
    if (e != RL_OK) {
        r->camera_errors++;
        logf_(r, RL_LOG_CAMERA, "camera: %s; reopening", r->cam.error[0] ? r->cam.error : rl_strerror(e));
        camera_down(r, now);
        send_status(r, RL_STATUS_CAMERA_ERROR, 0, 0, now);
        return RL_OK;
    }
    r->timeouts = 0;
    r->frames++;
    rl_recog_frame_size(r->rec, &w, &h);
    if (f.img.width != w || f.img.height != h) {
        logf_(r, RL_LOG_FRAME, "frame %ld is %dx%d, the calibration is for %dx%d; skipped", f.index,
              f.img.width, f.img.height, w, h);
        rl_cam_release(&r->cam, &f);
        send_status(r, RL_STATUS_CONFIG_ERROR, 0, 0, f.t_us);
        return RL_OK;
    }
    if (r->io.frame != NULL)
        r->io.frame(r->io.frame_ctx, &f);
    e = rl_recog_run(r->rec, &f.img, r->res);
    rl_cam_release(&r->cam, &f);
    if (e != RL_OK) {
        /* a bad frame (noise beyond the workspace) never stops the loop */
        logf_(r, RL_LOG_FRAME, "frame %ld: recognition failed: %s", f.index, rl_strerror(e));
        send_status(r, RL_STATUS_TOO_FEW, 0, 0, f.t_us);
        return RL_OK;
    }
    e = solve(r, f.t_us, &pose);
    for (i = 0; i < r->res->n_landmarks; i++)
        local |= r->res->landmarks[i].pass == RL_PASS_LOCAL;
    r->local_used += local;
    if (e == RL_OK) {
        rl_msg m;
        uint64_t sent = r->io.clock.now_us(r->io.clock.ctx);
        memset(&m, 0, sizeof m);
        m.type = RL_PACKET_POSE;
        m.time_ms = (uint32_t)(f.t_us / 1000u);
        m.x_mm = clamp32(pose.x * 1000.0);
        m.y_mm = clamp32(pose.y * 1000.0);
        m.yaw_e4 = (int16_t)lround(pose.yaw * 1e4); /* |yaw| <= pi fits */
        m.used = (uint8_t)(pose.used > 255 ? 255 : pose.used);
        m.flags = (uint8_t)(local | (pose.tilt_solved ? 2 : 0));
        m.residual_e4 = clampu16(pose.residual * 1e4);
        m.latency_e4 = clampu16((double)(sent > f.t_us ? sent - f.t_us : 0) / 100.0);
        m.version = RL_PACKET_VERSION;
        m.sigma_x_e4 = clampu16(pose.sigma_x * 1e4);
        m.sigma_y_e4 = clampu16(pose.sigma_y * 1e4);
        m.sigma_yaw_e4 = clampu16(pose.sigma_yaw * 1e4);
        m.roll_e4 = clamp16(pose.roll * 1e4);
        m.pitch_e4 = clamp16(pose.pitch * 1e4);
        send_msg(r, &m);
    } else if (e == RL_ETOOFEW) {
        send_status(r, RL_STATUS_TOO_FEW, r->res->n_landmarks, r->res->n_candidates, f.t_us);
    } else if (e == RL_EAMBIGUOUS) {
        r->ambiguous++;
        send_status(r, RL_STATUS_AMBIGUOUS, r->res->n_landmarks, r->res->n_candidates, f.t_us);
    } else {
        logf_(r, RL_LOG_FRAME, "pose: %s (check the map and robot heights)", rl_strerror(e));
        send_status(r, RL_STATUS_CONFIG_ERROR, r->res->n_landmarks, r->res->n_candidates, f.t_us);
    }
    return RL_OK;
}

/* The pose of the frame taken at t_us: by id, or on a map that repeats
 * ids by place, with the last pose as the prior. */
static rl_err solve(rl_runner *r, uint64_t t_us, rl_pose *pose)
{
    rl_place_prior prior;
    rl_place_found found;
    rl_err e;
    if (r->place == NULL)
        return rl_pose_solve(r->calib, r->map, r->mount, r->res->landmarks, r->res->n_landmarks, r->offsets, pose);
    prior.valid = r->have_pose && t_us >= r->last_pose_us;
    prior.x = r->last_pose.x;
    prior.y = r->last_pose.y;
    prior.yaw = r->last_pose.yaw;
    prior.age = prior.valid ? (double)(t_us - r->last_pose_us) / 1e6 : 0;
    e = rl_place_solve(r->place, r->calib, r->mount, r->res->landmarks, r->res->n_landmarks, r->offsets, &prior,
                       pose, &found);
    if (e == RL_OK) {
        r->have_pose = 1;
        r->last_pose = *pose;
        r->last_pose_us = t_us;
        r->tracked += found.status == RL_PLACE_TRACKED;
    }
    return e;
}

void rl_run_close(rl_runner *r)
{
    if (r->cam_up)
        rl_cam_close(&r->cam);
    if (r->out_up)
        r->io.out.close(r->io.out.ctx);
    r->cam_up = r->out_up = 0;
}
