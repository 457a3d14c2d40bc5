#include "rl_view_json.h"
#include "rl_view_focus.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* A buffer written front to back; once something did not fit, `over`
 * stays set and the caller gets 0. */
typedef struct {
    char *p;
    size_t cap, n;
    int over;
} jbuf;

static void put(jbuf *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void put(jbuf *b, const char *fmt, ...)
{
    va_list ap;
    int k;
    if (b->over)
        return;
    va_start(ap, fmt);
    k = vsnprintf(b->p + b->n, b->cap - b->n, fmt, ap);
    va_end(ap);
    if (k < 0 || (size_t)k >= b->cap - b->n) {
        b->over = 1;
        return;
    }
    b->n += (size_t)k;
}

/* A number, or null when it is not finite (JSON has no NaN). */
static void num(jbuf *b, const char *key, double v, int decimals)
{
    if (isfinite(v))
        put(b, "\"%s\": %.*f", key, decimals, v);
    else
        put(b, "\"%s\": null", key);
}

/* A number and the comma after it. */
static void num_sep(jbuf *b, const char *key, double v, int decimals)
{
    num(b, key, v, decimals);
    put(b, ", ");
}

static void str(jbuf *b, const char *key, const char *s)
{
    put(b, "\"%s\": \"", key);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            put(b, "\\%c", c);
        else if (c < 0x20 || c >= 0x7f)
            put(b, "\\u%04x", c); /* bytes past ASCII as themselves: no UTF-8 assumed */
        else
            put(b, "%c", c);
    }
    put(b, "\"");
}

static size_t done(jbuf *b)
{
    return b->over ? 0 : b->n;
}

void rl_view_json_hist(const rl_view_snap *s, unsigned long hist[256])
{
    size_t i, n = (size_t)s->width * (size_t)s->height;
    memset(hist, 0, 256 * sizeof hist[0]);
    if (!s->have_image)
        return;
    for (i = 0; i < n; i++)
        hist[s->image[i]]++;
}

static void detection(jbuf *b, const rl_detection *d, double sharp)
{
    put(b, "{\"id\": %d, ", d->id);
    num_sep(b, "u", d->u, 2);
    num_sep(b, "v", d->v, 2);
    num_sep(b, "radius", d->radius, 2);
    num(b, "score", d->score, 3);
    put(b, ", \"pass\": \"%s\", \"complete\": %s, ", d->pass == RL_PASS_LOCAL ? "local" : "global",
        d->complete ? "true" : "false");
    num(b, "visible", d->visible, 3);
    put(b, ", ");
    num(b, "focus", sharp, 4);
    put(b, "}");
}

/* Visible fraction below which the global pass does not read a
 * candidate (rl_global.c's). */
#define READ_MIN_VISIBLE 0.95

/* What an unread candidate lacked, from what the recognizer recorded:
 * too little of it in the image, a ring the border cuts, a size unlike
 * the frame's landmarks, a score under the pass's threshold; past those,
 * the best id did not lead clearly (a zone twin, a code one zone away,
 * read nearly as well) or its contrast was too low. */
static const char *lacked(const rl_detection *d, double threshold, double median, double tol)
{
    if (d->visible < READ_MIN_VISIBLE)
        return "too little visible";
    if (!d->complete)
        return "ring not closed";
    if (median > 0 && d->radius < median * (1 - tol))
        return "too small";
    if (median > 0 && d->radius > median * (1 + tol))
        return "too large";
    if (!(d->score >= threshold))
        return "score under the threshold";
    return "zone twin too close or too little contrast";
}

static void unread(jbuf *b, const rl_view_snap *s, const rl_detection *d, double median)
{
    double threshold = d->pass == RL_PASS_LOCAL ? s->local_min_score : s->min_score;
    put(b, "{\"id\": -1, \"best_id\": %d, ", d->best_id);
    num_sep(b, "u", d->u, 2);
    num_sep(b, "v", d->v, 2);
    num_sep(b, "radius", d->radius, 2);
    num_sep(b, "score", d->score, 3);
    num(b, "threshold", threshold, 3);
    put(b, ", \"pass\": \"%s\", \"complete\": %s, ", d->pass == RL_PASS_LOCAL ? "local" : "global",
        d->complete ? "true" : "false");
    num(b, "visible", d->visible, 3);
    put(b, ", \"lacked\": \"%s\"}", lacked(d, threshold, median, s->size_tolerance));
}

/* The identified landmarks' median radius (0 with fewer than 3: the
 * recognizer's size check needs 3). */
static double median_radius(const rl_result *r)
{
    double a[RL_MAX_LANDMARKS], t;
    int n = r->n_landmarks < RL_MAX_LANDMARKS ? r->n_landmarks : RL_MAX_LANDMARKS, i, j;
    if (n < 3)
        return 0;
    for (i = 0; i < n; i++) {
        for (t = r->landmarks[i].radius, j = i; j > 0 && a[j - 1] > t; j--)
            a[j] = a[j - 1];
        a[j] = t;
    }
    return n % 2 ? a[n / 2] : 0.5 * (a[n / 2 - 1] + a[n / 2]);
}

/* How sharp the frame is (rl_view_focus.h), the best since start, and
 * each landmark's into per. */
static void focus(jbuf *b, const rl_view_snap *s, double *per)
{
    double f = s->have_image ? rl_view_focus_frame(s->image, s->width, s->height, s->res, per) : NAN;
    put(b, "\"focus\": {");
    num_sep(b, "frame", f, 4);
    num_sep(b, "blur_px", rl_view_focus_blur_px(f), 2);
    num(b, "best", s->focus_best > 0 ? s->focus_best : NAN, 4);
    put(b, ", \"best_frame\": %ld}, ", s->focus_best_frame);
}

static void result(jbuf *b, const rl_view_snap *s)
{
    const rl_result *r = s->res;
    double median = median_radius(r), per[RL_MAX_LANDMARKS];
    const rl_levels *l = &r->levels;
    int i;
    put(b, "\"levels\": {\"light\": %d, \"threshold\": %d, ", l->light, l->threshold);
    num_sep(b, "fg", l->fg, 1);
    num(b, "bg", l->bg, 1);
    put(b, ", \"k\": %d}, ", l->k);
    num(b, "gamma", r->gamma, 3);
    put(b, ", ");
    for (i = 0; i < RL_MAX_LANDMARKS; i++)
        per[i] = NAN;
    focus(b, s, per);
    put(b, "\"landmarks\": [");
    for (i = 0; i < r->n_landmarks && i < RL_MAX_LANDMARKS; i++) {
        put(b, i ? ", " : "");
        detection(b, &r->landmarks[i], per[i]);
    }
    put(b, "], \"unidentified\": [");
    for (i = 0; i < r->n_unidentified && i < RL_MAX_CANDIDATES; i++) {
        put(b, i ? ", " : "");
        unread(b, s, &r->unidentified[i], median);
    }
    put(b, "], \"lights\": [");
    for (i = 0; i < r->n_lights && i < RL_MAX_LIGHTS; i++)
        put(b, "%s[%d, %d, %d, %d]", i ? ", " : "", r->lights[i].x0, r->lights[i].y0, r->lights[i].x1,
            r->lights[i].y1);
    put(b, "], \"candidates\": %d, \"regions\": %d, \"local_tried\": %d, \"local_found\": %d, ",
        r->n_candidates, r->n_regions, r->local_tried, r->local_found);
    put(b, "\"dropped\": {\"regions\": %d, \"lights\": %d, \"candidates\": %d, \"landmarks\": %d}, ",
        r->dropped.regions, r->dropped.lights, r->dropped.candidates, r->dropped.landmarks);
}

/* The robot's axes in the image: where its forward (0.5 m) and left
 * lead from the point above it, for a level robot (the pose does not
 * matter: robot-frame points). */
static void axes(jbuf *b, const rl_view_geom *g)
{
    rl_pose zero;
    double u0, v0, uf, vf, ul, vl;
    memset(&zero, 0, sizeof zero);
    if (!rl_pose_project(g->calib, g->map, g->mount, &zero, 0, 0, g->map->ceiling_height, &u0, &v0) ||
        !rl_pose_project(g->calib, g->map, g->mount, &zero, 0.5, 0, g->map->ceiling_height, &uf, &vf) ||
        !rl_pose_project(g->calib, g->map, g->mount, &zero, 0, 0.5, g->map->ceiling_height, &ul, &vl)) {
        put(b, "\"axes\": null, ");
        return;
    }
    /* forward's angle clockwise from the image's up; mirrored: left is
     * clockwise of forward on the image, as it is not on a map seen from
     * above */
    put(b, "\"axes\": {\"origin\": [%.2f, %.2f], \"forward\": [%.2f, %.2f], \"left\": [%.2f, %.2f], "
           "\"forward_deg\": %.1f, \"mirrored\": %s}, ",
        u0, v0, uf, vf, ul, vl, atan2(uf - u0, -(vf - v0)) * 180.0 / M_PI,
        (uf - u0) * (vl - v0) - (vf - v0) * (ul - u0) > 0 ? "true" : "false");
}

/* The map's landmarks where the pose says they are in the image, each
 * with how far the one detected with its id is from there (px; null
 * when it was not detected). */
static void projected(jbuf *b, const rl_view_snap *s)
{
    const rl_view_geom *g = s->geom;
    int i, j, n = 0;
    if (g == NULL || g->calib == NULL || g->map == NULL || g->mount == NULL)
        return;
    axes(b, g);
    put(b, "\"projected\": [");
    for (i = 0; s->have_pose && i < g->map->count && i < RL_MAX_MAP_LANDMARKS; i++) {
        double u, v, off = -1;
        if (!rl_pose_project(g->calib, g->map, g->mount, &s->pose, g->map->lm[i].x, g->map->lm[i].y,
                             rl_map_height(g->map, i), &u, &v) ||
            u < -s->width || u > 2 * s->width || v < -s->height || v > 2 * s->height)
            continue;
        for (j = 0; s->have_result && j < s->res->n_landmarks && j < RL_MAX_LANDMARKS; j++) {
            const rl_detection *d = &s->res->landmarks[j];
            double e = hypot(d->u - u, d->v - v);
            if (d->id == g->map->lm[i].id && (off < 0 || e < off))
                off = e;
        }
        put(b, "%s{\"id\": %d, ", n++ ? ", " : "", g->map->lm[i].id);
        num_sep(b, "u", u, 2);
        num(b, "v", v, 2);
        if (off >= 0)
            put(b, ", \"off_px\": %.2f}", off);
        else
            put(b, ", \"off_px\": null}");
    }
    put(b, "], ");
}

static void pose(jbuf *b, const rl_view_snap *s)
{
    const rl_pose *p = &s->pose;
    static const char *places[] = {"none", "found", "tracked", "ambiguous"};
    put(b, "\"pose\": {\"current\": %s, ", s->have_pose ? "true" : "false");
    num_sep(b, "x", p->x, 4);
    num_sep(b, "y", p->y, 4);
    num_sep(b, "yaw", p->yaw, 5);
    num_sep(b, "sigma_x", p->sigma_x, 5);
    num_sep(b, "sigma_y", p->sigma_y, 5);
    num_sep(b, "sigma_yaw", p->sigma_yaw, 5);
    num_sep(b, "roll", p->roll, 5);
    num_sep(b, "pitch", p->pitch, 5);
    num(b, "residual", p->residual, 4);
    put(b, ", \"used\": %d, \"place\": \"%s\"}, ", p->used,
        s->place >= 0 && s->place < 4 ? places[s->place] : "unique ids");
}

/* When the reader wrote the snapshot out (the loop's last report when
 * it did not say). */
static uint64_t served(const rl_view_snap *s)
{
    return s->served_us > s->now_us ? s->served_us : s->now_us;
}

/* Milliseconds from t_us to when the snapshot was served; null for never. */
static void ago(jbuf *b, const char *key, const rl_view_snap *s, uint64_t t_us)
{
    uint64_t now = served(s);
    if (t_us == 0)
        put(b, "\"%s\": null", key);
    else
        put(b, "\"%s\": %.1f", key, now > t_us ? (double)(now - t_us) / 1e3 : 0.0);
}

static void counters(jbuf *b, const rl_view_snap *s)
{
    static const char *names[RL_VIEW_REASONS] = {"pose", "too_few", "camera_error", "camera_timeout",
                                                 "config_error", "ambiguous", "reason6", "reason7"};
    const rl_view_counts *c = &s->counts;
    int i;
    put(b, "\"counters\": {");
    num_sep(b, "fps", s->fps, 2);
    num_sep(b, "latency_ms", s->latency_ms, 2);
    num(b, "landmarks_per_frame", s->landmarks, 2);
    put(b, ", \"uptime_s\": %.1f, ", s->now_us > s->start_us ? (double)(s->now_us - s->start_us) / 1e6 : 0.0);
    put(b, "\"frames\": %ld, \"poses\": %ld, \"statuses\": %ld, \"camera_errors\": %ld, "
           "\"camera_timeouts\": %ld, \"bad_frames\": %ld, \"serial_errors\": %ld, \"dropped\": %ld, "
           "\"ambiguous\": %ld, \"tracked\": %ld, \"local_used\": %ld, \"view_skipped\": %ld, \"reasons\": {",
        c->frames, c->poses, c->statuses, c->camera_errors, c->camera_timeouts, c->bad_frames,
        c->serial_errors, c->dropped, c->ambiguous, c->tracked, c->local_used, s->skipped);
    for (i = 0; i < RL_VIEW_REASONS; i++)
        put(b, "%s\"%s\": %ld", i ? ", " : "", names[i], s->reasons[i]);
    put(b, "}}, ");
    put(b, "\"serial\": {\"up\": %s, ", c->serial_up ? "true" : "false");
    str(b, "device", s->serial);
    put(b, ", ");
    str(b, "error", s->serial_error);
    put(b, ", ");
    ago(b, "last_ok_ago_ms", s, s->serial_ok_us);
    put(b, "}, \"camera_error\": {");
    str(b, "text", s->cam_error);
    put(b, ", ");
    ago(b, "ago_ms", s, s->cam_error_us);
    put(b, "}, \"recording\": {\"on\": %s, \"can\": %s, \"kept\": %ld, \"skipped\": %ld, ",
        c->recording ? "true" : "false", c->rec_can ? "true" : "false", c->rec_kept, c->rec_skipped);
    str(b, "note", s->rec_note);
    put(b, "}, ");
}

size_t rl_view_json_status(const rl_view_snap *s, char *buf, size_t cap)
{
    jbuf b = {buf, cap, 0, cap == 0};
    unsigned long hist[256];
    int i;
    /* the capture time in whole ms, as the pose packet carries it (cut, not
     * rounded: a script matches the two) */
    put(&b, "{\"seq\": %ld, \"width\": %d, \"height\": %d, \"image\": %s, \"frame\": %ld, \"t_ms\": %llu, ",
        s->seq, s->width, s->height, s->have_image ? "true" : "false", s->frame_index,
        (unsigned long long)(s->t_us / 1000u));
    /* how old the frame shown is when the snapshot was taken (the camera
     * down: status frames go on, the image stays the last one) */
    put(&b, "\"frame_age_ms\": %.1f, \"reason\": %d, ",
        s->have_image && s->now_us > s->t_us ? (double)(s->now_us - s->t_us) / 1e3 : 0.0, s->reason);
    /* the same when it was served (the page adds its own wait), and how
     * long the loop has been silent (a stalled firmware whose server lives) */
    ago(&b, "image_age_ms", s, s->have_image ? s->t_us : 0);
    put(&b, ", ");
    ago(&b, "loop_age_ms", s, s->now_us);
    put(&b, ", ");
    str(&b, "camera", s->cam_info);
    put(&b, ", ");
    if (s->have_result)
        result(&b, s);
    pose(&b, s);
    projected(&b, s);
    counters(&b, s);
    rl_view_json_hist(s, hist);
    put(&b, "\"hist\": [");
    for (i = 0; i < 256; i++)
        put(&b, "%s%lu", i ? "," : "", hist[i]);
    put(&b, "], \"track\": [");
    for (i = 0; i < s->n_track && i < RL_VIEW_TRACK; i++)
        put(&b, "%s[%.3f, %.3f, %d]", i ? ", " : "", isfinite(s->track[i].x) ? s->track[i].x : 0.0,
            isfinite(s->track[i].y) ? s->track[i].y : 0.0, s->track[i].gap);
    put(&b, "]}\n");
    return done(&b);
}

size_t rl_view_json_map_size(const rl_map *m)
{
    /* a landmark: {"id": 255, "x": -100000.000, "y": ...}, well under 80 bytes */
    return 256 + (size_t)(m->count > 0 ? m->count : 0) * 80;
}

size_t rl_view_json_map(const rl_map *m, char *buf, size_t cap)
{
    jbuf b = {buf, cap, 0, cap == 0};
    int i;
    put(&b, "{\"family\": \"ring%d\", ", m->family.bits);
    num_sep(&b, "diameter", m->diameter, 4);
    num(&b, "ceiling", m->ceiling_height, 3);
    put(&b, ", \"landmarks\": [");
    for (i = 0; i < m->count && i < RL_MAX_MAP_LANDMARKS; i++) {
        put(&b, "%s{\"id\": %d, ", i ? ", " : "", m->lm[i].id);
        num_sep(&b, "x", m->lm[i].x, 3);
        num(&b, "y", m->lm[i].y, 3);
        put(&b, "}");
    }
    put(&b, "]}\n");
    return done(&b);
}
