#include "rl_site_plan.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_VIEW 256 /* grid points one footprint can hold */
#define STAGE_TOP 8  /* the first stage's view size */

void rl_site_plan_defaults(rl_site_plan_input *in)
{
    memset(in, 0, sizeof *in);
    in->min_view = 3;
    in->seed = 1;
    in->max_rounds = 12;
    in->clearance = 0.3;
}

typedef struct {
    int x, y;
} pt;

/* An other placement of a view: x -> R^k (x - from) + to. */
typedef struct {
    int k;
    pt from, to;
} motion;

typedef struct {
    const rl_site_plan_input *in;
    int cols, rows, *ids;
    int pool[256], n_pool;        /* the ids to draw from */
    int L;                        /* longest offset within a view, grid steps */
    double x0;                    /* first landmark's x (and y0) */
    double y0;
    int n_keys;
    int *first;                   /* [n_keys + 1]: pair table by (id, id, offset) */
    int *entry;                   /* start point index * 4 + turn */
    long n_entries;
    uint64_t rng;
    long redrawn;
} planner;

static uint64_t next(planner *p)
{
    p->rng ^= p->rng << 13;
    p->rng ^= p->rng >> 7;
    p->rng ^= p->rng << 17;
    return p->rng;
}

static pt turn(pt v, int k)
{
    int i;
    for (i = 0; i < (k & 3); i++) {
        int t = v.x;
        v.x = -v.y;
        v.y = t;
    }
    return v;
}

/* The offset turned into x > 0, y >= 0, and how many quarter turns that took. */
static pt canonical(pt v, int *k)
{
    for (*k = 0; *k < 4; (*k)++) {
        if (v.x > 0 && v.y >= 0)
            return v;
        v = turn(v, 1);
    }
    return v; /* (0, 0): not a pair */
}

static int id_at(const planner *p, pt q)
{
    if (q.x < 0 || q.y < 0 || q.x >= p->cols || q.y >= p->rows)
        return 0; /* off the site: no landmark */
    return p->ids[q.y * p->cols + q.x];
}

static int pool_index(const planner *p, int id)
{
    int i;
    for (i = 0; i < p->n_pool; i++)
        if (p->pool[i] == id)
            return i;
    return -1;
}

/* Table key of ordered pair (a at id ia, offset v to b at id ib), and the
 * quarter turns that made v canonical; -1 beyond the view's reach. */
static int key_of(const planner *p, int ia, int ib, pt v, int *k)
{
    pt c = canonical(v, k);
    int a = pool_index(p, ia), b = pool_index(p, ib);
    if (c.x > p->L || c.y > p->L || c.x * c.x + c.y * c.y > p->L * p->L || a < 0 || b < 0)
        return -1;
    return (a * p->n_pool + b) * (p->L + 1) * (p->L + 1) + c.y * (p->L + 1) + c.x;
}

/* Every ordered pair of the site within reach, by key (count, prefix, fill). */
static int build_table(planner *p)
{
    int pass, n = p->cols * p->rows, a, dx, dy;
    memset(p->first, 0, (size_t)(p->n_keys + 1) * sizeof(int));
    for (pass = 0; pass < 2; pass++) {
        for (a = 0; a < n; a++) {
            pt pa = {a % p->cols, a / p->cols};
            for (dy = -p->L; dy <= p->L; dy++)
                for (dx = -p->L; dx <= p->L; dx++) {
                    pt v = {dx, dy}, pb = {pa.x + dx, pa.y + dy};
                    int k, key, ib = id_at(p, pb);
                    if ((dx == 0 && dy == 0) || ib == 0)
                        continue;
                    key = key_of(p, id_at(p, pa), ib, v, &k);
                    if (key < 0)
                        continue;
                    if (pass == 0)
                        p->first[key + 1]++;
                    else
                        p->entry[p->first[key]++] = a * 4 + k;
                }
        }
        if (pass == 0) {
            for (a = 0; a < p->n_keys; a++)
                p->first[a + 1] += p->first[a];
            p->n_entries = p->first[p->n_keys];
            free(p->entry);
            p->entry = malloc((size_t)(p->n_entries > 0 ? p->n_entries : 1) * sizeof(int));
            if (p->entry == NULL)
                return 0;
        }
    }
    for (a = p->n_keys; a > 0; a--)
        p->first[a] = p->first[a - 1];
    p->first[0] = 0;
    return 1;
}

static pt apply(const motion *m, pt x)
{
    pt d = {x.x - m->from.x, x.y - m->from.y}, r = turn(d, m->k);
    pt y = {r.x + m->to.x, r.y + m->to.y};
    return y;
}

/* Landmarks of the view that the motion puts on another id or off the site. */
static int differing(const planner *p, const pt *v, int n, const motion *m, int stop)
{
    int i, d = 0;
    for (i = 0; i < n && d < stop; i++)
        d += id_at(p, apply(m, v[i])) != id_at(p, v[i]);
    return d;
}

/* A new id for q: not id `avoid`, none of its neighbours' within the gap
 * (when any is left). */
static void redraw(planner *p, pt q, int avoid)
{
    int g = (int)floor(p->in->gap / p->in->pitch + 1e-9), ok[256], n = 0, i, dx, dy, relax;
    for (relax = 0; relax < 2 && n == 0; relax++) {
        for (i = 0; i < p->n_pool; i++) {
            int id = p->pool[i], bad = id == avoid || id == id_at(p, q);
            for (dy = -g; dy <= g && !bad && !relax; dy++)
                for (dx = -g; dx <= g && !bad; dx++) {
                    pt r = {q.x + dx, q.y + dy};
                    bad = (dx || dy) && dx * dx + dy * dy <= g * g && id_at(p, r) == id;
                }
            if (!bad)
                ok[n++] = id;
        }
    }
    if (n > 0) {
        p->ids[q.y * p->cols + q.x] = ok[next(p) % (uint64_t)n];
        p->redrawn++;
    }
}

/* Redraw agreeing landmarks until the motion shows two differences. */
static void repair(planner *p, const pt *v, int n, const motion *m)
{
    int i, tries = 0;
    while (differing(p, v, n, m, 2) < 2 && tries++ < 4) {
        int cand[MAX_VIEW], c = 0;
        for (i = 0; i < n; i++) {
            pt y = apply(m, v[i]);
            if ((y.x != v[i].x || y.y != v[i].y) && id_at(p, y) == id_at(p, v[i]))
                cand[c++] = i;
        }
        if (c == 0)
            return;
        i = cand[next(p) % (uint64_t)c];
        redraw(p, v[i], id_at(p, apply(m, v[i])));
    }
}

/* Whether some other placement shows the view with fewer than two
 * differences (and that placement). */
static int ambiguous(const planner *p, const pt *v, int n, motion *bad)
{
    int s, t;
    for (s = 0; s < 3; s++) {
        int a = s == 2 ? 1 : 0, b = s == 0 ? 1 : 2, ka, key, e;
        pt d = {v[b].x - v[a].x, v[b].y - v[a].y};
        key = key_of(p, id_at(p, v[a]), id_at(p, v[b]), d, &ka);
        if (key < 0)
            continue;
        for (e = p->first[key]; e < p->first[key + 1]; e++) {
            int q = p->entry[e] / 4, kq = p->entry[e] % 4;
            motion m;
            m.k = (ka - kq + 8) & 3;
            m.from = v[a];
            m.to.x = q % p->cols;
            m.to.y = q / p->cols;
            if (m.k == 0 && m.to.x == v[a].x && m.to.y == v[a].y)
                continue; /* the view itself */
            t = differing(p, v, n, &m, 2);
            if (t < 2) {
                *bad = m;
                return 1;
            }
        }
    }
    return 0;
}

/* The grid points whose whole landmark a footprint at (cx, cy), heading
 * th, holds. */
static int view_at(const planner *p, double cx, double cy, double th, pt *v)
{
    double fw = 0.5 * (p->in->view_w - p->in->diameter), fh = 0.5 * (p->in->view_h - p->in->diameter);
    double c = cos(th), s = sin(th), hd = hypot(fw, fh), P = p->in->pitch;
    int i0 = (int)ceil((cx - hd - p->x0) / P), i1 = (int)floor((cx + hd - p->x0) / P);
    int j0 = (int)ceil((cy - hd - p->y0) / P), j1 = (int)floor((cy + hd - p->y0) / P), i, j, n = 0;
    i0 = i0 < 0 ? 0 : i0;
    j0 = j0 < 0 ? 0 : j0;
    i1 = i1 >= p->cols ? p->cols - 1 : i1;
    j1 = j1 >= p->rows ? p->rows - 1 : j1;
    for (j = j0; j <= j1; j++)
        for (i = i0; i <= i1; i++) {
            double dx = p->x0 + i * P - cx, dy = p->y0 + j * P - cy;
            if (fabs(c * dx + s * dy) <= fw && fabs(-s * dx + c * dy) <= fh && n < MAX_VIEW) {
                v[n].x = i;
                v[n].y = j;
                n++;
            }
        }
    return n;
}

/* One pass over every view: how many of k or more landmarks are not
 * unique (repaired when `fix`); the largest such size into *worst. */
static long check_round(planner *p, int k, int fix, rl_site_plan_result *out, int *worst)
{
    const rl_site_plan_input *in = p->in;
    double step = in->pitch / 3, th;
    long failing = 0, views = 0;
    int prev_n = -1, h;
    pt v[MAX_VIEW], prev[MAX_VIEW];
    *worst = 0;
    out->smallest_view = MAX_VIEW;
    for (h = 0; h < 24; h++) {
        double cx, cy;
        th = h * M_PI / 24;
        for (cy = in->clearance; cy <= in->height - in->clearance + 1e-9; cy += step)
            for (cx = in->clearance; cx <= in->width - in->clearance + 1e-9; cx += step) {
                motion m;
                int n = view_at(p, cx, cy, th, v);
                if (n < 3 || (n == prev_n && memcmp(v, prev, (size_t)n * sizeof *v) == 0))
                    continue;
                memcpy(prev, v, (size_t)n * sizeof *v);
                prev_n = n;
                views++;
                if (n < out->smallest_view)
                    out->smallest_view = n;
                if (!ambiguous(p, v, n, &m))
                    continue;
                if (n > *worst)
                    *worst = n;
                if (n >= k) {
                    failing++;
                    if (fix)
                        repair(p, v, n, &m);
                }
            }
    }
    out->views = views;
    return failing;
}

/* Random ids, none repeating within the gap of those drawn before. */
static int first_draw(planner *p)
{
    int i, j;
    for (j = 0; j < p->rows; j++)
        for (i = 0; i < p->cols; i++) {
            pt q = {i, j};
            p->ids[j * p->cols + i] = 0;
            redraw(p, q, 0);
            if (p->ids[j * p->cols + i] == 0)
                return 0;
        }
    p->redrawn = 0;
    return 1;
}

static int make_pool(planner *p)
{
    int id;
    p->n_pool = 0;
    for (id = 1; id <= p->in->n_ids && id < 256; id++) {
        int bits = 0, b;
        for (b = 0; b < p->in->bits; b++)
            bits += (id >> b) & 1;
        if (!p->in->even_parity || bits % 2 == 0)
            p->pool[p->n_pool++] = id;
    }
    return p->n_pool >= 2;
}

static rl_err finish(planner *p, rl_site_plan_result *out, rl_err e, clock_t t0)
{
    int seen[256] = {0}, i;
    out->ids_used = 0;
    for (i = 0; i < p->cols * p->rows; i++)
        if (p->ids[i] > 0 && p->ids[i] < 256 && !seen[p->ids[i]]++)
            out->ids_used++;
    out->redrawn = p->redrawn;
    out->seconds = (double)(clock() - t0) / CLOCKS_PER_SEC;
    free(p->first);
    free(p->entry);
    return e;
}

rl_err rl_site_plan(const rl_site_plan_input *in0, int *ids, int max, rl_site_plan_result *out)
{
    rl_site_plan_input in = *in0;
    planner p;
    clock_t t0 = clock();
    int worst = 0, k, *saved;
    double fw, fh;
    memset(out, 0, sizeof *out);
    memset(&p, 0, sizeof p);
    if (!(in.pitch > 0) || !(in.width >= in.pitch) || !(in.height >= in.pitch) || !(in.view_w > in.diameter) ||
        !(in.view_h > in.diameter) || !(in.diameter > 0) || in.n_ids < 2 || in.min_view < 3 ||
        in.max_rounds < 1 || !(in.gap >= 0) || ids == NULL ||
        !(in.clearance >= 0) || !(2 * in.clearance < in.width) || !(2 * in.clearance < in.height))
        return RL_EINVAL;
    if (in.gap == 0)
        in.gap = 2 * in.pitch;
    p.in = &in;
    p.cols = (int)floor(in.width / in.pitch + 1e-9);
    p.rows = (int)floor(in.height / in.pitch + 1e-9);
    out->cols = p.cols;
    out->rows = p.rows;
    if ((long)p.cols * p.rows > max)
        return RL_ENOMEM;
    p.ids = ids;
    p.x0 = 0.5 * (in.width - (p.cols - 1) * in.pitch);
    p.y0 = 0.5 * (in.height - (p.rows - 1) * in.pitch);
    out->x0 = p.x0;
    out->y0 = p.y0;
    p.rng = 0x9E3779B97F4A7C15ull ^ (uint64_t)in.seed * 0x100000001B3ull;
    if (!make_pool(&p))
        return RL_EINVAL;
    fw = in.view_w - in.diameter;
    fh = in.view_h - in.diameter;
    p.L = (int)ceil(hypot(fw, fh) / in.pitch);
    p.n_keys = p.n_pool * p.n_pool * (p.L + 1) * (p.L + 1);
    p.first = malloc((size_t)(p.n_keys + 1) * sizeof(int));
    if (p.first == NULL)
        return finish(&p, out, RL_ENOMEM, t0);
    if (!first_draw(&p))
        return finish(&p, out, RL_ERANGE, t0);
    /* stages: views of STAGE_TOP landmarks or more unique, then one fewer,
     * ... down to min_view; a stage that does not converge in its rounds
     * is undone and the last one that did stands */
    saved = malloc((size_t)p.cols * p.rows * sizeof(int));
    if (saved == NULL)
        return finish(&p, out, RL_ENOMEM, t0);
    for (k = STAGE_TOP; k >= in.min_view; k--) {
        long failing = -1, fewest = -1;
        int r, stale = 0;
        memcpy(saved, ids, (size_t)p.cols * p.rows * sizeof(int));
        /* rounds until none fails, max_rounds, or four rounds without a new fewest */
        for (r = 0; r < in.max_rounds && failing != 0 && stale < 4; r++) {
            if (!build_table(&p)) {
                free(saved);
                return finish(&p, out, RL_ENOMEM, t0);
            }
            failing = check_round(&p, k, 1, out, &worst);
            out->rounds++;
            stale = fewest >= 0 && failing >= fewest ? stale + 1 : 0;
            if (fewest < 0 || failing < fewest)
                fewest = failing;
            if (in.progress)
                in.progress(in.progress_ctx, k, failing);
        }
        if (failing != 0) {
            memcpy(ids, saved, (size_t)p.cols * p.rows * sizeof(int));
            break;
        }
    }
    free(saved);
    /* the figures of the ids kept */
    if (!build_table(&p))
        return finish(&p, out, RL_ENOMEM, t0);
    out->failing = check_round(&p, in.min_view, 0, out, &worst);
    out->k_achieved = worst + 1 < 3 ? 3 : worst + 1;
    return finish(&p, out, out->k_achieved > in.min_view ? RL_ELIMIT : RL_OK, t0);
}
