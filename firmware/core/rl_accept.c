#include "rl_accept.h"

rl_accept_rule rl_accept_rule_of(const rl_recog_config *cfg, rl_pass pass)
{
    rl_accept_rule r;
    r.min_score = pass == RL_PASS_LOCAL ? cfg->local_min_score : cfg->min_score;
    r.min_lead = pass == RL_PASS_LOCAL ? cfg->local_min_lead : cfg->min_lead;
    r.min_contrast = cfg->min_contrast;
    return r;
}

int rl_accept(const rl_accept_rule *rule, const rl_match *m, double span)
{
    return m->id >= 0 && m->score >= rule->min_score &&
           (1.0 - m->second * m->second) >= rule->min_lead * (1.0 - m->score * m->score) &&
           m->contrast >= rule->min_contrast * span;
}
