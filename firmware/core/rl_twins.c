#include "rl_twins.h"

#include "rl_match.h"
#include "rl_profile.h"
#include "rl_result.h"

/* Radius scales a landmark and its twins are scored at: the radius was
 * read through the other curve. */
static const double scales[3] = {0.97, 1.0, 1.03};
/* How much better a twin must read through the other curve: a landmark
 * read through the right one leads its twins there too, by less (up to
 * 0.015 on wide-angle ellipses); one read through the wrong one, by more. */
#define TWIN_MARGIN 0.01

/* 1 when a zone twin of d reads clearly better than d's id through tone. */
static int twin_wins(const rl_recog *rec, const rl_image *img, const rl_tone *tone, const rl_detection *d)
{
    int twins[2], n = rl_match_twins(&rec->templates, d->id, twins), k;
    double own = -1, twin = -1;
    if (n == 0)
        return 0;
    for (k = 0; k < 3; k++) {
        rl_profile p;
        rl_match m;
        rl_profile_gather(img, tone, d->u, d->v, d->radius * scales[k], &p);
        rl_match_ids(&rec->templates, &p, &d->id, 1, -1, &m);
        if (m.id >= 0 && m.score > own)
            own = m.score;
        rl_match_ids(&rec->templates, &p, twins, n, -1, &m);
        if (m.id >= 0 && m.score > twin)
            twin = m.score;
    }
    return twin >= own + TWIN_MARGIN;
}

void rl_twins_check(const rl_recog *rec, const rl_image *img, const rl_tone *other, rl_result *res)
{
    int i, kept = 0;
    for (i = 0; i < res->n_landmarks; i++) {
        const rl_detection *d = &res->landmarks[i];
        if (d->pass == RL_PASS_LOCAL && twin_wins(rec, img, other, d))
            rl_result_add_unidentified(res, d);
        else
            res->landmarks[kept++] = *d;
    }
    res->n_landmarks = kept;
}
