/* rl_survey_build: which observations are the same landmark, and the
 * first map and poses, from the level model.
 *
 * Frames are taken in order. A frame's landmarks, put on the ceiling of a
 * level robot (rl_pose_fit_level_point), are matched to landmarks already
 * placed: near where the previous frame's pose puts them (tracking), else
 * by pairs whose distance apart agrees with the map so far (finding the
 * place: on a site with unique ids each pair has one candidate). Two or
 * more consistent matches give the frame's pose (a rigid fit), taken only
 * when the frame's other landmarks that it puts inside the mapped area
 * mostly land on placed ones of their ids; its new landmarks are placed
 * from it, level (a tilt fitted to one frame trades against its position
 * and walks the map away; the rocking averages out). A frame that fits
 * nowhere waits for a later pass; one that never fits is LOST. Then the
 * map is moved into the survey's frame (origin at (0, 0), axis on +x, the
 * scale of a measured distance). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_pose_fit.h"
#include "rl_survey.h"

/* How far apart two placings of the same landmark may be in a frame's
 * level model (a rocking robot stretches it by a few per cent). */
#define PAIR_TOL 0.05
#define PAIR_REL 0.04

typedef struct {
    rl_survey *sv;
    rl_pose_model md; /* the mount, the ceiling, the noise, the tilt prior */
    double *p;     /* level-model point of every observation, robot frame: x, y */
    int *head;     /* first landmark of each id, -1 */
    int *next;     /* next landmark of the same id */
    double *sum;   /* running sums of each landmark's placings: x, y, count */
    int repeats;   /* an id was placed at two places */
    int *cell;     /* landmarks by where they were placed: first in each hash bucket, -1 */
    int *cell_next;
} builder;

#define CELL 0.5        /* m */
#define CELL_BUCKETS 65536
#define MAPPED 0.45     /* a point this near a placed landmark lies in the mapped area */

static unsigned cell_of(double x, double y)
{
    long ix = (long)floor(x / CELL), iy = (long)floor(y / CELL);
    return (unsigned)((unsigned long)ix * 73856093ul ^ (unsigned long)iy * 19349663ul) % CELL_BUCKETS;
}

/* 1 if some placed landmark (any id) lies within r of q. */
static int mapped_near(const builder *b, const double *q, double r)
{
    int dx, dy, k;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++)
            for (k = b->cell[cell_of(q[0] + dx * CELL, q[1] + dy * CELL)]; k >= 0; k = b->cell_next[k])
                if (hypot(b->sv->lm[k].x - q[0], b->sv->lm[k].y - q[1]) < r)
                    return 1;
    return 0;
}

static void to_map(const double *pose, const double *p, double *q)
{
    double c = cos(pose[2]), s = sin(pose[2]);
    q[0] = pose[0] + c * p[0] - s * p[1];
    q[1] = pose[1] + s * p[0] + c * p[1];
}

static int add_landmark(builder *b, int id, const double *q)
{
    rl_survey *sv = b->sv;
    rl_survey_landmark *lm = &sv->lm[sv->n_lm];
    memset(lm, 0, sizeof *lm);
    lm->id = id;
    lm->x = q[0];
    lm->y = q[1];
    b->sum[3 * sv->n_lm] = q[0];
    b->sum[3 * sv->n_lm + 1] = q[1];
    b->sum[3 * sv->n_lm + 2] = 1;
    b->repeats |= b->head[id] >= 0;
    {
        unsigned c = cell_of(q[0], q[1]);
        b->cell_next[sv->n_lm] = b->cell[c];
        b->cell[c] = sv->n_lm;
    }
    b->next[sv->n_lm] = b->head[id];
    b->head[id] = sv->n_lm;
    return sv->n_lm++;
}

/* The landmark of `id` nearest q within `gate`, not yet taken; -1. */
static int nearest(const builder *b, int id, const double *q, double gate, const int *taken, int nt)
{
    const rl_survey *sv = b->sv;
    int k, best = -1, t;
    double bd = gate;
    for (k = b->head[id]; k >= 0; k = b->next[k]) {
        double d = hypot(sv->lm[k].x - q[0], sv->lm[k].y - q[1]);
        for (t = 0; t < nt && taken[t] != k; t++)
            ;
        if (t == nt && d < bd) {
            bd = d;
            best = k;
        }
    }
    return best;
}

/* Match frame f's observations near where `pose` (x, y, yaw) puts them;
 * refit the pose from the matches (dropping the worst while they
 * disagree). The number of matches kept (match[i]: landmark of
 * observation i or -1). */
static int match_near(builder *b, const rl_survey_frame *f, double *pose, double gate, int *match)
{
    rl_pose_pt pt[RL_MAX_LANDMARKS];
    int idx[RL_MAX_LANDMARKS], taken[RL_MAX_LANDMARKS];
    int i, m = 0, n = f->n < RL_MAX_LANDMARKS ? f->n : RL_MAX_LANDMARKS;
    for (i = 0; i < n; i++) {
        const double *p = b->p + 2 * (f->first + i);
        double q[2];
        int k;
        to_map(pose, p, q);
        k = nearest(b, b->sv->obs[f->first + i].id, q, gate, taken, m);
        match[i] = k;
        if (k < 0)
            continue;
        taken[m] = k;
        idx[m] = i;
        pt[m].px = p[0];
        pt[m].py = p[1];
        pt[m].mx = b->sv->lm[k].x;
        pt[m].my = b->sv->lm[k].y;
        m++;
    }
    while (m >= 2) {
        int worst = -1;
        double wd = PAIR_TOL;
        rl_pose_fit_rigid(pt, m, &pose[0], &pose[1], &pose[2]);
        for (i = 0; i < m; i++) {
            double q[2], p[2] = {pt[i].px, pt[i].py}, d;
            to_map(pose, p, q);
            d = hypot(q[0] - pt[i].mx, q[1] - pt[i].my);
            if (d > wd) {
                wd = d;
                worst = i;
            }
        }
        if (worst < 0)
            break;
        match[idx[worst]] = -1;
        pt[worst] = pt[m - 1];
        idx[worst] = idx[m - 1];
        m--;
    }
    return m;
}

/* Where observation i's ray from the camera of robot pose q meets the
 * ceiling; 0 if it does not. */
static int ray_point(const builder *b, const double *q, int i, double *out)
{
    const rl_survey_obs *o = &b->sv->obs[i];
    double Rc[9], C[3], d[3], t;
    int r;
    rl_pose_fit_camera(&b->md, q, Rc, C);
    for (r = 0; r < 3; r++)
        d[r] = Rc[3 * r] * -o->yn + Rc[3 * r + 1] * o->xn + Rc[3 * r + 2];
    if (!(d[2] > 1e-6))
        return 0;
    t = (b->md.height - C[2]) / d[2];
    out[0] = C[0] + t * d[0];
    out[1] = C[1] + t * d[1];
    return 1;
}

/* Votes for `pose`: observations with a landmark of their id near where
 * it puts them; with `miss`, also those it puts inside the mapped area
 * with none of their id there. */
static int votes(const builder *b, const rl_survey_frame *f, const double *pose, int *miss)
{
    int i, v = 0;
    for (i = 0; i < f->n; i++) {
        double q[2];
        to_map(pose, b->p + 2 * (f->first + i), q);
        if (nearest(b, b->sv->obs[f->first + i].id, q, PAIR_TOL * 2, NULL, 0) >= 0)
            v++;
        else if (miss != NULL && mapped_near(b, q, MAPPED))
            (*miss)++;
    }
    return v;
}

/* Whether `pose` agrees with the map so far: of the frame's landmarks
 * that it puts inside the mapped area, most must land on a placed one of
 * their id (a wrong pose puts them where other ids hang, or nothing). */
static int supported(const builder *b, const rl_survey_frame *f, const double *pose)
{
    int miss = 0, hit = votes(b, f, pose, &miss);
    return hit >= 2 && miss <= hit / 3;
}

/* Find frame f's place from pairs of its landmarks: each placed pair of
 * the same ids whose distance agrees proposes a pose; the one with the
 * most votes is taken when no other place has as many. 1 and *pose. */
static int find_place(const builder *b, const rl_survey_frame *f, double *pose)
{
    const rl_survey *sv = b->sv;
    int i, j, best = 0, second = 0;
    double bp[3] = {0, 0, 0};
    for (i = 0; i < f->n; i++)
        for (j = i + 1; j < f->n; j++) {
            const double *pi = b->p + 2 * (f->first + i), *pj = b->p + 2 * (f->first + j);
            double dobs = hypot(pi[0] - pj[0], pi[1] - pj[1]);
            int A, B;
            for (A = b->head[sv->obs[f->first + i].id]; A >= 0; A = b->next[A])
                for (B = b->head[sv->obs[f->first + j].id]; B >= 0; B = b->next[B]) {
                    double d = hypot(sv->lm[A].x - sv->lm[B].x, sv->lm[A].y - sv->lm[B].y), hp[3];
                    rl_pose_pt pt[2];
                    int v;
                    if (A == B || fabs(d - dobs) > PAIR_TOL + PAIR_REL * d)
                        continue;
                    pt[0].px = pi[0], pt[0].py = pi[1], pt[0].mx = sv->lm[A].x, pt[0].my = sv->lm[A].y;
                    pt[1].px = pj[0], pt[1].py = pj[1], pt[1].mx = sv->lm[B].x, pt[1].my = sv->lm[B].y;
                    rl_pose_fit_rigid(pt, 2, &hp[0], &hp[1], &hp[2]);
                    v = votes(b, f, hp, NULL);
                    if (v > best) {
                        if (hypot(hp[0] - bp[0], hp[1] - bp[1]) > sv->cfg.gate)
                            second = best;
                        best = v;
                        memcpy(bp, hp, sizeof bp);
                    } else if (v > second && hypot(hp[0] - bp[0], hp[1] - bp[1]) > sv->cfg.gate) {
                        second = v;
                    }
                }
        }
    /* where ids repeat, two landmarks at the right distance happen by
     * chance: a place needs a third that agrees, and a clear lead */
    if (best < 2 || second >= best || (b->repeats && (best < 3 || best < second + 2)))
        return 0;
    memcpy(pose, bp, sizeof bp);
    return 1;
}

/* Place frame f at robot pose q (x, y, yaw; level): its matched landmarks'
 * running means, its unmatched ones new. */
static void place(builder *b, rl_survey_frame *f, const double *q, const int *match)
{
    rl_survey *sv = b->sv;
    int i;
    for (i = 0; i < f->n; i++) {
        double at[2];
        int k = i < RL_MAX_LANDMARKS ? match[i] : -1;
        if (!ray_point(b, q, f->first + i, at))
            continue;
        /* one the matching left out may still be one placed before */
        if (k < 0)
            k = nearest(b, sv->obs[f->first + i].id, at, sv->cfg.gate, NULL, 0);
        if (k < 0) {
            k = add_landmark(b, sv->obs[f->first + i].id, at);
        } else {
            double *s = b->sum + 3 * k;
            s[0] += at[0];
            s[1] += at[1];
            s[2] += 1;
            sv->lm[k].x = s[0] / s[2];
            sv->lm[k].y = s[1] / s[2];
        }
        sv->obs_lm[f->first + i] = k;
    }
    f->x = q[0];
    f->y = q[1];
    f->yaw = q[2];
    f->roll = q[3];
    f->pitch = q[4];
    f->status = RL_SURVEY_USED;
}

/* Try to place frame f (prev: the pose of the frame just before, or NULL). */
static int try_frame(builder *b, rl_survey_frame *f, const double *prev)
{
    double pose[3], q[5] = {0, 0, 0, 0, 0};
    int match[RL_MAX_LANDMARKS], ok = 0;
    if (b->sv->n_lm == 0) {
        memset(match, 0xff, sizeof match);
        place(b, f, q, match);
        return 1;
    }
    if (prev) {
        memcpy(pose, prev, sizeof pose);
        ok = match_near(b, f, pose, b->sv->cfg.gate, match) >= 2 &&
             match_near(b, f, pose, b->sv->cfg.gate, match) >= 2 && supported(b, f, pose);
    }
    if (!ok)
        ok = find_place(b, f, pose) && match_near(b, f, pose, b->sv->cfg.gate, match) >= 2;
    if (!ok || !supported(b, f, pose))
        return 0;
    q[0] = pose[0], q[1] = pose[1], q[2] = pose[2];
    place(b, f, q, match);
    return 1;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The ceiling's height to start from: known, or from the median radius. */
static double first_height(const rl_survey *sv)
{
    const rl_survey_config *c = &sv->cfg;
    double *z, h = 0;
    int i, n = 0;
    if (c->ceiling_height > 0)
        return c->ceiling_height;
    z = malloc((size_t)(sv->n_obs + 1) * sizeof *z);
    if (z == NULL)
        return 0;
    for (i = 0; i < sv->n_obs; i++)
        if (sv->obs[i].rn > 0)
            z[n++] = 0.5 * c->diameter / sv->obs[i].rn;
    if (n > 0) {
        qsort(z, (size_t)n, sizeof *z, cmp_double);
        h = z[n / 2] + c->mount.z;
    }
    free(z);
    return h;
}

/* Frames seeing each landmark; too rarely seen ones unplaced; frames
 * left with fewer than two; ids seen only alone. */
static void count_views(rl_survey *sv)
{
    int i, j, again = 1;
    while (again) {
        again = 0;
        for (i = 0; i < sv->n_lm; i++)
            sv->lm[i].views = 0;
        for (i = 0; i < sv->n_fr; i++)
            if (sv->fr[i].status == RL_SURVEY_USED)
                for (j = 0; j < sv->fr[i].n; j++)
                    if (sv->obs_lm[sv->fr[i].first + j] >= 0)
                        sv->lm[sv->obs_lm[sv->fr[i].first + j]].views++;
        for (i = 0; i < sv->n_obs; i++) {
            int k = sv->obs_lm[i];
            if (k >= 0 && sv->lm[k].views < sv->cfg.min_views) {
                sv->lm[k].status = RL_SURVEY_RARE;
                sv->obs_lm[i] = -1;
            }
        }
        for (i = 0; i < sv->n_fr; i++) {
            rl_survey_frame *f = &sv->fr[i];
            int n = 0;
            if (f->status != RL_SURVEY_USED)
                continue;
            for (j = 0; j < f->n; j++)
                n += sv->obs_lm[f->first + j] >= 0;
            if (n < 2) {
                f->status = RL_SURVEY_FEW;
                for (j = 0; j < f->n; j++)
                    sv->obs_lm[f->first + j] = -1;
                again = 1;
            }
        }
    }
    sv->n_alone = 0;
    for (i = 0; i < sv->n_fr; i++) {
        const rl_survey_frame *f = &sv->fr[i];
        int id, k, a;
        if (f->n != 1)
            continue;
        id = sv->obs[f->first].id;
        for (k = 0; k < sv->n_lm && !(sv->lm[k].id == id && sv->lm[k].status == RL_SURVEY_PLACED); k++)
            ;
        for (a = 0; a < sv->n_alone && sv->alone[a] != id; a++)
            ;
        if (k == sv->n_lm && a == sv->n_alone && sv->n_alone < (int)(sizeof sv->alone / sizeof sv->alone[0]))
            sv->alone[sv->n_alone++] = id;
    }
}

/* The one placed landmark of `id`; -1 (err set) if none or several. */
static int gauge_landmark(rl_survey *sv, int id, const char *what)
{
    int i, k = -1, n = 0;
    for (i = 0; i < sv->n_lm; i++)
        if (sv->lm[i].id == id && sv->lm[i].status == RL_SURVEY_PLACED) {
            k = i;
            n++;
        }
    if (n == 1)
        return k;
    if (n == 0)
        snprintf(sv->err, sizeof sv->err, "the %s landmark %d was not placed (not seen, or seen in fewer than "
                 "%d frames with another landmark)", what, id, sv->cfg.min_views);
    else
        snprintf(sv->err, sizeof sv->err, "the %s landmark %d is at %d places: choose an id the site has once",
                 what, id, n);
    return -1;
}

/* Move the map and the poses into the survey's frame. */
static int to_survey_frame(rl_survey *sv)
{
    const rl_survey_config *c = &sv->cfg;
    int o = gauge_landmark(sv, c->origin_id, "origin"), a, i;
    double ox, oy, th, cs, sn, s = 1, d;
    if (o < 0)
        return 0;
    if ((a = gauge_landmark(sv, c->axis_id, "axis")) < 0)
        return 0;
    ox = sv->lm[o].x;
    oy = sv->lm[o].y;
    d = hypot(sv->lm[a].x - ox, sv->lm[a].y - oy);
    if (!(d > 0)) {
        snprintf(sv->err, sizeof sv->err, "the origin and axis landmarks are at one place");
        return 0;
    }
    th = atan2(sv->lm[a].y - oy, sv->lm[a].x - ox);
    if (c->axis_distance > 0) {
        s = c->axis_distance / d;
        sv->height = c->mount.z + s * (sv->height - c->mount.z);
    }
    cs = cos(th);
    sn = sin(th);
    for (i = 0; i < sv->n_lm; i++) {
        double x = sv->lm[i].x - ox, y = sv->lm[i].y - oy;
        sv->lm[i].x = s * (cs * x + sn * y);
        sv->lm[i].y = s * (-sn * x + cs * y);
    }
    for (i = 0; i < sv->n_fr; i++) {
        rl_survey_frame *f = &sv->fr[i];
        double x = f->x - ox, y = f->y - oy;
        f->x = s * (cs * x + sn * y);
        f->y = s * (-sn * x + cs * y);
        f->yaw -= th;
    }
    sv->lm[a].y = 0;
    return 1;
}

rl_err rl_survey_build(rl_survey *sv)
{
    builder b;
    int i, progress, max_id = 0, prev = -1;
    rl_err e = RL_OK;
    double Z;

    sv->height = first_height(sv);
    Z = sv->height - sv->cfg.mount.z;
    if (!(Z > 0)) {
        snprintf(sv->err, sizeof sv->err, sv->height > 0 ? "the ceiling (%.3f m) is not above the camera (%.3f m)"
                 : "no landmark radius to set the scale from (give --ceiling-height or --axis-distance)",
                 sv->height, sv->cfg.mount.z);
        return RL_ERANGE;
    }
    for (i = 0; i < sv->n_obs; i++)
        if (sv->obs[i].id > max_id)
            max_id = sv->obs[i].id;
    memset(&b, 0, sizeof b);
    b.sv = sv;
    free(sv->lm);
    free(sv->obs_lm);
    sv->n_lm = 0;
    sv->lm = malloc((size_t)(sv->n_obs + 1) * sizeof *sv->lm);
    sv->obs_lm = malloc((size_t)(sv->n_obs + 1) * sizeof *sv->obs_lm);
    b.p = malloc((size_t)(sv->n_obs + 1) * 2 * sizeof *b.p);
    b.sum = malloc((size_t)(sv->n_obs + 1) * 3 * sizeof *b.sum);
    b.next = malloc((size_t)(sv->n_obs + 1) * sizeof *b.next);
    b.head = malloc((size_t)(max_id + 1) * sizeof *b.head);
    b.cell = malloc(CELL_BUCKETS * sizeof *b.cell);
    b.cell_next = malloc((size_t)(sv->n_obs + 1) * sizeof *b.cell_next);
    if (!sv->lm || !sv->obs_lm || !b.p || !b.sum || !b.next || !b.head || !b.cell || !b.cell_next) {
        snprintf(sv->err, sizeof sv->err, "out of memory for %d observations", sv->n_obs);
        e = RL_ENOMEM;
        goto out;
    }
    for (i = 0; i <= max_id; i++)
        b.head[i] = -1;
    for (i = 0; i < CELL_BUCKETS; i++)
        b.cell[i] = -1;
    rl_pose_fit_model(&b.md, &sv->cfg.mount, sv->height, 0.5 * sv->cfg.diameter);
    b.md.sn = sv->cfg.pixel_sigma / sv->cfg.pixel_scale;
    b.md.prior[0] = b.md.prior[1] = sv->cfg.tilt_sigma;
    for (i = 0; i < sv->n_obs; i++) {
        sv->obs_lm[i] = -1;
        if (!rl_pose_fit_level_point(&b.md, Z, sv->obs[i].xn, sv->obs[i].yn, &b.p[2 * i], &b.p[2 * i + 1]))
            b.p[2 * i] = b.p[2 * i + 1] = 1e9; /* matches nothing */
    }
    for (i = 0; i < sv->n_fr; i++)
        sv->fr[i].status = sv->fr[i].n >= 2 ? RL_SURVEY_LOST : RL_SURVEY_FEW;
    do {
        progress = 0;
        for (i = 0; i < sv->n_fr; i++) {
            rl_survey_frame *f = &sv->fr[i];
            double pp[3];
            if (f->status != RL_SURVEY_LOST)
                continue;
            if (prev == i - 1 && prev >= 0) {
                pp[0] = sv->fr[prev].x;
                pp[1] = sv->fr[prev].y;
                pp[2] = sv->fr[prev].yaw;
            }
            if (try_frame(&b, f, prev == i - 1 && prev >= 0 ? pp : NULL)) {
                progress = 1;
                prev = i;
            }
        }
    } while (progress);
    for (i = 0; i < sv->n_lm; i++)
        sv->lm[i].status = RL_SURVEY_PLACED;
    count_views(sv);
    if (!to_survey_frame(sv))
        e = RL_ETOOFEW;
out:
    free(b.p);
    free(b.sum);
    free(b.next);
    free(b.head);
    free(b.cell);
    free(b.cell_next);
    return e;
}
