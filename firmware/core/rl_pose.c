#include "rl_pose.h"

#include <math.h>
#include <string.h>

void rl_mount_defaults(rl_mount *m, double z)
{
    m->x = m->y = m->yaw = 0.0;
    m->z = z;
}

int rl_offsets_terms(int degree)
{
    return degree <= 1 ? 3 : degree == 2 ? 6 : 10;
}

/* Monomials 1, u, v, u^2, uv, v^2, u^3, u^2 v, u v^2, v^3. */
static void monomials(double u, double v, double *t)
{
    t[0] = 1;
    t[1] = u;
    t[2] = v;
    t[3] = u * u;
    t[4] = u * v;
    t[5] = v * v;
    t[6] = u * u * u;
    t[7] = u * u * v;
    t[8] = u * v * v;
    t[9] = v * v * v;
}

void rl_offsets_eval(const rl_offsets *o, double u, double v, double *fwd, double *left)
{
    double t[RL_OFFSET_TERMS];
    int i, n = rl_offsets_terms(o->degree);
    monomials((u - o->u0) / o->scale, (v - o->v0) / o->scale, t);
    *fwd = *left = 0;
    for (i = 0; i < n; i++) {
        *fwd += o->cx[i] * t[i];
        *left += o->cy[i] * t[i];
    }
}

void rl_pose_ceiling_point(const rl_camera *cam, const rl_offsets *offsets, double distance,
                           double u, double v, double *fwd, double *left)
{
    if (offsets != NULL) {
        /* offsets scale with the distance to the ceiling (similar triangles) */
        double k = distance / offsets->distance;
        rl_offsets_eval(offsets, u, v, fwd, left);
        *fwd *= k;
        *left *= k;
    } else {
        double xn, yn;
        rl_camera_unproject(cam, u, v, &xn, &yn);
        /* image top (-v) is forward, +u is left */
        *fwd = -yn * distance;
        *left = xn * distance;
    }
}

typedef struct {
    int id;
    double px, py; /* observed, camera horizontal frame */
    double mx, my; /* map */
} pair_pt;

/* Least-squares rotation and translation taking p onto m (2-D Procrustes
 * without scale): the rotation angle has a closed form. */
static void rigid_fit(const pair_pt *pt, int n, double *tx, double *ty, double *yaw)
{
    double pcx = 0, pcy = 0, mcx = 0, mcy = 0, sc = 0, ss = 0, c, s;
    int i;
    for (i = 0; i < n; i++) {
        pcx += pt[i].px;
        pcy += pt[i].py;
        mcx += pt[i].mx;
        mcy += pt[i].my;
    }
    pcx /= n;
    pcy /= n;
    mcx /= n;
    mcy /= n;
    for (i = 0; i < n; i++) {
        double ax = pt[i].px - pcx, ay = pt[i].py - pcy, bx = pt[i].mx - mcx, by = pt[i].my - mcy;
        sc += ax * bx + ay * by;
        ss += ax * by - ay * bx;
    }
    *yaw = atan2(ss, sc);
    c = cos(*yaw);
    s = sin(*yaw);
    *tx = mcx - (c * pcx - s * pcy);
    *ty = mcy - (s * pcx + c * pcy);
}

rl_err rl_pose_solve(const rl_camera *cam, const rl_map *map, const rl_mount *mount,
                     const rl_detection *lm, int n, const rl_offsets *offsets, rl_pose *out)
{
    pair_pt pt[RL_MAX_LANDMARKS];
    int i, j, m = 0;
    double Z, tx, ty, yaw, c, s, sum2 = 0;
    if (cam == NULL || map == NULL || mount == NULL || out == NULL || (n > 0 && lm == NULL) ||
        n < 0 || rl_camera_check(cam) != RL_OK)
        return RL_EINVAL;
    memset(out, 0, sizeof *out);
    Z = map->ceiling_height - mount->z;
    if (!(Z > 0))
        return RL_ERANGE;
    for (i = 0; i < n && m < RL_MAX_LANDMARKS; i++) {
        int k = rl_map_find(map, lm[i].id);
        if (!(fabs(lm[i].u - 0.5 * cam->width) <= 1.5 * cam->width) ||
            !(fabs(lm[i].v - 0.5 * cam->height) <= 1.5 * cam->height)) {
            /* no camera of this size sees a landmark there */
            out->dropped[out->n_dropped++] = lm[i].id;
            continue;
        }
        if (k < 0) {
            out->n_unknown++;
            continue;
        }
        pt[m].id = lm[i].id;
        rl_pose_ceiling_point(cam, offsets, Z, lm[i].u, lm[i].v, &pt[m].px, &pt[m].py);
        pt[m].mx = map->lm[k].x;
        pt[m].my = map->lm[k].y;
        m++;
    }
    /* Consistency: distances between observed points must match the map's
     * (a rigid motion keeps them). Drop the landmark that disagrees with
     * most others until all agree; two that disagree cannot be told apart. */
    for (;;) {
        int worst = -1, worst_bad = 0;
        for (i = 0; i < m; i++) {
            int bad = 0;
            for (j = 0; j < m; j++) {
                double dp, dm;
                if (j == i)
                    continue;
                dp = hypot(pt[i].px - pt[j].px, pt[i].py - pt[j].py);
                dm = hypot(pt[i].mx - pt[j].mx, pt[i].my - pt[j].my);
                bad += fabs(dp - dm) > RL_POSE_PAIR_TOLERANCE + 0.02 * dm;
            }
            if (bad > worst_bad) {
                worst_bad = bad;
                worst = i;
            }
        }
        if (worst < 0)
            break;
        if (m <= 2) {
            /* two landmarks that disagree: neither can be trusted */
            for (i = 0; i < m; i++)
                out->dropped[out->n_dropped++] = pt[i].id;
            m = 0;
            break;
        }
        out->dropped[out->n_dropped++] = pt[worst].id;
        pt[worst] = pt[--m];
    }
    out->used = m;
    if (m < 2)
        return RL_ETOOFEW;
    rigid_fit(pt, m, &tx, &ty, &yaw);
    c = cos(yaw);
    s = sin(yaw);
    for (i = 0; i < m; i++) {
        double fx = tx + c * pt[i].px - s * pt[i].py, fy = ty + s * pt[i].px + c * pt[i].py;
        sum2 += (fx - pt[i].mx) * (fx - pt[i].mx) + (fy - pt[i].my) * (fy - pt[i].my);
    }
    out->residual = sqrt(sum2 / m);
    out->cam_x = tx;
    out->cam_y = ty;
    out->cam_yaw = yaw;
    /* robot base from the camera: yaw_cam = yaw_robot + mount yaw, and the
     * camera sits at the mount offset rotated by the robot's yaw */
    out->yaw = atan2(sin(yaw - mount->yaw), cos(yaw - mount->yaw));
    c = cos(out->yaw);
    s = sin(out->yaw);
    out->x = tx - (c * mount->x - s * mount->y);
    out->y = ty - (s * mount->x + c * mount->y);
    /* what leaves for JSON or the wire is a number, or there is no pose */
    if (!isfinite(out->x) || !isfinite(out->y) || !isfinite(out->yaw) || !isfinite(out->residual) ||
        !isfinite(out->cam_x) || !isfinite(out->cam_y) || !isfinite(out->cam_yaw) ||
        !(fabs(out->x) <= 2 * RL_MAP_MAX_COORD) || !(fabs(out->y) <= 2 * RL_MAP_MAX_COORD))
        return RL_ERANGE;
    return RL_OK;
}
