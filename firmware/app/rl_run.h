/* rl_run: the one loop from frames to poses, for devices and files alike.
 *
 * Each step takes a frame from the source, recognizes its landmarks with
 * the site's recognizer and, when the site has a calibration, map and
 * robot, localizes (on a map that repeats ids, `place` finds which
 * landmarks the frame shows, near the last pose first); then it hands a
 * report to the sink. The firmware's sink sends a pose or status packet on
 * the serial line (rl_packet_sink.h); `detect`, `locate`, the calibrations
 * and the survey's frame reading are sinks of their own over a source of
 * PNG files (the PNG camera). Faults are states, not exits: a source that
 * fails is closed and reopened with backoff while reports saying so keep
 * going out; a source that times out repeatedly is reopened; a sink that
 * fails is reopened later and what it missed is counted; a bad frame is
 * reported and skipped. Source, sink, clock and log come in through one
 * seam (rl_run_io), so tests inject every fault; settings through
 * rl_run_config with defaults; the state is the loop's own, read through
 * rl_run_counts. Nothing is allocated after rl_run_init for frames of the
 * calibration's size; recognition and localizing are timed (recog_us,
 * pose_us).
 *
 *   static rl_runner runner;
 *   static rl_result result;
 *   static rl_site site;            // loaded and prepared (rl_site.h)
 *   rl_run_camera camera;           // rl_run_camera.h
 *   rl_cam_config cc;
 *   rl_run_config cfg;
 *   rl_run_io io;
 *   rl_cam_defaults(&cc);
 *   rl_run_defaults(&cfg);
 *   memset(&io, 0, sizeof io);
 *   io.source = rl_run_camera_source(&camera, &cc);
 *   io.clock = rl_clock_system();
 *   // io.sink: where reports go (rl_packet_sink_make for the serial line)
 *   rl_run_init(&runner, &cfg, &io, &site, &result);
 *   while (rl_run_step(&runner) != RL_ENOTFOUND)
 *       continue;
 *   rl_run_close(&runner);
 */
#ifndef RL_RUN_H
#define RL_RUN_H

#include <stddef.h>
#include <stdint.h>
#include "rl_cam.h"
#include "rl_clock.h"
#include "rl_place.h"
#include "rl_pose.h"
#include "rl_recog.h"
#include "rl_site.h"
#include "rl_track.h"

/* Where frames come from. grab: RL_OK, RL_ETIMEOUT, RL_ENOTFOUND at the
 * end, RL_EFORMAT for a bad frame that was skipped, another error when
 * the source failed (closed and opened again). */
typedef struct {
    rl_err (*open)(void *ctx, char *err, size_t errlen);
    rl_err (*grab)(void *ctx, int timeout_ms, rl_cam_frame *f);
    void (*release)(void *ctx, rl_cam_frame *f);
    void (*close)(void *ctx);
    const char *(*error)(void *ctx); /* why the last grab failed, naming the file or device, or "" */
    const char *(*info)(void *ctx);  /* what was opened (format, size), or "" */
    void *ctx;
} rl_run_source;

typedef enum {
    RL_RUN_FRAME,     /* a frame recognized (and localized when the site can) */
    RL_RUN_BAD_FRAME, /* a frame that could not be read or used; error says why */
    RL_RUN_NO_FRAME   /* the source is down or timed out; error says why */
} rl_run_event;

/* What one step gave, lent to the sink for the call. */
typedef struct {
    rl_run_event event;
    long seq;                   /* reports made so far, this one excluded (dropped ones too) */
    uint64_t t_us;              /* the frame's capture time, or now */
    uint64_t sent_us;           /* now */
    const rl_cam_frame *frame;  /* FRAME: the frame; else NULL */
    const rl_result *res;       /* FRAME: its landmarks; else NULL */
    double recog_us;            /* FRAME: recognition's time alone */
    double pose_us;             /* FRAME: localizing's time alone (the place and the pose) */
    int local_used;             /* FRAME: 1 when the local pass identified one of its landmarks */
    int windows;                /* FRAME: 1 when read by tracking windows only (rl_track.h) */
    const rl_track *track;      /* FRAME: the tracker after the frame (its unjudged reads) */
    rl_err pose_err;            /* FRAME: RL_OK with a pose; RL_ETOOFEW, RL_EAMBIGUOUS, ...;
                                   RL_EUNSUPPORTED when the site cannot localize */
    const rl_pose *pose;        /* FRAME after a solve (the failed one too: n_dropped) */
    const rl_place_found *place;/* FRAME after a solve */
    int status;                 /* no pose: the status packet's reason (RL_STATUS_*) */
    const char *error;          /* BAD_FRAME, NO_FRAME: why, naming the file or device */
} rl_run_report;

/* Where reports go. put failing: the sink is closed and opened again
 * after a backoff, the reports between are counted as dropped. */
typedef struct {
    const char *name;           /* for log lines ("serial") */
    rl_err (*open)(void *ctx, char *err, size_t errlen); /* NULL: always open */
    rl_err (*put)(void *ctx, const rl_run_report *rep);
    void (*close)(void *ctx);   /* may be NULL */
    const char *(*why)(void *ctx); /* the system's reason for the last failure, or NULL; may be NULL */
    void *ctx;
} rl_run_sink;

typedef struct {
    rl_run_source source;
    rl_run_sink sink;
    rl_clock clock;             /* rl_clock_system(), or a test's */
    void (*log)(void *ctx, const char *line); /* one line, no newline; NULL: none */
    void *log_ctx;
    /* every report, whether the sink took it or not (the firmware's
     * recorder and web view, rl_run_view.h); lent for the call; NULL:
     * none */
    void (*observe)(void *ctx, const rl_run_report *rep);
    void *observe_ctx;
} rl_run_io;

typedef struct {
    int timeout_ms;             /* a grab waits at most this long (500) */
    int reopen_after_timeouts;  /* consecutive timeouts before reopening (3) */
    uint64_t backoff_min_us;    /* first retry delay (100 ms), doubling ... */
    uint64_t backoff_max_us;    /* ... up to this (2 s) */
    uint64_t status_period_us;  /* reports while the source is down (200 ms) */
    uint64_t log_interval_us;   /* rate limit of repeated log lines (5 s) */
    double frame_interval;      /* > 0: frames this many seconds apart for the prior (files
                                   without capture times); 0: capture times (default) */
    int alone;                  /* 1: each frame without the last pose as prior (and no
                                   tracking windows) */
    rl_track_config track;      /* tracking windows on a site that can localize: a full frame
                                   every track.full_every (10); 0: every frame full */
    double readout;             /* a rolling shutter's readout, top row to bottom, s: each
                                   centre moved to the middle row's instant by the motion of
                                   the last two poses (rl_shutter.h); 0 (default): a global
                                   shutter */
} rl_run_config;

void rl_run_defaults(rl_run_config *c);

typedef struct {
    long frames;                /* frames recognized */
    long poses, statuses;       /* reports the sink took with and without a pose */
    long camera_errors, camera_timeouts, bad_frames;
    long sink_errors, dropped;  /* failed puts and opens; reports the sink never took */
    long local_used;            /* frames where the local pass identified a landmark */
    long ambiguous;             /* frames whose landmarks fit several places */
    long tracked;               /* poses found near the previous one */
    long windowed;              /* frames read by tracking windows only */
    long window_fallbacks;      /* frames whose windows failed or whose pose jumped: read in full */
} rl_run_counts;

/* Kinds of log line; each kind is printed at most once per log interval. */
enum { RL_LOG_CAMERA, RL_LOG_TIMEOUT, RL_LOG_SERIAL, RL_LOG_FRAME, RL_LOG_INFO, RL_LOG_KINDS };
/* Bad-frame lines that are logged the first time whatever the interval
 * (each bad file of a PNG camera named once); past these, the interval. */
#define RL_RUN_FRAME_LINES 64

/* A pose the loop found, and its frame's time (have 0: none). */
typedef struct {
    int have;
    rl_pose pose;
    uint64_t t_us;
} rl_run_pose;

/* The loop's state: read it through rl_run_counts. */
typedef struct {
    rl_run_config cfg;
    rl_run_io io;
    rl_site *site;
    rl_result *res;
    int src_up, sink_up, timeouts;
    uint64_t sink_ok_us;        /* when the sink last took a report (0: never) */
    char sink_error[256];       /* why it last failed (open or put), or "" */
    uint64_t src_retry_at, src_backoff, sink_retry_at, sink_backoff;
    long seq, reads;
    uint64_t last_log[RL_LOG_KINDS];
    long suppressed[RL_LOG_KINDS];
    uint32_t frame_lines[RL_RUN_FRAME_LINES];
    int n_frame_lines;
    rl_run_pose last, prev;     /* the last two poses (prev: the one before) */
    rl_track track;
    rl_run_counts counts;
    /* each id's height in the site's map (rl_map_id_heights), made on the
     * first frame that needs it, again when the map is another */
    double id_height[RL_MAX_IDS];
    const rl_map *id_height_map;
    int id_height_count;
} rl_runner;

/* The loop over io for a loaded, prepared site (rl_site_prepare); res is
 * the caller's (large). */
void rl_run_init(rl_runner *r, const rl_run_config *cfg, const rl_run_io *io, rl_site *site, rl_result *res);

/* One step. RL_OK to go on; RL_ENOTFOUND when the source has no more
 * frames (a PNG sequence at its end). */
RL_CHECK rl_err rl_run_step(rl_runner *r);

const rl_run_counts *rl_run_counts_of(const rl_runner *r);

/* A pose known at t_us (where the robot starts): the prior of the next
 * frame's place. */
void rl_run_start_at(rl_runner *r, const rl_pose *pose, uint64_t t_us);

/* Close what is open. */
void rl_run_close(rl_runner *r);

/* the camera as a source (its own module; included here for the loop's users) */
#include "rl_run_camera.h"

#endif
