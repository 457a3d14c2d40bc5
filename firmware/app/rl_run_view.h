/* rl_run_view: the loop's observer that feeds the live web view: each
 * report of the loop (rl_run.h: a frame recognized with its result and
 * pose, or the status sent instead; the sink up or not) becomes an
 * rl_view_obs with the loop's counters, the camera's description and its
 * last error, and the serial line's state (up when the report was
 * written; its last error and last good write), offered to the view (rl_view.h: a copy a few times
 * a second, never a wait). Runs in the loop thread and allocates nothing
 * (app_no_alloc; test_run counts heap calls with it on).
 *
 *   static rl_runner runner;          // rl_run_init'ed
 *   static rl_view view;              // rl_view_init'ed
 *   rl_run_view rv;
 *   rl_run_io io;
 *   memset(&io, 0, sizeof io);
 *   rl_run_view_init(&rv, &view, &runner, "/dev/serial0", NULL);
 *   io.observe = rl_run_view_report;   // before rl_run_init, which copies io
 *   io.observe_ctx = &rv;
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
    const rl_record *rec;     /* NULL: not recording; else on while running and not stopped */
    const char *rec_note;     /* why recording is off though asked for, or ""; NULL: none (set after init) */
    int rec_paused;           /* 1: stopped from the page (set by the firmware's side features) */
} rl_run_view;

void rl_run_view_init(rl_run_view *rv, rl_view *view, const rl_runner *runner, const char *serial,
                      const rl_record *rec);

/* The observer (rl_run_io.observe): ctx is an rl_run_view. */
void rl_run_view_report(void *ctx, const rl_run_report *rep);

#endif
