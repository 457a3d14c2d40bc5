/* rl_record: saving the camera's frames while the firmware runs, for a
 * survey (`ringloc survey`) or a bug report, without slowing the pose
 * frames. Every Nth frame is copied into one of a few buffers made at
 * start; a writer thread encodes it as PNG and appends "name time_ms" to
 * frames.txt (a list the PNG camera plays back). Each run records into a
 * new subfolder of the configured folder, drive_001, drive_002, ... (made
 * exclusively: an earlier drive is never written over); the folder must
 * be the running user's and not a link, and every file is created with
 * O_EXCL | O_NOFOLLOW. When every buffer is still being written, the
 * frame is skipped and counted, never waited for; at max_mb on disk, a
 * full disk or a folder gone recording stops (a partial frame removed)
 * and rl_record_news says so once, while the loop goes on. A start that
 * fails leaves no drive_NNN behind, and a drive that recorded no frame is
 * removed at the stop (a service restarted every few seconds at boot does
 * not use up the 999 drives).
 *
 *   rl_record rec;
 *   rl_record_config rc;
 *   char err[256];
 *   rl_record_defaults(&rc);
 *   rc.dir = "/var/lib/ringloc/drive";
 *   if (rl_record_start(&rec, &rc, 640, 480, err, sizeof err) == RL_OK) {
 *       rl_record_offer(&rec, &frame, 0, 1000);   // from the loop, each frame
 *       if (rl_record_news(&rec) != NULL)          // stopped: log it once
 *           use(rec.error);
 *       rl_record_stop(&rec);                     // waits for the writer
 *       use(rec.saved, rec.skipped, rec.bytes);
 *   }
 */
#ifndef RL_RECORD_H
#define RL_RECORD_H

#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include "rl_error.h"
#include "rl_image.h"

#define RL_RECORD_SLOTS 4
#define RL_RECORD_MAX_DRIVES 999 /* drive_001 .. drive_999 in one folder */

typedef struct {
    const char *dir;   /* folder, made if missing; each run a new drive_NNN in it */
    int every;         /* keep one frame in this many (default 10) */
    double max_mb;     /* stop once this much is on disk (default 1000) */
} rl_record_config;

typedef struct {
    char dir[512];               /* this run's folder, DIR/drive_NNN */
    int list_fd;                 /* its frames.txt, open for appending */
    long list_bytes;             /* frames.txt's length after its last whole line */
    int told;                    /* rl_record_news gave the stop's reason */
    int every, width, height;
    uint64_t max_bytes;
    uint8_t *buf[RL_RECORD_SLOTS];
    long index[RL_RECORD_SLOTS];
    uint64_t t_us[RL_RECORD_SLOTS];
    int full[RL_RECORD_SLOTS];   /* waiting for the writer */
    pthread_t writer;
    pthread_mutex_t lock;
    pthread_cond_t wake;
    int quit, running, stopped; /* stopped: at max_mb, or a write failed (under lock) */
    int write_failed;            /* the writer's own: max_mb reached, or a write failed */
    long offered;
    long kept;                   /* the loop's: frames handed to the writer (not counted once stopped) */
    /* what happened, read after rl_record_stop */
    long saved, skipped;
    uint64_t bytes;
    char error[1024];            /* why recording stopped early ("" if it did not) */
} rl_record;

void rl_record_defaults(rl_record_config *c);

/* Make the drive's folder and the buffers for w x h frames, start the
 * writer. RL_EIO (err names the folder: not a folder, another user's, not
 * writable), RL_ELIMIT (RL_RECORD_MAX_DRIVES drives there), RL_ENOMEM. */
RL_CHECK rl_err rl_record_start(rl_record *r, const rl_record_config *c, int w, int h, char *err,
                                size_t errlen);

/* From the loop: keep the frame if it is one in every N and a buffer is
 * free (a copy; never blocks on the disk). */
void rl_record_offer(rl_record *r, const rl_image *img, long index, uint64_t t_us);

/* From the loop: the reason recording stopped (a full disk, the folder
 * gone, max_mb), once, the first time it is asked after the stop (after
 * rl_record_stop too: a stop the writer met after the last frame); NULL
 * otherwise. */
const char *rl_record_news(rl_record *r);

/* Write what is waiting, stop the writer, free the buffers; a drive with
 * no frame saved (and an empty frames.txt) is removed. */
void rl_record_stop(rl_record *r);

#endif
