/* rl_view: the hand-off from the firmware's loop to the live web view
 * (rl_http.h). The loop offers each frame it recognized, with the result,
 * the pose and its counters; at most max_rate times a second one is copied
 * into a snapshot made at start, under a mutex the loop only tries: when a
 * reader holds it, the frame is skipped (and counted), never waited for.
 * The loop side never allocates and makes no system call but the
 * try-lock; the memory is the caller's, sized by rl_view_size. A reader
 * (the server's thread) takes a whole copy of the latest snapshot into its
 * own rl_view_snap and works on that copy. Frame rate, latency, landmarks
 * per frame, status reasons and the track (one pose every track_period)
 * are kept on the loop's side between copies, so a skipped copy loses no
 * count.
 *
 *   static rl_view view;
 *   static rl_view_snap snap;
 *   static union { rl_result align; uint8_t b[sizeof(rl_result) + 640 * 480]; } mem, smem;
 *   rl_view_config vc;
 *   rl_view_obs obs;
 *   rl_view_defaults(&vc);
 *   vc.width = 640;
 *   vc.height = 480;                       // rl_view_size(&vc) == sizeof mem
 *   if (rl_view_init(&view, &vc, &mem, sizeof mem) == RL_OK &&
 *       rl_view_snap_init(&snap, &vc, &smem, sizeof smem) == RL_OK) {
 *       memset(&obs, 0, sizeof obs);       // the loop fills it for each frame
 *       rl_view_offer(&view, &obs);        // loop thread: never allocates
 *       if (rl_view_take(&view, &snap))    // server thread: a newer snapshot
 *           use(snap.seq, snap.image, snap.res->n_landmarks);
 *       rl_view_destroy(&view);
 *   }
 */
#ifndef RL_VIEW_H
#define RL_VIEW_H

#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include "rl_cam.h"
#include "rl_error.h"
#include "rl_pose.h"
#include "rl_recog.h"

/* Track points kept: at the default 0.5 s, the last five minutes. */
#ifndef RL_VIEW_TRACK
#define RL_VIEW_TRACK 600
#endif
/* Status reasons counted (rl_packet.h's RL_STATUS_*, 0 = a pose). */
#define RL_VIEW_REASONS 8

typedef struct {
    int width, height;     /* the frames' size (the calibration's) */
    double max_rate;       /* snapshots per second at most (default 5) */
    double track_period;   /* seconds between track points (default 0.5) */
    /* the recognizer's acceptance (rl_recog_config), to say what an unread
     * candidate lacked (defaults: rl_recog_defaults') */
    double min_score, local_min_score, size_tolerance;
} rl_view_config;

/* What the loop counted since start (the runner's counters, copied). */
typedef struct {
    long frames, poses, statuses, camera_errors, camera_timeouts, bad_frames;
    long serial_errors, dropped, ambiguous, tracked, local_used;
    int serial_up;          /* 1 when the last report reached the serial line (a write that
                               succeeded, not a descriptor held open) */
    int recording;          /* 1 while frames are recorded */
    int rec_can;            /* 1: a recording folder is configured (the page may start and stop it) */
    long rec_kept, rec_skipped; /* frames handed to the writer, and skipped */
} rl_view_counts;

/* One observation, from the loop thread; everything is read during the
 * call only. */
typedef struct {
    const rl_cam_frame *frame; /* the frame recognized; NULL: a status without one */
    const rl_result *res;      /* its result; NULL with no frame */
    const rl_pose *pose;       /* the pose sent; NULL when a status was sent */
    int reason;                /* the status sent (RL_STATUS_*), 0 with a pose */
    int place;                 /* rl_place's status of the pose (-1: ids are unique) */
    uint64_t now_us;           /* when the pose or status was sent (rl_clock.h) */
    const char *cam_info;      /* the camera's format, exposure, gain; may be NULL */
    const char *serial;        /* the serial device; may be NULL */
    const char *rec_note;      /* why recording is off though asked for (cannot start, stopped); may be NULL */
    const char *serial_error;  /* why the serial line last failed (its open or a write), or ""; may be NULL */
    uint64_t serial_ok_us;     /* when a report last reached the serial line (0: never) */
    const char *cam_error;     /* this report's camera error (the driver's message); NULL: none */
    rl_view_counts counts;
} rl_view_obs;

/* A track point; gap: the track broke before it (frames without a pose
 * between, or a jump of more than RL_VIEW_JUMP metres). */
typedef struct {
    double x, y;
    int gap;
} rl_view_point;

/* Metres between two track points past which the robot cannot have
 * driven in one track period: the pose jumped. */
#ifndef RL_VIEW_JUMP
#define RL_VIEW_JUMP 1.0
#endif

/* The camera's geometry, for drawing the map into the image (the
 * reader's; every pointer NULL: not drawn). */
typedef struct {
    const rl_calib *calib;     /* NULL: none, or an offset map instead of a pinhole model */
    const rl_map *map;
    const rl_mount *mount;
} rl_view_geom;

/* A copy of the loop's state, as a reader sees it. */
typedef struct {
    long seq;                  /* snapshots since start; 0: none yet */
    int width, height;
    double min_score, local_min_score, size_tolerance; /* the configuration's */
    uint8_t *image;            /* width x height grey, packed (caller's memory) */
    int have_image;
    long frame_index;
    uint64_t t_us;             /* the frame's capture time */
    rl_result *res;            /* (caller's memory) */
    int have_result;
    rl_pose pose;              /* the last pose sent (all 0 before the first) */
    int have_pose;             /* 1: it is this snapshot's frame's */
    int reason, place;
    rl_view_counts counts;
    long reasons[RL_VIEW_REASONS]; /* frames per status sent (0: poses) */
    double fps;                /* frames per second, smoothed */
    double latency_ms;         /* capture to pose sent, smoothed */
    double landmarks;          /* identified per frame, smoothed */
    long skipped;              /* copies skipped: a reader held the snapshot */
    uint64_t start_us, now_us;
    char cam_info[256], serial[128], rec_note[256];
    char serial_error[256];    /* why the serial line last failed, or "" */
    uint64_t serial_ok_us;     /* when a report last reached it (0: never) */
    char cam_error[256];       /* the camera's last error (the driver's message), or "" */
    uint64_t cam_error_us;     /* when it came (0: never) */
    uint64_t served_us;        /* the reader's: when it wrote this copy out (rl_http) */
    const rl_view_geom *geom;  /* the reader's: the map into the image (NULL: not drawn) */
    double focus_best;         /* the reader's: the sharpest frame's focus since start (0: none) */
    long focus_best_frame;     /* ... and its frame */
    int lost;                  /* the loop's: a report without a pose since the last track point */
    int n_track;               /* oldest first */
    rl_view_point track[RL_VIEW_TRACK];
} rl_view_snap;

typedef struct {
    rl_view_config cfg;
    pthread_mutex_t lock;
    rl_view_snap shared;       /* under lock */
    rl_view_snap loop;         /* the loop's own: counters, track, without the image */
    uint64_t next_us, next_track_us, last_t_us;
    int rec_ask;               /* the reader's request to the loop (atomic): -1 none, 0 stop, 1 start */
} rl_view;

void rl_view_defaults(rl_view_config *c);

/* Bytes of memory an rl_view or an rl_view_snap needs for these frames
 * (0 for a size outside 1 .. RL_MAX_IMAGE_DIM). */
size_t rl_view_size(const rl_view_config *c);

/* Lay the view out in mem[0..size) (the caller's; kept while the view
 * lives). RL_EINVAL for a bad size or rate, RL_ENOMEM when size is less
 * than rl_view_size, RL_EIO when the mutex cannot be made. */
RL_CHECK rl_err rl_view_init(rl_view *v, const rl_view_config *c, void *mem, size_t size);

/* A reader's copy in mem[0..size) (the caller's). Same errors. */
RL_CHECK rl_err rl_view_snap_init(rl_view_snap *s, const rl_view_config *c, void *mem, size_t size);

/* Loop thread: count the observation, and copy it when its time has come
 * and no reader holds the snapshot. Returns 1 when copied. A frame of
 * another size than configured is counted, its image not copied. */
int rl_view_offer(rl_view *v, const rl_view_obs *o);

/* Reader: copy the snapshot into s if it is newer than s (by seq); 1 when
 * copied, 0 when s is already the latest. Blocks the loop's copy only for
 * the memcpy. */
int rl_view_take(rl_view *v, rl_view_snap *s);

/* Reader: the seq of the latest snapshot (0: none yet), without a copy. */
long rl_view_seq(rl_view *v);

/* Reader: ask the loop to start (on 1) or stop (0) recording; the loop
 * takes it with rl_view_record_asked. Atomic: neither side waits. */
void rl_view_ask_record(rl_view *v, int on);

/* Loop thread: what a reader asked since the last call (-1 nothing, 0
 * stop, 1 start), taken. */
int rl_view_record_asked(rl_view *v);

/* Destroy the mutex (the memory stays the caller's). */
void rl_view_destroy(rl_view *v);

#endif
