/* rl_accept: when an identification is taken as a landmark, one rule for
 * both passes with thresholds from rl_recog_config (internal).
 *
 * Besides the correlation, the best id must explain the candidate clearly
 * better than any other: the runner-up's unexplained variance (1 - r^2)
 * must be min_lead times the best's. Neighbouring codes differ in one
 * zone, so a blurred true landmark has a close runner-up in r but not in
 * residual, while ring-like clutter fits many codes equally badly. And a
 * printed landmark must show the full contrast of ink on paper: grey
 * ring-like clutter (speaker grilles) correlates, but only at a fraction
 * of the grey span.
 *
 * The local pass takes no match at the blurriest templates (a Gaussian of
 * 0.10 R, wider than code zone 1): what is that soft is no print in
 * focus but a blurred object next to a light (a shade, a fixture's
 * edge), and with its sectors normalized one by one such a blob looks
 * like a disk in a ring; and a local read, whichever circle or ellipse
 * took it, still needs its id's contrast in the plain (not sector-
 * normalized) profile at RL_ACCEPT_LOCAL_SHARE of the frame's span
 * (rl_accept_plain_share). The global pass sees the whole ring at the
 * frame's levels, and a landmark smeared by motion may match there.
 *
 *   rl_accept_rule rule = rl_accept_rule_of(&cfg, RL_PASS_GLOBAL);
 *   rl_match m;
 *   rl_match_all(&tt, &p, &m);
 *   if (rl_accept(&rule, &m, res.levels.bg - res.levels.fg))
 *       use(m.id);
 */
#ifndef RL_ACCEPT_H
#define RL_ACCEPT_H

#include "rl_illum.h"
#include "rl_match.h"
#include "rl_profile.h"
#include "rl_recog.h"

typedef struct {
    double min_score;    /* Pearson correlation of the best id */
    double min_lead;     /* runner-up's residual over the best's */
    double min_contrast; /* fitted contrast, fraction of the grey span */
    int max_blur;        /* blurriest template level taken */
} rl_accept_rule;

/* The thresholds of one pass. */
rl_accept_rule rl_accept_rule_of(const rl_recog_config *cfg, rl_pass pass);

/* The same for a candidate beside a lamp (near_light 1): a soft blob there
 * (a shade, a fixture's edge out of focus) matches the softest templates,
 * so, as in the local pass, none is taken at them. */
rl_accept_rule rl_accept_rule_at(const rl_recog_config *cfg, rl_pass pass, int near_light);

/* 1 if match m passes the rule; span is the grey span its contrast is
 * measured against (the frame's background - foreground in the global
 * pass, 255 on sector-normalized levels in the local pass). */
int rl_accept(const rl_accept_rule *rule, const rl_match *m, double span);

/* How far m's winner leads its runner-up: the runner-up's residual over
 * the winner's, (1 - second^2) / (1 - score^2), as rl_accept compares it
 * with min_lead (huge for a perfect score). */
double rl_accept_lead(const rl_match *m);

/* The frame's foreground and background levels as the light falls at
 * (u, v) (rl_illum's scale there). */
void rl_accept_levels_at(const rl_illum *il, const rl_levels *frame, double u, double v,
                         rl_levels *local);

/* The span of light a candidate's contrast is judged against, from its
 * plain (not sector-normalized) profile p: the local levels' background
 * to foreground as light (tone), or less where the landmark's own paper,
 * its quiet zone, is darker (a sheet in a shadow). */
double rl_accept_span(const rl_levels *local, const rl_tone *tone, const rl_profile *p);

/* The local pass's reads (sector by sector, each sector's levels its own)
 * still need this share of the span at the read's circle
 * (rl_accept_plain_share): a ceiling thing's thin grey ring, read at a
 * landmark's size through a scaler's blur after the curve, matched id 16
 * (a plain thick ring) at 0.86-0.91 with its sectors normalized and
 * showed 0.17-0.22 of the span; right local reads 0.44 or more
 * (docs/results.md, fifteenth session). */
#define RL_ACCEPT_LOCAL_SHARE 0.3

/* The contrast id's templates fit in the plain profile of the circle
 * (cx, cy, r) of img read through tone, as a share of the span of light
 * there (rl_accept_span at the frame's levels, scaled by il's light at
 * the centre). */
double rl_accept_plain_share(const rl_templates *tt, const rl_illum *il, const rl_levels *frame,
                             const rl_image *img, const rl_tone *tone, double cx, double cy, double r, int id);

#endif
