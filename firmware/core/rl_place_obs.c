/* rl_place_obs: a frame's landmarks for the place search (rl_place_obs.h). */
#include "rl_place_obs.h"

#include <math.h>

/* Detections on the ceiling, complete ones first, then nearest the image
 * centre (the best measured propose first). */
void rl_place_obs_make(const rl_place *pl, const rl_calib *cam, const rl_mount *mount, const rl_detection *lm, int n,
                       const rl_offsets *offsets, rl_place_obs *o)
{
    double key[RL_MAX_LANDMARKS];
    int i, j;
    o->n = 0;
    o->mx = mount->x;
    o->my = mount->y;
    o->cz = mount->z;
    o->Z = pl->map->ceiling_height - mount->z;
    /* landmarks hung down to the camera are never matched (usable) */
    o->spread = fmax(pl->z_hi - pl->map->ceiling_height,
                     pl->map->ceiling_height - fmax(pl->z_lo, mount->z + RL_POSE_MIN_DEPTH)) / o->Z;
    for (i = 0; i < n && i < RL_MAX_LANDMARKS; i++) {
        double x, y, du = lm[i].u - cam->cx, dv = lm[i].v - cam->cy, k;
        if (!(fabs(lm[i].u - 0.5 * cam->width) <= 1.5 * cam->width) ||
            !(fabs(lm[i].v - 0.5 * cam->height) <= 1.5 * cam->height) ||
            !rl_family_valid(&pl->map->family, lm[i].id) ||
            !rl_pose_level_point(cam, pl->map, mount, offsets, &lm[i], &x, &y))
            continue;
        k = (lm[i].complete ? 0 : 1e12) + du * du + dv * dv;
        for (j = o->n++; j > 0 && key[j - 1] > k; j--) {
            key[j] = key[j - 1];
            o->det[j] = o->det[j - 1];
            o->id[j] = o->id[j - 1];
            o->px[j] = o->px[j - 1];
            o->py[j] = o->py[j - 1];
        }
        key[j] = k;
        o->det[j] = i;
        o->id[j] = lm[i].id;
        o->px[j] = x;
        o->py[j] = y;
    }
}


double rl_place_obs_distance(const rl_place_obs *o, int i, int j)
{
    return hypot(o->px[i] - o->px[j], o->py[i] - o->py[j]);
}


/* 1 when map landmark m hangs far enough above the camera to be matched. */
int rl_place_obs_usable(const rl_place *pl, const rl_place_obs *o, int m)
{
    return pl->map->lm[m].z <= 0 || pl->map->lm[m].z - o->cz >= RL_POSE_MIN_DEPTH;
}


/* Observation k's point were it map landmark m (at m's height). */
void rl_place_obs_at(const rl_place *pl, const rl_place_obs *o, int k, int m, double *x, double *y)
{
    double z = pl->map->lm[m].z, r;
    if (!(z > 0)) { /* on the ceiling */
        *x = o->px[k];
        *y = o->py[k];
        return;
    }
    r = (z - o->cz) / o->Z;
    *x = o->mx + r * (o->px[k] - o->mx);
    *y = o->my + r * (o->py[k] - o->my);
}

/* How far observation k's point may move with the height of the map
 * landmark it is (0 on a map of one plane). */
double rl_place_obs_slack(const rl_place_obs *o, int k)
{
    return o->spread > 0 ? o->spread * hypot(o->px[k] - o->mx, o->py[k] - o->my) : 0.0;
}


/* Observations i and j's distance were they map landmarks a and b. */
double rl_place_obs_distance_at(const rl_place *pl, const rl_place_obs *o, int i, int j, int a, int b)
{
    double ix, iy, jx, jy;
    if (o->spread <= 0)
        return rl_place_obs_distance(o, i, j);
    rl_place_obs_at(pl, o, i, a, &ix, &iy);
    rl_place_obs_at(pl, o, j, b, &jx, &jy);
    return hypot(ix - jx, iy - jy);
}
