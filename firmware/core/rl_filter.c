#include "rl_filter.h"

#include <math.h>
#include "rl_result.h"

/* 1 when detections a and b are one landmark: centres closer than the
 * larger radius (printed landmarks lie a diameter apart at least). */
static int overlap(const rl_detection *a, const rl_detection *b)
{
    double r = a->radius > b->radius ? a->radius : b->radius, dx = a->u - b->u, dy = a->v - b->v;
    return dx * dx + dy * dy < r * r;
}

void rl_filter_duplicates(rl_result *res)
{
    unsigned char keep[RL_MAX_LANDMARKS];
    int i, j, kept = 0;
    for (i = 0; i < res->n_landmarks; i++) {
        const rl_detection *d = &res->landmarks[i];
        keep[i] = 1;
        for (j = 0; j < res->n_landmarks && keep[i]; j++)
            if (j != i && overlap(&res->landmarks[j], d) &&
                (res->landmarks[j].score > d->score || (res->landmarks[j].score == d->score && j < i)))
                keep[i] = 0;
    }
    for (i = 0; i < res->n_landmarks; i++) {
        if (keep[i])
            res->landmarks[kept++] = res->landmarks[i];
        else
            rl_result_add_unidentified(res, &res->landmarks[i]);
    }
    res->n_landmarks = kept;
}

void rl_filter_size(rl_result *res, double tolerance)
{
    double med, t;
    int i, n = res->n_landmarks, kept = 0;
    if (n < 3)
        return;
    med = rl_result_median_radius(res);
    t = tolerance * med;
    for (i = 0; i < n; i++) {
        const rl_detection *d = &res->landmarks[i];
        if (fabs(d->radius - med) <= t)
            res->landmarks[kept++] = *d;
        else
            rl_result_add_unidentified(res, d);
    }
    res->n_landmarks = kept;
}

static int before(const rl_detection *a, const rl_detection *b)
{
    return a->u != b->u ? a->u < b->u : a->v < b->v;
}

void rl_filter_sort(rl_result *res)
{
    rl_detection *d = res->landmarks;
    int i, j;
    for (i = 1; i < res->n_landmarks; i++) { /* insertion sort: a few dozen at most */
        rl_detection t = d[i];
        for (j = i; j > 0 && before(&t, &d[j - 1]); j--)
            d[j] = d[j - 1];
        d[j] = t;
    }
}
