/* rl_track: tracking windows (rl_track.h). */
#include "rl_track.h"

#include <math.h>
#include <string.h>
#include "rl_filter.h"
#include "rl_geom.h"
#include "rl_global.h"
#include "rl_local.h"
#include "rl_pose_fit.h"
#include "rl_recog_state.h"
#include "rl_result.h"
#include "rl_tones.h"
#include "rl_track_order.h"
#include "rl_twins.h"
#include "rl_verify.h"

/* A landmark is whole for the windows when its disk, this much enlarged
 * (the prediction's error), is in the frame. */
#define WHOLE_MARGIN 1.2
/* Landmarks predicted at least this much in view are kept: the frame's
 * shift (read_windows) may bring them in. */
#define PREDICT_MIN_VISIBLE 0.05

void rl_track_defaults(rl_track_config *cfg)
{
    cfg->full_every = 10;
    cfg->max_age = 0.5;
    cfg->max_jump = 0.2;
    cfg->max_jump_yaw = 0.35;
    cfg->min_visible = 0.5;
    cfg->max_shift = 1.0;
    cfg->max_first_shift = 1.5;
    cfg->max_reads = 0;
    cfg->window_visible = 0.9;
}

void rl_track_init(rl_track *t, const rl_track_config *cfg)
{
    memset(t, 0, sizeof *t);
    t->cfg = *cfg;
}

static double wrap(double a)
{
    return atan2(sin(a), cos(a));
}

/* The pose at t_s: the last one moved by the odometry, or by the last
 * two poses' velocity. */
static void predict_pose(rl_track *t, double t_s, const rl_track_motion *odom)
{
    double c = cos(t->yaw), s = sin(t->yaw), dt = t->t - t->pt;
    t->ex = t->x;
    t->ey = t->y;
    t->eyaw = t->yaw;
    if (odom != NULL) {
        t->ex += c * odom->dx - s * odom->dy;
        t->ey += s * odom->dx + c * odom->dy;
        t->eyaw = wrap(t->yaw + odom->dyaw);
    } else if (t->have_prev && dt > 0) {
        double k = (t_s - t->t) / dt;
        t->ex += k * (t->x - t->px);
        t->ey += k * (t->y - t->py);
        t->eyaw = wrap(t->yaw + k * wrap(t->yaw - t->pyaw));
    }
}

/* A window's predicted radius at least this many times the least for an
 * id (a prediction a few percent large must not give a window that reads
 * none). */
#define MIN_RADIUS_MARGIN 1.05

/* How far from the camera's foot, per metre of height above it, a
 * landmark can be and still be in view: the farthest image corner's ray,
 * and 30% more. */
static double view_slope(const rl_calib *cam)
{
    double m = 0;
    int k;
    for (k = 0; k < 4; k++) {
        double xn, yn;
        rl_calib_unproject(cam, k & 1 ? cam->width - 1 : 0, k & 2 ? cam->height - 1 : 0, &xn, &yn);
        if (hypot(xn, yn) > m)
            m = hypot(xn, yn);
    }
    return 1.3 * m;
}

/* Whether map landmark i is too far from the camera's foot C to be in
 * view, at its own height (rl_map_height: one above the ceiling, in a
 * skylight's well, is seen from farther). Every landmark of the map is
 * looked at each frame (a large site's 6,400: this test was a third of
 * the tracked frames' instructions there with the height fetched by a
 * call each), so the reach at the ceiling (ceiling_reach, the same sum)
 * is worked out once a frame for the landmarks that hang there. */
static int out_of_reach(const rl_map *map, int i, const double *C, double slope, double ceiling_reach)
{
    const rl_map_landmark *lm = &map->lm[i];
    double reach = rl_map_at_ceiling(map, i) ? ceiling_reach
                                              : slope * (rl_map_height(map, i) - C[2]) + map->diameter;
    return fabs(lm->x - C[0]) > reach || fabs(lm->y - C[1]) > reach;
}

/* Map landmark i's image centre and radius from the camera (Rc, C); 0
 * when it is behind the camera. */
static int project(const rl_calib *cam, const rl_pose_model *md, const double *Rc, const double *C,
                   const rl_map *map, int i, rl_track_window *w)
{
    double X = map->lm[i].x, Y = map->lm[i].y, Z = rl_map_height(map, i), r = 0.5 * map->diameter;
    double xn, yn, u1, v1, u2, v2;
    if (!rl_pose_fit_predict(md, Rc, C, X, Y, Z, &xn, &yn))
        return 0;
    rl_calib_project(cam, xn, yn, &w->u, &w->v);
    if (!rl_pose_fit_predict(md, Rc, C, X + r, Y, Z, &xn, &yn))
        return 0;
    rl_calib_project(cam, xn, yn, &u1, &v1);
    if (!rl_pose_fit_predict(md, Rc, C, X, Y + r, Z, &xn, &yn))
        return 0;
    rl_calib_project(cam, xn, yn, &u2, &v2);
    w->radius = 0.5 * (hypot(u1 - w->u, v1 - w->v) + hypot(u2 - w->u, v2 - w->v));
    w->visible = rl_geom_visible_in(cam->width, cam->height, w->u, w->v, w->radius);
    w->index = i;
    w->id = map->lm[i].id;
    return 1;
}

static int is_whole(const rl_track_window *w, int W, int H)
{
    return rl_geom_disk_complete(W, H, w->u, w->v, WHOLE_MARGIN * w->radius);
}

/* The landmarks the predicted pose puts in view, into t->win, but those
 * too small for an id (rl_twins_min_radius: no read would name them, and
 * a window that reads none fails the frame); how many of them are whole. */
static int predict_windows(rl_track *t, const rl_calib *cam, const rl_mount *mount, const rl_map *map)
{
    rl_pose_model md;
    double q[RL_POSE_NQ] = {0}, Rc[9], C[3], slope = view_slope(cam), min_radius = rl_twins_min_radius(&map->family);
    double ceiling_reach;
    int i, whole = 0;
    rl_pose_fit_model(&md, mount, map->ceiling_height, 0.5 * map->diameter);
    q[0] = t->ex;
    q[1] = t->ey;
    q[2] = t->eyaw;
    rl_pose_fit_camera(&md, q, Rc, C);
    ceiling_reach = slope * (map->ceiling_height - C[2]) + map->diameter;
    t->n = 0;
    for (i = 0; i < map->count && t->n < RL_MAX_LANDMARKS; i++) {
        rl_track_window *w = &t->win[t->n];
        if (out_of_reach(map, i, C, slope, ceiling_reach) || !project(cam, &md, Rc, C, map, i, w) ||
            w->visible < PREDICT_MIN_VISIBLE || w->radius < MIN_RADIUS_MARGIN * min_radius)
            continue;
        whole += is_whole(w, cam->width, cam->height);
        t->n++;
    }
    return whole;
}

/* The map entries of the full frame's reads (t->full_*) among this
 * frame's predictions, each projected as the full frame's pose puts it
 * (the robot level): a read of its id, the only one within NAMED_REACH
 * radii of that, is its pair; the robot's tilt moves every read alike, so
 * an entry is named when its pair lies within NAMED_NEAR radii of its
 * projection moved by the pairs' mean offset. */
#define NAMED_REACH 4.0
#define NAMED_NEAR 1.5

static void name_full_reads(rl_track *t, const rl_calib *cam, const rl_mount *mount, const rl_map *map)
{
    rl_pose_model md;
    rl_track_window at[RL_MAX_LANDMARKS];
    double q[RL_POSE_NQ] = {0}, Rc[9], C[3], du = 0, dv = 0;
    int i, k, pair[RL_MAX_LANDMARKS], n = 0;
    rl_pose_fit_model(&md, mount, map->ceiling_height, 0.5 * map->diameter);
    q[0] = t->x;
    q[1] = t->y;
    q[2] = t->yaw;
    rl_pose_fit_camera(&md, q, Rc, C);
    for (i = 0; i < t->n; i++) {
        pair[i] = -1;
        if (!project(cam, &md, Rc, C, map, t->win[i].index, &at[i]))
            continue;
        for (k = 0; k < t->n_full; k++)
            if (t->full_id[k] == at[i].id &&
                hypot(t->full_u[k] - at[i].u, t->full_v[k] - at[i].v) <= NAMED_REACH * at[i].radius)
                pair[i] = pair[i] == -1 ? k : -2;
        if (pair[i] >= 0) {
            du += t->full_u[pair[i]] - at[i].u;
            dv += t->full_v[pair[i]] - at[i].v;
            n++;
        }
    }
    for (i = 0; i < t->n && n > 0; i++)
        if (pair[i] >= 0 && hypot(t->full_u[pair[i]] - at[i].u - du / n, t->full_v[pair[i]] - at[i].v - dv / n) <=
                                NAMED_NEAR * at[i].radius)
            t->named[t->n_named++] = at[i].index;
}

int rl_track_plan(rl_track *t, const rl_calib *cam, const rl_mount *mount, const rl_map *map, double t_s,
                  const rl_track_motion *odom)
{
    t->tracked = 0;
    t->n = 0;
    if (t->cfg.full_every <= 0 || t->full_next || !t->have || !t->have_levels ||
        t->since_full + 1 >= t->cfg.full_every || !(t_s >= t->t) || t_s - t->t > t->cfg.max_age ||
        cam == NULL || mount == NULL || map == NULL)
        return 0;
    predict_pose(t, t_s, odom);
    if (predict_windows(t, cam, mount, map) < 2)
        return 0;
    if (t->full_reads)
        name_full_reads(t, cam, mount, map);
    t->full_reads = 0;
    rl_track_order_spread(t, cam->cx, cam->cy);
    return 1;
}

/* A window around prediction w, as the local pass takes a candidate. */
static void window_candidate(const rl_track_window *w, int W, int H, rl_detection *u)
{
    memset(u, 0, sizeof *u);
    u->id = -1;
    u->u = w->u;
    u->v = w->v;
    u->radius = w->radius;
    u->box.x0 = (int)floor(w->u - w->radius);
    u->box.y0 = (int)floor(w->v - w->radius);
    u->box.x1 = (int)ceil(w->u + w->radius);
    u->box.y1 = (int)ceil(w->v + w->radius);
    u->complete = rl_geom_disk_complete(W, H, w->u, w->v, w->radius);
    u->visible = w->visible;
    u->pass = RL_PASS_LOCAL;
}

/* A box read whose centre the refinement moved this far is read again
 * from there (the prediction a few pixels off). */
#define BOX_RETRY_PX 1.5

/* The global pass's read of a candidate whose box is the disk of c
 * (centre, radius): into *d; its id. */
static int read_box(const rl_recog *rec, const rl_image *img, const rl_result *res, const rl_detection *c,
                    rl_detection *d)
{
    rl_clr clr;
    clr.box.x0 = (int)floor(c->u - c->radius);
    clr.box.y0 = (int)floor(c->v - c->radius);
    clr.box.x1 = (int)ceil(c->u + c->radius);
    clr.box.y1 = (int)ceil(c->v + c->radius);
    clr.shape = rl_shape_circle();
    rl_global_read(rec, img, &clr, rec->tone, res, d);
    d->band_ready = 0; /* a window's read takes no band radius (rl_recog_run's end does) */
    return d->id;
}

/* 1 when read d names w's id within `shift` radii of w's place. */
static int verifies(const rl_track_window *w, double shift, const rl_detection *d)
{
    return d->id == w->id && hypot(d->u - w->u, d->v - w->v) <= shift * w->radius;
}

/* A landmark the border cuts, as predicted (less than CUT_VISIBLE of it
 * in view: a whole one is read whatever the prediction's error; CUT_VISIBLE
 * and more may also be verified from its edge, rl_verify_read_border), that
 * is not verified is read as the local pass reads one (some ten times a
 * verification's cost) only while fewer than CUT_READS were read: the
 * pose has enough without it, and the next full frame reads it. */
#define CUT_READS 3
#define CUT_VISIBLE 0.97

/* Whether map entry index is in list[0 .. n - 1]: t->known (kept its id
 * through the zone twins' check in the frame before) or t->named. */
static int in_list(const int *list, int n, int index)
{
    int k;
    for (k = 0; k < n; k++)
        if (list[k] == index)
            return 1;
    return 0;
}

static int was_known(const rl_track *t, int index)
{
    return in_list(t->known, t->n_known, index);
}

/* 1 when the window of w reads its predicted id near the prediction
 * (within `shift` radii; the read into *d): first verified there
 * (rl_verify); when that is not clear and `full` is 1, as the global pass
 * reads a candidate whose box is the predicted one (a whole landmark),
 * else as the local pass reads one (its own window and threshold). A box
 * read that takes another id, its circle whole in the frame, ends a whole
 * window (is_whole) there: the window holds another landmark (the
 * prediction failed; the frame is read in full), and the local read after it (some 500,000 instructions) never
 * took the window's own id on the bench's drives (docs/tracking.md). */
static int read_window(const rl_track *t, rl_recog *rec, const rl_image *img, const rl_track_window *w,
                       double shift, int full, const rl_result *res, rl_detection *d)
{
    rl_detection u;
    /* kept in the frame before (read by windows, its pose taken), or read
     * by the full frame before (named): its id judged against its rivals
     * alone (rl_verify) */
    int known = was_known(t, w->index) || in_list(t->named, t->n_named, w->index);
    /* a window verification does not take is read the costly way, even
     * when its ink drew the centre past the reach or no ink showed (*away):
     * a review found both where the costly reads find the landmark (the
     * centre settled just past 1.5 radii off, a faint one under midway grey) */
    if (rl_verify_read(rec, img, res, w->id, known, w->u, w->v, w->radius, d, NULL) && verifies(w, shift, d))
        return 1;
    if (!full)
        return 0;
    /* next to the border and about whole (CUT_VISIBLE): verified from the
     * outer edge's visible part before the costly reads; a landmark cut
     * deeper is not read this way (among the first reads it moved the
     * frame's shift: docs/tracking.md) */
    if (w->visible >= CUT_VISIBLE &&
        rl_verify_read_border(rec, img, res, w->id, known, w->u, w->v, w->radius, d) && verifies(w, shift, d))
        return 1;
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_WIN_COSTLY);
    window_candidate(w, img->width, img->height, &u);
    if (u.complete) {
        int id = read_box(rec, img, res, &u, d);
        if (id != w->id && hypot(d->u - u.u, d->v - u.v) > BOX_RETRY_PX)
            id = read_box(rec, img, res, d, d);
        if (id == w->id && verifies(w, shift, d))
            return 1;
        /* another landmark there, in a window whose failure reads the
         * frame in full (is_whole) */
        if (id >= 0 && id != w->id && is_whole(w, img->width, img->height) &&
            rl_geom_disk_complete(img->width, img->height, d->u, d->v, d->radius))
            return 0;
    }
    return w->visible >= t->cfg.window_visible && rl_local_read(rec, img, res, &u, w->radius, d) &&
           verifies(w, shift, d);
}

/* The windows read, whole ones first: the first within max_first_shift
 * radii of its prediction; each next one where the reads so far put it
 * (rl_track_shift), within max_shift. Returns how many were read; *missed 1
 * (and no more read) as soon as a whole one is missed. Each landmark of
 * res: its map entry (index) and whether the twins' check may take its id
 * as known (known: kept in the frame before). */
static int read_windows(rl_track *t, rl_recog *rec, const rl_image *img, rl_result *res, int *missed,
                        int *index, unsigned char *known)
{
    rl_track_shift fs;
    int pass, i, read = 0;
    memset(&fs, 0, sizeof fs);
    fs.cu = 0.5 * (img->width - 1);
    fs.cv = 0.5 * (img->height - 1);
    *missed = 0;
    for (pass = 0; pass < 2; pass++)
        for (i = 0; i < t->n; i++) {
            rl_track_window w = t->win[i];
            rl_detection d;
            int whole = is_whole(&w, img->width, img->height);
            if (whole != (pass == 0))
                continue;
            /* where the shift puts it: whole, or enough in view, there */
            rl_track_shift_apply(&fs, &w);
            w.visible = rl_geom_visible_in(img->width, img->height, w.u, w.v, w.radius);
            whole = is_whole(&w, img->width, img->height);
            if (w.visible < t->cfg.min_visible)
                continue;
            if (t->cfg.max_reads > 0 && read >= t->cfg.max_reads)
                return read; /* enough for the pose; the full frame reads the rest */
            res->local_tried++;
            if (!read_window(t, rec, img, &w, read ? t->cfg.max_shift : t->cfg.max_first_shift,
                             read < CUT_READS || w.visible >= CUT_VISIBLE,
                             res, &d) ||
                !rl_result_add_landmark(res, &d)) {
                if (whole) {
                    *missed = 1; /* the prediction failed: the frame is read in full */
                    return read;
                }
                continue;
            }
            index[res->n_landmarks - 1] = w.index;
            known[res->n_landmarks - 1] = (unsigned char)was_known(t, w.index);
            rl_track_shift_add(&fs, &t->win[i], &d);
            read++;
        }
    return read;
}

rl_err rl_track_read(rl_track *t, rl_recog *rec, const rl_image *img, rl_result *res, int *ok)
{
    int read, missed, index[RL_MAX_LANDMARKS], i;
    unsigned char known[RL_MAX_LANDMARKS], kept[RL_MAX_LANDMARKS];
    if (t == NULL || rec == NULL || img == NULL || res == NULL || ok == NULL || !rl_image_valid(img) ||
        img->width != rec->width || img->height != rec->height)
        return RL_EINVAL;
    *ok = 0;
    rl_result_clear(res, rec->width, rec->height);
    res->levels = t->levels;
    res->gamma = rl_tones_gamma(&rec->tones);
    read = read_windows(t, rec, img, res, &missed, index, known);
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_WIN_FRAME);
    /* the zone twins' check of a full frame (rl_twins): a read it refuses
     * is missed, and the frame read in full. A read of a landmark the check
     * kept in the frame before (read by windows) is not judged again: its
     * id is the map's, named again by the read within the windows' reach
     * of where the track has followed it since the check
     * (docs/tracking.md) */
    t->n_seen = 0;
    t->n_unjudged = 0;
    if (res->n_landmarks > 0) {
        int before = res->n_landmarks;
        rl_twins_check_known(rec, img, rl_tones_other(&rec->tones, rec->tone), res, known, kept);
        missed |= res->n_landmarks < before;
        read -= before - res->n_landmarks;
        for (i = 0; i < before; i++) {
            if (kept[i])
                t->seen[t->n_seen++] = index[i];
            if (kept[i] && known[i])
                t->unjudged[t->n_unjudged++] = index[i];
        }
    }
    res->local_found = read;
    rl_filter_sort(res);
    *ok = missed == 0 && read >= 2;
    if (*ok) {
        t->tracked = 1;
        t->since_full++;
        t->frames_tracked++;
    } else {
        t->fallbacks++;
    }
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_DONE);
    return RL_OK;
}

void rl_track_full(rl_track *t, const rl_result *res)
{
    int i;
    /* its reads, named by the next plan once its pose is taken; not a
     * frame read again after a jump or with no pose */
    t->n_full = 0;
    for (i = 0; i < res->n_landmarks && !t->full_next; i++)
        if (res->landmarks[i].id >= 0) {
            t->full_id[t->n_full] = res->landmarks[i].id;
            t->full_u[t->n_full] = res->landmarks[i].u;
            t->full_v[t->n_full++] = res->landmarks[i].v;
        }
    t->tracked = 0;
    t->since_full = 0;
    t->full_next = 0;
    t->n_known = t->n_named = 0;
    t->n_unjudged = 0;
    t->levels = res->levels;
    t->have_levels = res->levels.threshold > 0;
    t->frames_full++;
}

int rl_track_pose(rl_track *t, const rl_pose *pose, double t_s)
{
    if (t->tracked && (pose == NULL || hypot(pose->x - t->ex, pose->y - t->ey) > t->cfg.max_jump ||
                       fabs(wrap(pose->yaw - t->eyaw)) > t->cfg.max_jump_yaw)) {
        t->tracked = 0;
        t->fallbacks++;
        t->n_known = t->n_named = t->full_reads = 0;
        t->full_next = 1; /* the frame is read again in full, not by the same windows */
        return 1;
    }
    /* the reads the twins' check kept count as known only from a frame
     * read by windows whose pose was taken (from a full frame's reads, the
     * next frame's first, the moving drive's poses came out worse: a read
     * the check refuses there sends the frame back to a full read) */
    t->n_known = 0;
    t->n_named = 0;
    t->full_reads = 0;
    if (pose == NULL) {
        t->full_next = 1;
        t->have_prev = 0;
        return 0;
    }
    t->full_reads = !t->tracked && t->n_full > 0;
    if (t->tracked) {
        memcpy(t->known, t->seen, (size_t)t->n_seen * sizeof t->seen[0]);
        t->n_known = t->n_seen;
    }
    t->px = t->x;
    t->py = t->y;
    t->pyaw = t->yaw;
    t->pt = t->t;
    t->have_prev = t->have;
    t->x = pose->x;
    t->y = pose->y;
    t->yaw = pose->yaw;
    t->t = t_s;
    t->have = 1;
    return 0;
}
