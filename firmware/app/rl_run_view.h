/* rl_run_view: the loop's observer that feeds the live web view: each
 * frame the loop recognized (with its result and pose, or the status it
 * sent instead) becomes an rl_view_obs with the runner's counters, the
 * camera's description and the serial line's state, offered to the view
 * (rl_view.h: a copy a few times a second, never a wait). Runs in the loop
 * thread and allocates nothing (app_no_alloc).
 *
 *   static rl_runner runner;          // rl_run_init'ed
 *   static rl_view view;              // rl_view_init'ed
 *   rl_run_view rv;
 *   const rl_cam_frame *f = NULL;      // the frame the loop lends its observer
 *   const rl_result *res = NULL;
 *   const rl_pose *pose = NULL;
 *   rl_run_view_init(&rv, &view, &runner, "/dev/serial0", NULL);
 *   rl_run_view_frame(&rv, f, res, pose, 1);   // from the loop's per-frame callback
 */
#ifndef RL_RUN_VIEW_H
#define RL_RUN_VIEW_H

#include "rl_record.h"
#include "rl_run.h"
#include "rl_view.h"

typedef struct {
    rl_view *view;
    const rl_runner *runner;
    const char *serial;       /* the serial device's name */
    const rl_record *rec;     /* NULL: not recording */
    long tracked;             /* the runner's count at the last frame */
} rl_run_view;

void rl_run_view_init(rl_run_view *rv, rl_view *view, const rl_runner *runner, const char *serial,
                      const rl_record *rec);

/* One frame: its result and the pose sent (NULL and the status's reason,
 * RL_STATUS_*, when a status went out instead). ctx is an rl_run_view. */
void rl_run_view_frame(void *ctx, const rl_cam_frame *f, const rl_result *res, const rl_pose *pose,
                       int reason);

#endif
