#include "rl_search.h"

#include <math.h>
#include "rl_accept.h"

/* Search steps: centre (px) and radius (fraction) steps of each round,
 * after a first sweep over radii. The sweep only looks further out: an
 * edge fit that glare or the border leaves with a short arc errs inwards
 * (5-12% short), while the crosses reach 4.5% either way. */
#define SEARCH_ROUNDS 2
static const double search_shift[SEARCH_ROUNDS] = {1.0, 0.5};
static const double search_scale[SEARCH_ROUNDS] = {0.03, 0.015};
#define SWEEP_SCALE 1.06
/* Sectors with less contrast than this (light, the candidate's brightest
 * at 255) are washed out. */
#define SECTOR_MIN_CONTRAST 20.0
/* Most likely ids: the best and up to three one code zone away. */
#define LIKELY_IDS 4

const double rl_search_twin_scale[RL_SEARCH_TWIN_SCALES] = {0.95, 1.0, 1.05, 1.1};

/* Where the search stands: the best centre shift and radius scale so far,
 * their score over the likely ids at one blur, and their profile (at the
 * start the circle's own); at: the octants moved to the best centre (x, y),
 * for the tries and the twin check there at other radii. */
typedef struct {
    rl_match_list likely;
    double x, y, s, score;
    rl_profile best;
    rl_polar_shift at;
} search_state;

/* Score the likely ids with the centre moved by (x, y), its octants
 * moved there in *sh, and the radius scaled by s; kept if better. The
 * score is returned. */
static double search_try_at(const rl_polar_shift *sh, search_state *st, double x, double y, double s)
{
    rl_profile p;
    rl_match mm;
    rl_polar_shift_profile(sh, s, &p);
    rl_match_list_score(&st->likely, &p, &mm);
    if (mm.score > st->score) {
        st->score = mm.score;
        st->x = x;
        st->y = y;
        st->s = s;
        st->best = p;
        if (sh != &st->at)
            st->at = *sh;
    }
    return mm.score;
}

/* search_try_at with the octants moved to (x, y) here. */
static double search_try(const rl_polar *pol, search_state *st, double x, double y, double s)
{
    rl_polar_shift sh;
    rl_polar_shift_make(pol, x, y, RL_POLAR_ALL, &sh);
    return search_try_at(&sh, st, x, y, s);
}

/* The likely ids for first match m of profile p: the best and those one
 * code zone away that come close (a radius error confuses the outer ring
 * with zone 1). Each is scored from the sums the first match kept of p
 * (keep): the same bits as rl_match_ids on p, without a walk over the
 * bins an id. */
static int likely_ids(const rl_templates *tt, const rl_profile *p, const rl_match_kept *keep, const rl_match *m,
                      int *ids)
{
    int n = 0, k, bits = tt->fam.bits;
    ids[n++] = m->id;
    for (k = 1; k <= bits && n < LIKELY_IDS; k++) {
        int alt = m->id ^ (1 << (bits - k));
        rl_match mm;
        if (!rl_family_valid(&tt->fam, alt))
            continue;
        rl_match_kept_ids(tt, p, keep, &alt, 1, &mm);
        if (mm.id >= 0 && mm.score > m->second - 0.05)
            ids[n++] = alt;
    }
    return n;
}

/* The crosses (and a parabola's peak) around the best so far. */
static void search_crosses(const rl_polar *pol, search_state *st)
{
    static const int dir[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int it, k;
    for (it = 0; it < SEARCH_ROUNDS; it++) {
        double cx0 = st->x, cy0 = st->y, cs0 = st->s, f0 = st->score, fv[6], off[3];
        double step = search_shift[it], sstep = search_scale[it];
        /* the tries in radius keep the centre (x + 0 * step is x): its
         * octants as moved there already */
        rl_polar_shift centre = st->at;
        for (k = 0; k < 6; k++)
            fv[k] = dir[k][2] ? search_try_at(&centre, st, cx0, cy0, cs0 * (1.0 + dir[k][2] * sstep))
                              : search_try(pol, st, cx0 + dir[k][0] * step, cy0 + dir[k][1] * step, cs0);
        if (st->x != cx0 || st->y != cy0 || st->s != cs0)
            continue; /* moved: a finer cross around the new best */
        for (k = 0; k < 3; k++) {
            double den = fv[2 * k] - 2 * f0 + fv[2 * k + 1];
            off[k] = den < 0 ? 0.5 * (fv[2 * k + 1] - fv[2 * k]) / den : 0.0;
        }
        search_try(pol, st, cx0 + off[0] * step, cy0 + off[1] * step, cs0 * (1.0 + off[2] * sstep));
        break;
    }
}

/* The winner's rivals (sh: the octants read, moved to the winner's
 * centre, made once for the radii below; at_s: their profile at scale s,
 * its columns' sums in keep as its match kept them),
 * every id one code zone from it (its zone twins in
 * the two zones next to the outer ring and the ids that differ in any
 * other zone: rl_family_zone_twins), each at its best radius
 * (RL_SEARCH_TWIN_SCALES) near the found one and its best blur, read from
 * the octants of the mask: when one comes close, the evidence between the
 * two codes is close, and m->second says so. Every zone: a circle a tenth
 * of a radius off and a few percent large moves every zone's edges, and
 * the search's climb can end where a code with one inner zone changed fits
 * better than the truth (a whole 25 of isp_blur_s21 read as 29, the zone-3
 * bit set, at a radius 9% large, with 25 ahead of 29 at 0.95 of it:
 * 0.917 against 0.892). Every blur: a twin that reads well only at a
 * blurred template is the case (a list of one block, 8 columns, held the
 * second twin's sharpest blur only). Read from circles as an edge fit
 * errs, the rendered sets' landmarks passed for a zone twin 253 times
 * with that list and for the id one zone away in zone 3 80 times (4 of
 * them kept by rl_twins) with the two zone twins alone (test_search_twins;
 * docs/results.md, "The search's twin check at every blur" and "Every id
 * one zone away"). */
static void twin_check(const rl_templates *tt, const rl_polar_shift *sh, double s, const rl_profile *at_s,
                       const rl_match_kept *keep, rl_match *m)
{
    int rivals[RL_MAX_BITS], n = rl_family_zone_twins(&tt->fam, m->id, rivals), k;
    for (k = 0; n > 0 && k < RL_SEARCH_TWIN_SCALES; k++) {
        rl_profile p;
        rl_match mm;
        /* at scale 1 the profile is at_s, the caller's from the same
         * arguments (s * 1.0 is s): not made again, nor its columns summed */
        if (rl_search_twin_scale[k] != 1.0) {
            rl_polar_shift_profile(sh, s * rl_search_twin_scale[k], &p); /* the octants moved once */
            rl_match_ids(tt, &p, rivals, n, -1, &mm);
        } else {
            rl_match_kept_ids(tt, at_s, keep, rivals, n, &mm); /* at_s's sums, kept by its match */
        }
        if (mm.id >= 0 && mm.score > m->second)
            m->second = mm.score;
    }
}

void rl_search_across_motion(const rl_templates *tt, const rl_polar *pol, rl_match_kept *keep, double cx,
                             double cy, double r, int id, int max_blur, const unsigned *reads, int n_reads,
                             rl_match *m)
{
    double x = cx - pol->cx, y = cy - pol->cy, s = r / pol->r;
    int a;
    m->id = -1;
    m->score = m->second = m->contrast = 0;
    m->blur = 0; /* no read: a match of no id, every field set */
    for (a = 0; a < n_reads; a++) {
        rl_profile p;
        rl_match ma;
        rl_polar_shift sh;
        rl_polar_shift_make(pol, x, y, reads[a], &sh);
        rl_polar_shift_profile(&sh, s, &p);
        if (!rl_match_all_kept_as(tt, &p, id, max_blur, &ma, keep) || ma.id != id || ma.blur > max_blur)
            continue; /* another code, or smeared: along the motion */
        if (m->id >= 0 && ma.second >= 0 && rl_accept_lead(&ma) <= rl_accept_lead(m))
            continue; /* its twins only lower its lead (a runner-up at or over 0): it cannot lead */
        twin_check(tt, &sh, s, &p, keep, &ma);
        if (m->id < 0 || rl_accept_lead(&ma) > rl_accept_lead(m))
            *m = ma;
    }
}

void rl_search_identify(const rl_templates *tt, rl_polar *pol, rl_match_kept *keep, const rl_image *img,
                        const rl_tone *tone, int light, double min_score, double *cx, double *cy,
                        double *r, rl_match *m)
{
    (void)rl_search_identify_over(tt, pol, keep, img, tone, light, -INFINITY, min_score, cx, cy, r, m);
}

int rl_search_identify_over(const rl_templates *tt, rl_polar *pol, rl_match_kept *keep, const rl_image *img,
                            const rl_tone *tone, int light, double min_first, double min_score, double *cx,
                            double *cy, double *r, rl_match *m)
{
    rl_profile p;
    int ids[LIKELY_IDS], n;
    search_state st;
    double sweep;
    rl_polar_gather(img, tone, *cx, *cy, *r, light, SECTOR_MIN_CONTRAST, pol);
    rl_polar_shift_make(pol, 0, 0, RL_POLAR_ALL, &st.at); /* the circle's centre: its profile, the sweep's */
    rl_polar_shift_profile(&st.at, 1.0, &p);
    rl_match_all_kept(tt, &p, m, keep);
    if (m->id < 0)
        return 1;
    n = likely_ids(tt, &p, keep, m, ids);
    rl_match_list_make(tt, ids, n, m->blur, &st.likely);
    st.x = st.y = 0;
    st.s = 1.0;
    st.score = m->score;
    st.best = p; /* the profile at (0, 0, 1): the twin check's where the search stays */
    sweep = search_try_at(&st.at, &st, 0, 0, SWEEP_SCALE);
    if (m->score < min_first && sweep < min_first)
        return 0; /* neither the circle nor the step out matches any id closely */
    search_crosses(pol, &st);
    if (st.x != 0 || st.y != 0 || st.s != 1.0) {
        /* every id at every blur where the search ended (its profile as
         * the search made it) */
        rl_match_all_kept(tt, &st.best, m, keep);
        *cx += st.x;
        *cy += st.y;
        *r *= st.s;
    }
    if (m->id >= 0 && m->score >= min_score)
        twin_check(tt, &st.at, st.s, &st.best, keep, m); /* st.at: moved to st.x, st.y; keep: st.best's sums */
    return 1;
}
