/* rl_track_order: the windows' order and the reads' shift (rl_track_order.h). */
#include "rl_track_order.h"

void rl_track_shift_add(rl_track_shift *f, const rl_track_window *w, const rl_detection *d)
{
    double x = w->u - f->cu, y = w->v - f->cv, du = d->u - w->u, dv = d->v - w->v;
    f->n++;
    f->x += x;
    f->y += y;
    f->q += x * x + y * y;
    f->du += du;
    f->dv += dv;
    f->w += x * dv - y * du;
}

/* w moved as the reads so far say. */
void rl_track_shift_apply(const rl_track_shift *f, rl_track_window *w)
{
    double x = w->u - f->cu, y = w->v - f->cv, spread, a = 0;
    if (f->n == 0)
        return;
    spread = f->q - (f->x * f->x + f->y * f->y) / f->n;
    if (f->n >= 2 && spread > 400.0) /* reads 20 px apart or more tell a turn */
        a = (f->w + (f->y * f->du - f->x * f->dv) / f->n) / spread;
    w->u += (f->du + a * f->y) / f->n - a * y;
    w->v += (f->dv - a * f->x) / f->n + a * x;
}

/* The predictions reordered so that each next one lies farthest from
 * those before it, the one nearest the image centre first: the first
 * few reads span the frame (the pose from them is well conditioned). */
void rl_track_order_spread(rl_track *t, double cu, double cv)
{
    double dmin[RL_MAX_LANDMARKS]; /* squared: from each one left to those placed (i > 0) */
    int i, j;
    for (j = 0; j < t->n; j++) {
        double du = t->win[j].u - cu, dv = t->win[j].v - cv;
        dmin[j] = -(du * du + dv * dv);
    }
    for (i = 0; i < t->n; i++) {
        int best = i;
        for (j = i + 1; j < t->n; j++)
            if (dmin[j] > dmin[best])
                best = j;
        if (best != i) {
            rl_track_window w = t->win[i];
            double d = dmin[i];
            t->win[i] = t->win[best];
            t->win[best] = w;
            dmin[i] = dmin[best];
            dmin[best] = d;
        }
        for (j = i + 1; j < t->n; j++) {
            double du = t->win[j].u - t->win[i].u, dv = t->win[j].v - t->win[i].v, d2 = du * du + dv * dv;
            if (i == 0 || d2 < dmin[j])
                dmin[j] = d2;
        }
    }
}
