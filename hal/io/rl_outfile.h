/* rl_outfile: every output file written whole or not at all.
 *
 * The new content goes to a temporary file beside the target (same
 * folder, so the rename cannot cross a file system), created with O_EXCL
 * and O_NOFOLLOW so that nothing planted in the folder is written through.
 * On commit it is flushed, checked (the stream's errors and any error a
 * writer library reported), fsync'ed and renamed over the target; on any
 * failure the temporary file is removed and the target is untouched. A
 * target that is a symbolic link, not a regular file, or another user's
 * file is refused before anything is written. The error line names the
 * target and the system's reason ("robot.yaml: No space left on device").
 *
 * A rewritten file keeps the old one's group and mode (the group where the
 * user may give it). The temporary is ".NAME.tmpPID_N", NAME shortened
 * when the whole would pass the folder's name limit, so any name the
 * folder takes can be written. SIGINT, SIGTERM and SIGHUP remove the open
 * temporaries before the program ends, where the program left those
 * signals' default action (a program with its own stop handler aborts or
 * commits itself).
 *
 *   rl_outfile o;
 *   char err[600];
 *   if (rl_outfile_open(&o, "robot.yaml", err, sizeof err) == RL_OK) {
 *       fprintf(o.f, "camera_mount: {x: 0, y: 0, z: 0.88, yaw: 0}\n");
 *       if (rl_outfile_commit(&o, err, sizeof err) != RL_OK)
 *           use(err);   // "robot.yaml: No space left on device"; the old file kept
 *   }
 *
 * Libraries that write through a callback (libpng, cairo) call
 * rl_outfile_write, which keeps the first failure's errno for the commit.
 */
#ifndef RL_OUTFILE_H
#define RL_OUTFILE_H

#include <stddef.h>
#include <stdio.h>
#include "rl_error.h"

/* Longest target path, and its temporary's. */
#define RL_OUTFILE_PATH 1024

typedef struct {
    char path[RL_OUTFILE_PATH]; /* the target */
    char tmp[RL_OUTFILE_PATH];  /* the temporary beside it ("" once gone) */
    FILE *f;                    /* write here between open and commit */
    int errnum;                 /* the first failure's errno (0: none yet) */
    int slot;                   /* its place among the temporaries a signal removes (-1: none) */
} rl_outfile;

/* Check the target and create its temporary. RL_EINVAL (a link, not a
 * regular file, another user's, a path too long) or RL_EIO (the folder
 * refuses), err naming the target; nothing is created then. */
RL_CHECK rl_err rl_outfile_open(rl_outfile *o, const char *path, char *err, size_t errlen);

/* Write n bytes (for a library's write callback): 0, or -1 with the
 * failure kept for the commit. Once one write failed, every later one
 * fails without writing. */
int rl_outfile_write(rl_outfile *o, const void *p, size_t n);

/* A writer library failed without a system error of its own: remembered
 * (as errnum, EIO when 0) unless an earlier failure is. */
void rl_outfile_set_error(rl_outfile *o, int errnum);

/* Flush, check, fsync, close and rename over the target. On failure the
 * temporary is removed, the target untouched, err says "PATH: reason" and
 * the result is RL_EIO. The outfile is closed either way. */
RL_CHECK rl_err rl_outfile_commit(rl_outfile *o, char *err, size_t errlen);

/* Give up: close and remove the temporary; the target untouched. Safe
 * after a commit or a failed open. */
void rl_outfile_abort(rl_outfile *o);

#endif
