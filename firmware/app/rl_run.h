/* rl_run: the firmware's main loop, one step at a time.
 *
 * Each step grabs a frame from the camera, recognizes, localizes and sends
 * a pose frame, or a status frame saying why there is no pose (on a map
 * that repeats ids, `place` finds which landmarks the frame shows, near
 * the last pose first: a status "ambiguous" when no place is clear). Faults are
 * part of the loop, not exits: a camera that fails is closed and reopened
 * with backoff while status frames keep going out; a camera that times out
 * repeatedly is reopened; a serial line that disappears is reopened; a bad
 * frame is reported and skipped. The camera is an rl_cam opened from
 * the configuration in rl_run_io (a test's double is one more camera
 * backend); the output, the clock and the log are reached through
 * rl_run_io too, so tests can inject every fault. Nothing is allocated
 * after rl_run_init.
 *
 *   static rl_runner runner;
 *   static rl_result result;
 *   rl_cam_config cc;
 *   rl_run_io io;
 *   rl_mount mount;
 *   rl_cam_defaults(&cc);
 *   memset(&io, 0, sizeof io);
 *   io.cam = &cc;
 *   io.clock = rl_clock_system();
 *   // io.out: the serial line's open, write, close
 *   rl_mount_defaults(&mount, 0.88);
 *   rl_run_init(&runner, &io, rec, &cam, &map, &mount, &result);
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
#include "rl_packet.h"
#include "rl_place.h"
#include "rl_pose.h"
#include "rl_recog.h"

/* Where frames go: the serial line (rl_fw.c wires rl_serial to it), or a
 * test's decoder. */
typedef struct {
    rl_err (*open)(void *ctx, char *err, size_t errlen);
    rl_err (*write)(void *ctx, const uint8_t *p, size_t n);
    void (*close)(void *ctx);
    /* the system's reason for the last failed write ("No space left on
     * device"), or NULL (then the error code's message); may be NULL */
    const char *(*why)(void *ctx);
    void *ctx;
} rl_run_out;

typedef struct {
    const rl_cam_config *cam; /* the camera the loop opens (and reopens) */
    rl_run_out out;
    rl_clock clock;           /* rl_clock_system(), or a test's */
    void (*log)(void *ctx, const char *line); /* one line, no newline */
    void *log_ctx;
    /* each frame the loop will recognize, while it is lent (a recorder
     * copies some; NULL: none) */
    void (*frame)(void *ctx, const rl_cam_frame *f);
    void *frame_ctx;
} rl_run_io;

/* Kinds of log line; each kind is printed at most once per log interval. */
enum { RL_LOG_CAMERA, RL_LOG_TIMEOUT, RL_LOG_SERIAL, RL_LOG_FRAME, RL_LOG_INFO, RL_LOG_KINDS };
/* Bad-frame lines that are logged the first time whatever the interval
 * (each bad file of a PNG camera named once); past these, the interval. */
#define RL_RUN_FRAME_LINES 64

typedef struct {
    rl_run_io io;
    rl_cam cam;
    rl_recog *rec;
    const rl_calib *calib;
    const rl_map *map;
    const rl_mount *mount;
    const rl_offsets *offsets;  /* NULL: pinhole model */
    const rl_place *place;      /* the index of a map that repeats ids (NULL: ids unique) */
    rl_result *res;             /* caller's (large) */
    /* settings, defaults from rl_run_init */
    int timeout_ms;             /* a grab waits at most this long (500) */
    int reopen_after_timeouts;  /* consecutive timeouts before reopening (3) */
    uint64_t backoff_min_us;    /* first retry delay (100 ms), doubling ... */
    uint64_t backoff_max_us;    /* ... up to this (2 s) */
    uint64_t status_period_us;  /* status frames while the camera is down (200 ms) */
    uint64_t log_interval_us;   /* rate limit of repeated log lines (5 s) */
    /* state */
    int cam_up, out_up, timeouts;
    uint64_t cam_retry_at, cam_backoff, out_retry_at, out_backoff;
    uint16_t seq;
    uint64_t last_log[RL_LOG_KINDS];
    long suppressed[RL_LOG_KINDS];
    uint32_t frame_lines[RL_RUN_FRAME_LINES]; /* hashes of the bad-frame lines logged so far */
    int n_frame_lines;
    /* counters */
    long frames, poses, statuses, camera_errors, camera_timeouts, serial_errors, dropped;
    long bad_frames;            /* frames the camera could not read, skipped */
    long local_used;
    long ambiguous;             /* frames whose landmarks fit several places */
    long tracked;               /* poses found near the previous one */
    /* the last pose, the prior of the next frame's place */
    int have_pose;
    rl_pose last_pose;
    uint64_t last_pose_us;
} rl_runner;

void rl_run_init(rl_runner *r, const rl_run_io *io, rl_recog *rec, const rl_calib *calib,
                 const rl_map *map, const rl_mount *mount, rl_result *res);

/* One step. RL_OK to go on; RL_ENOTFOUND when the camera has no more
 * frames (a PNG sequence at its end). */
RL_CHECK rl_err rl_run_step(rl_runner *r);

/* Close what is open. */
void rl_run_close(rl_runner *r);

#endif
