/* rl_run: the one loop from frames to poses (rl_run.h). */
#include "rl_run.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "rl_packet.h"
#include "rl_shutter.h"

void rl_run_defaults(rl_run_config *c)
{
    memset(c, 0, sizeof *c);
    c->timeout_ms = 500;
    c->reopen_after_timeouts = 3;
    c->backoff_min_us = 100000;
    c->backoff_max_us = 2000000;
    c->status_period_us = 200000;
    c->log_interval_us = 5000000;
    rl_track_defaults(&c->track);
}

void rl_run_init(rl_runner *r, const rl_run_config *cfg, const rl_run_io *io, rl_site *site, rl_result *res)
{
    memset(r, 0, sizeof *r);
    r->cfg = *cfg;
    r->io = *io;
    r->site = site;
    r->res = res;
    r->src_backoff = r->sink_backoff = cfg->backoff_min_us;
    rl_track_init(&r->track, &cfg->track);
    if (cfg->alone)
        r->track.cfg.full_every = 0;
}

const rl_run_counts *rl_run_counts_of(const rl_runner *r)
{
    return &r->counts;
}

void rl_run_start_at(rl_runner *r, const rl_pose *pose, uint64_t t_us)
{
    r->prev.have = 0;
    r->last.have = 1;
    r->last.pose = *pose;
    r->last.t_us = t_us;
}

static uint64_t now_us(const rl_runner *r)
{
    return r->io.clock.now_us(r->io.clock.ctx);
}

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

/* Logs are rate-limited per kind: the first line of a kind goes out, then
 * at most one per interval with a count of the ones held back. */
static void logf_(rl_runner *r, int kind, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static void logf_(rl_runner *r, int kind, const char *fmt, ...)
{
    char line[512], full[600];
    uint64_t now = now_us(r);
    va_list ap;
    if (r->io.log == NULL)
        return;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (r->last_log[kind] != 0 && now - r->last_log[kind] < r->cfg.log_interval_us &&
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
    return 2 * b > r->cfg.backoff_max_us ? r->cfg.backoff_max_us : 2 * b;
}

static const char *sink_name(const rl_runner *r)
{
    return r->io.sink.name ? r->io.sink.name : "output";
}

/* Open the sink unless it is up or still backing off; 1 when it is up. */
static int sink_ready(rl_runner *r, uint64_t now)
{
    char err[256];
    rl_err e;
    if (r->sink_up)
        return 1;
    if (now < r->sink_retry_at)
        return 0;
    if (r->io.sink.open != NULL && (e = r->io.sink.open(r->io.sink.ctx, err, sizeof err)) != RL_OK) {
        logf_(r, RL_LOG_SERIAL, "%s: %s; retrying", sink_name(r), err);
        snprintf(r->sink_error, sizeof r->sink_error, "%s", err);
        r->sink_retry_at = now + r->sink_backoff;
        r->sink_backoff = next_backoff(r, r->sink_backoff);
        r->counts.sink_errors++;
        return 0;
    }
    r->sink_up = 1;
    r->sink_backoff = r->cfg.backoff_min_us;
    return 1;
}

/* Hand a report to the sink; a failed sink is closed and reopened later,
 * and the report counted as dropped (a serial line's controller sees a
 * gap in seq). */
static void to_sink(rl_runner *r, rl_run_report *rep, uint64_t now)
{
    rl_err e;
    if (!sink_ready(r, now)) {
        r->counts.dropped++;
        return;
    }
    if ((e = r->io.sink.put(r->io.sink.ctx, rep)) != RL_OK) {
        const char *why = r->io.sink.why ? r->io.sink.why(r->io.sink.ctx) : NULL;
        logf_(r, RL_LOG_SERIAL, "%s: write failed (%s); reopening", sink_name(r), why ? why : rl_strerror(e));
        snprintf(r->sink_error, sizeof r->sink_error, "write failed: %s", why ? why : rl_strerror(e));
        if (r->io.sink.close != NULL)
            r->io.sink.close(r->io.sink.ctx);
        r->sink_up = 0;
        r->sink_retry_at = now + r->sink_backoff;
        r->sink_backoff = next_backoff(r, r->sink_backoff);
        r->counts.sink_errors++;
        r->counts.dropped++;
        return;
    }
    /* taken: the summary counts what reached the sink */
    r->sink_ok_us = now;
    if (rep->event == RL_RUN_FRAME && rep->pose_err == RL_OK)
        r->counts.poses++;
    else
        r->counts.statuses++;
}

/* A report to the sink, then to the observer (which sees it whatever the
 * sink did). */
static void report(rl_runner *r, rl_run_report *rep)
{
    uint64_t now = now_us(r);
    rep->seq = r->seq++;
    rep->sent_us = now;
    to_sink(r, rep, now);
    if (r->io.observe != NULL)
        r->io.observe(r->io.observe_ctx, rep);
}

/* A report without a frame: the source down, timed out, or a bad frame. */
static void report_no_frame(rl_runner *r, rl_run_event event, int status, uint64_t t_us, const char *why)
{
    rl_run_report rep;
    memset(&rep, 0, sizeof rep);
    rep.event = event;
    rep.status = status;
    rep.t_us = t_us;
    rep.error = why;
    report(r, &rep);
}

static const char *source_error(const rl_runner *r, rl_err e)
{
    const char *why = r->io.source.error ? r->io.source.error(r->io.source.ctx) : "";
    return why && why[0] ? why : rl_strerror(e);
}

static void source_down(rl_runner *r, uint64_t now)
{
    r->io.source.close(r->io.source.ctx);
    r->src_up = 0;
    r->src_retry_at = now + r->src_backoff;
    r->src_backoff = next_backoff(r, r->src_backoff);
}

/* The source opened when it is due, status reports while it is down. */
static void source_open(rl_runner *r, uint64_t now)
{
    char err[512];
    rl_err e;
    uint64_t wait;
    if (now >= r->src_retry_at) {
        if ((e = r->io.source.open(r->io.source.ctx, err, sizeof err)) == RL_OK) {
            const char *info = r->io.source.info ? r->io.source.info(r->io.source.ctx) : "";
            r->src_up = 1;
            r->timeouts = 0;
            r->src_backoff = r->cfg.backoff_min_us;
            logf_(r, RL_LOG_INFO, "camera: open%s%s", info[0] ? ": " : "", info);
            return;
        }
        r->counts.camera_errors++;
        logf_(r, RL_LOG_CAMERA, "camera: %s; retrying", err);
        r->src_retry_at = now + r->src_backoff;
        r->src_backoff = next_backoff(r, r->src_backoff);
        report_no_frame(r, RL_RUN_NO_FRAME, RL_STATUS_CAMERA_ERROR, now, err);
    } else {
        report_no_frame(r, RL_RUN_NO_FRAME, RL_STATUS_CAMERA_ERROR, now, "camera down");
    }
    /* while the source is down, the sink still hears from us */
    wait = r->src_retry_at > now ? r->src_retry_at - now : 0;
    r->io.clock.sleep_us(r->io.clock.ctx, wait < r->cfg.status_period_us ? wait : r->cfg.status_period_us);
}

/* A grab that gave no frame: RL_OK to go on, RL_ENOTFOUND at the end. */
static rl_err grab_failed(rl_runner *r, rl_err e, uint64_t now)
{
    const char *why = source_error(r, e);
    if (e == RL_ENOTFOUND)
        return RL_ENOTFOUND;
    if (e == RL_ETIMEOUT) {
        r->counts.camera_timeouts++;
        logf_(r, RL_LOG_TIMEOUT, "camera: no frame in %d ms", r->cfg.timeout_ms);
        report_no_frame(r, RL_RUN_NO_FRAME, RL_STATUS_CAMERA_TIMEOUT, now_us(r), "no frame");
        if (++r->timeouts >= r->cfg.reopen_after_timeouts) {
            logf_(r, RL_LOG_CAMERA, "camera: %d timeouts in a row; reopening", r->timeouts);
            source_down(r, now_us(r));
            r->src_retry_at = 0; /* reopen at once */
        }
    } else if (e == RL_EFORMAT) {
        /* a frame that could not be read: reported and skipped */
        r->counts.bad_frames++;
        logf_(r, RL_LOG_FRAME, "camera: %s; frame skipped", why);
        report_no_frame(r, RL_RUN_BAD_FRAME, RL_STATUS_CAMERA_ERROR, now, why);
    } else {
        r->counts.camera_errors++;
        logf_(r, RL_LOG_CAMERA, "camera: %s; reopening", why);
        source_down(r, now);
        report_no_frame(r, RL_RUN_NO_FRAME, RL_STATUS_CAMERA_ERROR, now, why);
    }
    return RL_OK;
}

/* The prior of a frame: the last pose, its age from capture times or
 * from the configured interval between frames. */
static const rl_place_prior *make_prior(const rl_runner *r, uint64_t t_us, rl_place_prior *prior)
{
    memset(prior, 0, sizeof *prior);
    if (r->cfg.alone)
        return NULL;
    prior->valid = r->last.have && t_us >= r->last.t_us;
    prior->x = r->last.pose.x;
    prior->y = r->last.pose.y;
    prior->yaw = r->last.pose.yaw;
    prior->age = prior->valid ? (double)(t_us - r->last.t_us) / 1e6 : 0;
    return prior;
}

static int can_localize(const rl_site *s)
{
    return s->has_calib && s->has_map && s->has_mount;
}

/* The last two poses at most this far apart (s) give the motion a
 * rolling shutter's centres are moved by. */
#define SHUTTER_MAX_GAP 0.5

/* The centres of the frame at t_us into moved, each moved to the middle
 * row's instant (rl_shutter.h) by the motion of the last two poses, each
 * at its landmark's height in the map (rl_map_id_heights): moved,
 * or the centres as they are when the shutter is global or the motion
 * unknown (no two recent poses before the frame). */
static const rl_detection *shutter_moved(rl_runner *r, uint64_t t_us, rl_detection *moved)
{
    const rl_site *s = r->site;
    const rl_result *res = r->res;
    double distance[RL_MAX_LANDMARKS];
    rl_motion m;
    int i;
    if (!(r->cfg.readout > 0) || r->cfg.alone || !r->last.have || !r->prev.have ||
        !rl_motion_between(&r->prev.pose, (double)r->prev.t_us / 1e6, &r->last.pose, (double)r->last.t_us / 1e6,
                           (double)t_us / 1e6, SHUTTER_MAX_GAP, &m))
        return res->landmarks;
    memcpy(moved, res->landmarks, sizeof *moved * (size_t)res->n_landmarks);
    if (r->id_height_map != &s->map || r->id_height_count != s->map.count) {
        rl_map_id_heights(&s->map, r->id_height);
        r->id_height_map = &s->map;
        r->id_height_count = s->map.count;
    }
    for (i = 0; i < res->n_landmarks; i++) /* a landmark on a beam is nearer: it moves further */
        distance[i] = (moved[i].id >= 0 && moved[i].id < RL_MAX_IDS ? r->id_height[moved[i].id]
                                                                    : s->map.ceiling_height) - s->mount.z;
    rl_shutter_correct_each(&s->calib, &s->mount, distance, r->cfg.readout, &m, moved, res->n_landmarks);
    return moved;
}

/* The frame's pose into rep (rep->pose_err says whether there is one);
 * rep->pose_us is its time. */
static void localize(rl_runner *r, uint64_t t_us, rl_run_report *rep, rl_pose *pose, rl_place_found *found)
{
    rl_place_prior prior;
    rl_detection moved[RL_MAX_LANDMARKS];
    const rl_result *res = r->res;
    uint64_t t0 = rl_clock_now_us();
    memset(pose, 0, sizeof *pose);
    memset(found, 0, sizeof *found);
    if (!can_localize(r->site)) {
        rep->pose_err = RL_EUNSUPPORTED;
        return;
    }
    rep->pose = pose;
    rep->place = found;
    rep->pose_err = rl_site_solve(r->site, shutter_moved(r, t_us, moved), res->n_landmarks,
                                  make_prior(r, t_us, &prior), pose, found);
    rep->pose_us += (double)(rl_clock_now_us() - t0);
    if (rep->pose_err == RL_OK) {
        r->prev = r->last;
        r->prev.have = r->last.have && t_us > r->last.t_us;
        r->last.have = 1;
        r->last.pose = *pose;
        r->last.t_us = t_us;
        r->counts.tracked += found->status == RL_PLACE_TRACKED;
    } else if (rep->pose_err == RL_ETOOFEW) {
        rep->status = RL_STATUS_TOO_FEW;
    } else if (rep->pose_err == RL_EAMBIGUOUS) {
        r->counts.ambiguous++;
        rep->status = RL_STATUS_AMBIGUOUS;
    } else {
        logf_(r, RL_LOG_FRAME, "pose: %s (check the map and robot heights)", rl_strerror(rep->pose_err));
        rep->status = RL_STATUS_CONFIG_ERROR;
    }
}

/* The recognizer ready for the frame's size: the calibration's, or any
 * size when the site has none (made anew, outside the timed part). */
static rl_err ready_for(rl_runner *r, const rl_cam_frame *f, char *why, size_t whylen)
{
    rl_site *s = r->site;
    rl_err e;
    char frame[40];
    const char *name = f->name;
    if (name == NULL) {
        snprintf(frame, sizeof frame, "frame %ld", f->index);
        name = frame;
    }
    if (s->has_calib && (f->img.width != s->calib.width || f->img.height != s->calib.height)) {
        snprintf(why, whylen, "%.200s: image is %dx%d but %.200s (image_width, image_height) is for %dx%d", name,
                 f->img.width, f->img.height, s->files.calibration, s->calib.width, s->calib.height);
        return RL_EINVAL;
    }
    if ((e = rl_heap_recog_prepare(&s->recog, f->img.width, f->img.height)) != RL_OK)
        snprintf(why, whylen, "%.200s: cannot prepare recognition for %dx%d: %s", name, f->img.width,
                 f->img.height, rl_strerror(e));
    return e;
}

/* The frame's landmarks into r->res: by tracking windows when the last
 * poses predict them (rep->windows), else (or when they fail) in full;
 * rep->recog_us is the time of both. */
static rl_err recognize(rl_runner *r, const rl_cam_frame *f, double t_s, rl_run_report *rep)
{
    rl_site *s = r->site;
    uint64_t t0 = rl_clock_now_us();
    rl_err e = RL_OK;
    int ok = 0;
    if (can_localize(s) && rl_track_plan(&r->track, &s->calib, &s->mount, &s->map, t_s, NULL))
        e = rl_track_read(&r->track, s->recog.rec, &f->img, r->res, &ok);
    if (e == RL_OK && !ok) {
        r->counts.window_fallbacks += r->track.n > 0;
        e = rl_recog_run(s->recog.rec, &f->img, r->res);
        if (e == RL_OK)
            rl_track_full(&r->track, r->res);
    }
    rep->windows = ok;
    rep->recog_us += (double)(rl_clock_now_us() - t0);
    return e;
}

/* Localize the frame and tell the tracker; a frame read by windows whose
 * pose jumped from the prediction (the robot carried) is read again in
 * full, from the prior it had. */
static rl_err localize_tracked(rl_runner *r, const rl_cam_frame *f, uint64_t t_us, rl_run_report *rep,
                               rl_pose *pose, rl_place_found *found)
{
    rl_run_pose last = r->last, prev = r->prev;
    rl_err e;
    localize(r, t_us, rep, pose, found);
    if (!rl_track_pose(&r->track, rep->pose_err == RL_OK ? pose : NULL, (double)t_us / 1e6))
        return RL_OK;
    r->counts.window_fallbacks++;
    r->last = last;
    r->prev = prev;
    if ((e = recognize(r, f, (double)t_us / 1e6, rep)) != RL_OK)
        return e;
    localize(r, t_us, rep, pose, found);
    (void)rl_track_pose(&r->track, rep->pose_err == RL_OK ? pose : NULL, (double)t_us / 1e6);
    return RL_OK;
}

/* Recognize and localize a frame, report it. */
static void use_frame(rl_runner *r, const rl_cam_frame *f)
{
    rl_run_report rep;
    rl_pose pose;
    rl_place_found found;
    char why[512];
    uint64_t t_us;
    rl_err e;
    int i;
    r->counts.frames++;
    if ((e = ready_for(r, f, why, sizeof why)) != RL_OK) {
        logf_(r, RL_LOG_FRAME, "%s; skipped", why);
        report_no_frame(r, RL_RUN_BAD_FRAME, RL_STATUS_CONFIG_ERROR, f->t_us, why);
        return;
    }
    memset(&rep, 0, sizeof rep);
    rep.event = RL_RUN_FRAME;
    rep.t_us = f->t_us;
    rep.frame = f;
    rep.track = &r->track;
    t_us = r->cfg.frame_interval > 0 ? (uint64_t)(r->reads * r->cfg.frame_interval * 1e6) : f->t_us;
    e = recognize(r, f, (double)t_us / 1e6, &rep);
    if (e == RL_OK)
        e = localize_tracked(r, f, t_us, &rep, &pose, &found);
    if (e != RL_OK) {
        /* a bad frame (noise beyond the workspace) never stops the loop */
        if (f->name)
            snprintf(why, sizeof why, "%.300s: recognition failed: %s", f->name, rl_strerror(e));
        else
            snprintf(why, sizeof why, "frame %ld: recognition failed: %s", f->index, rl_strerror(e));
        logf_(r, RL_LOG_FRAME, "%s", why);
        report_no_frame(r, RL_RUN_BAD_FRAME, RL_STATUS_TOO_FEW, f->t_us, why);
        return;
    }
    rep.res = r->res;
    for (i = 0; i < r->res->n_landmarks && !rep.windows; i++)
        rep.local_used |= r->res->landmarks[i].pass == RL_PASS_LOCAL;
    r->counts.local_used += rep.local_used;
    r->counts.windowed += rep.windows;
    report(r, &rep);
}

rl_err rl_run_step(rl_runner *r)
{
    uint64_t now = now_us(r);
    rl_cam_frame f;
    rl_err e;
    if (!r->src_up) {
        source_open(r, now);
        return RL_OK;
    }
    e = r->io.source.grab(r->io.source.ctx, r->cfg.timeout_ms, &f);
    if (e != RL_ETIMEOUT && e != RL_ENOTFOUND)
        r->reads++;
    if (e != RL_OK)
        return grab_failed(r, e, now);
    r->timeouts = 0;
    use_frame(r, &f);
    r->io.source.release(r->io.source.ctx, &f);
    return RL_OK;
}

void rl_run_close(rl_runner *r)
{
    if (r->src_up)
        r->io.source.close(r->io.source.ctx);
    if (r->sink_up && r->io.sink.close != NULL)
        r->io.sink.close(r->io.sink.ctx);
    r->src_up = r->sink_up = 0;
}
