#include "rl_view.h"

#include <math.h>
#include <string.h>
#include "rl_config.h"

/* Smoothing of the rates shown: about the last ten frames. */
#define SMOOTH 0.1

void rl_view_defaults(rl_view_config *c)
{
    rl_recog_config rc;
    rl_recog_defaults(&rc);
    memset(c, 0, sizeof *c);
    c->max_rate = 5;
    c->track_period = 0.5;
    c->min_score = rc.min_score;
    c->local_min_score = rc.local_min_score;
    c->size_tolerance = rc.size_tolerance;
}

size_t rl_view_size(const rl_view_config *c)
{
    if (c->width < 1 || c->height < 1 || c->width > RL_MAX_IMAGE_DIM || c->height > RL_MAX_IMAGE_DIM)
        return 0;
    /* the result first: its alignment is the block's (malloc's) */
    return sizeof(rl_result) + (size_t)c->width * (size_t)c->height;
}

/* What the recognizer accepts, for the JSON's unread candidates. */
static void thresholds(rl_view_snap *s, const rl_view_config *c)
{
    s->min_score = c->min_score;
    s->local_min_score = c->local_min_score;
    s->size_tolerance = c->size_tolerance;
}

rl_err rl_view_snap_init(rl_view_snap *s, const rl_view_config *c, void *mem, size_t size)
{
    size_t need = rl_view_size(c);
    memset(s, 0, sizeof *s);
    if (need == 0 || !(c->max_rate > 0) || !(c->track_period > 0))
        return RL_EINVAL;
    if (mem == NULL || size < need)
        return RL_ENOMEM;
    s->width = c->width;
    s->height = c->height;
    thresholds(s, c);
    s->res = (rl_result *)mem;
    s->image = (uint8_t *)mem + sizeof(rl_result);
    s->place = -1;
    return RL_OK;
}

rl_err rl_view_init(rl_view *v, const rl_view_config *c, void *mem, size_t size)
{
    rl_err e;
    memset(v, 0, sizeof *v);
    if ((e = rl_view_snap_init(&v->shared, c, mem, size)) != RL_OK)
        return e;
    v->cfg = *c;
    v->loop.width = c->width;
    v->loop.height = c->height;
    v->loop.place = -1;
    thresholds(&v->loop, c);
    v->rec_ask = -1;
    if (pthread_mutex_init(&v->lock, NULL) != 0)
        return RL_EIO;
    return RL_OK;
}

void rl_view_destroy(rl_view *v)
{
    pthread_mutex_destroy(&v->lock);
}

static void copy_str(char *dst, size_t cap, const char *src)
{
    size_t n = src ? strlen(src) : 0;
    if (n >= cap)
        n = cap - 1;
    if (n)
        memcpy(dst, src, n);
    dst[n] = 0;
}

/* A track point, the oldest dropped when full; marked as a gap after
 * frames without a pose or a jump. */
static void track_add(rl_view_snap *l, const rl_pose *p)
{
    rl_view_point *t;
    if (l->n_track == RL_VIEW_TRACK) {
        memmove(l->track, l->track + 1, (RL_VIEW_TRACK - 1) * sizeof l->track[0]);
        l->n_track--;
    }
    t = &l->track[l->n_track];
    t->x = p->x;
    t->y = p->y;
    t->gap = l->n_track > 0 && (l->lost || hypot(p->x - t[-1].x, p->y - t[-1].y) > RL_VIEW_JUMP);
    l->lost = 0;
    l->n_track++;
}

/* The loop's own bookkeeping: every observation, copied or not. */
static void count(rl_view *v, const rl_view_obs *o)
{
    rl_view_snap *l = &v->loop;
    double n;
    l->counts = o->counts;
    l->now_us = o->now_us;
    if (l->start_us == 0)
        l->start_us = o->now_us ? o->now_us : 1;
    l->reason = o->reason;
    l->place = o->place;
    if (o->pose != NULL)
        l->pose = *o->pose; /* the last pose stays shown; have_pose says whose */
    if (o->reason >= 0 && o->reason < RL_VIEW_REASONS)
        l->reasons[o->reason]++;
    if (o->cam_error != NULL) {
        copy_str(l->cam_error, sizeof l->cam_error, o->cam_error);
        l->cam_error_us = o->now_us;
    }
    if (o->pose == NULL)
        l->lost = 1;
    if (o->frame == NULL)
        return;
    if (v->last_t_us != 0 && o->frame->t_us > v->last_t_us) {
        double fps = 1e6 / (double)(o->frame->t_us - v->last_t_us);
        l->fps = l->fps > 0 ? l->fps + SMOOTH * (fps - l->fps) : fps;
    }
    v->last_t_us = o->frame->t_us;
    n = o->res ? o->res->n_landmarks : 0;
    l->landmarks = l->landmarks + SMOOTH * (n - l->landmarks);
    if (o->pose != NULL && o->now_us >= o->frame->t_us) {
        double ms = (double)(o->now_us - o->frame->t_us) / 1000.0;
        l->latency_ms = l->latency_ms > 0 ? l->latency_ms + SMOOTH * (ms - l->latency_ms) : ms;
    }
    if (o->pose != NULL && o->now_us >= v->next_track_us) {
        track_add(l, o->pose);
        v->next_track_us = o->now_us + (uint64_t)(v->cfg.track_period * 1e6);
    }
}

static void copy_image(rl_view_snap *s, const rl_image *img)
{
    int y;
    if (img->width != s->width || img->height != s->height || img->data == NULL) {
        s->have_image = 0;
        return;
    }
    for (y = 0; y < s->height; y++)
        memcpy(s->image + (size_t)y * (size_t)s->width, img->data + (size_t)y * (size_t)img->stride,
               (size_t)s->width);
    s->have_image = 1;
}

/* Everything but the storage of image and result (the pointers stay). */
static void copy_fields(rl_view_snap *dst, const rl_view_snap *src)
{
    uint8_t *image = dst->image;
    rl_result *res = dst->res;
    int have_image = dst->have_image, have_result = dst->have_result;
    long index = dst->frame_index;
    uint64_t t_us = dst->t_us;
    const rl_view_geom *geom = dst->geom;
    double best = dst->focus_best;
    long best_frame = dst->focus_best_frame;
    memcpy(dst, src, sizeof *dst);
    dst->geom = geom;
    dst->focus_best = best;
    dst->focus_best_frame = best_frame;
    dst->image = image;
    dst->res = res;
    dst->have_image = have_image;
    dst->have_result = have_result;
    dst->frame_index = index;
    dst->t_us = t_us;
}

int rl_view_offer(rl_view *v, const rl_view_obs *o)
{
    rl_view_snap *s = &v->shared;
    count(v, o);
    if (o->now_us < v->next_us)
        return 0;
    if (pthread_mutex_trylock(&v->lock) != 0) {
        v->loop.skipped++;
        return 0;
    }
    copy_fields(s, &v->loop);
    s->seq = v->loop.seq + 1;
    v->loop.seq = s->seq;
    copy_str(s->cam_info, sizeof s->cam_info, o->cam_info);
    copy_str(s->serial, sizeof s->serial, o->serial);
    copy_str(s->rec_note, sizeof s->rec_note, o->rec_note);
    copy_str(s->serial_error, sizeof s->serial_error, o->serial_error);
    s->serial_ok_us = o->serial_ok_us;
    s->have_pose = o->pose != NULL;
    if (o->frame != NULL) {
        copy_image(s, &o->frame->img);
        s->frame_index = o->frame->index;
        s->t_us = o->frame->t_us;
        s->have_result = o->res != NULL;
        if (o->res != NULL)
            memcpy(s->res, o->res, sizeof *s->res);
    }
    pthread_mutex_unlock(&v->lock);
    v->next_us = o->now_us + (uint64_t)(1e6 / v->cfg.max_rate);
    return 1;
}

int rl_view_take(rl_view *v, rl_view_snap *s)
{
    int newer;
    pthread_mutex_lock(&v->lock);
    newer = v->shared.seq != s->seq;
    if (newer) {
        copy_fields(s, &v->shared);
        if (v->shared.have_image && s->width == v->shared.width && s->height == v->shared.height)
            memcpy(s->image, v->shared.image, (size_t)s->width * (size_t)s->height);
        s->have_image = v->shared.have_image;
        if (v->shared.have_result)
            memcpy(s->res, v->shared.res, sizeof *s->res);
        s->have_result = v->shared.have_result;
        s->frame_index = v->shared.frame_index;
        s->t_us = v->shared.t_us;
    }
    pthread_mutex_unlock(&v->lock);
    return newer;
}

void rl_view_ask_record(rl_view *v, int on)
{
    __atomic_store_n(&v->rec_ask, on ? 1 : 0, __ATOMIC_RELEASE);
}

int rl_view_record_asked(rl_view *v)
{
    return __atomic_exchange_n(&v->rec_ask, -1, __ATOMIC_ACQ_REL);
}

long rl_view_seq(rl_view *v)
{
    long seq;
    pthread_mutex_lock(&v->lock);
    seq = v->shared.seq;
    pthread_mutex_unlock(&v->lock);
    return seq;
}
