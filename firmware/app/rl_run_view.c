#include "rl_run_view.h"

#include <string.h>
#include "rl_place.h"

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
    c->frames = r->frames;
    c->poses = r->poses;
    c->statuses = r->statuses;
    c->camera_errors = r->camera_errors;
    c->camera_timeouts = r->camera_timeouts;
    c->bad_frames = r->bad_frames;
    c->serial_errors = r->serial_errors;
    c->dropped = r->dropped;
    c->ambiguous = r->ambiguous;
    c->tracked = r->tracked;
    c->local_used = r->local_used;
    c->serial_up = r->out_up;
    /* the recorder's loop-side counts only (its writer's are its own) */
    c->recording = rec != NULL;
    if (rec != NULL) {
        c->rec_kept = rec->every > 0 ? rec->offered / rec->every - rec->skipped : 0;
        c->rec_skipped = rec->skipped;
    }
}

void rl_run_view_frame(void *ctx, const rl_cam_frame *f, const rl_result *res, const rl_pose *pose, int reason)
{
    rl_run_view *rv = (rl_run_view *)ctx;
    const rl_runner *r = rv->runner;
    rl_view_obs o;
    memset(&o, 0, sizeof o);
    o.frame = f;
    o.res = f != NULL ? res : NULL;
    o.pose = pose;
    o.reason = pose != NULL ? 0 : reason;
    /* on a map that repeats ids, the place: tracked when the runner's count
     * of tracked poses just grew, else found from the frame alone */
    o.place = -1;
    if (r->place != NULL)
        o.place = pose == NULL ? (reason == RL_STATUS_AMBIGUOUS ? RL_PLACE_AMBIGUOUS : RL_PLACE_NONE)
                  : r->tracked > rv->tracked ? RL_PLACE_TRACKED : RL_PLACE_FOUND;
    rv->tracked = r->tracked;
    o.now_us = r->io.clock.now_us(r->io.clock.ctx);
    o.cam_info = r->cam.info;
    o.serial = rv->serial;
    counts(r, rv->rec, &o.counts);
    (void)rl_view_offer(rv->view, &o);
}
