/* render_ceiling: the ceiling's radiance (render_ceiling.h). */
#include "render_ceiling.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>
#include "render_random.h"

/* radiances: 1 is the paper near the white point */
#define PAPER 0.86
#define TILE 0.70
#define TBAR 0.80
#define LIGHT 6.0
/* the tiles' value noise, lattice cells per metre: their shading, their
 * fissures and their pits (render_grid's coarse, fine, pits) */
#define COARSE 20
#define FINE 90
#define PITS 300

static apriltag_family_t *tagfam;
static image_u8_t *tag_images[32];

int render_ceiling_tags_open(void)
{
    int i;
    if ((tagfam = tag36h11_create()) == NULL)
        return -1;
    for (i = 0; i < 32; i++)
        tag_images[i] = apriltag_to_image(tagfam, i);
    return 0;
}

void render_ceiling_tags_close(void)
{
    tag36h11_destroy(tagfam);
    tagfam = NULL;
}

/* floor(u), as floor gives it: the truncation moved down below 0, where
 * it fits an int */
static double floor_of(double u)
{
    double f;
    if (!(fabs(u) < 1e9))
        return floor(u);
    f = (int)u;
    return f > u ? f - 1 : f;
}

static double tile_pattern(const render_scene *s, const render_grid *g, double X, double Y)
{
    double u = (X - s->tile_px) / s->tile, v = (Y - s->tile_py) / s->tile;
    double fu = (u - floor_of(u)) * s->tile, fv = (v - floor_of(v)) * s->tile;
    double bar = 0.012; /* half of a 24 mm T-bar */
    /* fmin's (neither is NaN, and no zeros of both signs: fu >= 0, tile - fu > 0) */
    double du = fu < s->tile - fu ? fu : s->tile - fu, dv = fv < s->tile - fv ? fv : s->tile - fv;
    if (du < bar || dv < bar)
        return TBAR;
    if (du < bar + 0.003 || dv < bar + 0.003)
        return 0.55; /* the shadow line along the bar */
    /* fissured mineral tile: fine noise and a few darker pits */
    return TILE + 0.05 * (render_random_vnoise_in(&g->fine, X * FINE, Y * FINE) - 0.5) +
           0.03 * (render_random_vnoise_in(&g->coarse, X * COARSE, Y * COARSE) - 0.5) -
           (render_random_vnoise_over(&g->pits, X * PITS, Y * PITS, 0.93) ? 0.15 : 0.0);
}

/* The ceiling as bright as the scene says (darker or lighter than paper). */
static double tile_radiance(const render_scene *s, const render_grid *g, double X, double Y)
{
    return s->ceiling * tile_pattern(s, g, X, Y);
}

/* Radiance of an object at local coordinates (lx, ly), or -1 if outside. */
static double object_radiance(const render_scene *s, const render_object *o, double lx, double ly)
{
    double r = sqrt(lx * lx + ly * ly);
    switch (o->kind) {
    case RENDER_OBJ_PAPER:
        return fabs(lx) <= o->a && fabs(ly) <= o->b ? PAPER : -1;
    case RENDER_OBJ_LANDMARK:
        if (!s->twin) {
            if (r > o->a)
                return -1;
            return rl_family_dark_at(&s->fam, o->id, r / o->a) ? s->ink : PAPER;
        } else {
            /* tag36h11: 10 x 10 cells, black border 8 cells = D */
            double cell = 2 * o->a / 8.0;
            int ci = (int)floor(lx / cell + 5), cj = (int)floor(ly / cell + 5);
            image_u8_t *im = tag_images[o->id % 32];
            if (ci < 0 || cj < 0 || ci >= 10 || cj >= 10)
                return -1;
            return im->buf[cj * im->stride + ci] < 128 ? s->ink : PAPER;
        }
    case RENDER_OBJ_SMOKE: /* white disk, grey ring, LED */
        if (r > o->a) return -1;
        if (r < 0.004) return 0.10;
        if (r > 0.75 * o->a && r < 0.82 * o->a) return 0.45;
        return 0.82;
    case RENDER_OBJ_DOWNLIGHT: /* dark trim around a lamp */
        if (r > o->a) return -1;
        if (r > 0.8 * o->a) return 0.22;
        return LIGHT;
    case RENDER_OBJ_SPRINKLER:
        if (r > o->a) return -1;
        if (r < 0.45 * o->a) return 0.12;
        if (r > 0.85 * o->a) return 0.30;
        return 0.65;
    case RENDER_OBJ_VENT: /* square grille of dark slots */
        if (fabs(lx) > o->a || fabs(ly) > o->a) return -1;
        if (fabs(lx) > 0.9 * o->a || fabs(ly) > 0.9 * o->a) return 0.60;
        return fmod(fabs(lx) + 10, 0.02) < 0.008 ? 0.10 : 0.50;
    case RENDER_OBJ_SPEAKER: /* round grille: concentric dark rings, ring-like clutter */
        if (r > o->a) return -1;
        if (r > 0.93 * o->a) return 0.12;
        if (fmod(r, 0.018) < 0.006) return 0.18;
        return 0.48 + 0.1 * (render_random_vnoise(lx * 400, ly * 400) - 0.5);
    case RENDER_OBJ_BOX:
        if (fabs(lx) > o->a || fabs(ly) > o->b) return -1;
        if (fabs(lx) > o->a - 0.006 || fabs(ly) > o->b - 0.006) return 0.08;
        return 0.30;
    case RENDER_OBJ_EXIT:
        if (fabs(lx) > o->a || fabs(ly) > o->b) return -1;
        return fabs(ly) < 0.3 * o->b && fabs(lx) < 0.7 * o->a ? 0.9 : 1.6;
    case RENDER_OBJ_LIGHT:
        if (fabs(lx) > o->a || fabs(ly) > o->b) return -1;
        if (fabs(lx) > o->a - 0.02 || fabs(ly) > o->b - 0.02) return 0.85; /* frame */
        return LIGHT;
    }
    return -1;
}

/* Gap from a point to a light's rectangle (0 inside). */
static double light_gap(const render_object *o, double X, double Y)
{
    double c = o->cr, s = o->sr, dx = X - o->x, dy = Y - o->y;
    double lx = fabs(c * dx + s * dy) - o->a, ly = fabs(-s * dx + c * dy) - o->b;
    lx = lx > 0 ? lx : 0;
    ly = ly > 0 ? ly : 0;
    return sqrt(lx * lx + ly * ly);
}

double render_ceiling_light_gap(const render_object *o, double X, double Y)
{
    return light_gap(o, X, Y);
}

/* The cell of the grid (X, Y) falls in; outside it, the cell that lists
 * every object. */
static int cell_at(const render_grid *g, double X, double Y)
{
    double u = (X - g->x0) * (1.0 / RENDER_GRID_CELL), v = (Y - g->y0) * (1.0 / RENDER_GRID_CELL);
    if (u >= 0 && v >= 0 && u < g->nx && v < g->ny)
        return (int)v * g->nx + (int)u;
    return g->nx * g->ny;
}

/* The halo at (X, Y): the lights of cell c, in the scene's order. */
static double halo_at(const render_scene *s, const render_grid *g, int c, double X, double Y)
{
    double halo = 0;
    int k;
    for (k = g->glow[c]; k < g->glow[c + 1]; k++) {
        const render_grid_entry *e = &g->at[k];
        double dx = X - e->x, dy = Y - e->y;
        if (fabs(dx) < e->reach && fabs(dy) < e->reach) {
            const render_object *o = e->o;
            double gap = o->kind == RENDER_OBJ_LIGHT ? light_gap(o, X, Y) : fmax(0, sqrt(dx * dx + dy * dy) - 0.8 * o->a);
            /* exp(-0) is 1 */
            halo += s->halo_amp * (gap > 0 ? exp(-gap / s->halo_sigma) : 1.0) * (o->kind == RENDER_OBJ_LIGHT ? 1.0 : 0.4);
        }
    }
    return halo;
}

double render_ceiling_radiance(const render_scene *s, const render_grid *g, double X, double Y)
{
    int c = cell_at(g, X, Y), k;
    double halo = halo_at(s, g, c, X, Y);
    /* objects later in the list lie on top: the last that covers the point */
    for (k = g->cover[c + 1] - 1; k >= g->cover[c]; k--) {
        const render_grid_entry *e = &g->at[k];
        const render_object *o = e->o;
        double dx = X - e->x, dy = Y - e->y, r;
        if (fabs(dx) > e->reach || fabs(dy) > e->reach)
            continue;
        r = object_radiance(s, o, o->cr * dx + o->sr * dy, -o->sr * dx + o->cr * dy);
        if (r >= 0)
            return r + halo;
    }
    /* the tile only where no object covers it */
    return tile_radiance(s, g, X, Y) + halo;
}

double render_ceiling_object(const render_scene *s, const render_object *o, double X, double Y)
{
    double dx = X - o->x, dy = Y - o->y;
    return object_radiance(s, o, o->cr * dx + o->sr * dy, -o->sr * dx + o->cr * dy);
}

/* The cells within e of (x, y) (a square), clipped to the grid, into
 * r[4] (x0, x1, y0, y1; none where x0 > x1 or y0 > y1). A sample's cell
 * (cell_at) rounds differently: e is widened by far more than that. */
static void cells_near(const render_grid *g, double x, double y, double e, int *r)
{
    e += 1e-6;
    r[0] = (int)fmax(0, floor((x - e - g->x0) * (1.0 / RENDER_GRID_CELL)));
    r[1] = (int)fmin(g->nx - 1, floor((x + e - g->x0) * (1.0 / RENDER_GRID_CELL)));
    r[2] = (int)fmax(0, floor((y - e - g->y0) * (1.0 / RENDER_GRID_CELL)));
    r[3] = (int)fmin(g->ny - 1, floor((y + e - g->y0) * (1.0 / RENDER_GRID_CELL)));
}

/* Object o, reaching e, counted in the cells of one list (start: cover
 * or glow) within e of it and in the cell outside the grid: start[c + 1]
 * counts cell c's entries. */
static void count_object(const render_grid *g, const render_object *o, double e, int *start)
{
    int r[4], cx, cy, out = g->nx * g->ny;
    cells_near(g, o->x, o->y, e, r);
    for (cy = r[2]; cy <= r[3]; cy++)
        for (cx = r[0]; cx <= r[1]; cx++)
            start[cy * g->nx + cx + 1]++;
    start[out + 1]++;
}

/* Object o, reaching e, written into the same cells as count_object's,
 * each at the cell's next free place in g->at, next[c] (moved on). */
static void place_object(render_grid *g, const render_object *o, double e, int *next)
{
    int r[4], cx, cy, out = g->nx * g->ny;
    render_grid_entry en;
    en.x = o->x;
    en.y = o->y;
    en.reach = e;
    en.o = o;
    cells_near(g, o->x, o->y, e, r);
    for (cy = r[2]; cy <= r[3]; cy++)
        for (cx = r[0]; cx <= r[1]; cx++)
            g->at[next[cy * g->nx + cx]++] = en;
    g->at[next[out]++] = en;
}

/* How far object o reaches on the ceiling (1.5 times its size), and a
 * light's halo (glow, else -1): 0, or -1 where it hangs below the ceiling
 * (render_ceiling_object) and is listed nowhere. */
static int object_reach(const render_scene *s, const render_object *o, double *cover, double *glow)
{
    double reach = o->a > o->b ? o->a : o->b;
    if (o->drop > 0)
        return -1;
    *cover = reach * 1.5;
    *glow = o->kind == RENDER_OBJ_LIGHT || o->kind == RENDER_OBJ_DOWNLIGHT ? reach + 8 * s->halo_sigma : -1;
    return 0;
}

/* The cells' lists, in the scene's order: every object on the ceiling
 * in the cells it can cover and every light in those its halo can reach,
 * counted, their places in g->at laid out (the covers, then the glows)
 * and written. g->cover and g->glow are the write positions while they
 * are written (each cell's moves to its end, the next cell's start), then
 * moved up a cell back to the starts: no scratch. 0, or -1 out of memory. */
static int list_objects(const render_scene *s, render_grid *g)
{
    int i, n = g->nx * g->ny + 1;
    double cover, glow;
    memset(g->cover, 0, sizeof(int) * (size_t)(n + 1));
    memset(g->glow, 0, sizeof(int) * (size_t)(n + 1));
    for (i = 0; i < s->n; i++)
        if (object_reach(s, &s->obj[i], &cover, &glow) == 0) {
            count_object(g, &s->obj[i], cover, g->cover);
            if (glow >= 0)
                count_object(g, &s->obj[i], glow, g->glow);
        }
    for (i = 0; i < n; i++)
        g->cover[i + 1] += g->cover[i];
    g->glow[0] = g->cover[n];
    for (i = 0; i < n; i++)
        g->glow[i + 1] += g->glow[i];
    if ((g->at = malloc(sizeof *g->at * (size_t)(g->glow[n] + 1))) == NULL)
        return -1;
    for (i = 0; i < s->n; i++)
        if (object_reach(s, &s->obj[i], &cover, &glow) == 0) {
            place_object(g, &s->obj[i], cover, g->cover);
            if (glow >= 0)
                place_object(g, &s->obj[i], glow, g->glow);
        }
    /* cover[c] is now cell c's end, cover[c + 1]'s start; the covers end
     * where the glows start */
    memmove(g->cover + 1, g->cover, sizeof(int) * (size_t)n);
    g->cover[0] = 0;
    memmove(g->glow + 1, g->glow, sizeof(int) * (size_t)n);
    g->glow[0] = g->cover[n];
    return 0;
}

/* One of the tiles' noise lattices over the grid, at scale k (cells per
 * metre); none without a grid (every look-up hashes: a frame's table is
 * not left over the last frame's view): 0, or -1 out of memory. */
static int noise_table(const render_grid *g, double k, render_noise *t)
{
    double x1 = g->x0 + g->nx * RENDER_GRID_CELL, y1 = g->y0 + g->ny * RENDER_GRID_CELL;
    if (g->nx == 0) {
        render_random_noise_free(t);
        return 0;
    }
    return render_random_noise_make(t, g->x0 * k, g->y0 * k, x1 * k, y1 * k);
}

/* The grid's cells over view b widened by m (none where it would be
 * too large: every sample in the cell outside it). */
static void grid_cells(const double *b, double m, render_grid *g)
{
    g->x0 = b[0] - m;
    g->y0 = b[1] - m;
    g->nx = (int)ceil((b[2] + m - g->x0) / RENDER_GRID_CELL);
    g->ny = (int)ceil((b[3] + m - g->y0) / RENDER_GRID_CELL);
    if (!(g->nx > 0 && g->ny > 0 && g->nx <= RENDER_GRID_MAX && g->ny <= RENDER_GRID_MAX))
        g->nx = g->ny = 0;
}

int render_ceiling_grid(const render_scene *s, const double *b, double m, render_grid *g)
{
    free(g->at);
    g->at = NULL;
    grid_cells(b, m, g);
    if (list_objects(s, g) != 0 || noise_table(g, COARSE, &g->coarse) != 0 || noise_table(g, FINE, &g->fine) != 0 ||
        noise_table(g, PITS, &g->pits) != 0) {
        render_ceiling_grid_free(g);
        return -1;
    }
    return 0;
}

void render_ceiling_grid_free(render_grid *g)
{
    render_random_noise_free(&g->coarse);
    render_random_noise_free(&g->fine);
    render_random_noise_free(&g->pits);
    free(g->at);
    g->at = NULL;
}
