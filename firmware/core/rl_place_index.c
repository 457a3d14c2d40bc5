#include "rl_place_index.h"

#include <math.h>
#include <string.h>
#include "rl_workspace.h"

#define MAX_INDEXED 65535 /* map indexes are 16 bits */
#define MAX_REACH 60.0    /* distances are 16-bit millimetres */
#define NN_SAMPLES 256

void rl_place_defaults(rl_place_config *cfg)
{
    cfg->reach = 0;
    cfg->gate = 0;
    cfg->min_landmarks = 3;
    cfg->margin = 2;
    cfg->max_speed = 1.5;
    cfg->max_turn = 3.0;
    cfg->track_age = 2.0;
}

/* The map's typical spacing: the median nearest-neighbour distance of up
 * to NN_SAMPLES landmarks spread through it (0 with one landmark). */
static double typical_spacing(const rl_map *map)
{
    double d[NN_SAMPLES];
    int n = map->count < NN_SAMPLES ? map->count : NN_SAMPLES, k, j, m = 0;
    for (k = 0; k < n; k++) {
        int i = (int)((long)k * map->count / n);
        double best = HUGE_VAL;
        for (j = 0; j < map->count; j++) {
            double dx = map->lm[j].x - map->lm[i].x, dy = map->lm[j].y - map->lm[i].y;
            if (j != i && dx * dx + dy * dy < best)
                best = dx * dx + dy * dy;
        }
        if (best < HUGE_VAL) {
            /* insertion into the sorted samples */
            double v = sqrt(best);
            for (j = m++; j > 0 && d[j - 1] > v; j--)
                d[j] = d[j - 1];
            d[j] = v;
        }
    }
    return m > 0 ? d[m / 2] : 0.0;
}

/* Reach, gate and the grid's cell for this map; 0 if the config is bad. */
static int resolve(const rl_map *map, const rl_place_config *in, rl_place_config *cfg, double *cell)
{
    double nn = typical_spacing(map);
    *cfg = *in;
    if (!(cfg->reach >= 0) || !(cfg->gate >= 0) || cfg->min_landmarks < 2 || cfg->margin < 1 ||
        !(cfg->max_speed >= 0) || !(cfg->max_turn >= 0) || !(cfg->track_age >= 0))
        return 0;
    if (cfg->reach == 0)
        cfg->reach = nn > 0 ? 2.05 * nn : 1.0;
    if (cfg->gate == 0)
        cfg->gate = nn > 0 ? fmin(0.15, 0.25 * nn) : 0.15;
    if (cfg->reach > MAX_REACH)
        cfg->reach = MAX_REACH;
    *cell = fmax(nn, 2 * cfg->gate);
    return 1;
}

static void bounds(const rl_map *map, double *x0, double *y0, double *x1, double *y1)
{
    int i;
    *x0 = *y0 = HUGE_VAL;
    *x1 = *y1 = -HUGE_VAL;
    for (i = 0; i < map->count; i++) {
        *x0 = fmin(*x0, map->lm[i].x);
        *y0 = fmin(*y0, map->lm[i].y);
        *x1 = fmax(*x1, map->lm[i].x);
        *y1 = fmax(*y1, map->lm[i].y);
    }
}

/* The grid over the map: cells at least `cell` wide, and no more than
 * about four per landmark however far apart the landmarks are. */
static void grid_shape(const rl_map *map, double cell, rl_place *pl)
{
    double x0, y0, x1, y1, w, h;
    bounds(map, &x0, &y0, &x1, &y1);
    w = x1 - x0;
    h = y1 - y0;
    cell = fmax(cell, sqrt(w * h / (4.0 * map->count + 1)));
    cell = fmax(cell, fmax(w, h) / 4096.0);
    if (!(cell > 0))
        cell = 1.0;
    pl->cell = cell;
    pl->x0 = x0;
    pl->y0 = y0;
    pl->gw = (int)(w / cell) + 1;
    pl->gh = (int)(h / cell) + 1;
}

static int bucket_of(int ia, int ib)
{
    if (ia > ib) {
        int t = ia;
        ia = ib;
        ib = t;
    }
    return (ib - 1) * ib / 2 + (ia - 1);
}

static int indexed(const rl_map *map, double reach, int a, int b)
{
    double dx = map->lm[a].x - map->lm[b].x, dy = map->lm[a].y - map->lm[b].y;
    return fabs(dx) <= reach && fabs(dy) <= reach && dx * dx + dy * dy <= reach * reach;
}

static long count_pairs(const rl_map *map, double reach)
{
    long n = 0;
    int a, b;
    for (a = 0; a < map->count; a++)
        for (b = a + 1; b < map->count; b++)
            n += indexed(map, reach, a, b);
    return n;
}

/* The slices of the index, in order, from ws (sizing or real). */
static rl_err carve(rl_ws *ws, rl_place **pl, int n_ids, long n_pairs, long cells, int count)
{
    rl_err e;
    void *p;
    size_t buckets = (size_t)n_ids * (n_ids + 1) / 2 + 1;
    if ((e = rl_ws_alloc(ws, sizeof(rl_place), RL_WS_ALIGN, &p)) != RL_OK)
        return e;
    *pl = p;
    if ((e = rl_ws_alloc(ws, buckets * sizeof(uint32_t), RL_WS_ALIGN, &p)) != RL_OK)
        return e;
    if (*pl)
        (*pl)->bucket = p;
    if ((e = rl_ws_alloc(ws, (size_t)(n_pairs > 0 ? n_pairs : 1) * sizeof(rl_place_pair), RL_WS_ALIGN, &p)) != RL_OK)
        return e;
    if (*pl)
        (*pl)->pair = p;
    if ((e = rl_ws_alloc(ws, (size_t)(cells + 1) * sizeof(uint16_t), RL_WS_ALIGN, &p)) != RL_OK)
        return e;
    if (*pl)
        (*pl)->cell_first = p;
    if ((e = rl_ws_alloc(ws, (size_t)(count > 0 ? count : 1) * sizeof(uint16_t), RL_WS_ALIGN, &p)) != RL_OK)
        return e;
    if (*pl)
        (*pl)->cell_lm = p;
    return RL_OK;
}

/* Shape of the index: config resolved, grid, pair count; 0 if refused. */
static int shape(const rl_map *map, const rl_place_config *cfg, rl_place *pl)
{
    double cell;
    int bad;
    if (map == NULL || cfg == NULL || rl_map_check(map, &bad) != RL_OK || map->count > MAX_INDEXED ||
        map->count < 1 || !resolve(map, cfg, &pl->cfg, &cell))
        return 0;
    grid_shape(map, cell, pl);
    pl->n_ids = rl_family_count(&map->family);
    pl->n_pairs = count_pairs(map, pl->cfg.reach);
    pl->map = map;
    return 1;
}

size_t rl_place_size(const rl_map *map, const rl_place_config *cfg)
{
    rl_place s, *pl;
    rl_ws ws;
    if (!shape(map, cfg, &s))
        return 0;
    rl_ws_init_sizing(&ws);
    if (carve(&ws, &pl, s.n_ids, s.n_pairs, (long)s.gw * s.gh, map->count) != RL_OK)
        return 0;
    return ws.peak + RL_WS_ALIGN; /* mem may be unaligned */
}

static int cell_of(const rl_place *pl, double x, double y)
{
    int i = (int)floor((x - pl->x0) / pl->cell), j = (int)floor((y - pl->y0) / pl->cell);
    i = i < 0 ? 0 : i >= pl->gw ? pl->gw - 1 : i;
    j = j < 0 ? 0 : j >= pl->gh ? pl->gh - 1 : j;
    return j * pl->gw + i;
}

/* Landmarks by cell: count, prefix sum, fill. */
static void fill_grid(rl_place *pl)
{
    const rl_map *map = pl->map;
    int cells = pl->gw * pl->gh, i;
    memset(pl->cell_first, 0, (size_t)(cells + 1) * sizeof(uint16_t));
    for (i = 0; i < map->count; i++)
        pl->cell_first[cell_of(pl, map->lm[i].x, map->lm[i].y) + 1]++;
    for (i = 0; i < cells; i++)
        pl->cell_first[i + 1] = (uint16_t)(pl->cell_first[i + 1] + pl->cell_first[i]);
    /* cell_first[c] is a cursor while filling, then moved back */
    for (i = 0; i < map->count; i++) {
        int c = cell_of(pl, map->lm[i].x, map->lm[i].y);
        pl->cell_lm[pl->cell_first[c]++] = (uint16_t)i;
    }
    for (i = cells; i > 0; i--)
        pl->cell_first[i] = pl->cell_first[i - 1];
    pl->cell_first[0] = 0;
}

/* Heap sort of a bucket's pairs by distance. */
static void sift(rl_place_pair *p, long root, long n)
{
    for (;;) {
        long c = 2 * root + 1;
        rl_place_pair t;
        if (c >= n)
            return;
        if (c + 1 < n && p[c + 1].d_mm > p[c].d_mm)
            c++;
        if (p[root].d_mm >= p[c].d_mm)
            return;
        t = p[root];
        p[root] = p[c];
        p[c] = t;
        root = c;
    }
}

static void sort_by_distance(rl_place_pair *p, long n)
{
    long i;
    for (i = n / 2 - 1; i >= 0; i--)
        sift(p, i, n);
    for (i = n - 1; i > 0; i--) {
        rl_place_pair t = p[0];
        p[0] = p[i];
        p[i] = t;
        sift(p, 0, i);
    }
}

/* Each indexed pair once (a < b), handed to `put`. */
static void each_pair(rl_place *pl, int fill)
{
    const rl_map *map = pl->map;
    int a, r = (int)ceil(pl->cfg.reach / pl->cell);
    for (a = 0; a < map->count; a++) {
        int ci = (int)floor((map->lm[a].x - pl->x0) / pl->cell), cj = (int)floor((map->lm[a].y - pl->y0) / pl->cell);
        int i, j, k;
        for (j = cj - r; j <= cj + r; j++)
            for (i = ci - r; i <= ci + r; i++) {
                int c;
                if (i < 0 || j < 0 || i >= pl->gw || j >= pl->gh)
                    continue;
                c = j * pl->gw + i;
                for (k = pl->cell_first[c]; k < pl->cell_first[c + 1]; k++) {
                    int b = pl->cell_lm[k], ia = map->lm[a].id, ib = map->lm[b].id, q;
                    if (b <= a || !indexed(map, pl->cfg.reach, a, b))
                        continue;
                    q = bucket_of(ia, ib);
                    if (!fill) {
                        pl->bucket[q + 1]++;
                    } else {
                        rl_place_pair *p = &pl->pair[pl->bucket[q]++];
                        int lo = ia <= ib ? a : b;
                        p->a = (uint16_t)lo;
                        p->b = (uint16_t)(lo == a ? b : a);
                        p->d_mm = (uint16_t)lround(1000.0 * hypot(map->lm[a].x - map->lm[b].x,
                                                                   map->lm[a].y - map->lm[b].y));
                    }
                }
            }
    }
}

static void fill_pairs(rl_place *pl)
{
    long nb = (long)pl->n_ids * (pl->n_ids + 1) / 2, q;
    memset(pl->bucket, 0, (size_t)(nb + 1) * sizeof(uint32_t));
    each_pair(pl, 0);
    for (q = 0; q < nb; q++)
        pl->bucket[q + 1] += pl->bucket[q];
    each_pair(pl, 1); /* bucket[q] ends at the next bucket's start */
    for (q = nb; q > 0; q--)
        pl->bucket[q] = pl->bucket[q - 1];
    pl->bucket[0] = 0;
    for (q = 0; q < nb; q++)
        sort_by_distance(pl->pair + pl->bucket[q], (long)(pl->bucket[q + 1] - pl->bucket[q]));
}

rl_err rl_place_init(rl_place **out, const rl_map *map, const rl_place_config *cfg, void *mem, size_t size)
{
    rl_place s, *pl;
    rl_ws ws;
    rl_err e;
    size_t need;
    int i;
    if (out == NULL || mem == NULL)
        return RL_EINVAL;
    *out = NULL;
    if ((need = rl_place_size(map, cfg)) == 0 || !shape(map, cfg, &s))
        return RL_EINVAL;
    if (size < need)
        return RL_ENOMEM;
    rl_ws_init(&ws, mem, size);
    if ((e = carve(&ws, &pl, s.n_ids, s.n_pairs, (long)s.gw * s.gh, map->count)) != RL_OK)
        return e;
    s.bucket = pl->bucket;
    s.pair = pl->pair;
    s.cell_first = pl->cell_first;
    s.cell_lm = pl->cell_lm;
    s.bytes = need;
    *pl = s;
    pl->z_lo = pl->z_hi = map->ceiling_height;
    for (i = 0; i < map->count; i++) {
        pl->z_lo = fmin(pl->z_lo, rl_map_height(map, i));
        pl->z_hi = fmax(pl->z_hi, rl_map_height(map, i));
    }
    fill_grid(pl);
    fill_pairs(pl);
    *out = pl;
    return RL_OK;
}

size_t rl_place_bytes(const rl_place *pl)
{
    return pl->bytes;
}

long rl_place_pairs(const rl_place *pl)
{
    return pl->n_pairs;
}

void rl_place_index_pairs(const rl_place *pl, int ia, int ib, double lo, double hi, const rl_place_pair **first,
                          const rl_place_pair **end)
{
    const rl_place_pair *p, *e;
    long l, h;
    double lo_mm = 1000.0 * lo, hi_mm = 1000.0 * hi;
    *first = *end = pl->pair;
    if (ia < 1 || ib < 1 || ia > pl->n_ids || ib > pl->n_ids || !(hi >= lo))
        return;
    p = pl->pair + pl->bucket[bucket_of(ia, ib)];
    e = pl->pair + pl->bucket[bucket_of(ia, ib) + 1];
    /* first pair at lo or beyond */
    l = 0;
    h = e - p;
    while (l < h) {
        long m = (l + h) / 2;
        if (p[m].d_mm < lo_mm)
            l = m + 1;
        else
            h = m;
    }
    *first = p + l;
    for (*end = *first; *end < e && (*end)->d_mm <= hi_mm; (*end)++)
        ;
}

/* The grid cells that (x, y) +- r covers, clipped; 0 if none. */
static int cell_range(const rl_place *pl, double x, double y, double r, int *i0, int *i1, int *j0, int *j1)
{
    if (!(fabs(x) < 4 * RL_MAP_MAX_COORD) || !(fabs(y) < 4 * RL_MAP_MAX_COORD) || !(r >= 0) ||
        !(r < 4 * RL_MAP_MAX_COORD))
        return 0;
    *i0 = (int)floor((x - r - pl->x0) / pl->cell);
    *i1 = (int)floor((x + r - pl->x0) / pl->cell);
    *j0 = (int)floor((y - r - pl->y0) / pl->cell);
    *j1 = (int)floor((y + r - pl->y0) / pl->cell);
    *i0 = *i0 < 0 ? 0 : *i0;
    *j0 = *j0 < 0 ? 0 : *j0;
    *i1 = *i1 >= pl->gw ? pl->gw - 1 : *i1;
    *j1 = *j1 >= pl->gh ? pl->gh - 1 : *j1;
    return *i0 <= *i1 && *j0 <= *j1;
}

int rl_place_index_near(const rl_place *pl, double x, double y, double r, int id)
{
    const rl_map *map = pl->map;
    int i0, i1, j0, j1, i, j, k, best = -1;
    double best_d2 = r * r;
    if (!cell_range(pl, x, y, r, &i0, &i1, &j0, &j1))
        return -1;
    for (j = j0; j <= j1; j++)
        for (i = i0; i <= i1; i++) {
            int c = j * pl->gw + i;
            for (k = pl->cell_first[c]; k < pl->cell_first[c + 1]; k++) {
                const rl_map_landmark *lm = &map->lm[pl->cell_lm[k]];
                double dx = lm->x - x, dy = lm->y - y, d2 = dx * dx + dy * dy;
                if (d2 <= best_d2 && (id == 0 || lm->id == id)) {
                    best_d2 = d2;
                    best = pl->cell_lm[k];
                }
            }
        }
    return best;
}

int rl_place_index_within(const rl_place *pl, double x, double y, double r, int id, int *out, int max)
{
    const rl_map *map = pl->map;
    int i0, i1, j0, j1, i, j, k, n = 0;
    if (!cell_range(pl, x, y, r, &i0, &i1, &j0, &j1))
        return 0;
    for (j = j0; j <= j1; j++)
        for (i = i0; i <= i1; i++) {
            int c = j * pl->gw + i;
            for (k = pl->cell_first[c]; k < pl->cell_first[c + 1]; k++) {
                const rl_map_landmark *lm = &map->lm[pl->cell_lm[k]];
                double dx = lm->x - x, dy = lm->y - y;
                if (lm->id == id && dx * dx + dy * dy <= r * r) {
                    if (n < max)
                        out[n] = pl->cell_lm[k];
                    n++;
                }
            }
        }
    return n;
}
