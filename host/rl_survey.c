/* rl_survey: the survey's data (frames, observations, landmarks). */
#include "rl_survey.h"

#include <stdlib.h>
#include <string.h>

void rl_survey_defaults(rl_survey_config *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    rl_mount_defaults(&cfg->mount, 0.88);
    cfg->diameter = 0.21;
    cfg->pixel_scale = 460.0;
    cfg->pixel_sigma = RL_POSE_PIXEL_SIGMA;
    cfg->radius_sigma = 0.15;
    cfg->tilt_sigma = 0.05;
    cfg->gate = 0.3;
    cfg->min_views = 2;
}

void rl_survey_init(rl_survey *sv, const rl_survey_config *cfg)
{
    memset(sv, 0, sizeof *sv);
    sv->cfg = *cfg;
}

/* Room for n elements of size sz in *p (capacity *cap, doubling). */
static int grow(void **p, int *cap, int n, size_t sz)
{
    void *q;
    int c;
    if (n <= *cap)
        return 1;
    c = *cap ? 2 * *cap : 256;
    while (c < n)
        c *= 2;
    q = realloc(*p, (size_t)c * sz);
    if (q == NULL)
        return 0;
    *p = q;
    *cap = c;
    return 1;
}

rl_err rl_survey_add_frame(rl_survey *sv, const char *name, const rl_survey_obs *obs, int n)
{
    rl_survey_frame *f;
    if (n < 0)
        return RL_EINVAL;
    if (!grow((void **)&sv->fr, &sv->cap_fr, sv->n_fr + 1, sizeof *sv->fr) ||
        !grow((void **)&sv->obs, &sv->cap_obs, sv->n_obs + n, sizeof *sv->obs))
        return RL_ENOMEM;
    f = &sv->fr[sv->n_fr];
    memset(f, 0, sizeof *f);
    f->name = strdup(name ? name : "");
    if (f->name == NULL)
        return RL_ENOMEM;
    f->first = sv->n_obs;
    f->n = n;
    if (n > 0) /* a frame without landmarks: the array may not exist yet */
        memcpy(sv->obs + sv->n_obs, obs, (size_t)n * sizeof *obs);
    sv->n_obs += n;
    sv->n_fr++;
    return RL_OK;
}

void rl_survey_free(rl_survey *sv)
{
    int i;
    for (i = 0; i < sv->n_fr; i++)
        free(sv->fr[i].name);
    free(sv->fr);
    free(sv->obs);
    free(sv->obs_lm);
    free(sv->lm);
    memset(sv, 0, sizeof *sv);
}
