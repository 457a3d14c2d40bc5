#include "rl_place.h"

#include <math.h>
#include <string.h>
#include "rl_place_index.h"
#include "rl_place_obs.h"

#define SEEDS 12      /* observations that propose places (the most reliable first) */
#define TRACK_SEEDS 8 /* observations tracking looks near */
#define NEAR_MAX 16   /* map landmarks of one id near a tracked prediction */

/* A place: the rigid motion from the robot frame to the map, and what it
 * verified. */
typedef struct {
    double x, y, yaw;
    int matched, conflicts;
    int match[RL_MAX_LANDMARKS]; /* per observation: map landmark, or -1 */
} place;

typedef struct {
    place best, second;
    int have_best, have_second, candidates;
    double gate;
    /* when near_r > 0, only places within near_r of (near_x, near_y) count */
    double near_x, near_y, near_r;
} search;

static double wrap(double a)
{
    return atan2(sin(a), cos(a));
}

/* How far two landmarks' observed distance may be from the map's: the
 * level model's errors (rocking, the ceiling's height) grow with it. */
static double tolerance(double d)
{
    return 0.03 + 0.03 * d;
}

/* How far observations i and j's distance may be from their map
 * landmarks': the level model's tolerance, and the heights' slack (the
 * index's look-up; each pair found is then held to the tolerance at its
 * landmarks' heights: pair_fits). */
static double pair_tolerance(const rl_place_obs *o, int i, int j)
{
    return tolerance(rl_place_obs_distance(o, i, j)) + rl_place_obs_slack(o, i) + rl_place_obs_slack(o, j);
}

/* 1 when observations i and j can be map landmarks a and b: both usable
 * and, at their heights, as far apart as they are within the tolerance
 * (on a map of one plane the index's look-up has held them to it). */
static int pair_fits(const rl_place *pl, const rl_place_obs *o, int i, int j, int a, int b)
{
    double d;
    if (o->spread <= 0)
        return 1;
    d = rl_place_obs_distance_at(pl, o, i, j, a, b);
    return rl_place_obs_usable(pl, o, a) && rl_place_obs_usable(pl, o, b) &&
           fabs(d - hypot(pl->map->lm[a].x - pl->map->lm[b].x, pl->map->lm[a].y - pl->map->lm[b].y)) <= tolerance(d);
}

/* The motion putting observations i and j on map landmarks a and b. */
static void propose(const rl_place *pl, const rl_place_obs *o, int i, int j, int a, int b, place *p)
{
    const rl_map *map = pl->map;
    double ix, iy, jx, jy, mx = map->lm[b].x - map->lm[a].x, my = map->lm[b].y - map->lm[a].y;
    double ox, oy, yaw, c, s, cx, cy;
    rl_place_obs_at(pl, o, i, a, &ix, &iy);
    rl_place_obs_at(pl, o, j, b, &jx, &jy);
    ox = jx - ix;
    oy = jy - iy;
    yaw = atan2(my, mx) - atan2(oy, ox);
    c = cos(yaw);
    s = sin(yaw);
    cx = 0.5 * (ix + jx);
    cy = 0.5 * (iy + jy);
    p->yaw = wrap(yaw);
    p->x = 0.5 * (map->lm[a].x + map->lm[b].x) - (c * cx - s * cy);
    p->y = 0.5 * (map->lm[a].y + map->lm[b].y) - (s * cx + c * cy);
}

/* How far observation k lies from map landmark m under place p (at m's
 * height); HUGE_VAL for one that cannot be matched. */
static double miss_at(const rl_place *pl, const rl_place_obs *o, const place *p, int k, int m)
{
    double x, y, c = cos(p->yaw), s = sin(p->yaw);
    if (!rl_place_obs_usable(pl, o, m))
        return HUGE_VAL;
    rl_place_obs_at(pl, o, k, m, &x, &y);
    return hypot(p->x + c * x - s * y - pl->map->lm[m].x, p->y + s * x + c * y - pl->map->lm[m].y);
}

/* The map landmark of its id observation k lies on under place p (within
 * the gate, at that landmark's height), or -1; *other 1 when it lies on
 * another id's instead. On a map of one plane: the nearest landmark
 * within the gate. */
static int lies_on(const rl_place *pl, const rl_place_obs *o, const place *p, int k, int *other)
{
    double c = cos(p->yaw), s = sin(p->yaw), best = pl->cfg.gate;
    double X = p->x + c * o->px[k] - s * o->py[k], Y = p->y + s * o->px[k] + c * o->py[k];
    int near[NEAR_MAX], n, q, m = -1;
    *other = 0;
    if (o->spread <= 0) {
        m = rl_place_index_near(pl, X, Y, pl->cfg.gate, 0);
        *other = m >= 0 && pl->map->lm[m].id != o->id[k];
        return *other ? -1 : m;
    }
    n = rl_place_index_within(pl, X, Y, pl->cfg.gate + rl_place_obs_slack(o, k), o->id[k], near, NEAR_MAX);
    for (q = 0; q < n && q < NEAR_MAX; q++) {
        double miss = miss_at(pl, o, p, k, near[q]);
        if (miss <= best) {
            best = miss;
            m = near[q];
        }
    }
    if (m < 0) {
        int any = rl_place_index_near(pl, X, Y, pl->cfg.gate + rl_place_obs_slack(o, k), 0);
        *other = any >= 0 && pl->map->lm[any].id != o->id[k] && miss_at(pl, o, p, k, any) <= pl->cfg.gate;
    }
    return m;
}

/* Count the observations the place puts within the gate of a map landmark
 * of their id (and those it puts on another id's). 0 as soon as it cannot
 * reach `need`. The pair that proposed it (observations i, j on map
 * landmarks a, b; i < 0: none) counts without a look-up when the motion
 * cannot have moved them out of the gate (half the distance tolerance). */
static int verify(const rl_place *pl, const rl_place_obs *o, place *p, int need, int i, int j, int a, int b)
{
    int k, known = i >= 0 && 0.5 * tolerance(rl_place_obs_distance_at(pl, o, i, j, a, b)) <= pl->cfg.gate;
    p->matched = p->conflicts = 0;
    if (known) {
        p->match[i] = a;
        p->match[j] = b;
        p->matched = 2;
    }
    for (k = 0; k < o->n; k++) {
        int other;
        if (known && (k == i || k == j))
            continue;
        p->match[k] = lies_on(pl, o, p, k, &other);
        p->matched += p->match[k] >= 0;
        p->conflicts += other;
        /* what is left to look at: the rest, less the pair when counted already */
        if (p->matched + (o->n - k - 1) - (known ? (k < i) + (k < j) : 0) < need)
            return 0;
    }
    return 1;
}

static int same_place(const search *s, const place *a, const place *b)
{
    return hypot(a->x - b->x, a->y - b->y) < 2 * s->gate && fabs(wrap(a->yaw - b->yaw)) < 0.1;
}

/* Keep the best place and the best of the other places. */
static void consider(search *s, const place *p)
{
    if (s->near_r > 0 && hypot(p->x - s->near_x, p->y - s->near_y) > s->near_r)
        return;
    if (!s->have_best || p->matched > s->best.matched) {
        if (s->have_best && !same_place(s, &s->best, p)) {
            s->second = s->best;
            s->have_second = 1;
        } else if (s->have_second && same_place(s, &s->second, p)) {
            s->have_second = 0;
        }
        s->best = *p;
        s->have_best = 1;
    } else if (!same_place(s, &s->best, p) && (!s->have_second || p->matched > s->second.matched)) {
        s->second = *p;
        s->have_second = 1;
    }
}

/* Places verifying fewer than this cannot change the decision. */
static int needed(const search *s, int margin)
{
    int need = s->have_best ? s->best.matched - margin + 1 : 2;
    return need < 2 ? 2 : need;
}

/* Every place the index proposes for observations i and j. */
static void propose_pair(const rl_place *pl, const rl_place_obs *o, int i, int j, int margin, search *s)
{
    const rl_place_pair *p, *end;
    double d = rl_place_obs_distance(o, i, j), t = pair_tolerance(o, i, j);
    if (d - t > pl->cfg.reach)
        return;
    rl_place_index_pairs(pl, o->id[i], o->id[j], d - t, d + t, &p, &end);
    for (; p < end; p++) {
        int turn;
        for (turn = 0; turn < 2; turn++) {
            /* which map landmark is observation i: the ids say (one way
             * passes), or, the same id twice, both ways */
            int a = turn ? p->b : p->a, b = turn ? p->a : p->b;
            place c;
            if (pl->map->lm[a].id != o->id[i] || !pair_fits(pl, o, i, j, a, b))
                continue;
            propose(pl, o, i, j, a, b, &c);
            s->candidates++;
            if (verify(pl, o, &c, needed(s, margin), i, j, a, b))
                consider(s, &c);
        }
    }
}

/* Three observations close enough together that the index holds their
 * map pairs, the most reliable first; 0 if there are none. */
static int seed_triangle(const rl_place *pl, const rl_place_obs *o, int *t)
{
    int n = o->n < SEEDS ? o->n : SEEDS, i, j, k;
    for (k = 2; k < n; k++)
        for (j = 1; j < k; j++)
            for (i = 0; i < j; i++) {
                if (rl_place_obs_distance(o, i, j) + pair_tolerance(o, i, j) <= pl->cfg.reach &&
                    rl_place_obs_distance(o, i, k) + pair_tolerance(o, i, k) <= pl->cfg.reach &&
                    rl_place_obs_distance(o, j, k) + pair_tolerance(o, j, k) <= pl->cfg.reach) {
                    t[0] = i;
                    t[1] = j;
                    t[2] = k;
                    return 1;
                }
            }
    return 0;
}

/* The search with no prior: a seed triangle's pairs, then (when the best
 * place leaves an observation unverified) every pair of seeds. */
static void search_all(const rl_place *pl, const rl_place_obs *o, search *s)
{
    int t[3], n = o->n < SEEDS ? o->n : SEEDS, i, j, triangle = seed_triangle(pl, o, t);
    if (triangle) {
        propose_pair(pl, o, t[0], t[1], pl->cfg.margin, s);
        propose_pair(pl, o, t[0], t[2], pl->cfg.margin, s);
        propose_pair(pl, o, t[1], t[2], pl->cfg.margin, s);
        if (s->have_best && s->best.matched == o->n)
            return;
    }
    for (j = 1; j < n; j++)
        for (i = 0; i < j; i++) {
            int done = triangle && (i == t[0] || i == t[1] || i == t[2]) && (j == t[0] || j == t[1] || j == t[2]);
            if (!done)
                propose_pair(pl, o, i, j, pl->cfg.margin, s);
        }
}

/* How far the robot can have moved since the prior's pose, m. */
static double prior_reach(const rl_place *pl, const rl_place_prior *pr)
{
    return pl->cfg.max_speed * pr->age + pl->cfg.gate;
}

/* Tracking: places within the prior's bound, from the map landmarks of
 * each id near where the prior puts the observations. */
static void search_near(const rl_place *pl, const rl_place_obs *o, const rl_place_prior *pr, search *s)
{
    const rl_map *map = pl->map;
    double R = prior_reach(pl, pr), turn = pl->cfg.max_turn * pr->age + 0.02;
    double c = cos(pr->yaw), sn = sin(pr->yaw);
    int near[TRACK_SEEDS][NEAR_MAX], cnt[TRACK_SEEDS], n = o->n < TRACK_SEEDS ? o->n : TRACK_SEEDS;
    int i, j, a, b, first = -1, far = -1;
    double far_d = 0;
    for (i = 0; i < n; i++) {
        double X = pr->x + c * o->px[i] - sn * o->py[i], Y = pr->y + sn * o->px[i] + c * o->py[i];
        double r = R + turn * hypot(o->px[i], o->py[i]) + pl->cfg.gate + rl_place_obs_slack(o, i);
        cnt[i] = rl_place_index_within(pl, X, Y, r, o->id[i], near[i], NEAR_MAX);
        if (cnt[i] > NEAR_MAX)
            cnt[i] = NEAR_MAX; /* a bound too wide to tell: the global search decides */
        if (cnt[i] > 0 && first < 0)
            first = i;
    }
    if (first < 0)
        return;
    for (j = 0; j < n; j++)
        if (j != first && cnt[j] > 0 && rl_place_obs_distance(o, first, j) > far_d) {
            far_d = rl_place_obs_distance(o, first, j);
            far = j;
        }
    if (far < 0)
        return;
    for (a = 0; a < cnt[first]; a++)
        for (b = 0; b < cnt[far]; b++) {
            int ma = near[first][a], mb = near[far][b];
            double dm = hypot(map->lm[ma].x - map->lm[mb].x, map->lm[ma].y - map->lm[mb].y);
            place p;
            if (ma == mb || fabs(dm - far_d) > pair_tolerance(o, first, far) || !pair_fits(pl, o, first, far, ma, mb))
                continue;
            propose(pl, o, first, far, ma, mb, &p);
            if (hypot(p.x - pr->x, p.y - pr->y) > R || fabs(wrap(p.yaw - pr->yaw)) > turn)
                continue;
            s->candidates++;
            if (verify(pl, o, &p, needed(s, 1), -1, -1, -1, -1))
                consider(s, &p);
        }
}

/* The best place is taken when enough verify, it leads every other place
 * by the margin and more land on their ids than on others'. */
static int clear(const search *s, int min_landmarks, int margin)
{
    int second = s->have_second ? s->second.matched : 0;
    return s->have_best && s->best.matched >= min_landmarks && s->best.matched - second >= margin &&
           s->best.matched >= s->best.conflicts + margin;
}

/* Near the last pose two landmarks are enough; a tracked place that
 * leaves more than half of the frame's landmarks unverified is checked
 * against the whole map first: the robot may have been carried (or the
 * last pose was wrong), and two ids that happen to lie near where the
 * prior puts them are a coincidence of a map whose ids repeat. It is kept
 * when the whole map gives no clear place (the frame's other landmarks
 * may be ones the map does not hold). */
static int explains(const search *s, const rl_place_obs *o)
{
    return 2 * s->best.matched >= o->n;
}

static void report(const search *s, const rl_place_obs *o, int status, rl_place_found *f)
{
    int k;
    f->status = status;
    f->verified = s->have_best ? s->best.matched : 0;
    f->runner_up = s->have_second ? s->second.matched : 0;
    f->candidates += s->candidates;
    if (s->have_best) {
        f->x = s->best.x;
        f->y = s->best.y;
        f->yaw = s->best.yaw;
    }
    if (status == RL_PLACE_FOUND || status == RL_PLACE_TRACKED)
        for (k = 0; k < o->n; k++)
            f->match[o->det[k]] = s->best.match[k];
}

/* A place once found is kept: when neither the tracked search (a turn
 * faster than max_turn, a brisk corner, leaves it no place) nor the
 * whole map gives a clear place, the whole map's places are gated by
 * the prior: one that lies within reach of the last pose (any heading)
 * and leads every other place there, explaining the frame, is the only
 * plausible one. 1 with it in *kept. */
static int prior_kept(const rl_place *pl, const rl_place_obs *o, const rl_place_prior *prior, const search *all,
                      search *kept)
{
    if (prior == NULL || !prior->valid || prior->age < 0 || prior->age > pl->cfg.track_age || !all->have_best)
        return 0;
    memset(kept, 0, sizeof *kept);
    kept->gate = pl->cfg.gate;
    kept->near_x = prior->x;
    kept->near_y = prior->y;
    kept->near_r = prior_reach(pl, prior);
    search_all(pl, o, kept);
    return clear(kept, 2, 1) && explains(kept, o);
}

rl_err rl_place_find(const rl_place *pl, const rl_calib *cam, const rl_mount *mount, const rl_detection *lm, int n,
                     const rl_offsets *offsets, const rl_place_prior *prior, rl_place_found *found)
{
    rl_place_obs o;
    search s, tracked;
    int i, have_tracked = 0;
    if (pl == NULL || cam == NULL || mount == NULL || found == NULL || n < 0 || (n > 0 && lm == NULL) ||
        rl_calib_check(cam) != RL_OK)
        return RL_EINVAL;
    memset(found, 0, sizeof *found);
    for (i = 0; i < RL_MAX_LANDMARKS; i++)
        found->match[i] = -1;
    rl_place_obs_make(pl, cam, mount, lm, n, offsets, &o);
    if (o.n < 2)
        return RL_ETOOFEW;
    memset(&s, 0, sizeof s);
    memset(&tracked, 0, sizeof tracked); /* read only when have_tracked; GCC's -O3 cannot tell */
    s.gate = pl->cfg.gate;
    if (prior != NULL && prior->valid && prior->age >= 0 && prior->age <= pl->cfg.track_age) {
        search_near(pl, &o, prior, &s);
        if (clear(&s, 2, 1)) {
            if (explains(&s, &o)) {
                report(&s, &o, RL_PLACE_TRACKED, found);
                return RL_OK;
            }
            tracked = s; /* kept unless the whole map gives a clear place */
            have_tracked = 1;
        }
        found->candidates = s.candidates;
        memset(&s, 0, sizeof s);
        s.gate = pl->cfg.gate;
    }
    search_all(pl, &o, &s);
    if (clear(&s, pl->cfg.min_landmarks, pl->cfg.margin)) {
        report(&s, &o, RL_PLACE_FOUND, found);
        return RL_OK;
    }
    if (have_tracked) {
        found->candidates = s.candidates; /* report adds the tracked search's */
        report(&tracked, &o, RL_PLACE_TRACKED, found);
        return RL_OK;
    }
    if (prior_kept(pl, &o, prior, &s, &tracked)) {
        found->candidates += s.candidates;
        report(&tracked, &o, RL_PLACE_TRACKED, found);
        return RL_OK;
    }
    report(&s, &o, RL_PLACE_AMBIGUOUS, found);
    return RL_EAMBIGUOUS;
}

rl_err rl_place_solve(const rl_place *pl, const rl_calib *cam, const rl_mount *mount, const rl_detection *lm,
                      int n, const rl_offsets *offsets, const rl_place_prior *prior, rl_pose *pose,
                      rl_place_found *found)
{
    rl_err e;
    if (pose == NULL)
        return RL_EINVAL;
    memset(pose, 0, sizeof *pose);
    if ((e = rl_place_find(pl, cam, mount, lm, n, offsets, prior, found)) != RL_OK)
        return e;
    return rl_pose_solve_matched(cam, pl->map, mount, lm, n < RL_MAX_LANDMARKS ? n : RL_MAX_LANDMARKS,
                                 found->match, offsets, pose);
}
