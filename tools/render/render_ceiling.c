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

static double tile_pattern(const render_scene *s, double X, double Y)
{
    double u = (X - s->tile_px) / s->tile, v = (Y - s->tile_py) / s->tile;
    double fu = (u - floor(u)) * s->tile, fv = (v - floor(v)) * s->tile;
    double bar = 0.012; /* half of a 24 mm T-bar */
    double du = fmin(fu, s->tile - fu), dv = fmin(fv, s->tile - fv);
    if (du < bar || dv < bar)
        return TBAR;
    if (du < bar + 0.003 || dv < bar + 0.003)
        return 0.55; /* the shadow line along the bar */
    /* fissured mineral tile: fine noise and a few darker pits */
    return TILE + 0.05 * (render_random_vnoise(X * 90, Y * 90) - 0.5) + 0.03 * (render_random_vnoise(X * 20, Y * 20) - 0.5) -
           (render_random_vnoise(X * 300, Y * 300) > 0.93 ? 0.15 : 0.0);
}

/* The ceiling as bright as the scene says (darker or lighter than paper). */
static double tile_radiance(const render_scene *s, double X, double Y)
{
    return s->ceiling * tile_pattern(s, X, Y);
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
double render_ceiling_light_gap(const render_object *o, double X, double Y)
{
    double c = o->cr, s = o->sr, dx = X - o->x, dy = Y - o->y;
    double lx = fabs(c * dx + s * dy) - o->a, ly = fabs(-s * dx + c * dy) - o->b;
    lx = lx > 0 ? lx : 0;
    ly = ly > 0 ? ly : 0;
    return sqrt(lx * lx + ly * ly);
}

double render_ceiling_radiance(const render_scene *s, const render_grid *g, double X, double Y)
{
    double v = -1, halo = 0;
    int gx = (int)floor((X - g->x0) / RENDER_GRID_CELL), gy = (int)floor((Y - g->y0) / RENDER_GRID_CELL), k, k0, k1;
    int all = gx < 0 || gy < 0 || gx >= g->nx || gy >= g->ny;
    k0 = all ? 0 : g->start[gy * g->nx + gx];
    k1 = all ? s->n : g->start[gy * g->nx + gx + 1];
    /* objects later in the list lie on top */
    for (k = k0; k < k1; k++) {
        const render_object *o = &s->obj[all ? k : g->idx[k]];
        double dx = X - o->x, dy = Y - o->y, reach = o->a > o->b ? o->a : o->b;
        double r;
        if (o->drop > 0)
            continue; /* hangs below the ceiling: render_ceiling_object */
        if ((o->kind == RENDER_OBJ_LIGHT || o->kind == RENDER_OBJ_DOWNLIGHT) &&
            fabs(dx) < reach + 8 * s->halo_sigma && fabs(dy) < reach + 8 * s->halo_sigma) {
            double gap = o->kind == RENDER_OBJ_LIGHT ? render_ceiling_light_gap(o, X, Y) : fmax(0, sqrt(dx * dx + dy * dy) - 0.8 * o->a);
            halo += s->halo_amp * exp(-gap / s->halo_sigma) * (o->kind == RENDER_OBJ_LIGHT ? 1.0 : 0.4);
        }
        if (fabs(dx) > reach * 1.5 || fabs(dy) > reach * 1.5)
            continue;
        r = object_radiance(s, o, o->cr * dx + o->sr * dy, -o->sr * dx + o->cr * dy);
        if (r >= 0)
            v = r;
    }
    /* the tile only where no object covers it */
    return (v >= 0 ? v : tile_radiance(s, X, Y)) + halo;
}

double render_ceiling_object(const render_scene *s, const render_object *o, double X, double Y)
{
    double dx = X - o->x, dy = Y - o->y;
    return object_radiance(s, o, o->cr * dx + o->sr * dy, -o->sr * dx + o->cr * dy);
}

/* The grid cells an object's reach (1.5 times its size, a light's halo)
 * touches, clipped to the grid. */
static void object_cells(const render_scene *s, const render_grid *g, const render_object *o, int *x0, int *x1, int *y0, int *y1)
{
    double reach = o->a > o->b ? o->a : o->b, e = reach * 1.5;
    if (o->kind == RENDER_OBJ_LIGHT || o->kind == RENDER_OBJ_DOWNLIGHT)
        e = fmax(e, reach + 8 * s->halo_sigma);
    e += 1e-9;
    *x0 = (int)fmax(0, floor((o->x - e - g->x0) / RENDER_GRID_CELL));
    *x1 = (int)fmin(g->nx - 1, floor((o->x + e - g->x0) / RENDER_GRID_CELL));
    *y0 = (int)fmax(0, floor((o->y - e - g->y0) / RENDER_GRID_CELL));
    *y1 = (int)fmin(g->ny - 1, floor((o->y + e - g->y0) / RENDER_GRID_CELL));
}

int render_ceiling_grid(const render_scene *s, const double *b, double m, render_grid *g)
{
    static int fill[RENDER_GRID_MAX * RENDER_GRID_MAX];
    int i, cx, cy, pass;
    g->x0 = b[0] - m;
    g->y0 = b[1] - m;
    g->nx = (int)ceil((b[2] + m - g->x0) / RENDER_GRID_CELL);
    g->ny = (int)ceil((b[3] + m - g->y0) / RENDER_GRID_CELL);
    g->idx = NULL;
    if (!(g->nx > 0 && g->ny > 0 && g->nx <= RENDER_GRID_MAX && g->ny <= RENDER_GRID_MAX)) {
        g->nx = g->ny = 0; /* every sample looks at every object */
        return 0;
    }
    /* each object into the cells its reach touches: counted, then filled
     * in the scene's order */
    memset(g->start, 0, sizeof(int) * (size_t)(g->nx * g->ny + 1));
    for (pass = 0; pass < 2; pass++) {
        for (i = 0; i < s->n; i++) {
            int x0, x1, y0, y1;
            object_cells(s, g, &s->obj[i], &x0, &x1, &y0, &y1);
            for (cy = y0; cy <= y1; cy++)
                for (cx = x0; cx <= x1; cx++) {
                    int c = cy * g->nx + cx;
                    if (pass == 0)
                        g->start[c + 1]++;
                    else
                        g->idx[fill[c]++] = i;
                }
        }
        if (pass == 0) {
            for (i = 0; i < g->nx * g->ny; i++)
                g->start[i + 1] += g->start[i];
            memcpy(fill, g->start, sizeof(int) * (size_t)(g->nx * g->ny));
            if ((g->idx = malloc(sizeof(int) * (size_t)(g->start[g->nx * g->ny] + 1))) == NULL)
                return -1;
        }
    }
    return 0;
}
