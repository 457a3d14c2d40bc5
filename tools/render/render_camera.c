/* render_camera: the camera's pose, its projection and the frame it
 * delivers (render_camera.h). */
#include "render_camera.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "render_ceiling.h"
#include "render_random.h"

#define SUB 3 /* subsamples per pixel axis */

void render_camera_default(rl_calib *cam, int w, int h)
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

/* Map point on the ceiling -> pixel. Camera frame: x right (+u), y down
 * (+v), z up; image top is the robot's forward (+x_r), +u its left (+y_r). */
void render_camera_to_pixel(const render_scene *s, double X, double Y, double drop, double *u, double *v)
{
    const double *R = s->R;
    double dx = X - s->cx, dy = Y - s->cy, dz = s->ceiling_height - drop - s->cz;
    double f = R[0] * dx + R[3] * dy + R[6] * dz, l = R[1] * dx + R[4] * dy + R[7] * dz,
           up = R[2] * dx + R[5] * dy + R[8] * dz;
    rl_calib_project(&s->cam, l / up, -f / up, u, v);
}

/* Where the ray of normalized image point (xn, yn), the camera moved by
 * (ox, oy), meets the plane `drop` below the ceiling. */
static void ray_to_map(const render_scene *s, double xn, double yn, double ox, double oy, double drop, double *X,
                       double *Y)
{
    const double *R = s->R;
    double f = -yn, l = xn;
    double dx = R[0] * f + R[1] * l + R[2], dy = R[3] * f + R[4] * l + R[5], dz = R[6] * f + R[7] * l + R[8];
    double t = (s->ceiling_height - drop - s->cz) / dz;
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

void render_camera_pose(render_scene *s, const render_mount *m, double rx, double ry, double ryaw, double rr,
                        double rp)
{
    double Rr[9], Rm[9], T[9], Y[9];
    rotation(ryaw, rp, rr, Rr);
    /* the mount's tilt about the robot's axes, then its yaw */
    rotation(0, m->pitch, m->roll, T);
    rotation(m->yaw, 0, 0, Y);
    mat_mul(T, Y, Rm);
    mat_mul(Rr, Rm, s->R);
    s->cx = rx + Rr[0] * m->x + Rr[1] * m->y + Rr[2] * s->cam_z;
    s->cy = ry + Rr[3] * m->x + Rr[4] * m->y + Rr[5] * s->cam_z;
    s->cz = Rr[6] * m->x + Rr[7] * m->y + Rr[8] * s->cam_z;
    s->yaw = atan2(s->R[3], s->R[0]);
    s->pitch = -asin(s->R[6]);
    s->roll = atan2(s->R[7], s->R[8]);
}

void render_camera_shutter(render_scene *s, const render_mount *m, double yaw, double readout_s, double speed,
                           double turn)
{
    /* the camera's velocity: the robot's, and the turn carrying the mount's offset round */
    double c = cos(yaw), sn = sin(yaw), ox = c * m->x - sn * m->y, oy = sn * m->x + c * m->y;
    s->shutter_dx = readout_s * (speed * c - turn * oy);
    s->shutter_dy = readout_s * (speed * sn + turn * ox);
    s->shutter_turn = readout_s * turn;
}

/* Undistorted rays of every subsample, cached per camera. */
static double *ray_table;
static render_grid grid; /* remade each frame in its own memory */
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
static double illumination(const render_scene *s, double du, double dv)
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
static int view_grid(const render_scene *s, render_grid *g)
{
    int W = s->cam.width, H = s->cam.height, x, y;
    double b[4] = {1e30, 1e30, -1e30, -1e30}, m = 0.5 * s->motion + 0.05;
    for (y = 0; y < H; y += 4)
        for (x = 0; x < W; x += 4) {
            const double *r = ray_table + 2 * (((size_t)y * W + x) * SUB * SUB);
            double X, Y;
            ray_to_map(s, r[0], r[1], 0, 0, 0, &X, &Y);
            b[0] = fmin(b[0], X), b[1] = fmin(b[1], Y), b[2] = fmax(b[2], X), b[3] = fmax(b[3], Y);
        }
    return render_ceiling_grid(s, b, m, g);
}

/* The objects that hang below the ceiling, into low[], and the pixels
 * each may cover into box[] (x0, y0, x1, y1: its reach's corners in the
 * image, widened by the motion's and the rolling shutter's travel and the
 * lens's bend between them): how many. */
static int hanging(const render_scene *s, int *low, int (*box)[4])
{
    int i, k, n = 0;
    double travel = s->motion + hypot(s->shutter_dx, s->shutter_dy);
    for (i = 0; i < s->n; i++) {
        const render_object *o = &s->obj[i];
        double e = 1.5 * (o->a > o->b ? o->a : o->b), b[4] = {1e9, 1e9, -1e9, -1e9};
        if (!(o->drop > 0))
            continue;
        for (k = 0; k < 9; k++) { /* the corners, the edges' middles and the centre */
            double u, v;
            render_camera_to_pixel(s, o->x + (k % 3 - 1) * e, o->y + (k / 3 - 1) * e, o->drop, &u, &v);
            b[0] = fmin(b[0], u), b[1] = fmin(b[1], v), b[2] = fmax(b[2], u), b[3] = fmax(b[3], v);
        }
        /* the travel at the object's depth, in pixels, and the turn's at the image's edge */
        e = 0.1 * (b[2] - b[0] + b[3] - b[1]) + travel / (s->distance - o->drop) * s->cam.fx + 3 +
            (fabs(s->shutter_turn) + fabs(s->motion_turn)) * s->cam.fx;
        box[n][0] = (int)floor(b[0] - e);
        box[n][1] = (int)floor(b[1] - e);
        box[n][2] = (int)ceil(b[2] + e);
        box[n][3] = (int)ceil(b[3] + e);
        low[n++] = i;
    }
    return n;
}

/* Of the n hanging objects, those whose box holds pixel (x, y), into in[]:
 * how many. */
static int hanging_at(const int *low, const int (*box)[4], int n, int x, int y, int *in)
{
    int i, m = 0;
    for (i = 0; i < n; i++)
        if (x >= box[i][0] && x <= box[i][2] && y >= box[i][1] && y <= box[i][3])
            in[m++] = low[i];
    return m;
}

/* The radiance along a ray (normalized xn, yn; the camera moved by ox, oy):
 * the nearest hanging object it meets (the later on one plane), else the
 * ceiling. */
static double ray_radiance(const render_scene *s, const render_grid *g, const int *low, int n_low, double xn,
                           double yn, double ox, double oy)
{
    double X, Y, v = -1, best = 0;
    int i;
    for (i = 0; i < n_low; i++) {
        const render_object *o = &s->obj[low[i]];
        double r;
        if (o->drop < best)
            continue;
        ray_to_map(s, xn, yn, ox, oy, o->drop, &X, &Y);
        if ((r = render_ceiling_object(s, o, X, Y)) >= 0) {
            v = r;
            best = o->drop;
        }
    }
    if (v >= 0)
        return v;
    ray_to_map(s, xn, yn, ox, oy, 0, &X, &Y);
    return render_ceiling_radiance(s, g, X, Y);
}

static double rng_normal(void) { return render_random_normal(); }
static double rng_uniform(void) { return render_random_uniform(0, 1); }

int render_camera_frame(const render_scene *s, uint8_t *out)
{
    int W = s->cam.width, H = s->cam.height, x, y, a, b, e, n_low;
    double *lin = malloc(sizeof(double) * (size_t)W * H);
    static int low[RENDER_MAX_OBJ], box[RENDER_MAX_OBJ][4], here[RENDER_MAX_OBJ];
    double rmax = sqrt(s->cam.cx * s->cam.cx + s->cam.cy * s->cam.cy);
    render_rng rng = {rng_normal, rng_uniform};
    /* motion blur: each subsample at its own instant, the camera moved
     * and turned (about its axis) by then */
    double turn_c[SUB * SUB], turn_s[SUB * SUB], move_x[SUB * SUB], move_y[SUB * SUB];
    for (a = 0; a < SUB * SUB; a++) {
        double t = (a + 0.5) / (SUB * SUB) - 0.5;
        turn_c[a] = cos(t * s->motion_turn);
        turn_s[a] = sin(t * s->motion_turn);
        move_x[a] = t * s->motion * cos(s->motion_dir);
        move_y[a] = t * s->motion * sin(s->motion_dir);
    }
    if (!lin || build_rays(&s->cam) != 0 || view_grid(s, &grid) != 0) {
        free(lin);
        return -1;
    }
    n_low = hanging(s, low, box);
    for (y = 0; y < H; y++) {
        /* a rolling shutter: this row exposed f of the readout from the middle row's */
        double f = (y + 0.5) / H - 0.5, rc = cos(f * s->shutter_turn), rsn = sin(f * s->shutter_turn);
        double rox = f * s->shutter_dx, roy = f * s->shutter_dy;
        for (x = 0; x < W; x++) {
            double acc = 0, du = x - s->cam.cx, dv = y - s->cam.cy;
            int n_here = n_low ? hanging_at(low, (const int(*)[4])box, n_low, x, y, here) : 0;
            for (b = 0; b < SUB; b++)
                for (a = 0; a < SUB; a++) {
                    const double *r = ray_table + 2 * ((((size_t)y * W + x) * SUB + b) * SUB + a);
                    int k = b * SUB + a;
                    double c = turn_c[k], sn = turn_s[k];
                    double xr = c * r[0] - sn * r[1], yr = sn * r[0] + c * r[1];
                    acc += ray_radiance(s, &grid, here, n_here, rc * xr - rsn * yr, rsn * xr + rc * yr,
                                        move_x[k] + rox, move_y[k] + roy);
                }
            acc /= SUB * SUB;
            acc *= 1.0 - s->vignette * (du * du + dv * dv) / (rmax * rmax);
            acc *= illumination(s, du / rmax, dv / rmax);
            lin[(size_t)y * W + x] = acc * s->gain;
        }
    }
    e = render_sensor_develop(&s->se, lin, W, H, &rng, out);
    free(lin);
    return e;
}

void render_camera_free(void)
{
    free(ray_table);
    ray_table = NULL;
    render_ceiling_grid_free(&grid);
}
