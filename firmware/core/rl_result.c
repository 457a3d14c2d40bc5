#include "rl_result.h"

#include <stddef.h>
#include <string.h>
#include "rl_geom.h"
#include "rl_median.h"

void rl_result_clear(rl_result *res, int W, int H)
{
    memset(res, 0, offsetof(rl_result, landmarks)); /* up to n_landmarks */
    res->n_unidentified = res->n_lights = 0;
    res->n_candidates = res->n_regions = res->local_tried = res->local_found = res->local_floored = res->local_box_floored = 0;
    memset(&res->dropped, 0, sizeof res->dropped);
    res->width = W;
    res->height = H;
}

/* 1 if a list holding n of cap has room; else the drop is counted. */
static int room(int n, int cap, int *dropped)
{
    if (n < cap)
        return 1;
    (*dropped)++;
    return 0;
}

int rl_result_add_landmark(rl_result *res, const rl_detection *d)
{
    if (!room(res->n_landmarks, RL_MAX_LANDMARKS, &res->dropped.landmarks))
        return 0;
    res->landmarks[res->n_landmarks++] = *d;
    return 1;
}

int rl_result_add_unidentified(rl_result *res, const rl_detection *d)
{
    if (!room(res->n_unidentified, RL_MAX_CANDIDATES, &res->dropped.candidates))
        return 0;
    res->unidentified[res->n_unidentified] = *d;
    if (d->id >= 0) /* taken, then dropped by a later check: it was read */
        res->unidentified[res->n_unidentified].best_id = d->id;
    res->unidentified[res->n_unidentified++].id = -1;
    return 1;
}

int rl_result_add_light(rl_result *res, const rl_box *b)
{
    if (!room(res->n_lights, RL_MAX_LIGHTS, &res->dropped.lights))
        return 0;
    res->lights[res->n_lights++] = *b;
    return 1;
}

double rl_result_median_radius(const rl_result *res)
{
    double r[RL_MAX_LANDMARKS];
    int i;
    for (i = 0; i < res->n_landmarks; i++)
        r[i] = res->landmarks[i].radius;
    return rl_median(r, res->n_landmarks);
}

double rl_result_light_gap(const rl_result *res, const rl_box *b)
{
    double best = 1e9;
    int i;
    for (i = 0; i < res->n_lights; i++) {
        double d = rl_geom_box_gap(&res->lights[i], b);
        if (d < best)
            best = d;
    }
    return best;
}
