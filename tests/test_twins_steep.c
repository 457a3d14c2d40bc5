/* rl_twins_steep (docs/design.md, rule 9) reads less than it decides:
 * its 2.6 read stops at the first scale past the id's own three where a
 * rival reaches the id (rl_twins_lead_reached), and the frame's evidence
 * is weighed at the first doubted read, the reads left unasked where it
 * says linear (rl_twins_steep_settle). Both must decide what the plain
 * order decides; the oracle here is the plain order itself, from the
 * full lead read (rl_twins_lead at 0.91 .. 1.09, every scale) and every
 * asked read's doubt before the evidence.
 *
 * Landmarks: the recognizer's reads of tests/frames/steep_linear_00N (a
 * 2.2 camera with processing after its curve, renderer's frames), with
 * every id of the table given in turn (so that rivals reach some and not
 * others, at their first scale or later), as global reads (the id's zone
 * twins as rivals) and local ones (every other id). Settled at gamma 1 (the frames fit a curve) and,
 * the same frames, at 2.2 (the evidence then says linear: fit through
 * gamma 1 less fit through 2.2), every read asked: both branches of the
 * evidence, each asserted to be taken. */
#include "rl_test.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_heap_recog.h"
#include "rl_png.h"
/* the static evidence, called by the oracle */
#include "rl_twins_steep.c"

#define FRAMES 4

static rl_image load(int k)
{
    char path[1024], err[256];
    const char *src = getenv("RL_SOURCE_DIR");
    rl_image img;
    snprintf(path, sizeof path, "%s/tests/frames/steep_linear_%03d.png", src ? src : ".", k);
    if (rl_png_read_gray(path, &img, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    return img;
}

/* d read with id (its rivals as the pass gives them) through tone: the
 * stopping read against the full one. Returns the full read's answer. */
static int check_reached(const rl_recog *rec, const rl_image *img, const rl_tone *tone, rl_detection d, int id,
                         int pass)
{
    int rv[RL_MAX_IDS], n, want, got;
    double fit;
    d.id = id;
    d.pass = pass;
    n = rl_twins_rivals(rec, &d, rv);
    want = !(rl_twins_lead(rec, img, tone, &d, rv, n, 1, -1, &fit) > 0);
    got = rl_twins_lead_reached(rec, img, tone, &d, rv, n);
    assert_int_equal(got, want);
    return want;
}

static void reached_decides_as_the_full_read(void **state)
{
    static rl_result res;
    int k, counts[2] = {0, 0};
    (void)state;
    for (k = 0; k < FRAMES; k++) {
        rl_recog_config cfg;
        rl_heap_recog hr;
        rl_image img = load(k);
        int i, j, t;
        rl_recog_defaults(&cfg);
        cfg.gamma = 1.0;
        rl_heap_recog_init(&hr, &cfg);
        assert_int_equal(rl_heap_recog_run(&hr, &img, &res), RL_OK);
        for (i = 0; i < res.n_landmarks; i++) {
            const rl_recog *rec = hr.rec;
            static rl_tone steep;
            const rl_tone *tones[2] = {&steep, rl_tones_other(&rec->tones, rec->tone)};
            rl_tones_steep(&rec->tones, &steep);
            for (j = 0; j < rec->templates.n; j++)
                for (t = 0; t < 2; t++) {
                    int id = rec->templates.ids[j];
                    counts[check_reached(rec, &img, tones[t], res.landmarks[i], id, RL_PASS_GLOBAL)]++;
                    counts[check_reached(rec, &img, tones[t], res.landmarks[i], id, RL_PASS_LOCAL)]++;
                }
        }
        rl_heap_recog_free(&hr);
        rl_png_free(&img);
    }
    /* both answers met */
    assert_true(counts[0] > 10);
    assert_true(counts[1] > 10);
}

/* in's landmarks, each asked, settled by rl_twins_steep_settle against
 * the plain order. Returns 1 where a doubt met evidence over the bar, -1
 * where it met evidence under it, 0 with no doubt. */
static int check_settle(const rl_recog *rec, const rl_image *img, const rl_result *in)
{
    static rl_result got, want;
    unsigned char ask[RL_MAX_LANDMARKS], doubt[RL_MAX_LANDMARKS], kept[RL_MAX_LANDMARKS];
    double none[RL_MAX_LANDMARKS], read[RL_MAX_LANDMARKS];
    int from[RL_MAX_LANDMARKS], k, m = 0, any = 0, branch = 0;
    rl_tone steep;
    rl_tone_init(&steep, RL_TONES_STEEP); /* the curve whole, as the plain order kept it */
    want = *in;
    for (k = 0; k < in->n_landmarks; k++) {
        int rv[RL_MAX_IDS], n = rl_twins_rivals(rec, &in->landmarks[k], rv);
        double fit;
        rl_detection alone = in->landmarks[k];
        ask[k] = 1;
        from[k] = in->n_landmarks - 1 - k; /* any order: kept[] and far_fit[] by it */
        none[from[k]] = NAN;
        /* every other one's fit given, as rl_twins_check gives those it read */
        alone.pass = RL_PASS_LOCAL;
        read[from[k]] = NAN;
        if (k % 2 == 0)
            rl_twins_lead(rec, img, rl_tones_other(&rec->tones, rec->tone), &alone, rv, n, 1, -1, &read[from[k]]);
        kept[from[k]] = 1;
        doubt[k] = (unsigned char)!(
            rl_twins_lead(rec, img, &steep, &in->landmarks[k], rv, n, 1, -1, &fit) > 0);
        any |= doubt[k];
    }
    if (any) {
        branch = curve_evidence(rec, img, in, from, none) > RL_TWINS_STEEP_FRAME ? 1 : -1;
        if (branch > 0) {
            for (k = 0; k < in->n_landmarks; k++)
                if (!doubt[k])
                    want.landmarks[m++] = in->landmarks[k];
            want.n_landmarks = m;
        }
    }
    got = *in;
    rl_twins_steep_settle(rec, img, &got, ask, from, read, kept);
    assert_int_equal(got.n_landmarks, want.n_landmarks);
    assert_int_equal(got.n_unidentified, in->n_unidentified + in->n_landmarks - want.n_landmarks);
    for (k = 0; k < want.n_landmarks; k++) {
        assert_int_equal(got.landmarks[k].id, want.landmarks[k].id);
        assert_true(got.landmarks[k].u == want.landmarks[k].u);
    }
    for (k = 0; k < in->n_landmarks; k++)
        assert_int_equal(kept[from[k]], !(branch > 0 && doubt[k]));
    return branch;
}

static void settle_decides_as_the_plain_order(void **state)
{
    static rl_result res, twins;
    static const double gammas[2] = {1.0, 2.2};
    int k, g, branches[3] = {0, 0, 0};
    (void)state;
    for (k = 0; k < FRAMES; k++) {
        rl_image img = load(k);
        for (g = 0; g < 2; g++) {
            rl_recog_config cfg;
            rl_heap_recog hr;
            int i, tw[RL_MAX_IDS];
            rl_recog_defaults(&cfg);
            cfg.gamma = gammas[g];
            rl_heap_recog_init(&hr, &cfg);
            assert_int_equal(rl_heap_recog_run(&hr, &img, &res), RL_OK);
            branches[check_settle(hr.rec, &img, &res) + 1]++;
            /* the reads given their first zone twin's id: more doubts */
            twins = res;
            for (i = 0; i < twins.n_landmarks; i++)
                if (rl_family_zone_twins(&hr.rec->templates.fam, twins.landmarks[i].id, tw) > 0)
                    twins.landmarks[i].id = tw[0];
            branches[check_settle(hr.rec, &img, &twins) + 1]++;
            rl_heap_recog_free(&hr);
        }
        rl_png_free(&img);
    }
    /* a doubt met evidence over the bar, and under it */
    assert_true(branches[2] > 0);
    assert_true(branches[0] > 0);
}

/* The steep curve made from its 512 B gathers as the whole curve would:
 * its packed words rl_tone_init's, level by level, and its light within
 * half a step of the curve's, for a configured gamma and auto. */
static void steep_curve_is_the_whole_curve(void **state)
{
    static const double gammas[3] = {1.0, 2.2, 0.0};
    int g, v;
    (void)state;
    for (g = 0; g < 3; g++) {
        rl_tones ts;
        rl_tone whole, made;
        rl_tones_init(&ts, gammas[g]);
        rl_tone_init(&whole, RL_TONES_STEEP);
        rl_tones_steep(&ts, &made);
        for (v = 0; v < 256; v++) {
            double l = RL_TONE_MAX * pow(v / 255.0, 2.6);
            assert_true(made.packed[v] == whole.packed[v]);
            assert_true(fabs(made.light[v] - l) <= 0.5);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reached_decides_as_the_full_read),
        cmocka_unit_test(settle_decides_as_the_plain_order),
        cmocka_unit_test(steep_curve_is_the_whole_curve),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
