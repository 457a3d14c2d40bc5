#include "rl_run_view.h"

#include <string.h>

void rl_run_view_init(rl_run_view *rv, rl_view *view, const rl_runner *runner, const char *serial,
                      const rl_record *rec)
{
    memset(rv, 0, sizeof *rv);
    rv->view = view;
    rv->runner = runner;
    rv->serial = serial;
    rv->rec = rec;
}

static void counts(const rl_runner *r, const rl_record *rec, rl_view_counts *c)
{
    const rl_run_counts *n = rl_run_counts_of(r);
    c->frames = n->frames;
    c->poses = n->poses;
    c->statuses = n->statuses;
    c->camera_errors = n->camera_errors;
    c->camera_timeouts = n->camera_timeouts;
    c->bad_frames = n->bad_frames;
    c->serial_errors = n->sink_errors;
    c->dropped = n->dropped;
    c->ambiguous = n->ambiguous;
    c->tracked = n->tracked;
    c->local_used = n->local_used;
    /* the recorder's loop-side counts only (its writer's are its own) */
    /* off once the loop was told it stopped (a full disk, max_mb): the
     * counts then stay as they were */
    c->recording = rec != NULL && rec->running && !rec->told;
    c->rec_can = rec != NULL;
    if (rec != NULL) {
        c->rec_kept = rec->kept;
        c->rec_skipped = rec->skipped;
    }
}

void rl_run_view_report(void *ctx, const rl_run_report *rep)
{
    rl_run_view *rv = (rl_run_view *)ctx;
    const rl_runner *r = rv->runner;
    int frame = rep->event == RL_RUN_FRAME && rep->frame != NULL;
    rl_view_obs o;
    memset(&o, 0, sizeof o);
    o.frame = frame ? rep->frame : NULL;
    o.res = frame ? rep->res : NULL;
    o.pose = frame && rep->pose_err == RL_OK ? rep->pose : NULL;
    o.reason = o.pose != NULL ? 0 : rep->status;
    /* on a map that repeats ids, how the place was found */
    o.place = r->site->place.pl != NULL && rep->place != NULL ? rep->place->status : -1;
    o.now_us = rep->sent_us;
    o.cam_info = r->io.source.info != NULL ? r->io.source.info(r->io.source.ctx) : NULL;
    o.serial = rv->serial;
    o.rec_note = rv->rec_note;
    counts(r, rv->rec, &o.counts);
    o.counts.recording &= !rv->rec_paused;
    /* up: this report reached the line (a write that succeeded; a
     * descriptor held open proves nothing) */
    o.counts.serial_up = r->sink_ok_us != 0 && r->sink_ok_us == rep->sent_us;
    o.serial_ok_us = r->sink_ok_us;
    o.serial_error = r->sink_error;
    /* the driver's message; "camera down" only says a retry is not due */
    if (rep->event != RL_RUN_FRAME && rep->error != NULL && strcmp(rep->error, "camera down") != 0)
        o.cam_error = rep->error;
    (void)rl_view_offer(rv->view, &o);
}
