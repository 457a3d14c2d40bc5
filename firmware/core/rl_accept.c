#include "rl_accept.h"

#include "rl_profile.h"
#include "rl_templates.h"

rl_accept_rule rl_accept_rule_of(const rl_recog_config *cfg, rl_pass pass)
{
    rl_accept_rule r;
    r.min_score = pass == RL_PASS_LOCAL ? cfg->local_min_score : cfg->min_score;
    r.min_lead = pass == RL_PASS_LOCAL ? cfg->local_min_lead : cfg->min_lead;
    r.min_contrast = cfg->min_contrast;
    r.max_blur = pass == RL_PASS_LOCAL ? RL_BLUR_LEVELS - 2 : RL_BLUR_LEVELS - 1;
    return r;
}

rl_accept_rule rl_accept_rule_at(const rl_recog_config *cfg, rl_pass pass, int near_light)
{
    rl_accept_rule r = rl_accept_rule_of(cfg, pass);
    if (near_light && r.max_blur > RL_BLUR_LEVELS - 2)
        r.max_blur = RL_BLUR_LEVELS - 2;
    return r;
}

double rl_accept_lead(const rl_match *m)
{
    double d = 1.0 - m->score * m->score;
    return d > 0 ? (1.0 - m->second * m->second) / d : 1e9;
}

int rl_accept(const rl_accept_rule *rule, const rl_match *m, double span)
{
    return m->id >= 0 && m->score >= rule->min_score && rl_accept_lead(m) >= rule->min_lead &&
           m->contrast >= rule->min_contrast * span && m->blur <= rule->max_blur;
}

void rl_accept_levels_at(const rl_illum *il, const rl_levels *frame, double u, double v,
                         rl_levels *local)
{
    double scale = rl_illum_scale(il, u, v);
    *local = *frame;
    local->bg *= scale;
    local->fg *= scale;
}

/* The paper's grey level in the candidate's quiet zone (1.05 R .. 1.2 R,
 * the profile's outermost bins), or -1 when nothing is seen there. */
static double quiet_zone(const rl_profile *p)
{
    double n = 0, s = 0;
    int k;
    for (k = (int)(1.05 / RL_PROFILE_EXTENT * RL_PROFILE_BINS); k < RL_PROFILE_BINS; k++) {
        n += p->n[k];
        s += p->sx[k];
    }
    return n > 0 ? RL_TONE_MAX - s / n : -1;
}

double rl_accept_span(const rl_levels *local, const rl_tone *tone, const rl_profile *p)
{
    double span = rl_tone_light(tone, local->bg) - rl_tone_light(tone, local->fg), q = quiet_zone(p);
    return q > 0 && q < span ? q : span;
}

double rl_accept_plain_share(const rl_templates *tt, const rl_illum *il, const rl_levels *frame,
                             const rl_image *img, const rl_tone *tone, double cx, double cy, double r, int id)
{
    rl_profile p;
    rl_levels local;
    rl_match m;
    double span;
    rl_profile_gather(img, tone, cx, cy, r, &p);
    rl_match_ids(tt, &p, &id, 1, -1, &m);
    rl_accept_levels_at(il, frame, cx, cy, &local);
    span = rl_accept_span(&local, tone, &p);
    return span > 0 ? m.contrast / span : 0.0;
}
