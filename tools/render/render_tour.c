#include "render_tour.h"

#include <math.h>
#include <stdint.h>

static double uniform(uint64_t *s, double lo, double hi)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return lo + (hi - lo) * (double)(*s >> 11) / 9007199254740992.0;
}

static uint64_t start(unsigned long seed, uint64_t kind)
{
    uint64_t s = 0x2545F4914F6CDD1Dull ^ ((uint64_t)seed * 0x9E3779B97F4A7C15ull) ^ kind;
    int i;
    for (i = 0; i < 8; i++)
        (void)uniform(&s, 0, 1);
    return s;
}

void render_random_poses(const render_area *a, unsigned long seed, int n, render_pose *out)
{
    uint64_t s = start(seed, 0x72616E646F6Dull);
    int k;
    for (k = 0; k < n; k++) {
        out[k].x = uniform(&s, a->x0, a->x1);
        out[k].y = uniform(&s, a->y0, a->y1);
        out[k].yaw = uniform(&s, -M_PI, M_PI);
        out[k].jumped = 0;
    }
}

/* One frame of a drive: turn towards `want` by at most `turn`, then
 * `step` ahead. */
static void steer(double want, double turn, double step, double *x, double *y, double *yaw)
{
    double d = atan2(sin(want - *yaw), cos(want - *yaw));
    *yaw += fmax(-turn, fmin(turn, d));
    *x += step * cos(*yaw);
    *y += step * sin(*yaw);
}

static void put_pose(double x, double y, double yaw, render_pose *p)
{
    p->x = x;
    p->y = y;
    p->yaw = atan2(sin(yaw), cos(yaw));
    p->jumped = 0;
}

void render_edge(const render_area *a, unsigned long seed, int n, double step, render_pose *out)
{
    uint64_t s = start(seed, 0x65646765ull);
    double x = a->x0 + 1.5, y = a->y0 + 1.0, yaw = -M_PI / 2, phase = uniform(&s, 0, 2 * M_PI);
    int k;
    for (k = 0; k < n; k++) {
        if (k > 0) {
            /* head out of the site, then turn along its edge, weaving */
            double want = y > a->y0 - 0.75 ? -M_PI / 2 : 0.25 * sin(phase + 0.2 * k) + 0.6 * (a->y0 - 0.75 - y);
            steer(want, 0.25, step, &x, &y, &yaw);
        }
        put_pose(x, y, yaw, &out[k]);
    }
}

void render_corner(const render_area *a, unsigned long seed, int n, double step, render_pose *out)
{
    uint64_t s = start(seed, 0x636F726Eull);
    double side = a->x1 + 0.75, below = a->y0 - 0.75, phase = uniform(&s, 0, 2 * M_PI);
    double x = a->x1 - 4.5 + uniform(&s, -0.5, 0.5), y = a->y0 + 1.0, yaw = -M_PI / 2;
    int k;
    for (k = 0; k < n; k++) {
        if (k > 0) {
            /* out past the lower edge, along it, then round the corner
             * and up along the side edge, weaving */
            double weave = 0.25 * sin(phase + 0.2 * k), want, turn = 0.25;
            if (y > below && x < side)
                want = -M_PI / 2;
            else if (x < side)
                want = weave + 0.6 * (below - y);
            else {
                /* the corner taken briskly: up to 0.8 rad a frame (8 rad/s
                 * at 10 frames a second), more than the place's tracking
                 * bound allows (rl_place_config.max_turn) */
                want = M_PI / 2 + weave - 0.6 * (side - x);
                turn = 0.8;
            }
            steer(want, turn, step, &x, &y, &yaw);
        }
        put_pose(x, y, yaw, &out[k]);
    }
}

void render_tour(const render_area *a, unsigned long seed, int n, double step, render_pose *out)
{
    uint64_t s = start(seed, 0x746F7572ull);
    double x = 0.5 * (a->x0 + a->x1), y = 0.5 * (a->y0 + a->y1), yaw = uniform(&s, -M_PI, M_PI), turn = 0;
    double margin = 1.5;
    int k;
    for (k = 0; k < n; k++) {
        int jumped = k > 0 && k == n / 2;
        if (jumped) {
            x = uniform(&s, a->x0 + margin, a->x1 - margin);
            y = uniform(&s, a->y0 + margin, a->y1 - margin);
            yaw = uniform(&s, -M_PI, M_PI);
        } else if (k > 0) {
            /* wander: the turn rate drifts; near an edge steer to the middle */
            double cx = 0.5 * (a->x0 + a->x1) - x, cy = 0.5 * (a->y0 + a->y1) - y;
            turn = 0.9 * turn + uniform(&s, -0.06, 0.06);
            if (x < a->x0 + margin || x > a->x1 - margin || y < a->y0 + margin || y > a->y1 - margin) {
                double want = atan2(cy, cx) - yaw;
                turn = 0.25 * atan2(sin(want), cos(want));
            }
            yaw = atan2(sin(yaw + turn), cos(yaw + turn));
            x += step * cos(yaw);
            y += step * sin(yaw);
            x = fmin(fmax(x, a->x0), a->x1);
            y = fmin(fmax(y, a->y0), a->y1);
        }
        out[k].x = x;
        out[k].y = y;
        out[k].yaw = yaw;
        out[k].jumped = jumped;
    }
}
