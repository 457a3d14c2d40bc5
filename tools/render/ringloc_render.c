/* ringloc-render: fixtures that know the truth.
 *
 * Ray-casts an upward-looking camera (pinhole + plumb_bob, the core's own
 * rl_calib model) onto a ceiling plane: tiles and T-bars, light fixtures
 * that saturate and wash out their surroundings, clutter (smoke detectors,
 * downlights, sprinklers, vents, round speaker grilles, boxes, exit signs),
 * landmarks printed per shared/landmark-spec.md on paper, and camera
 * effects (vignetting, exposure, blur, motion blur, noise). Writes each
 * frame as PNG with a ground-truth YAML: the camera and robot pose and,
 * for every landmark, id, projected centre, radius, visible fraction and
 * gap to the nearest light. With --twin it renders the same scene with
 * AprilTag 36h11 tags of the same size at the same places.
 *
 * Host tool: allocates freely, uses libapriltag for the tags' bit patterns.
 */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>
#include "rl_cli.h"
#include "rl_calib.h"
#include "rl_calibfile.h"
#include "rl_family.h"
#include "rl_mapfile.h"
#include "rl_outfile.h"
#include "rl_png.h"
#include "rl_robotfile.h"
#include "render_sensor.h"
#include "rl_print.h"
#include "render_tour.h"

#define MAX_OBJ 512
#define SUB 3 /* subsamples per pixel axis */

typedef enum {
    OBJ_PAPER, OBJ_LANDMARK, OBJ_SMOKE, OBJ_DOWNLIGHT, OBJ_SPRINKLER, OBJ_VENT, OBJ_SPEAKER,
    OBJ_BOX, OBJ_EXIT, OBJ_LIGHT
} obj_kind;

typedef struct {
    obj_kind kind;
    double x, y, rot; /* centre in the map frame, rotation */
    double a, b;      /* radius, or half extents */
    int id;           /* landmark id */
} object;

typedef struct {
    rl_calib cam;
    rl_family fam;
    double diameter;       /* landmark D, m */
    double distance;       /* camera to ceiling, m */
    double ceiling_height; /* for the map, m */
    double cam_z;          /* camera above floor, m */
    double tile, tile_px, tile_py; /* tile pitch and phase */
    double cx, cy, yaw;    /* camera optical centre and heading (image top) in the map */
    double cz;             /* camera optical centre above the floor (the mount's z, rocked) */
    double R[9];           /* camera (forward, left, up) to map, row-major */
    double roll, pitch;    /* the camera's tilt from vertical (its own x and y axes) */
    double motion, motion_dir; /* motion blur: camera travel during exposure, m */
    double motion_turn;        /* motion blur: the camera's turn during exposure, rad */
    double halo_amp, halo_sigma;
    double gain, vignette;     /* exposure (1: the paper near the white point), vignetting */
    render_sensor se;          /* optics' blur, sensor, tone curve */
    double sheet_w, sheet_h;   /* the landmarks' sheet, m (0: as wide as the landmark, A4's ratio) */
    double ceiling;            /* the ceiling's brightness, times the default tile's */
    double ink;                /* the landmarks' ink radiance (INK: black; more: grey) */
    double ramp, ramp_dir;     /* light falling off across the frame: fraction, direction */
    double shadow, shadow_at, shadow_dir; /* a shadow (a wall beside the ceiling): depth, edge, side */
    int twin;
    int n;
    object obj[MAX_OBJ];
} scene;

/* ---- random numbers (xorshift64*, reproducible across machines) ---- */
static uint64_t rng_state = 88172645463325252ull;
static uint64_t rng_next(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717ull;
}
static double urand(double a, double b) { return a + (b - a) * ((rng_next() >> 11) * (1.0 / 9007199254740992.0)); }
static double nrand(void)
{
    double u = urand(1e-12, 1), v = urand(0, 1);
    return sqrt(-2 * log(u)) * cos(2 * M_PI * v);
}
/* value noise for tile texture, hashed from integer lattice points */
static double hash2(int i, int j)
{
    uint64_t h = (uint64_t)(uint32_t)i * 0x9E3779B97F4A7C15ull ^ (uint64_t)(uint32_t)j * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return (h & 0xFFFF) / 65535.0;
}
static double vnoise(double x, double y)
{
    int i = (int)floor(x), j = (int)floor(y);
    double fx = x - i, fy = y - j;
    double a = hash2(i, j), b = hash2(i + 1, j), c = hash2(i, j + 1), d = hash2(i + 1, j + 1);
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}

/* ---- the ceiling ---- */
#define INK 0.04
#define PAPER 0.86
#define TILE 0.70
#define TBAR 0.80
#define LIGHT 6.0

static apriltag_family_t *tagfam;
static image_u8_t *tag_images[32];

static double tile_pattern(const scene *s, double X, double Y)
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
    return TILE + 0.05 * (vnoise(X * 90, Y * 90) - 0.5) + 0.03 * (vnoise(X * 20, Y * 20) - 0.5) -
           (vnoise(X * 300, Y * 300) > 0.93 ? 0.15 : 0.0);
}

/* The ceiling as bright as the scene says (darker or lighter than paper). */
static double tile_radiance(const scene *s, double X, double Y)
{
    return s->ceiling * tile_pattern(s, X, Y);
}

/* Radiance of an object at local coordinates (lx, ly), or -1 if outside. */
static double object_radiance(const scene *s, const object *o, double lx, double ly)
{
    double r = sqrt(lx * lx + ly * ly);
    switch (o->kind) {
    case OBJ_PAPER:
        return fabs(lx) <= o->a && fabs(ly) <= o->b ? PAPER : -1;
    case OBJ_LANDMARK:
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
    case OBJ_SMOKE: /* white disk, grey ring, LED */
        if (r > o->a) return -1;
        if (r < 0.004) return 0.10;
        if (r > 0.75 * o->a && r < 0.82 * o->a) return 0.45;
        return 0.82;
    case OBJ_DOWNLIGHT: /* dark trim around a lamp */
        if (r > o->a) return -1;
        if (r > 0.8 * o->a) return 0.22;
        return LIGHT;
    case OBJ_SPRINKLER:
        if (r > o->a) return -1;
        if (r < 0.45 * o->a) return 0.12;
        if (r > 0.85 * o->a) return 0.30;
        return 0.65;
    case OBJ_VENT: /* square grille of dark slots */
        if (fabs(lx) > o->a || fabs(ly) > o->a) return -1;
        if (fabs(lx) > 0.9 * o->a || fabs(ly) > 0.9 * o->a) return 0.60;
        return fmod(fabs(lx) + 10, 0.02) < 0.008 ? 0.10 : 0.50;
    case OBJ_SPEAKER: /* round grille: concentric dark rings, ring-like clutter */
        if (r > o->a) return -1;
        if (r > 0.93 * o->a) return 0.12;
        if (fmod(r, 0.018) < 0.006) return 0.18;
        return 0.48 + 0.1 * (vnoise(lx * 400, ly * 400) - 0.5);
    case OBJ_BOX:
        if (fabs(lx) > o->a || fabs(ly) > o->b) return -1;
        if (fabs(lx) > o->a - 0.006 || fabs(ly) > o->b - 0.006) return 0.08;
        return 0.30;
    case OBJ_EXIT:
        if (fabs(lx) > o->a || fabs(ly) > o->b) return -1;
        return fabs(ly) < 0.3 * o->b && fabs(lx) < 0.7 * o->a ? 0.9 : 1.6;
    case OBJ_LIGHT:
        if (fabs(lx) > o->a || fabs(ly) > o->b) return -1;
        if (fabs(lx) > o->a - 0.02 || fabs(ly) > o->b - 0.02) return 0.85; /* frame */
        return LIGHT;
    }
    return -1;
}

/* Gap from a point to a light's rectangle (0 inside). */
static double rect_gap(const object *o, double X, double Y)
{
    double c = cos(o->rot), s = sin(o->rot), dx = X - o->x, dy = Y - o->y;
    double lx = fabs(c * dx + s * dy) - o->a, ly = fabs(-s * dx + c * dy) - o->b;
    lx = lx > 0 ? lx : 0;
    ly = ly > 0 ? ly : 0;
    return sqrt(lx * lx + ly * ly);
}

/* The objects that can touch each 0.1 m cell of the frame's view of the
 * ceiling (in the scene's order), so that a sample looks at a few of
 * them, not all: the picture is the same. */
#define GRID_CELL 0.1
#define GRID_MAX 128
typedef struct {
    double x0, y0;
    int nx, ny;
    int start[GRID_MAX * GRID_MAX + 1];
    int *idx;
} obj_grid;

static double radiance(const scene *s, const obj_grid *g, double X, double Y)
{
    double v = tile_radiance(s, X, Y), halo = 0;
    int gx = (int)floor((X - g->x0) / GRID_CELL), gy = (int)floor((Y - g->y0) / GRID_CELL), k, k0, k1;
    int all = gx < 0 || gy < 0 || gx >= g->nx || gy >= g->ny;
    k0 = all ? 0 : g->start[gy * g->nx + gx];
    k1 = all ? s->n : g->start[gy * g->nx + gx + 1];
    /* objects later in the list lie on top */
    for (k = k0; k < k1; k++) {
        const object *o = &s->obj[all ? k : g->idx[k]];
        double dx = X - o->x, dy = Y - o->y, reach = o->a > o->b ? o->a : o->b;
        double c, sn, r;
        if ((o->kind == OBJ_LIGHT || o->kind == OBJ_DOWNLIGHT) &&
            fabs(dx) < reach + 8 * s->halo_sigma && fabs(dy) < reach + 8 * s->halo_sigma) {
            double gap = o->kind == OBJ_LIGHT ? rect_gap(o, X, Y) : fmax(0, sqrt(dx * dx + dy * dy) - 0.8 * o->a);
            halo += s->halo_amp * exp(-gap / s->halo_sigma) * (o->kind == OBJ_LIGHT ? 1.0 : 0.4);
        }
        if (fabs(dx) > reach * 1.5 || fabs(dy) > reach * 1.5)
            continue;
        c = cos(o->rot);
        sn = sin(o->rot);
        r = object_radiance(s, o, c * dx + sn * dy, -sn * dx + c * dy);
        if (r >= 0)
            v = r;
    }
    return v + halo;
}

/* ---- camera geometry ---- */

/* Map point on the ceiling -> pixel. Camera frame: x right (+u), y down
 * (+v), z up; image top is the robot's forward (+x_r), +u its left (+y_r). */
static void map_to_pixel(const scene *s, double X, double Y, double *u, double *v)
{
    const double *R = s->R;
    double dx = X - s->cx, dy = Y - s->cy, dz = s->ceiling_height - s->cz;
    double f = R[0] * dx + R[3] * dy + R[6] * dz, l = R[1] * dx + R[4] * dy + R[7] * dz,
           up = R[2] * dx + R[5] * dy + R[8] * dz;
    rl_calib_project(&s->cam, l / up, -f / up, u, v);
}

static void ray_to_map(const scene *s, double xn, double yn, double ox, double oy, double *X,
                       double *Y)
{
    const double *R = s->R;
    double f = -yn, l = xn;
    double dx = R[0] * f + R[1] * l + R[2], dy = R[3] * f + R[4] * l + R[5], dz = R[6] * f + R[7] * l + R[8];
    double t = (s->ceiling_height - s->cz) / dz;
    *X = s->cx + ox + t * dx;
    *Y = s->cy + oy + t * dy;
}

/* a = b c, 3 x 3 row-major */
static void mat_mul(const double *b, const double *c, double *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            a[3 * i + j] = b[3 * i] * c[j] + b[3 * i + 1] * c[3 + j] + b[3 * i + 2] * c[6 + j];
}

/* Rz(yaw) Ry(pitch) Rx(roll) */
static void rotation(double yaw, double pitch, double roll, double *R)
{
    double cz = cos(yaw), sz = sin(yaw), cy = cos(pitch), sy = sin(pitch), cx = cos(roll), sx = sin(roll);
    double Rz[9] = {cz, -sz, 0, sz, cz, 0, 0, 0, 1}, Ry[9] = {cy, 0, sy, 0, 1, 0, -sy, 0, cy},
           Rx[9] = {1, 0, 0, 0, cx, -sx, 0, sx, cx}, t[9];
    mat_mul(Rz, Ry, t);
    mat_mul(t, Rx, R);
}

/* Undistorted rays of every subsample, cached per camera. */
static double *ray_table;
static rl_calib ray_cam;

static int build_rays(const rl_calib *cam)
{
    int W = cam->width, H = cam->height, x, y, a, b;
    if (ray_table && memcmp(&ray_cam, cam, sizeof *cam) == 0)
        return 0;
    free(ray_table);
    ray_table = malloc(sizeof(double) * 2 * (size_t)W * H * SUB * SUB);
    if (!ray_table)
        return -1;
    ray_cam = *cam;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            for (b = 0; b < SUB; b++)
                for (a = 0; a < SUB; a++) {
                    double *r = ray_table + 2 * ((((size_t)y * W + x) * SUB + b) * SUB + a);
                    rl_calib_unproject(cam, x + (a + 0.5) / SUB - 0.5, y + (b + 0.5) / SUB - 0.5, &r[0], &r[1]);
                }
    return 0;
}

/* Light across the frame at normalized image offset (du, dv) from the
 * centre: a linear fall-off, and a soft-edged shadow on one side. */
static double illumination(const scene *s, double du, double dv)
{
    double along = du * cos(s->ramp_dir) + dv * sin(s->ramp_dir), f = 1.0;
    double side = du * cos(s->shadow_dir) + dv * sin(s->shadow_dir);
    if (s->ramp > 0)
        f *= 1.0 - s->ramp * 0.5 * (1.0 + fmax(-1.0, fmin(1.0, along)));
    if (s->shadow > 0)
        f *= 1.0 - s->shadow / (1.0 + exp(-(side - s->shadow_at) / 0.04));
    return f;
}

/* The grid over what the frame sees (every 4th pixel's ray, moved both
 * ways by the motion blur, and a margin). 0, or -1 out of memory. */
/* The grid cells an object's reach (1.5 times its size, a light's halo)
 * touches, clipped to the grid. */
static void object_cells(const scene *s, const obj_grid *g, const object *o, int *x0, int *x1, int *y0, int *y1)
{
    double reach = o->a > o->b ? o->a : o->b, e = reach * 1.5;
    if (o->kind == OBJ_LIGHT || o->kind == OBJ_DOWNLIGHT)
        e = fmax(e, reach + 8 * s->halo_sigma);
    e += 1e-9;
    *x0 = (int)fmax(0, floor((o->x - e - g->x0) / GRID_CELL));
    *x1 = (int)fmin(g->nx - 1, floor((o->x + e - g->x0) / GRID_CELL));
    *y0 = (int)fmax(0, floor((o->y - e - g->y0) / GRID_CELL));
    *y1 = (int)fmin(g->ny - 1, floor((o->y + e - g->y0) / GRID_CELL));
}

static int build_grid(const scene *s, obj_grid *g)
{
    static int fill[GRID_MAX * GRID_MAX];
    int W = s->cam.width, H = s->cam.height, x, y, i, cx, cy, pass;
    double b[4] = {1e30, 1e30, -1e30, -1e30}, m = 0.5 * s->motion + 0.05;
    for (y = 0; y < H; y += 4)
        for (x = 0; x < W; x += 4) {
            const double *r = ray_table + 2 * (((size_t)y * W + x) * SUB * SUB);
            double X, Y;
            ray_to_map(s, r[0], r[1], 0, 0, &X, &Y);
            b[0] = fmin(b[0], X), b[1] = fmin(b[1], Y), b[2] = fmax(b[2], X), b[3] = fmax(b[3], Y);
        }
    g->x0 = b[0] - m;
    g->y0 = b[1] - m;
    g->nx = (int)ceil((b[2] + m - g->x0) / GRID_CELL);
    g->ny = (int)ceil((b[3] + m - g->y0) / GRID_CELL);
    g->idx = NULL;
    if (!(g->nx > 0 && g->ny > 0 && g->nx <= GRID_MAX && g->ny <= GRID_MAX)) {
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

static double rng_normal(void) { return nrand(); }
static double rng_uniform(void) { return urand(0, 1); }

static int render(const scene *s, uint8_t *out)
{
    int W = s->cam.width, H = s->cam.height, x, y, a, b, e;
    double *lin = malloc(sizeof(double) * (size_t)W * H);
    double rmax = sqrt(s->cam.cx * s->cam.cx + s->cam.cy * s->cam.cy);
    static obj_grid grid;
    render_rng rng = {rng_normal, rng_uniform};
    if (!lin || build_rays(&s->cam) != 0 || build_grid(s, &grid) != 0)
        return -1;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double acc = 0, du = x - s->cam.cx, dv = y - s->cam.cy;
            for (b = 0; b < SUB; b++)
                for (a = 0; a < SUB; a++) {
                    const double *r = ray_table + 2 * ((((size_t)y * W + x) * SUB + b) * SUB + a);
                    /* motion blur: each subsample at its own instant, the
                     * camera moved and turned (about its axis) by then */
                    double t = (b * SUB + a + 0.5) / (SUB * SUB) - 0.5, X, Y;
                    double c = cos(t * s->motion_turn), sn = sin(t * s->motion_turn);
                    ray_to_map(s, c * r[0] - sn * r[1], sn * r[0] + c * r[1], t * s->motion * cos(s->motion_dir),
                               t * s->motion * sin(s->motion_dir), &X, &Y);
                    acc += radiance(s, &grid, X, Y);
                }
            acc /= SUB * SUB;
            acc *= 1.0 - s->vignette * (du * du + dv * dv) / (rmax * rmax);
            acc *= illumination(s, du / rmax, dv / rmax);
            lin[(size_t)y * W + x] = acc * s->gain;
        }
    e = render_sensor_develop(&s->se, lin, W, H, &rng, out);
    free(lin);
    free(grid.idx);
    return e;
}

/* ---- scenes ---- */

/* (the kinds' numbers seed the frames: new ones go at the end) */
typedef enum { SET_CLEAN, SET_CLUTTERED, SET_GLARE, SET_BORDER, SET_CLUTTER_ONLY, SET_DIM,
               SET_BLUR, SET_MOTION, SET_ILLUM, SET_DEGRADED, SET_LENS, SET_PATH, SET_MOVING,
               SET_HELDOUT, SET_REPEATS, SET_COUNT } set_kind;

static const char *set_names[SET_COUNT] = {"clean", "cluttered", "glare", "border", "clutter_only",
                                           "dim", "blur", "motion", "illum", "degraded", "lens", "path",
                                           "moving", "heldout", "repeats"};

/* The set called name (a drive's "path" is none), or -1. */
static int set_by_name(const char *name)
{
    int i;
    for (i = 0; i < SET_COUNT; i++)
        if (i != SET_PATH && strcmp(name, set_names[i]) == 0)
            return i;
    return -1;
}

static int add_obj(scene *s, obj_kind k, double x, double y, double rot, double a, double b, int id)
{
    object *o;
    if (s->n == MAX_OBJ)
        return -1;
    o = &s->obj[s->n++];
    o->kind = k; o->x = x; o->y = y; o->rot = rot; o->a = a; o->b = b; o->id = id;
    return 0;
}

static void add_landmark(scene *s, double x, double y, int id)
{
    double R = s->diameter / 2, rot = urand(-0.15, 0.15) + (rng_next() & 1 ? M_PI / 2 : 0);
    double a = R, b = R * 1.414;
    if (s->sheet_w > 0) { /* a paper size, the landmark in its middle */
        a = 0.5 * s->sheet_w;
        b = 0.5 * s->sheet_h;
    }
    /* printed on a sheet, rotated as taped */
    add_obj(s, OBJ_PAPER, x, y, rot, a, b, 0);
    add_obj(s, OBJ_LANDMARK, x, y, s->twin ? rot : 0, R, R, id);
}

static void add_clutter(scene *s, double x, double y, int ring_like)
{
    int k = ring_like ? (int)(rng_next() % 3) : (int)(rng_next() % 7);
    double rot = urand(0, M_PI);
    static const obj_kind kinds[] = {OBJ_SPEAKER, OBJ_DOWNLIGHT, OBJ_SMOKE, OBJ_SPRINKLER,
                                     OBJ_VENT, OBJ_BOX, OBJ_EXIT};
    switch (kinds[k]) {
    case OBJ_SPEAKER: add_obj(s, OBJ_SPEAKER, x, y, 0, urand(0.08, 0.14), 0, 0); break;
    case OBJ_DOWNLIGHT: add_obj(s, OBJ_DOWNLIGHT, x, y, 0, urand(0.07, 0.10), 0, 0); break;
    case OBJ_SMOKE: add_obj(s, OBJ_SMOKE, x, y, 0, urand(0.05, 0.07), 0, 0); break;
    case OBJ_SPRINKLER: add_obj(s, OBJ_SPRINKLER, x, y, 0, urand(0.02, 0.035), 0, 0); break;
    case OBJ_VENT: add_obj(s, OBJ_VENT, x, y, rot, urand(0.12, 0.2), 0, 0); break;
    case OBJ_BOX: add_obj(s, OBJ_BOX, x, y, rot, urand(0.05, 0.12), urand(0.05, 0.12), 0); break;
    default: add_obj(s, OBJ_EXIT, x, y, rot, 0.15, 0.08, 0); break;
    }
}

/* The site: a grid of landmarks every tile (the paper's 0.61 m), ids from
 * a fixed layout, some tiles holding lights instead. */
#define SITE_COLS 6
#define SITE_ROWS 5

static int site_id(int i, int j)
{
    /* ids 1..30 spread so that neighbours differ in several bits */
    return (int)((((unsigned)(j * SITE_COLS + i)) * 7u) % 30u) + 1;
}

/* Where the site's landmarks hang: on the grid, or (--site irregular)
 * each shifted by up to 15 cm and the whole layout turned 5 degrees, as
 * taped up by hand; --move shifts one landmark after that. Independent of
 * the frames' random numbers. */
static double site_xy[SITE_ROWS * SITE_COLS][2];

static void site_layout(double tile, int irregular, int move_id, double mdx, double mdy)
{
    uint64_t st = 0x2545F4914F6CDD1Dull;
    double cx = SITE_COLS * tile / 2, cy = SITE_ROWS * tile / 2, th = irregular ? 0.087 : 0;
    int i, j;
    for (j = 0; j < SITE_ROWS; j++)
        for (i = 0; i < SITE_COLS; i++) {
            double x = (i + 0.5) * tile, y = (j + 0.5) * tile, *p = site_xy[j * SITE_COLS + i];
            if (irregular) {
                double r, a;
                st ^= st << 13, st ^= st >> 7, st ^= st << 17;
                r = 0.15 * sqrt((double)(st >> 11) / 9007199254740992.0);
                st ^= st << 13, st ^= st >> 7, st ^= st << 17;
                a = 2 * M_PI * (double)(st >> 11) / 9007199254740992.0;
                x += r * cos(a);
                y += r * sin(a);
            }
            p[0] = cx + cos(th) * (x - cx) - sin(th) * (y - cy);
            p[1] = cy + sin(th) * (x - cx) + cos(th) * (y - cy);
            if (site_id(i, j) == move_id) {
                p[0] += mdx;
                p[1] += mdy;
            }
        }
}

static void site_scene(scene *s, set_kind kind)
{
    int i, j;
    s->tile_px = s->tile_py = 0;
    for (j = -1; j <= SITE_ROWS; j++)
        for (i = -1; i <= SITE_COLS; i++) {
            double x = (i + 0.5) * s->tile, y = (j + 0.5) * s->tile;
            int inside = i >= 0 && j >= 0 && i < SITE_COLS && j < SITE_ROWS;
            if (inside)
                add_landmark(s, site_xy[j * SITE_COLS + i][0], site_xy[j * SITE_COLS + i][1], site_id(i, j));
            else if ((i + j) % 3 == 0)
                add_obj(s, OBJ_LIGHT, x, y, 0, 0.29, 0.29, 0);
            else if ((i * 7 + j) % 5 == 0 && kind == SET_PATH)
                add_clutter(s, x + 0.1, y - 0.05, 0);
        }
}

/* --site-map: the map's landmarks the camera can see, and ceiling things
 * (sprinklers, smoke detectors, vents, ...) in some of the gaps between
 * them, placed by the gap's grid cell (the same in every frame). */
static rl_map site_map;
static double site_spacing; /* the map's landmark spacing */

static void map_scene(scene *s)
{
    double view = 0.5 * sqrt((double)s->cam.width * s->cam.width + (double)s->cam.height * s->cam.height) /
                  s->cam.fx * s->distance * 1.05, p = site_spacing;
    int i, j, ci = (int)floor(s->cx / p), cj = (int)floor(s->cy / p), r = (int)ceil(view / p) + 1;
    s->tile_px = s->tile_py = 0;
    for (i = 0; i < site_map.count; i++) {
        const rl_map_landmark *lm = &site_map.lm[i];
        if (hypot(lm->x - s->cx, lm->y - s->cy) < view + s->diameter)
            add_landmark(s, lm->x, lm->y, lm->id);
    }
    for (j = cj - r; j <= cj + r; j++)
        for (i = ci - r; i <= ci + r; i++) {
            double h = hash2(i, j), x = (i + 0.5) * p, y = (j + 0.5) * p;
            uint64_t keep = rng_state;
            if (h > 0.25 || hypot(x - s->cx, y - s->cy) > view + p)
                continue;
            /* the kind and size from the cell too */
            rng_state = (uint64_t)(h * 1e9) * 0x9E3779B97F4A7C15ull + 1;
            add_clutter(s, x, y, h < 0.08);
            rng_state = keep;
        }
}

static void random_scene(scene *s, set_kind kind)
{
    int i, j, pool[RL_MAX_IDS], npool = rl_family_count(&s->fam);
    double view, reach;
    s->tile_px = urand(0, s->tile);
    s->tile_py = urand(0, s->tile);
    for (i = 0; i < npool; i++)
        pool[i] = i + 1;
    /* the view's half-diagonal on the ceiling: landmarks only where they
     * can be seen (ids stay unique in a frame), other things a bit beyond */
    view = 0.5 * sqrt((double)s->cam.width * s->cam.width + (double)s->cam.height * s->cam.height) /
           s->cam.fx * s->distance * 1.05;
    if (kind == SET_LENS) {
        /* a wide-angle lens sees further than its focal length says */
        double xn, yn;
        rl_calib_unproject(&s->cam, 0, 0, &xn, &yn);
        view = hypot(xn, yn) * s->distance * 1.05;
    }
    reach = view + s->tile;
    for (j = -8; j <= 8; j++)
        for (i = -8; i <= 8; i++) {
            double x = s->tile_px + (floor(s->cx / s->tile) + i + 0.5) * s->tile;
            double y = s->tile_py + (floor(s->cy / s->tile) + j + 0.5) * s->tile;
            double p = urand(0, 1), d = hypot(x - s->cx, y - s->cy);
            if (d > reach)
                continue;
            if (kind == SET_CLUTTER_ONLY) {
                if (p < 0.12)
                    add_obj(s, OBJ_LIGHT, x, y, 0, 0.29, 0.29, 0);
                else if (p < 0.75)
                    add_clutter(s, x + urand(-0.15, 0.15), y + urand(-0.15, 0.15), p < 0.45);
                continue;
            }
            if (p < 0.55 && d < view + s->diameter && npool > 0) {
                int pick = (int)(rng_next() % (unsigned)npool), id = pool[pick];
                if (kind != SET_REPEATS)
                    pool[pick] = pool[--npool];
                else if (npool > 4)
                    npool = 4; /* four ids: a frame holds each two or three times */
                add_landmark(s, x + urand(-0.04, 0.04), y + urand(-0.04, 0.04), id);
                if ((kind == SET_GLARE && urand(0, 1) < 0.6) ||
                    ((kind == SET_MOVING || kind == SET_HELDOUT) && urand(0, 1) < 0.25)) {
                    /* a light 2 to 6 cm from the landmark's edge, on one side */
                    object *lm = &s->obj[s->n - 1];
                    double gap = urand(0.02, 0.06), hw = 0.29, side = (double)(rng_next() % 4);
                    double off = lm->a + gap + hw;
                    double lx = lm->x + (side == 0 ? off : side == 1 ? -off : urand(-0.1, 0.1));
                    double ly = lm->y + (side == 2 ? off : side == 3 ? -off : urand(-0.1, 0.1));
                    add_obj(s, OBJ_LIGHT, lx, ly, 0, hw, hw, 0);
                }
            } else if (p < 0.65 && kind != SET_CLEAN) {
                add_obj(s, OBJ_LIGHT, x, y, 0, 0.29, 0.29, 0);
            } else if (p < 0.85 && (kind == SET_CLUTTERED || kind == SET_BORDER || kind == SET_DIM ||
                                    kind == SET_ILLUM || kind == SET_DEGRADED || kind == SET_LENS ||
                                    kind == SET_MOVING || kind == SET_HELDOUT)) {
                add_clutter(s, x + urand(-0.12, 0.12), y + urand(-0.12, 0.12), p < 0.72);
            }
        }
    /* lights go last: they cover the paper they overlap */
    {
        int a, b = 0;
        object tmp[MAX_OBJ];
        for (a = 0; a < s->n; a++)
            if (s->obj[a].kind != OBJ_LIGHT)
                tmp[b++] = s->obj[a];
        for (a = 0; a < s->n; a++)
            if (s->obj[a].kind == OBJ_LIGHT)
                tmp[b++] = s->obj[a];
        memcpy(s->obj, tmp, sizeof(object) * (size_t)s->n);
    }
}

/* The scene's sheets: paper `name` (a paper rl_paper_find knows). */
static void use_sheet(scene *s, const char *name)
{
    const rl_paper *p = rl_paper_find(name);
    s->sheet_w = p->w_mm / 1000.0;
    s->sheet_h = p->h_mm / 1000.0;
}

/* A camera moving in dim light: ranges its frames are drawn from. */
typedef struct {
    double blur[2], defocus[2]; /* optics, px */
    double motion_px[2], turn;  /* travel during the exposure, px; turn, rad either way */
    double gain[2];             /* exposure */
    double full_well[2], read_noise[2], vignette[2];
    double ceiling[2];          /* the ceiling's brightness, times the default tile's */
    render_tone tone;
    int adc_bits;
} moving_look;

/* The development set: blur on the light, motion of any direction and a
 * turn, short exposures on sensors of several sizes, on ceilings darker
 * and lighter than paper (the sheets: every paper, drawn per frame). */
static const moving_look moving = {{0.6, 1.4}, {0, 0}, {1.0, 6.0}, 0.015, {0.25, 0.7},
                                   {2500, 9000}, {1.5, 4.0}, {0.1, 0.4}, {0.55, 1.3}, RENDER_TONE_GAMMA22, 10};
/* The set nothing is tuned on: another optics (a defocus disk), another
 * tone curve (sRGB), 12-bit raw values, the paper's letter sheets (3 mm
 * beside a 0.21 m landmark). Its figures are read, never worked towards. */
static const moving_look heldout = {{0.3, 0.8}, {0.5, 1.3}, {2.0, 6.0}, 0.015, {0.3, 0.5},
                                    {3000, 6000}, {2.0, 4.0}, {0.2, 0.45}, {0.6, 1.25}, RENDER_TONE_SRGB, 12};

static void moving_effects(scene *s, const moving_look *m)
{
    s->se.tone = m->tone;
    s->se.adc_bits = m->adc_bits;
    s->se.blur = urand(m->blur[0], m->blur[1]);
    s->se.defocus = m->defocus[1] > 0 ? urand(m->defocus[0], m->defocus[1]) : 0;
    s->motion = urand(m->motion_px[0], m->motion_px[1]) / s->cam.fx * s->distance;
    s->motion_dir = urand(0, 2 * M_PI);
    s->motion_turn = urand(-m->turn, m->turn);
    s->gain = urand(m->gain[0], m->gain[1]);
    s->se.full_well = urand(m->full_well[0], m->full_well[1]);
    s->se.read_noise = urand(m->read_noise[0], m->read_noise[1]);
    s->vignette = urand(m->vignette[0], m->vignette[1]);
    s->ceiling = urand(m->ceiling[0], m->ceiling[1]);
}

static void effects(scene *s, set_kind kind)
{
    s->gain = 1.0;
    s->vignette = 0.15;
    render_sensor_defaults(&s->se);
    s->se.blur = 0.5;
    s->se.read_noise = 1.5;
    s->motion = 0;
    s->motion_turn = 0;
    s->sheet_w = s->sheet_h = 0;
    s->ceiling = 1.0;
    s->halo_amp = urand(0.3, 0.7);
    s->halo_sigma = urand(0.03, 0.07);
    s->ink = INK;
    s->ramp = s->shadow = 0;
    switch (kind) {
    case SET_CLEAN: s->vignette = 0.1; s->se.read_noise = 1.0; break;
    case SET_CLUTTERED: s->vignette = urand(0.1, 0.4); s->se.blur = urand(0.4, 1.0); s->se.read_noise = urand(1, 3); s->gain = urand(0.7, 1.1); break;
    case SET_GLARE: s->halo_amp = urand(0.5, 0.9); s->halo_sigma = urand(0.04, 0.07); break;
    case SET_BORDER: s->vignette = 0.3; break;
    case SET_CLUTTER_ONLY: s->se.blur = urand(0.4, 1.0); s->se.read_noise = 2; break;
    case SET_DIM: s->gain = urand(0.25, 0.4); s->se.read_noise = 2.5; s->vignette = 0.35; break;
    case SET_BLUR: s->se.blur = urand(1.2, 1.8); break;
    case SET_MOTION: s->motion = urand(0.015, 0.03); s->motion_dir = urand(0, 2 * M_PI); break;
    case SET_ILLUM:
        /* what real ceilings do to a frame: lens vignetting as strong as a
         * wide-angle's, light falling off across the frame, a shadow on
         * one side (a wall), ink that is dark grey rather than black */
        s->vignette = urand(0.45, 0.6);
        s->ramp = urand(0.2, 0.5);
        s->ramp_dir = urand(0, 2 * M_PI);
        s->shadow = urand(0.3, 0.6);
        s->shadow_at = urand(0.4, 0.8);
        s->shadow_dir = urand(0, 2 * M_PI);
        s->ink = urand(0.06, 0.2);
        s->se.blur = urand(0.5, 1.0);
        s->se.read_noise = urand(1.5, 3);
        break;
    case SET_DEGRADED:
        /* blur 1.1 px, 4 px of motion, 0.35 of the exposure on a sensor:
         * photon noise (4,500 e- at the white point) and read noise 3 DN
         * before the tone curve */
            s->se.blur = 1.1;
        s->motion = 4.0 / s->cam.fx * s->distance;
        s->motion_dir = urand(0, 2 * M_PI);
        s->gain = 0.35;
        s->se.full_well = 4500;
        s->se.read_noise = 3.0;
        break;
    case SET_MOVING: {
        static const char *papers[] = {"letter", "a4", "a3"};
        int k = (int)(rng_next() % 4);
        moving_effects(s, &moving);
        if (k < 3)
            use_sheet(s, papers[k]);
        break;
    }
    case SET_HELDOUT:
        moving_effects(s, &heldout);
        use_sheet(s, "letter");
        break;
    case SET_LENS:
        /* a wide-angle M12 lens (3.6 mm class) as on the real photos:
         * strong barrel distortion, so landmarks towards the border are
         * ellipses (flattened radially, to about 0.8 at the edge) and
         * smaller, with the vignetting such lenses have */
        s->cam.k[0] = -0.22;
        s->cam.k[1] = 0.04;
        s->vignette = urand(0.35, 0.55);
        s->se.blur = urand(0.5, 0.9);
        s->se.read_noise = urand(1.5, 2.5);
        break;
    case SET_REPEATS: s->vignette = urand(0.1, 0.3); break;
    case SET_PATH:
    case SET_COUNT: break;
    }
}

/* ---- ground truth ---- */

/* 1 if a light fixture drawn over the ceiling covers (X, Y). */
static int under_light(const scene *s, double X, double Y)
{
    int i;
    for (i = 0; i < s->n; i++) {
        const object *l = &s->obj[i];
        if (l->kind == OBJ_LIGHT && rect_gap(l, X, Y) <= 0)
            return 1;
        if (l->kind == OBJ_DOWNLIGHT && hypot(X - l->x, Y - l->y) <= l->a)
            return 1;
    }
    return 0;
}

/* Fraction of the landmark's disk that the camera sees: inside the image
 * and not covered by a light fixture. */
static double visible_fraction(const scene *s, const object *o)
{
    int i, j, in = 0, n = 0;
    for (j = -20; j <= 20; j++)
        for (i = -20; i <= 20; i++) {
            double lx = i / 20.0 * o->a, ly = j / 20.0 * o->a, u, v;
            if (lx * lx + ly * ly > o->a * o->a)
                continue;
            n++;
            map_to_pixel(s, o->x + lx, o->y + ly, &u, &v);
            in += u >= -0.5 && v >= -0.5 && u <= s->cam.width - 0.5 && v <= s->cam.height - 0.5 &&
                  !under_light(s, o->x + lx, o->y + ly);
        }
    return (double)in / n;
}

static double light_gap(const scene *s, const object *o)
{
    double best = 1e9;
    int i, k;
    for (i = 0; i < s->n; i++) {
        const object *l = &s->obj[i];
        if (l->kind != OBJ_LIGHT && l->kind != OBJ_DOWNLIGHT)
            continue;
        for (k = 0; k < 72; k++) { /* landmark edge to light, sampled */
            double X = o->x + o->a * cos(k * M_PI / 36), Y = o->y + o->a * sin(k * M_PI / 36);
            double g = l->kind == OBJ_LIGHT ? rect_gap(l, X, Y)
                                            : fmax(0, hypot(X - l->x, Y - l->y) - l->a);
            if (g < best)
                best = g;
        }
    }
    return best;
}

static int write_truth(const char *path, const char *image, const scene *s, double rx, double ry,
                       double ryaw)
{
    rl_outfile out;
    FILE *f;
    char err[1200];
    int i, n = 0;
    if (rl_outfile_open(&out, path, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-render: %s\n", err), -1;
    f = out.f;
    fprintf(f, "image: %s\nwidth: %d\nheight: %d\nfamily: ring%d\ndiameter: %.4f\n", image,
            s->cam.width, s->cam.height, s->fam.bits, s->diameter);
    fprintf(f, "distance: %.4f\ncamera: {x: %.6f, y: %.6f, yaw: %.6f}\n", s->distance, s->cx, s->cy, s->yaw);
    fprintf(f, "robot: {x: %.6f, y: %.6f, yaw: %.6f}\n", rx, ry, ryaw);
    fprintf(f, "camera_tilt: {roll: %.6f, pitch: %.6f, z: %.6f}\n", s->roll, s->pitch, s->cz);
    fprintf(f, "twin: %s\nlandmarks:\n", s->twin ? "apriltag36h11" : "none");
    for (i = 0; i < s->n; i++) {
        const object *o = &s->obj[i];
        double u, v, vis, gap;
        if (o->kind != OBJ_LANDMARK)
            continue;
        map_to_pixel(s, o->x, o->y, &u, &v);
        if (u < -3 * o->a / s->distance * s->cam.fx || v < -3 * o->a / s->distance * s->cam.fx ||
            u > s->cam.width * 1.5 || v > s->cam.height * 1.5)
            continue;
        vis = visible_fraction(s, o);
        if (vis <= 0)
            continue;
        gap = light_gap(s, o);
        fprintf(f, "  - {id: %d, x: %.6f, y: %.6f, u: %.4f, v: %.4f, radius: %.3f, visible: %.4f, light_gap: %.4f, light_gap_radii: %.3f}\n",
                o->id, o->x, o->y, u, v, o->a / s->distance * s->cam.fx, vis, gap, gap / o->a);
        n++;
    }
    if (n == 0)
        fprintf(f, "  []\n");
    fprintf(f, "effects: {gain: %.3f, vignette: %.3f, blur: %.3f, noise: %.3f, motion: %.4f, halo: %.3f}\n",
            s->gain, s->vignette, s->se.blur, s->se.read_noise, s->motion, s->halo_amp);
    fprintf(f, "sensor: {full_well: %.0f, defocus: %.2f, tone: %s, adc_bits: %d, motion_px: %.2f, "
            "motion_turn: %.4f}\n",
            s->se.full_well, s->se.defocus, s->se.tone == RENDER_TONE_SRGB ? "srgb" : "gamma2.2",
            s->se.adc_bits, s->motion / s->distance * s->cam.fx, s->motion_turn);
    fprintf(f, "sheet: {width: %.4f, height: %.4f, ceiling: %.3f}\n", s->sheet_w, s->sheet_h, s->ceiling);
    if (rl_outfile_commit(&out, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-render: %s\n", err), -1;
    return 0;
}

/* ---- command line ---- */

static const char *help =
    "usage: ringloc-render --out DIR (--set NAME --count N | --path KIND --frames N)\n"
    "                      [--seed S] [--size 640x480] [--camera CAM.yaml] [--twin]\n"
    "                      [--mount X,Y,YAW] [--write-map FILE] [--write-camera FILE]\n"
    "                      [--write-robot FILE] [--rock SIGMA] [--site grid|irregular]\n"
    "                      [--move ID,DX,DY] [--look SET] [--sheet PAPER]\n\n"
    "Render ceiling fixtures with ground truth (NAME_NNN.png + NAME_NNN.yaml).\n"
    "  --set NAME      clean, cluttered, glare, border, clutter_only, dim, blur, motion,\n"
    "                  illum (vignetting, fall-off, a shadow, grey ink), degraded (blur\n"
    "                  1.1 px, 4 px motion, 0.35 exposure, 3 DN noise), lens (a wide-angle\n"
    "                  lens's barrel distortion, k1 -0.22: landmarks at the border as\n"
    "                  ellipses; replaces the camera's distortion), moving (a robot\n"
    "                  moving in dim light: blur, motion of any direction and a turn,\n"
    "                  photon and read noise, sheets of every paper on ceilings darker\n"
    "                  and lighter than paper), heldout (the same kind of frames by\n"
    "                  other optics, tone curve and raw depth, letter sheets: nothing\n"
    "                  is tuned on it), repeats (four ids, each two or three times a\n"
    "                  frame):\n"
    "                  random scenes around the paper's set-up (ring5, 0.21 m landmarks,\n"
    "                  1.87 m from camera to ceiling, 0.61 m tiles)\n"
    "  --path KIND     straight, rect, circle or survey (back and forth over the whole\n"
    "                  site, weaving): frames along a robot path under a fixed site of\n"
    "                  6x5 landmarks 0.61 m apart (the map of --write-map)\n"
    "  --site LAYOUT   grid (default) or irregular: each landmark up to 15 cm off the\n"
    "                  grid, the layout turned 5 degrees (a site taped up by hand)\n"
    "  --move ID,DX,DY the site's landmark ID moved by (DX, DY) m\n"
    "  --twin          also render each frame with AprilTag 36h11 tags of the same size\n"
    "                  at the same places (NAME_NNN_tag.png)\n"
    "  --camera FILE   calibration to render with (default: 640x480, 70 deg, mild\n"
    "                  barrel distortion; --size scales it)\n"
    "  --mount X,Y,YAW[,ROLL,PITCH]  camera offset in the robot frame, and its\n"
    "                  tilt (radians, roll about the robot's x, pitch about its y;\n"
    "                  default 0,0,0,0,0)\n"
    "  --rock SIGMA    the robot rocks: a random tilt per frame and axis (radians)\n"
    "  --look SET      with --path: the frames look as that set's do (degraded, dim, ...)\n"
    "  --sheet PAPER   the landmarks' sheets: letter, a4, a3, tabloid or WxH in mm\n"
    "                  (default: as wide as the landmark, A4's proportions; the\n"
    "                  moving set draws letter, A4, A3 or that, heldout letter)\n"
    "  --site-map FILE a large site's map (ringloc plan --area; any size, ids repeated):\n"
    "                  frames under it with --path random (poses uniform over the\n"
    "                  landmarks' extent, any heading) or --path tour (a drive over the\n"
    "                  site, 0.1 m a frame, carried elsewhere halfway) or --path edge (a\n"
    "                  drive out past the lower edge and along it: one row in view); its family,\n"
    "                  diameter and ceiling height\n";

/* mkdir -p */
static int mkdir_p(const char *dir)
{
    char buf[1024];
    size_t i, n = strlen(dir);
    if (n >= sizeof buf)
        return -1;
    memcpy(buf, dir, n + 1);
    for (i = 1; i <= n; i++)
        if (buf[i] == '/' || buf[i] == '\0') {
            char c = buf[i];
            buf[i] = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return -1;
            buf[i] = c;
        }
    return 0;
}

static int path_pose(const char *kind, int k, int n, double *x, double *y, double *yaw)
{
    double t = n > 1 ? (double)k / (n - 1) : 0;
    if (strcmp(kind, "straight") == 0) {
        *x = 0.6 + 2.4 * t;
        *y = 1.55;
        *yaw = 0.0;
    } else if (strcmp(kind, "circle") == 0) {
        double a = 2 * M_PI * t * (n - 1) / n;
        *x = 1.83 + 0.6 * cos(a);
        *y = 1.52 + 0.6 * sin(a);
        *yaw = a + M_PI / 2;
    } else if (strcmp(kind, "rect") == 0) {
        /* perimeter of (0.9, 0.9)-(2.7, 2.1), heading along each edge */
        double w = 1.8, h = 1.2, p = t * 2 * (w + h) * (n - 1) / n;
        if (p < w) { *x = 0.9 + p; *y = 0.9; *yaw = 0; }
        else if (p < w + h) { *x = 2.7; *y = 0.9 + p - w; *yaw = M_PI / 2; }
        else if (p < 2 * w + h) { *x = 2.7 - (p - w - h); *y = 2.1; *yaw = M_PI; }
        else { *x = 0.9; *y = 2.1 - (p - 2 * w - h); *yaw = -M_PI / 2; }
    } else if (strcmp(kind, "survey") == 0) {
        /* back and forth in three rows across the site, weaving */
        double row = 3.05, turn = 0.9, L = 3 * row + 2 * turn, p = t * L, w = 0.5 * sin(2 * M_PI * 7 * t);
        int r = (int)(p / (row + turn));
        double q = p - r * (row + turn);
        if (r > 2)
            r = 2, q = row;
        if (q < row) {
            *x = r % 2 ? 3.35 - q : 0.3 + q;
            *y = 0.6 + 0.9 * r;
            *yaw = (r % 2 ? M_PI : 0) + w;
        } else {
            *x = r % 2 ? 0.3 : 3.35;
            *y = 0.6 + 0.9 * r + (q - row);
            *yaw = M_PI / 2 + w;
        }
    } else {
        return -1;
    }
    *yaw = atan2(sin(*yaw), cos(*yaw));
    return 0;
}

static void default_camera(rl_calib *cam, int w, int h)
{
    rl_calib_defaults(cam, w, h, 70.0 * M_PI / 180.0);
    cam->model = RL_DIST_PLUMB_BOB;
    cam->k[0] = -0.12;
    cam->k[1] = 0.08;
    cam->k[2] = 0.0004;
    cam->k[3] = -0.0003;
    cam->fy = cam->fx * 1.002;
    cam->cx += 3.2 * w / 640.0;
    cam->cy -= 2.1 * h / 480.0;
}

int main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"out", required_argument, 0, 'o'}, {"set", required_argument, 0, 's'},
        {"count", required_argument, 0, 'n'}, {"path", required_argument, 0, 'p'},
        {"frames", required_argument, 0, 'n'}, {"seed", required_argument, 0, 'S'},
        {"size", required_argument, 0, 'z'}, {"camera", required_argument, 0, 'c'},
        {"twin", no_argument, 0, 't'}, {"mount", required_argument, 0, 'm'},
        {"write-map", required_argument, 0, 'M'}, {"write-camera", required_argument, 0, 'C'},
        {"write-robot", required_argument, 0, 'R'}, {"rock", required_argument, 0, 'r'},
        {"look", required_argument, 0, 'l'}, {"site", required_argument, 0, 'G'},
        {"move", required_argument, 0, 'V'}, {"site-map", required_argument, 0, 'E'},
        {"sheet", required_argument, 0, 'P'},
        {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    const char *look = NULL;
    set_kind look_kind = SET_PATH;
    const char *out = NULL, *set = NULL, *path = NULL, *cam_path = NULL, *map_out = NULL,
               *cam_out = NULL, *robot_out = NULL;
    int count = 10, w = 640, h = 480, twin = 0, c, k, i;
    unsigned long seed = 1;
    double mx = 0, my = 0, myaw = 0, mroll = 0, mpitch = 0, rock = 0, mdx = 0, mdy = 0;
    int irregular = 0, move_id = 0;
    rl_paper sheet = {NULL, 0, 0};
    const char *site_path = NULL;
    render_pose *poses = NULL;
    static scene s;
    rl_calib cam;
    set_kind kind = SET_CLEAN;
    char err[512], name[1024], file[1200];
    uint8_t *px;

    rl_cli_start("ringloc-render");
    while ((c = getopt_long(argc, argv, "h", opts, NULL)) != -1) {
        switch (c) {
        case 'o': out = optarg; break;
        case 's': set = optarg; break;
        case 'p': path = optarg; break;
        case 'n': count = atoi(optarg); break;
        case 'S': seed = strtoul(optarg, NULL, 10); break;
        case 'z':
            if (sscanf(optarg, "%dx%d", &w, &h) != 2 || w < 16 || h < 16 || w > 4096 || h > 4096) {
                fprintf(stderr, "ringloc-render: --size: '%s' is not a size like 640x480\n", optarg);
                return 2;
            }
            break;
        case 'c': cam_path = optarg; break;
        case 't': twin = 1; break;
        case 'm':
            k = sscanf(optarg, "%lf,%lf,%lf,%lf,%lf", &mx, &my, &myaw, &mroll, &mpitch);
            if (k != 3 && k != 5) {
                fprintf(stderr, "ringloc-render: --mount: '%s' is not X,Y,YAW[,ROLL,PITCH]\n", optarg);
                return 2;
            }
            break;
        case 'l': look = optarg; break;
        case 'G':
            if (strcmp(optarg, "grid") != 0 && strcmp(optarg, "irregular") != 0) {
                fprintf(stderr, "ringloc-render: --site: '%s' is not grid or irregular\n", optarg);
                return 2;
            }
            irregular = strcmp(optarg, "irregular") == 0;
            break;
        case 'V':
            if (sscanf(optarg, "%d,%lf,%lf", &move_id, &mdx, &mdy) != 3 || move_id < 1 || move_id > 30 ||
                !(fabs(mdx) < 1 && fabs(mdy) < 1)) {
                fprintf(stderr, "ringloc-render: --move: '%s' is not ID,DX,DY (an id 1..30, up to 1 m)\n", optarg);
                return 2;
            }
            break;
        case 'r':
            if (sscanf(optarg, "%lf", &rock) != 1 || !(rock >= 0 && rock < 0.3)) {
                fprintf(stderr, "ringloc-render: --rock: '%s' is not an angle 0 .. 0.3 rad\n", optarg);
                return 2;
            }
            break;
        case 'E': site_path = optarg; break;
        case 'P':
            if (!rl_paper_parse(optarg, &sheet)) {
                fprintf(stderr, "ringloc-render: --sheet: '%s' is not %s or WxH in mm\n", optarg, rl_paper_names());
                return 2;
            }
            break;
        case 'M': map_out = optarg; break;
        case 'C': cam_out = optarg; break;
        case 'R': robot_out = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: fprintf(stderr, "ringloc-render: see --help\n"); return 2;
        }
    }
    if (cam_path) {
        if (rl_calibfile_load(cam_path, &cam, err, sizeof err) != RL_OK) {
            fprintf(stderr, "ringloc-render: %s\n", err);
            return 1;
        }
    } else {
        default_camera(&cam, w, h);
    }
    if (out && mkdir_p(out) != 0) {
        fprintf(stderr, "ringloc-render: %s: %s\n", out, strerror(errno));
        return 1;
    }
    memset(&s, 0, sizeof s);
    s.cam = cam;
    s.fam.bits = 5;
    s.diameter = 0.21;
    s.distance = 1.87;
    s.ceiling_height = 2.75;
    s.cam_z = s.ceiling_height - s.distance;
    s.tile = 0.61;
    site_layout(s.tile, irregular, move_id, mdx, mdy);
    if (site_path) {
        int i2;
        if (rl_mapfile_load(site_path, &site_map, err, sizeof err) != RL_OK) {
            fprintf(stderr, "ringloc-render: %s\n", err);
            return 1;
        }
        if (site_map.count < 2) {
            fprintf(stderr, "ringloc-render: %s: a site needs two landmarks or more\n", site_path);
            return 1;
        }
        s.fam = site_map.family;
        s.diameter = site_map.diameter;
        s.ceiling_height = site_map.ceiling_height;
        s.distance = s.ceiling_height - s.cam_z;
        if (!(s.distance > 0.3)) {
            fprintf(stderr, "ringloc-render: %s: ceiling_height %.3f m is not above the camera (%.2f m)\n",
                    site_path, s.ceiling_height, s.cam_z);
            return 1;
        }
        /* the spacing: landmark 0's nearest neighbour (a planned grid is even) */
        site_spacing = HUGE_VAL;
        for (i2 = 1; i2 < site_map.count; i2++)
            site_spacing = fmin(site_spacing, hypot(site_map.lm[i2].x - site_map.lm[0].x,
                                                    site_map.lm[i2].y - site_map.lm[0].y));
    }
    if (cam_out && rl_calibfile_save(cam_out, &cam, err, sizeof err) != RL_OK) {
        fprintf(stderr, "ringloc-render: %s\n", err);
        return 1;
    }
    if (robot_out) {
        rl_mount mnt;
        mnt.x = mx;
        mnt.y = my;
        mnt.yaw = myaw;
        mnt.roll = mroll;
        mnt.pitch = mpitch;
        mnt.z = s.cam_z;
        if (rl_robotfile_save(robot_out, &mnt, err, sizeof err) != RL_OK) {
            fprintf(stderr, "ringloc-render: %s\n", err);
            return 1;
        }
    }
    if (map_out && site_path) {
        if (rl_mapfile_save(map_out, &site_map, err, sizeof err) != RL_OK) {
            fprintf(stderr, "ringloc-render: %s\n", err);
            return 1;
        }
    } else if (map_out) {
        static rl_map map;
        int a, b;
        map.family = s.fam;
        map.diameter = s.diameter;
        map.ceiling_height = s.ceiling_height;
        for (b = 0; b < SITE_ROWS; b++)
            for (a = 0; a < SITE_COLS; a++) {
                rl_map_landmark *lm = &map.lm[map.count++];
                lm->id = site_id(a, b);
                lm->x = site_xy[b * SITE_COLS + a][0];
                lm->y = site_xy[b * SITE_COLS + a][1];
            }
        if (rl_mapfile_save(map_out, &map, err, sizeof err) != RL_OK) {
            fprintf(stderr, "ringloc-render: %s\n", err);
            return 1;
        }
    }
    if (!out) {
        if (map_out || cam_out || robot_out)
            return 0;
        fprintf(stderr, "ringloc-render: --out DIR is required (see --help)\n");
        return 2;
    }
    if ((set == NULL) == (path == NULL)) {
        fprintf(stderr, "ringloc-render: give --set NAME or --path KIND (see --help)\n");
        return 2;
    }
    if (set) {
        if ((i = set_by_name(set)) < 0) {
            fprintf(stderr, "ringloc-render: --set: unknown set '%s'\n", set);
            return 2;
        }
        kind = (set_kind)i;
    } else {
        double x, y, yaw;
        kind = SET_PATH;
        if (look != NULL) {
            /* a path drive with the looks of a set (not lens: that changes
             * the camera the calibration was written for) */
            if ((i = set_by_name(look)) < 0 || (set_kind)i == SET_LENS) {
                fprintf(stderr, "ringloc-render: --look: '%s' is not a set's look (lens excepted)\n", look);
                return 2;
            }
            look_kind = (set_kind)i;
        }
        if (site_path) {
            render_area area = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
            if (strcmp(path, "random") != 0 && strcmp(path, "tour") != 0 && strcmp(path, "edge") != 0) {
                fprintf(stderr, "ringloc-render: --path: with --site-map, random, tour or edge ('%s')\n", path);
                return 2;
            }
            for (i = 0; i < site_map.count; i++) {
                area.x0 = fmin(area.x0, site_map.lm[i].x);
                area.y0 = fmin(area.y0, site_map.lm[i].y);
                area.x1 = fmax(area.x1, site_map.lm[i].x);
                area.y1 = fmax(area.y1, site_map.lm[i].y);
            }
            poses = malloc(sizeof *poses * (size_t)(count > 0 ? count : 1));
            if (poses == NULL) {
                fprintf(stderr, "ringloc-render: out of memory\n");
                return 1;
            }
            if (strcmp(path, "random") == 0)
                render_random_poses(&area, seed, count, poses);
            else if (strcmp(path, "edge") == 0)
                render_edge(&area, seed, count, 0.1, poses);
            else
                render_tour(&area, seed, count, 0.1, poses);
        } else if (path_pose(path, 0, 2, &x, &y, &yaw) != 0) {
            fprintf(stderr, "ringloc-render: --path: '%s' is not straight, rect, circle or survey\n", path);
            return 2;
        }
    }
    if (mkdir_p(out) != 0) {
        fprintf(stderr, "ringloc-render: %s: %s\n", out, strerror(errno));
        return 1;
    }
    tagfam = tag36h11_create();
    for (i = 0; i < 32; i++)
        tag_images[i] = apriltag_to_image(tagfam, i);
    px = malloc((size_t)cam.width * cam.height);
    for (k = 0; k < count; k++) {
        double rx, ry, ryaw;
        int pass;
        rng_state = 0x9E3779B97F4A7C15ull ^ (seed * 1000003ull + (uint64_t)k * 7919ull + kind * 104729ull);
        for (i = 0; i < 4; i++)
            rng_next();
        s.n = 0;
        s.twin = 0;
        effects(&s, kind == SET_PATH ? look_kind : kind);
        if (sheet.name != NULL) {
            s.sheet_w = sheet.w_mm / 1000.0;
            s.sheet_h = sheet.h_mm / 1000.0;
        }
        if (poses) {
            rx = poses[k].x;
            ry = poses[k].y;
            ryaw = poses[k].yaw;
            snprintf(name, sizeof name, "%s_%03d", path, k);
        } else if (kind == SET_PATH) {
            path_pose(path, k, count, &rx, &ry, &ryaw);
            snprintf(name, sizeof name, "%s_%03d", path, k);
        } else {
            rx = urand(2, 8);
            ry = urand(2, 8);
            ryaw = urand(-M_PI, M_PI);
            snprintf(name, sizeof name, "%s_%03d", set, k);
        }
        /* camera pose from the robot pose (rocking about its footprint on
         * the floor) and the mount (which may be tilted) */
        {
            double Rr[9], Rm[9], rr = rock > 0 ? rock * nrand() : 0, rp = rock > 0 ? rock * nrand() : 0;
            rotation(ryaw, rp, rr, Rr);
            {
                double T[9], Y[9]; /* the mount's tilt about the robot's axes, then its yaw */
                rotation(0, mpitch, mroll, T);
                rotation(myaw, 0, 0, Y);
                mat_mul(T, Y, Rm);
            }
            mat_mul(Rr, Rm, s.R);
            s.cx = rx + Rr[0] * mx + Rr[1] * my + Rr[2] * s.cam_z;
            s.cy = ry + Rr[3] * mx + Rr[4] * my + Rr[5] * s.cam_z;
            s.cz = Rr[6] * mx + Rr[7] * my + Rr[8] * s.cam_z;
            s.yaw = atan2(s.R[3], s.R[0]);
            s.pitch = -asin(s.R[6]);
            s.roll = atan2(s.R[7], s.R[8]);
        }
        {
            uint64_t keep = rng_state;
            if (site_path)
                map_scene(&s);
            else if (kind == SET_PATH)
                site_scene(&s, kind);
            else
                random_scene(&s, kind);
            (void)keep;
        }
        for (pass = 0; pass <= twin; pass++) {
            uint64_t noise_seed = rng_state;
            rl_image img = rl_image_view(cam.width, cam.height, cam.width, px);
            s.twin = pass;
            if (pass) { /* the twin sees the same noise */
                rng_state = noise_seed;
                for (i = 0; i < s.n; i++)
                    if (s.obj[i].kind == OBJ_PAPER)
                        s.obj[i].a *= 1.25, s.obj[i].b *= 1.25;
            }
            if (render(&s, px) != 0) {
                fprintf(stderr, "ringloc-render: out of memory\n");
                return 1;
            }
            snprintf(file, sizeof file, "%s/%s%s.png", out, name, pass ? "_tag" : "");
            if (rl_png_write_gray(file, &img, err, sizeof err) != RL_OK) {
                fprintf(stderr, "ringloc-render: %s\n", err);
                return 1;
            }
        }
        s.twin = 0;
        snprintf(file, sizeof file, "%s.png", name);
        {
            char truth[1200];
            snprintf(truth, sizeof truth, "%s/%s.yaml", out, name);
            if (write_truth(truth, file, &s, rx, ry, ryaw) != 0)
                return 1; /* the line is printed */
        }
    }
    free(px);
    free(poses);
    /* the tag bitmaps live until exit: libapriltag does not export
     * image_u8_destroy (tests/lsan.supp) */
    tag36h11_destroy(tagfam);
    free(ray_table);
    return 0;
}
