#include "rl_camera.h"

#include <math.h>
#include <string.h>
#include "rl_config.h"

void rl_camera_defaults(rl_camera *cam, int width, int height, double hfov)
{
    memset(cam, 0, sizeof *cam);
    cam->width = width;
    cam->height = height;
    cam->fx = cam->fy = (width / 2.0) / tan(hfov / 2.0);
    cam->cx = (width - 1) / 2.0;
    cam->cy = (height - 1) / 2.0;
    cam->model = RL_DIST_NONE;
}

rl_err rl_camera_check(const rl_camera *cam)
{
    int i;
    if (cam->width <= 0 || cam->height <= 0 || cam->width > RL_MAX_IMAGE_DIM ||
        cam->height > RL_MAX_IMAGE_DIM || !(cam->fx >= RL_CAMERA_MIN_F) ||
        !(cam->fx <= RL_CAMERA_MAX_F) || !(cam->fy >= RL_CAMERA_MIN_F) || !(cam->fy <= RL_CAMERA_MAX_F) ||
        !(fabs(cam->cx - 0.5 * cam->width) <= 1.5 * cam->width) ||
        !(fabs(cam->cy - 0.5 * cam->height) <= 1.5 * cam->height))
        return RL_ERANGE;
    for (i = 0; i < 8; i++)
        if (!(fabs(cam->k[i]) <= RL_CAMERA_MAX_K))
            return RL_ERANGE;
    return RL_OK;
}

void rl_camera_distort(const rl_camera *cam, double x, double y, double *xd, double *yd)
{
    const double *k = cam->k;
    double r2, r4, r6, radial, xy;
    if (cam->model == RL_DIST_NONE) {
        *xd = x;
        *yd = y;
        return;
    }
    r2 = x * x + y * y;
    r4 = r2 * r2;
    r6 = r4 * r2;
    xy = x * y;
    radial = (1.0 + k[0] * r2 + k[1] * r4 + k[4] * r6) / (1.0 + k[5] * r2 + k[6] * r4 + k[7] * r6);
    *xd = x * radial + 2.0 * k[2] * xy + k[3] * (r2 + 2.0 * x * x);
    *yd = y * radial + k[2] * (r2 + 2.0 * y * y) + 2.0 * k[3] * xy;
}

/* Fixed-point iterations; converges for the mild distortion of the lenses
 * in use and stops early once the step is below 1e-12. */
#define UNDISTORT_ITERATIONS 40

void rl_camera_undistort(const rl_camera *cam, double xd, double yd, double *x, double *y)
{
    const double *k = cam->k;
    double ux = xd, uy = yd;
    int i;
    if (cam->model == RL_DIST_NONE) {
        *x = xd;
        *y = yd;
        return;
    }
    for (i = 0; i < UNDISTORT_ITERATIONS; i++) {
        double r2 = ux * ux + uy * uy, r4 = r2 * r2, r6 = r4 * r2;
        double icdist = (1.0 + k[5] * r2 + k[6] * r4 + k[7] * r6) /
                        (1.0 + k[0] * r2 + k[1] * r4 + k[4] * r6);
        double dx = 2.0 * k[2] * ux * uy + k[3] * (r2 + 2.0 * ux * ux);
        double dy = k[2] * (r2 + 2.0 * uy * uy) + 2.0 * k[3] * ux * uy;
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

void rl_camera_project(const rl_camera *cam, double x, double y, double *u, double *v)
{
    double xd, yd;
    rl_camera_distort(cam, x, y, &xd, &yd);
    *u = cam->fx * xd + cam->cx;
    *v = cam->fy * yd + cam->cy;
}

void rl_camera_unproject(const rl_camera *cam, double u, double v, double *x, double *y)
{
    rl_camera_undistort(cam, (u - cam->cx) / cam->fx, (v - cam->cy) / cam->fy, x, y);
}
