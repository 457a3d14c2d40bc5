/* The local pass's polar gather (rl_polar_gather): every pixel within the
 * profile's reach counted once and light left out, at a landmark's usual
 * size and at one so large that the packed per-cell sums are moved out
 * during the gather; and the profiles it derives for a moved centre or a
 * changed radius are those of the landmark where it really is. */
#include "rl_test.h"
#include <math.h>
#include <string.h>
#include "rl_match.h"
#include "rl_polar.h"
#include "rl_raster.h"

#define S 1000
#define PAPER 215
#define INK 30
#define LIGHT 240
static uint8_t px[S * S], dk[S * S];
static rl_polar pol;
static rl_tone tone; /* the drawings are linear in grey: a linear camera */
static uint8_t wsmem[1 << 20];

/* Landmark `id` of radius r at (cx, cy) on paper, and a light patch in
 * its quiet zone to the right: 1.04 .. 1.16 r out, 0.1 r high. */
static rl_image draw(int id, double cx, double cy, double r)
{
    rl_family f = {5};
    rl_image img = rl_image_view(S, S, S, px), d = rl_image_view(S, S, S, dk);
    int x, y;
    assert_int_equal(rl_raster_draw(&f, id, cx, cy, r, NULL, &d, NULL), RL_OK);
    for (y = 0; y < S; y++)
        for (x = 0; x < S; x++) {
            double ux = x - cx, uy = y - cy;
            px[y * S + x] = (uint8_t)(PAPER - (PAPER - INK) * dk[y * S + x] / 255);
            if (ux > 1.04 * r && ux < 1.16 * r && fabs(uy) < 0.05 * r)
                px[y * S + x] = 255;
        }
    return img;
}

/* Pixels below LIGHT within 1.2 r of the centre (the profile's reach),
 * and how many lie so close to that circle that rounding may count them
 * either way. */
static void reference_count(double cx, double cy, double r, long *inside, long *edge)
{
    double reach = RL_PROFILE_EXTENT * r;
    int x, y;
    *inside = *edge = 0;
    for (y = 0; y < S; y++)
        for (x = 0; x < S; x++) {
            double d = hypot(x - cx, y - cy);
            if (px[y * S + x] >= LIGHT)
                continue;
            if (fabs(d - reach) < 1e-4 * reach)
                (*edge)++;
            else if (d < reach)
                (*inside)++;
        }
}

static void init_ident(rl_templates *id)
{
    rl_family f = {5};
    rl_ws ws;
    rl_tone_init(&tone, 1.0);
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_templates_init(id, &ws, &f, NULL, 0), RL_OK);
}

static void check_size(double r)
{
    rl_templates id;
    rl_profile p;
    rl_match m;
    long inside, edge;
    double cx = S / 2 + 0.37, cy = S / 2 - 0.21;
    rl_image img = draw(22, cx, cy, r);
    init_ident(&id);
    reference_count(cx, cy, r, &inside, &edge);
    rl_polar_gather(&img, &tone, cx, cy, r, LIGHT, 20.0, &pol);
    rl_polar_profile(&pol, 0, 0, 1.0, &p);
    if (p.total < inside - 0.5 || p.total > inside + edge + 0.5)
        fail_msg("r %.0f: %.0f pixels gathered, %ld (+%ld on the rim) within reach", r, p.total,
                 inside, edge);
    rl_match_all(&id, &p, &m);
    if (m.id != 22 || m.score < 0.97)
        fail_msg("r %.0f: id %d score %.3f, drawn 22", r, m.id, m.score);
}

static void test_counts_small(void **state)
{
    (void)state;
    check_size(24.0);
}

static void test_counts_large(void **state)
{
    (void)state;
    /* past PACK_MAX pixels per cell: the sums are moved out during the gather */
    check_size(420.0);
}

/* Gathered around a centre 1.2 px off, the profile moved back by that
 * much fits the landmark better than the one as gathered; moved the other
 * way, worse. The same for a radius 6% short. */
static void test_moved_profiles(void **state)
{
    rl_templates id;
    rl_profile p;
    rl_match as_is, back, away;
    double cx = 300.4, cy = 310.8, r = 24.0;
    rl_image img = draw(13, cx, cy, r);
    int ids[1] = {13};
    (void)state;
    init_ident(&id);
    rl_polar_gather(&img, &tone, cx - 1.2, cy + 0.6, r, LIGHT, 20.0, &pol);
    rl_polar_profile(&pol, 0, 0, 1.0, &p);
    rl_match_ids(&id, &p, ids, 1, 0, &as_is);
    rl_polar_profile(&pol, 1.2, -0.6, 1.0, &p);
    rl_match_ids(&id, &p, ids, 1, 0, &back);
    rl_polar_profile(&pol, -1.2, 0.6, 1.0, &p);
    rl_match_ids(&id, &p, ids, 1, 0, &away);
    if (!(back.score > as_is.score + 0.01 && away.score < as_is.score - 0.01))
        fail_msg("shift: as gathered %.3f, moved back %.3f, moved away %.3f", as_is.score,
                 back.score, away.score);
    rl_polar_gather(&img, &tone, cx, cy, 0.94 * r, LIGHT, 20.0, &pol);
    rl_polar_profile(&pol, 0, 0, 1.0, &p);
    rl_match_ids(&id, &p, ids, 1, 0, &as_is);
    rl_polar_profile(&pol, 0, 0, 1.0 / 0.94, &p);
    rl_match_ids(&id, &p, ids, 1, 0, &back);
    rl_polar_profile(&pol, 0, 0, 0.94, &p);
    rl_match_ids(&id, &p, ids, 1, 0, &away);
    if (!(back.score > as_is.score + 0.01 && away.score < as_is.score - 0.01))
        fail_msg("scale: as gathered %.3f, rescaled %.3f, the other way %.3f", as_is.score,
                 back.score, away.score);
    if (back.score < 0.95)
        fail_msg("rescaled to the true radius: score %.3f", back.score);
}

/* One shift of the octants (rl_polar_shift_make) read at several radii,
 * in any order and again, is the profile made anew at each
 * (rl_polar_profile_octants), bit for bit: the search reads its centre's
 * shift at three radii (the twin check) and twice in a cross. */
static void test_shift_read_at_radii(void **state)
{
    static const double scales[] = {1.0, 0.95, 1.05, 1.1, 0.95, 1.0};
    static const unsigned masks[] = {RL_POLAR_ALL, 0x41u, 0x11u, 0x03u};
    rl_image img = draw(22, 400.3, 380.6, 24.0);
    int k, j;
    (void)state;
    rl_polar_gather(&img, &tone, 401.1, 379.9, 23.0, LIGHT, 20.0, &pol);
    for (j = 0; j < 4; j++) {
        rl_polar_shift sh;
        rl_polar_shift_make(&pol, -0.8, 0.7, masks[j], &sh);
        for (k = 0; k < 6; k++) {
            rl_profile a, b;
            memset(&a, 0, sizeof a);
            memset(&b, 0, sizeof b);
            rl_polar_shift_profile(&sh, scales[k], &a);
            rl_polar_profile_octants(&pol, -0.8, 0.7, scales[k], masks[j], &b);
            assert_memory_equal(&a, &b, sizeof a);
            assert_true(a.total > 100);
        }
    }
}

/* The octants' directions after a gather are the odd multiples of 22.5
 * degrees, each once; an octant's opposite points the other way, its
 * mirror image has x's sign flipped (the octant numbering of rl_polar.h:
 * 4 for x < 0, 2 for y < 0, 1 for |x| > |y|). */
static void test_octant_directions(void **state)
{
    int o, seen = 0;
    rl_image img = draw(13, 300.0, 300.0, 24.0);
    (void)state;
    rl_polar_gather(&img, &tone, 300.0, 300.0, 24.0, LIGHT, 20.0, &pol);
    assert_int_equal(RL_POLAR_OCTANTS, 8);
    assert_int_equal(RL_POLAR_ALL, 0xFF);
    for (o = 0; o < RL_POLAR_OCTANTS; o++) {
        int p = rl_polar_opposite(o), m = rl_polar_mirror(o), k;
        double deg = atan2(pol.uy[o], pol.ux[o]) * 180.0 / M_PI;
        k = (int)floor((deg < 0 ? deg + 360.0 : deg) / 45.0);
        assert_true(fabs((deg < 0 ? deg + 360.0 : deg) - (45.0 * k + 22.5)) < 1e-6);
        seen |= 1 << k;
        assert_true((pol.ux[o] < 0) == ((o & 4) != 0) && (pol.uy[o] < 0) == ((o & 2) != 0));
        assert_true((fabs(pol.ux[o]) > fabs(pol.uy[o])) == ((o & 1) != 0));
        assert_true(fabs(pol.ux[p] + pol.ux[o]) < 1e-9 && fabs(pol.uy[p] + pol.uy[o]) < 1e-9);
        assert_true(fabs(pol.ux[m] + pol.ux[o]) < 1e-9 && fabs(pol.uy[m] - pol.uy[o]) < 1e-9);
    }
    assert_int_equal(seen, 0xFF);
}

/* Each sector's black and white, by hand: paper 215 with an ink disk (30)
 * of half the radius, no light. Groups of four bins wholly in the ink or
 * on the paper have those levels as their mean, in the table's 8 bits
 * (the brightest level, 215, at 255; a linear camera): 30 -> 36. With the
 * paper right of the centre at 150 (-> 178) the right-hand sectors'
 * white is that; and a centre left of the frame has no pixel in the
 * left-hand sectors (none usable, their levels as set). */
static void test_sector_levels(void **state)
{
    const double cx = 300.37, cy = 300.61, r = 30.0;
    int x, y, k, right;
    (void)state;
    rl_tone_init(&tone, 1.0);
    for (right = 0; right < 2; right++) {
        rl_image img = rl_image_view(S, S, S, px);
        for (y = 0; y < S; y++)
            for (x = 0; x < S; x++)
                px[y * S + x] = hypot(x - cx, y - cy) < 0.5 * r ? 30 : right && x > cx ? 150 : 215;
        rl_polar_gather(&img, &tone, cx, cy, r, 256, 20.0, &pol);
        for (k = 0; k < RL_SECTORS; k++) {
            double white = right && k < RL_SECTORS / 2 ? 178.0 : 255.0; /* sectors 8..15: x < 0 */
            if (pol.lo[k] != 36.0 || pol.hi[k] != white || !pol.usable[k])
                fail_msg("paper %s: sector %d black %.3f white %.3f (usable %d), by hand 36 and %.0f",
                         right ? "150 on the right" : "215", k, pol.lo[k], pol.hi[k], pol.usable[k], white);
        }
    }
    /* the brightest groups the fewest pixels: a small bright centre
     * (215) in dimmer paper (150) past the ink (30); the white is the
     * centre's (its groups' sums are the smallest), the black the ink's */
    {
        rl_image img = rl_image_view(S, S, S, px);
        for (y = 0; y < S; y++)
            for (x = 0; x < S; x++) {
                double d = hypot(x - cx, y - cy);
                px[y * S + x] = d < 0.3 * r ? 215 : d < 0.5 * r ? 30 : 150;
            }
        rl_polar_gather(&img, &tone, cx, cy, r, 256, 20.0, &pol);
        for (k = 0; k < RL_SECTORS; k++)
            if (pol.lo[k] != 36.0 || pol.hi[k] != 255.0)
                fail_msg("bright centre: sector %d black %.3f white %.3f, by hand 36 and 255", k, pol.lo[k],
                         pol.hi[k]);
    }
    {
        rl_image img = rl_image_view(S, S, S, px);
        rl_polar_gather(&img, &tone, -0.5, 300.61, r, 256, 20.0, &pol);
        for (k = RL_SECTORS / 2; k < RL_SECTORS; k++)
            if (pol.usable[k] || pol.lo[k] != 1e9 || pol.hi[k] != -1e9)
                fail_msg("sector %d left of the frame: black %g white %g usable %d", k, pol.lo[k], pol.hi[k],
                         pol.usable[k]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_counts_small),
        cmocka_unit_test(test_counts_large),
        cmocka_unit_test(test_moved_profiles),
        cmocka_unit_test(test_octant_directions),
        cmocka_unit_test(test_sector_levels),
        cmocka_unit_test(test_shift_read_at_radii),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
