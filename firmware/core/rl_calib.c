#include "rl_calib.h"

#include <math.h>
#include <string.h>
#include "rl_config.h"

void rl_calib_defaults(rl_calib *cam, int width, int height, double hfov)
{
    memset(cam, 0, sizeof *cam);
    cam->width = width;
    cam->height = height;
    cam->fx = cam->fy = (width / 2.0) / tan(hfov / 2.0);
    cam->cx = (width - 1) / 2.0;
    cam->cy = (height - 1) / 2.0;
    cam->model = RL_DIST_NONE;
}

rl_err rl_calib_check(const rl_calib *cam)
{
    int i;
    if (cam->width <= 0 || cam->height <= 0 || cam->width > RL_MAX_IMAGE_DIM ||
        cam->height > RL_MAX_IMAGE_DIM || !(cam->fx >= RL_CALIB_MIN_F) ||
        !(cam->fx <= RL_CALIB_MAX_F) || !(cam->fy >= RL_CALIB_MIN_F) || !(cam->fy <= RL_CALIB_MAX_F) ||
        !(fabs(cam->cx - 0.5 * cam->width) <= 1.5 * cam->width) ||
        !(fabs(cam->cy - 0.5 * cam->height) <= 1.5 * cam->height))
        return RL_ERANGE;
    for (i = 0; i < RL_CALIB_MAX_COEFFS; i++)
        if (!(fabs(cam->k[i]) <= RL_CALIB_MAX_K))
            return RL_ERANGE;
    return RL_OK;
}

/* theta_d of the fisheye model at ray angle theta */
static double fisheye_theta_d(const double *k, double t)
{
    double t2 = t * t;
    return t * (1.0 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3]))));
}

void rl_calib_distort(const rl_calib *cam, double x, double y, double *xd, double *yd)
{
    const double *k = cam->k;
    double r2, r4, r6, radial, xy;
    if (cam->model == RL_DIST_NONE) {
        *xd = x;
        *yd = y;
        return;
    }
    if (cam->model == RL_DIST_FISHEYE) {
        double r = sqrt(x * x + y * y), s = r > 1e-12 ? fisheye_theta_d(k, atan(r)) / r : 1.0;
        *xd = x * s;
        *yd = y * s;
        return;
    }
    r2 = x * x + y * y;
    r4 = r2 * r2;
    r6 = r4 * r2;
    xy = x * y;
    radial = (1.0 + k[0] * r2 + k[1] * r4 + k[4] * r6) / (1.0 + k[5] * r2 + k[6] * r4 + k[7] * r6);
    *xd = x * radial + 2.0 * k[2] * xy + k[3] * (r2 + 2.0 * x * x) + k[8] * r2 + k[9] * r4;
    *yd = y * radial + k[2] * (r2 + 2.0 * y * y) + 2.0 * k[3] * xy + k[10] * r2 + k[11] * r4;
}

/* Newton on theta_d(theta) = td, from theta = td; the ray's normalized
 * point at that angle. */
static void fisheye_undistort(const double *k, double xd, double yd, double *x, double *y)
{
    double td = sqrt(xd * xd + yd * yd), t = td, s;
    int i;
    if (td < 1e-12) {
        *x = xd;
        *y = yd;
        return;
    }
    if (td > 1.5)
        t = td = 1.5; /* beyond about 86 degrees off axis: no ceiling there */
    for (i = 0; i < 20; i++) {
        double t2 = t * t, f = fisheye_theta_d(k, t) - td;
        double df = 1.0 + t2 * (3 * k[0] + t2 * (5 * k[1] + t2 * (7 * k[2] + t2 * 9 * k[3])));
        double step = fabs(df) > 1e-9 ? f / df : 0;
        t -= step;
        if (fabs(step) < 1e-14)
            break;
    }
    s = tan(t) / td;
    *x = xd * s;
    *y = yd * s;
}

/* Fixed-point iterations; converges for the mild distortion of the lenses
 * in use and stops early once the step is below 1e-12. */
#define UNDISTORT_ITERATIONS 40

void rl_calib_undistort(const rl_calib *cam, double xd, double yd, double *x, double *y)
{
    const double *k = cam->k;
    double ux = xd, uy = yd;
    int i;
    if (cam->model == RL_DIST_NONE) {
        *x = xd;
        *y = yd;
        return;
    }
    if (cam->model == RL_DIST_FISHEYE) {
        fisheye_undistort(k, xd, yd, x, y);
        return;
    }
    for (i = 0; i < UNDISTORT_ITERATIONS; i++) {
        double r2 = ux * ux + uy * uy, r4 = r2 * r2, r6 = r4 * r2;
        double icdist = (1.0 + k[5] * r2 + k[6] * r4 + k[7] * r6) /
                        (1.0 + k[0] * r2 + k[1] * r4 + k[4] * r6);
        double dx = 2.0 * k[2] * ux * uy + k[3] * (r2 + 2.0 * ux * ux) + k[8] * r2 + k[9] * r4;
        double dy = k[2] * (r2 + 2.0 * uy * uy) + 2.0 * k[3] * ux * uy + k[10] * r2 + k[11] * r4;
        double nx = (xd - dx) * icdist, ny = (yd - dy) * icdist;
        double step = fabs(nx - ux) + fabs(ny - uy);
        ux = nx;
        uy = ny;
        if (step < 1e-12)
            break;
    }
    *x = ux;
    *y = uy;
}

void rl_calib_project(const rl_calib *cam, double x, double y, double *u, double *v)
{
    double xd, yd;
    rl_calib_distort(cam, x, y, &xd, &yd);
    *u = cam->fx * xd + cam->cx;
    *v = cam->fy * yd + cam->cy;
}

void rl_calib_unproject(const rl_calib *cam, double u, double v, double *x, double *y)
{
    rl_calib_undistort(cam, (u - cam->cx) / cam->fx, (v - cam->cy) / cam->fy, x, y);
}

/* The edge's centre is the mean of D(c + R u) over the circle: D(c) plus
 * R^2 / 4 times D's Laplacian (a five-point stencil here). */
void rl_calib_centre(const rl_calib *cam, double u, double v, double radius, double *x, double *y)
{
    double xd = (u - cam->cx) / cam->fx, yd = (v - cam->cy) / cam->fy, x0, y0, h = 0.01, k;
    double d[5][2];
    static const double at[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    int i;
    rl_calib_undistort(cam, xd, yd, &x0, &y0);
    if (cam->model == RL_DIST_NONE) {
        *x = x0;
        *y = y0;
        return;
    }
    for (i = 0; i < 5; i++)
        rl_calib_distort(cam, x0 + h * at[i][0], y0 + h * at[i][1], &d[i][0], &d[i][1]);
    k = radius * radius / 4.0 / (h * h);
    xd -= k * (d[1][0] + d[2][0] + d[3][0] + d[4][0] - 4 * d[0][0]);
    yd -= k * (d[1][1] + d[2][1] + d[3][1] + d[4][1] - 4 * d[0][1]);
    rl_calib_undistort(cam, xd, yd, x, y);
}

double rl_calib_radius(const rl_calib *cam, double u, double v, double r)
{
    static const double at[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    double x0, y0, sum = 0;
    int i;
    rl_calib_unproject(cam, u, v, &x0, &y0);
    for (i = 0; i < 4; i++) {
        double x, y;
        rl_calib_unproject(cam, u + r * at[i][0], v + r * at[i][1], &x, &y);
        sum += hypot(x - x0, y - y0);
    }
    return sum / 4;
}
