/* What a local try no longer reads twice (issue 43), held to reading it
 * again: the old computations are kept here as the oracle, and the new
 * ones must give the same bits.
 *
 * - rl_edge_fit_arc samples its rays once: it counted the circle against
 *   rl_edge_points from the start and fitted rl_edge_fit_rays from the
 *   same start, which samples the same rays again. Oracle: those two
 *   public calls and the count within max(1 px, r / 25).
 * - the search's twin check (rl_search.c) takes its profile at scale 1
 *   from the search (the last profile kept, or the circle's where none
 *   was; across the motion the read's own) instead of making it again.
 *   Its ids one zone away are scored from the first match's column sums
 *   (rl_match_kept, in the caller's block) and its twins at scale 1
 *   from the sums of the profile last matched. Oracle: the search and
 *   the reads across the motion as they were, copied below, every
 *   profile made and every id scored on it.
 * - the local pass's ellipse twins (rl_local.c) take the profile at the
 *   ellipse's own radius from local_ellipse. Oracle: every radius
 *   gathered, as before.
 *
 * The frames: ring5 landmarks drawn by rl_raster (a circle, or flattened
 * to an ellipse by reading its rows spread out), ink on paper with noise,
 * some next to a light patch and some cut by the border; the circles read
 * from start a few px and a few percent off the truth. */
#include "rl_test.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rl_raster.h"
#include "rl_recog.h"
/* the statics held to their old selves */
#include "rl_search.c"
#include "rl_local.c"

#define W 200
#define H 160
#define PAPER 205
#define INK 35
#define LIGHT 250
static uint8_t px[W * H], dk[W * (2 * H)];
static rl_polar pol_new, pol_old;
static rl_tone tone; /* the drawing is linear in grey */
static uint8_t wsmem[1 << 20];
static rl_templates tt;

static unsigned rnd_state = 2463534242u;
static double urand(void) /* [0, 1) */
{
    rnd_state ^= rnd_state << 13;
    rnd_state ^= rnd_state >> 17;
    rnd_state ^= rnd_state << 5;
    return (rnd_state >> 8) / 16777216.0;
}

/* Landmark id at (cx, cy), radius r across and r * flat down (flat 1: a
 * circle), noise of +-noise grey levels, a light patch (LIGHT and over)
 * at lx, ly (lx < 0: none). */
static rl_image draw(int id, double cx, double cy, double r, double flat, int noise, int lx, int ly)
{
    rl_family f = {5};
    rl_image d = rl_image_view(W, 2 * H, W, dk);
    int x, y;
    assert_int_equal(rl_raster_draw(&f, id, cx, cy / flat, r, NULL, &d, NULL), RL_OK);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int sy = (int)(y / flat + 0.5), v;
            sy = sy > 2 * H - 1 ? 2 * H - 1 : sy;
            v = PAPER - (PAPER - INK) * dk[sy * W + x] / 255;
            v += (int)(urand() * (2 * noise + 1)) - noise;
            if (lx >= 0 && abs(x - lx) < 12 && abs(y - ly) < 9)
                v = LIGHT + (int)(urand() * 6);
            px[y * W + x] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
        }
    return rl_image_view(W, H, W, px);
}

static rl_match_kept *kept_sums;

static void setup_templates(void)
{
    rl_family f = {5};
    rl_ws ws;
    rl_tone_init(&tone, 1.0);
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_templates_init(&tt, &ws, &f, NULL, 0), RL_OK);
    assert_int_equal(rl_match_kept_init(&kept_sums, &ws, &tt), RL_OK); /* the search's scratch */
}

/* A drawn frame and a start near its ring. */
typedef struct {
    int id, lx, ly;
    double cx, cy, r, flat, x0, y0, r0;
} scene;

static scene random_scene(int k, double max_flat)
{
    scene s;
    int ids = 0, cut = k % 5 == 0;
    while (!rl_family_valid(&tt.fam, ids = (int)(urand() * 32)))
        ;
    s.id = ids;
    s.r = 16 + urand() * 30;
    s.flat = max_flat < 1 ? max_flat + urand() * (1 - max_flat) : 1.0;
    s.cx = cut ? s.r * (0.55 + 0.4 * urand()) : W / 2 + (urand() - 0.5) * 40;
    s.cy = H / 2 + (urand() - 0.5) * 30;
    s.lx = k % 3 == 0 ? (int)(s.cx + 1.4 * s.r) : -1;
    s.ly = (int)s.cy;
    s.x0 = s.cx + (urand() - 0.5) * 4;
    s.y0 = s.cy + (urand() - 0.5) * 4;
    s.r0 = s.r * (0.9 + 0.2 * urand());
    return s;
}

/* ---- the arc fallback ---- */

static int old_fit_arc(const rl_image *img, double *cx, double *cy, double *r)
{
    double ex[RL_EDGE_RAYS], ey[RL_EDGE_RAYS], tol;
    int n = rl_edge_points(img, &tone, LIGHT, *cx, *cy, *r, ex, ey), i, near = 0;
    if (!rl_edge_fit_rays(img, &tone, LIGHT, cx, cy, r))
        return 0;
    tol = *r / 25.0 > 1.0 ? *r / 25.0 : 1.0;
    for (i = 0; i < n; i++)
        near += fabs(hypot(ex[i] - *cx, ey[i] - *cy) - *r) <= tol;
    return near >= RL_EDGE_ARC_MIN_POINTS;
}

static void arc_samples_once(void **state)
{
    int k, taken = 0, refused = 0, failed = 0;
    (void)state;
    setup_templates();
    for (k = 0; k < 400; k++) {
        scene s = random_scene(k, k % 2 ? 0.7 : 1.0);
        rl_image img = draw(s.id, s.cx, s.cy, s.r, s.flat, 30 + k % 40, s.lx, s.ly);
        /* starts from off the ring too: the fallback's from a candidate's
         * centre, a landmark's width away at times */
        double off = k % 4 == 3 ? 0.6 * s.r : 0.0;
        double x = s.x0 + off, y = s.y0, r = s.r0, ox = x, oy = y, orr = r;
        int got = rl_edge_fit_arc(&img, &tone, LIGHT, &x, &y, &r), want = old_fit_arc(&img, &ox, &oy, &orr);
        assert_int_equal(got, want);
        assert_true(x == ox && y == oy && r == orr);
        if (got)
            taken++;
        else if (x != s.x0 + off || r != s.r0)
            refused++; /* a circle fitted, too few points near it */
        else
            failed++;
    }
    printf("arc fallback: %d taken, %d fitted and refused, %d no circle: the same as the oracle's\n", taken,
           refused, failed);
    assert_true(taken > 50 && refused > 5 && failed > 5);
}

/* ---- the search, as it was ---- */

static void old_twin_check(const rl_polar *pol, double x, double y, double s, unsigned octants, rl_match *m)
{
    int rivals[RL_MAX_BITS], n = rl_family_zone_twins(&tt.fam, m->id, rivals), k;
    for (k = 0; n > 0 && k < RL_SEARCH_TWIN_SCALES; k++) {
        rl_profile p;
        rl_match mm;
        rl_polar_profile_octants(pol, x, y, s * rl_search_twin_scale[k], octants, &p);
        rl_match_ids(&tt, &p, rivals, n, -1, &mm);
        if (mm.id >= 0 && mm.score > m->second)
            m->second = mm.score;
    }
}

/* a try and the crosses as the search made them: each try's octants
 * moved to its centre anew (rl_polar_profile), st->at not used */
static double old_search_try(const rl_polar *pol, search_state *st, double x, double y, double s)
{
    rl_profile p;
    rl_match mm;
    rl_polar_profile(pol, x, y, s, &p);
    rl_match_list_score(&st->likely, &p, &mm);
    if (mm.score > st->score) {
        st->score = mm.score;
        st->x = x;
        st->y = y;
        st->s = s;
        st->best = p;
    }
    return mm.score;
}

static void old_search_crosses(const rl_polar *pol, search_state *st)
{
    static const int dir[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int it, k;
    for (it = 0; it < SEARCH_ROUNDS; it++) {
        double cx0 = st->x, cy0 = st->y, cs0 = st->s, f0 = st->score, fv[6], off[3];
        double step = search_shift[it], sstep = search_scale[it];
        for (k = 0; k < 6; k++)
            fv[k] = old_search_try(pol, st, cx0 + dir[k][0] * step, cy0 + dir[k][1] * step,
                                   cs0 * (1.0 + dir[k][2] * sstep));
        if (st->x != cx0 || st->y != cy0 || st->s != cs0)
            continue;
        for (k = 0; k < 3; k++) {
            double den = fv[2 * k] - 2 * f0 + fv[2 * k + 1];
            off[k] = den < 0 ? 0.5 * (fv[2 * k + 1] - fv[2 * k]) / den : 0.0;
        }
        old_search_try(pol, st, cx0 + off[0] * step, cy0 + off[1] * step, cs0 * (1.0 + off[2] * sstep));
        break;
    }
}

/* the likely ids as the search took them: the best and those one code
 * zone away that come close, each matched over the bins on its own */
static int old_likely_ids(const rl_profile *p, const rl_match *m, int *ids)
{
    int n = 0, k, bits = tt.fam.bits;
    ids[n++] = m->id;
    for (k = 1; k <= bits && n < LIKELY_IDS; k++) {
        int alt = m->id ^ (1 << (bits - k));
        rl_match mm;
        if (!rl_family_valid(&tt.fam, alt))
            continue;
        rl_match_ids(&tt, p, &alt, 1, -1, &mm);
        if (mm.id >= 0 && mm.score > m->second - 0.05)
            ids[n++] = alt;
    }
    return n;
}

static int old_identify_over(rl_polar *pol, const rl_image *img, double min_first, double min_score,
                             double *cx, double *cy, double *r, rl_match *m)
{
    rl_profile p;
    int ids[LIKELY_IDS], n;
    search_state st;
    double sweep;
    rl_polar_gather(img, &tone, *cx, *cy, *r, LIGHT, SECTOR_MIN_CONTRAST, pol);
    rl_polar_profile(pol, 0, 0, 1.0, &p);
    rl_match_all(&tt, &p, m);
    if (m->id < 0)
        return 1;
    n = old_likely_ids(&p, m, ids);
    rl_match_list_make(&tt, ids, n, m->blur, &st.likely);
    st.x = st.y = 0;
    st.s = 1.0;
    st.score = m->score;
    st.best = p;
    sweep = old_search_try(pol, &st, 0, 0, SWEEP_SCALE);
    if (m->score < min_first && sweep < min_first)
        return 0;
    old_search_crosses(pol, &st);
    if (st.x != 0 || st.y != 0 || st.s != 1.0) {
        rl_match_all(&tt, &st.best, m);
        *cx += st.x;
        *cy += st.y;
        *r *= st.s;
    }
    if (m->id >= 0 && m->score >= min_score)
        old_twin_check(pol, st.x, st.y, st.s, RL_POLAR_ALL, m);
    return 1;
}

static void old_across_motion(const rl_polar *pol, double cx, double cy, double r, int id, int max_blur,
                              const unsigned *reads, int n_reads, rl_match *m)
{
    double x = cx - pol->cx, y = cy - pol->cy, s = r / pol->r;
    int a;
    m->id = -1;
    m->score = m->second = m->contrast = 0;
    m->blur = 0;
    for (a = 0; a < n_reads; a++) {
        rl_profile p;
        rl_match ma;
        rl_polar_profile_octants(pol, x, y, s, reads[a], &p);
        rl_match_all(&tt, &p, &ma);
        if (ma.id != id || ma.blur > max_blur)
            continue;
        if (m->id >= 0 && ma.second >= 0 && rl_accept_lead(&ma) <= rl_accept_lead(m))
            continue;
        old_twin_check(pol, x, y, s, reads[a], &ma);
        if (m->id < 0 || rl_accept_lead(&ma) > rl_accept_lead(m))
            *m = ma;
    }
}

static void same_match(const rl_match *a, const rl_match *b)
{
    assert_int_equal(a->id, b->id);
    assert_int_equal(a->blur, b->blur);
    assert_true(a->score == b->score && a->second == b->second && a->contrast == b->contrast);
}

static void search_twins_once(void **state)
{
    static const double floors[3] = {-INFINITY, 0.5, 0.9};
    int k, searched = 0, moved = 0, stayed_twins = 0, twins = 0, across = 0, raised = 0;
    (void)state;
    setup_templates();
    for (k = 0; k < 300; k++) {
        scene s = random_scene(k, k % 3 == 1 ? 0.75 : 1.0);
        rl_image img = draw(s.id, s.cx, s.cy, s.r, s.flat, 20 + k % 60, s.lx, s.ly);
        double min_first = floors[k % 3], min_score = k % 2 ? 0.0 : 0.75;
        double x, y, r, ox, oy, orr;
        rl_match m, om;
        int got, want;
        if (k % 4 == 0) {
            /* from the true circle, where the search often stays (the
             * twin check's profile then the circle's own) */
            s.x0 = s.cx;
            s.y0 = s.cy;
            s.r0 = s.r;
            if (k % 8 == 0)
                img = draw(s.id, s.cx, s.cy, s.r, 1.0, 2, -1, 0);
        }
        x = ox = s.x0;
        y = oy = s.y0;
        r = orr = s.r0;
        got = rl_search_identify_over(&tt, &pol_new, kept_sums, &img, &tone, LIGHT, min_first, min_score, &x, &y,
                                      &r, &m);
        want = old_identify_over(&pol_old, &img, min_first, min_score, &ox, &oy, &orr, &om);
        assert_int_equal(got, want);
        same_match(&m, &om);
        assert_true(x == ox && y == oy && r == orr);
        searched += got;
        moved += got && (x != s.x0 || y != s.y0 || r != s.r0);
        stayed_twins += got && x == s.x0 && y == s.y0 && r == s.r0 && m.id >= 0 && m.score >= min_score;
        twins += got && m.id >= 0 && m.score >= min_score &&
                 rl_family_zone_twins(&tt.fam, m.id, (int[RL_MAX_BITS]){0}) > 0;
        if (got && m.id >= 0) {
            /* across the motion from the circle found: every axis, every
             * pair of an octant and its mirror, every octant's half axis */
            unsigned reads[3 * RL_POLAR_AXES];
            int a, n = 0;
            rl_match ma, oa;
            for (a = 0; a < RL_POLAR_AXES; a++) {
                reads[n++] = 1u << a | 1u << rl_polar_opposite(a);
                reads[n++] = 1u << a | 1u << rl_polar_mirror(a);
                reads[n++] = 1u << a;
            }
            rl_search_across_motion(&tt, &pol_new, kept_sums, x, y, r, m.id, RL_BLUR_LEVELS, reads, n, &ma);
            old_across_motion(&pol_old, x, y, r, m.id, RL_BLUR_LEVELS, reads, n, &oa);
            same_match(&ma, &oa);
            across += ma.id >= 0;
            raised += ma.id >= 0 && ma.second > 0;
        }
    }
    printf("search: %d searched (%d moved, %d stayed and checked), %d twin checks, %d read across (%d with a "
           "rival scored): the same\n",
           searched, moved, stayed_twins, twins, across, raised);
    assert_true(searched > 150 && moved > 50 && stayed_twins > 10 && twins > 100 && across > 50);
}

/* ---- the ellipse's twins, as they were ---- */

static void old_ellipse_twins(const rl_image *img, const rl_ellipse *e, rl_match *m)
{
    int twins[2], n = rl_match_twins(&tt, m->id, twins), k;
    for (k = 0; n > 0 && k < RL_SEARCH_TWIN_SCALES; k++) {
        rl_profile p;
        rl_match mm;
        rl_profile_gather_shaped(img, &tone, e->cx, e->cy, e->r * rl_search_twin_scale[k], &e->shape, &p);
        rl_match_ids(&tt, &p, twins, n, -1, &mm);
        if (mm.id >= 0 && mm.score > m->second)
            m->second = mm.score;
    }
}

static void ellipse_twins_once(void **state)
{
    rl_recog_config cfg;
    rl_recog *rec;
    size_t size;
    void *mem;
    static rl_result res;
    int k, fitted = 0, with_twins = 0;
    (void)state;
    rl_recog_defaults(&cfg);
    cfg.gamma = 1.0;
    size = rl_recog_workspace_size(W, H, &cfg);
    assert_true(size > 0);
    mem = malloc(size);
    assert_non_null(mem);
    assert_int_equal(rl_recog_init(&rec, &cfg, W, H, mem, size), RL_OK);
    tt = rec->templates;
    tone = *rec->tone;
    for (k = 0; k < 200; k++) {
        scene s = random_scene(k, 0.65);
        rl_image img = draw(s.id, s.cx, s.cy, s.r, s.flat, 15 + k % 40, s.lx, s.ly);
        rl_ellipse e;
        rl_match m, om;
        rl_profile p, fresh;
        double span;
        assert_int_equal(rl_recog_run(rec, &img, &res), RL_OK);
        if (!local_ellipse(rec, &img, &res, s.x0, s.y0, s.r0, &e, &m, &span, &p))
            continue;
        fitted++;
        /* the profile handed out is the ellipse's own, as gathered anew */
        rl_profile_gather_shaped(&img, rec->tone, e.cx, e.cy, e.r, &e.shape, &fresh);
        assert_memory_equal(&p, &fresh, sizeof p);
        rl_match_all(&tt, &fresh, &om); /* its match */
        same_match(&m, &om);
        if (m.id < 0)
            continue;
        om = m;
        ellipse_twins(&rec->templates, &img, rec->tone, &e, &p, &m);
        old_ellipse_twins(&img, &e, &om);
        same_match(&m, &om);
        with_twins += rl_match_twins(&rec->templates, m.id, (int[2]){0, 0}) > 0;
    }
    printf("ellipses: %d fitted, %d with twins scored: the same\n", fitted, with_twins);
    assert_true(fitted > 40 && with_twins > 20);
    free(mem);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(arc_samples_once),
        cmocka_unit_test(search_twins_once),
        cmocka_unit_test(ellipse_twins_once),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
