/* The tone curve's choice (rl_tones): votes worked out by hand. A vote
 * fades by 0.9 a frame, so n frames that each give the same curve a vote
 * leave it 10 (1 - 0.9^n): at least 6 (settled) from n = 9 on, 5.70 at
 * n = 8. A frame whose curves identify as many landmarks (at least one)
 * votes for the current curve; a frame with none votes for neither and
 * leaves the votes as they were. */
#include "rl_test.h"
#include <math.h>
#include "rl_tones.h"

/* One frame read through what rl_tones_to_try asks, the current curve
 * identifying cur landmarks and the other one other; how many curves
 * were read. */
static int frame(rl_tones *ts, int cur, int other)
{
    int which[RL_TONES_MAX], found[RL_TONES_MAX], n = rl_tones_to_try(ts, which), k;
    for (k = 0; k < n; k++)
        found[k] = which[k] == ts->current ? cur : other;
    rl_tones_vote(ts, which, n, found);
    return n;
}

static void test_ties_settle_on_the_current_curve(void **state)
{
    rl_tones ts;
    int i;
    (void)state;
    rl_tones_init(&ts, 0.0);
    assert_true(rl_tones_gamma(&ts) == 2.2);
    for (i = 0; i < 8; i++)
        assert_int_equal(frame(&ts, 7, 7), 2);
    assert_non_null(rl_tones_doubt(&ts, rl_tones_current(&ts))); /* 5.70 votes */
    assert_int_equal(frame(&ts, 7, 7), 2);                        /* the ninth: 6.13 */
    assert_null(rl_tones_doubt(&ts, rl_tones_current(&ts)));
    assert_true(rl_tones_gamma(&ts) == 2.2);
    /* settled: one curve a frame, both again on every 16th */
    for (i = 9; i < 16; i++)
        assert_int_equal(frame(&ts, 7, 7), 1);
    assert_int_equal(frame(&ts, 7, 7), 2);
    assert_int_equal(frame(&ts, 7, 7), 1);
}

static void test_empty_frames_do_not_vote(void **state)
{
    rl_tones ts;
    int i;
    (void)state;
    rl_tones_init(&ts, 0.0);
    for (i = 0; i < 40; i++)
        assert_int_equal(frame(&ts, 0, 0), 2);
    assert_non_null(rl_tones_doubt(&ts, rl_tones_current(&ts)));
}

/* An empty frame says nothing: a settled curve whose every-16th check
 * falls on frames with no landmark stays settled (6.13 votes faded would
 * be 5.52, and each frame read twice again). */
static void test_empty_frames_keep_the_curve_settled(void **state)
{
    rl_tones ts;
    int i;
    (void)state;
    rl_tones_init(&ts, 0.0);
    for (i = 0; i < 9; i++)
        assert_int_equal(frame(&ts, 7, 7), 2); /* 6.13 votes: settled */
    assert_null(rl_tones_doubt(&ts, rl_tones_current(&ts)));
    for (i = 9; i < 16; i++)
        assert_int_equal(frame(&ts, 0, 0), 1);
    assert_int_equal(frame(&ts, 0, 0), 2);     /* the 16th: both curves, none found */
    assert_null(rl_tones_doubt(&ts, rl_tones_current(&ts)));
    assert_int_equal(frame(&ts, 0, 0), 1);
    assert_int_equal(frame(&ts, 7, 7), 1);
}

static void test_the_better_curve_takes_over(void **state)
{
    rl_tones ts;
    int which[RL_TONES_MAX];
    (void)state;
    rl_tones_init(&ts, 0.0);
    /* three frames where the linear curve identifies one more: 1, 1.9,
     * then 2.71 votes against 0, a lead over 2: it becomes the current curve */
    frame(&ts, 5, 6);
    frame(&ts, 5, 6);
    assert_true(rl_tones_gamma(&ts) == 2.2);
    frame(&ts, 5, 6);
    assert_true(rl_tones_gamma(&ts) == 1.0);
    /* a frame is read through the other curve when it finds two more */
    assert_int_equal(rl_tones_to_try(&ts, which), 2);
    assert_int_equal(rl_tones_vote(&ts, which, 2, (int[]){3, 5}), 1);
    assert_int_equal(rl_tones_to_try(&ts, which), 2);
    assert_int_equal(rl_tones_vote(&ts, which, 2, (int[]){4, 5}), 0);
}

static void test_a_tie_between_holds_the_current_curve(void **state)
{
    rl_tones ts;
    (void)state;
    rl_tones_init(&ts, 0.0);
    /* linear one more twice (1.9 against 0), a tie (2.2 gets 1, linear
     * 1.71), linear one more (0.9 against 2.54): a lead of 1.64, short of 2 */
    frame(&ts, 5, 6);
    frame(&ts, 5, 6);
    frame(&ts, 5, 5);
    frame(&ts, 5, 6);
    assert_true(rl_tones_gamma(&ts) == 2.2);
    /* one more such frame: 0.81 against 3.29, a lead of 2.48 */
    frame(&ts, 5, 6);
    assert_true(rl_tones_gamma(&ts) == 1.0);
}

static void test_a_configured_curve_is_the_only_one(void **state)
{
    rl_tones ts;
    int which[RL_TONES_MAX];
    (void)state;
    rl_tones_init(&ts, 1.8);
    assert_int_equal(rl_tones_to_try(&ts, which), 1);
    assert_true(rl_tones_gamma(&ts) == 1.8);
    assert_null(rl_tones_doubt(&ts, rl_tones_current(&ts)));
}

/* Issue 44: the other image formation is at hand whatever the
 * configuration: for a curve, grey levels mixed (read linearly: light of
 * grey 128 is 128/255 of the top); for a linear camera, the sRGB-like 2.2
 * ((128/255)^2.2 = 0.2195 of the top). Worked out by hand. */
static void test_the_other_formation_is_always_at_hand(void **state)
{
    rl_tones ts;
    const rl_tone *o;
    (void)state;
    rl_tones_init(&ts, 2.2);
    o = rl_tones_other(&ts, rl_tones_current(&ts));
    assert_true(o != rl_tones_current(&ts));
    assert_true(fabs(o->light[128] - RL_TONE_MAX * 128.0 / 255.0) < 0.01);
    rl_tones_init(&ts, 1.0);
    o = rl_tones_other(&ts, rl_tones_current(&ts));
    assert_true(fabs(o->light[128] - RL_TONE_MAX * 0.21952) < 0.05);
    rl_tones_init(&ts, 0.0); /* auto: 2.2 first, the other linear */
    o = rl_tones_other(&ts, rl_tones_current(&ts));
    assert_true(fabs(o->light[128] - RL_TONE_MAX * 128.0 / 255.0) < 0.01);
}

/* The vote of a frame (a copy of ts) whose curves identify cur and other:
 * what it returns, the curve it leaves current and its votes. */
static void vote_of(const rl_tones *ts, int cur, int other, int *ret, int *current, double *votes)
{
    rl_tones t = *ts;
    int which[RL_TONES_MAX], found[RL_TONES_MAX], n = rl_tones_to_try(&t, which), k;
    for (k = 0; k < n; k++)
        found[k] = which[k] == t.current ? cur : other;
    *ret = which[rl_tones_vote(&t, which, n, found)];
    *current = t.current;
    votes[0] = t.votes[0];
    votes[1] = t.votes[1];
}

/* A read through the other curve stopped where rl_tones_decided says it
 * may votes as every way the rest of it could have gone: checked against
 * rl_tones_vote itself from a fresh state, one where the other curve is
 * a vote short of taking over, and one settled on the current curve. */
static void test_a_decided_read_votes_as_the_whole_read(void **state)
{
    rl_tones start[3];
    int s, cur, other, left, rest, i;
    (void)state;
    for (s = 0; s < 3; s++)
        rl_tones_init(&start[s], 0.0);
    for (i = 0; i < 2; i++)
        frame(&start[1], 3, 4); /* the other leads by 1.9 votes */
    for (i = 0; i < 15; i++)
        frame(&start[2], 7, 7);
    /* by hand: five left after none of five through the other can at most
     * tie; six left could lead; two more than the current is clear */
    assert_true(rl_tones_decided(5, 0, 5));
    assert_false(rl_tones_decided(5, 0, 6));
    assert_true(rl_tones_decided(3, 5, 4));
    assert_false(rl_tones_decided(3, 4, 4));
    for (s = 0; s < 3; s++)
        for (cur = 0; cur <= 6; cur++)
            for (other = 0; other <= 8; other++)
                for (left = 0; left <= 6; left++) {
                    int r0, c0, r1, c1;
                    double v0[2], v1[2];
                    if (!rl_tones_decided(cur, other, left))
                        continue;
                    vote_of(&start[s], cur, other, &r0, &c0, v0);
                    for (rest = 0; rest <= left; rest++) {
                        vote_of(&start[s], cur, other + rest, &r1, &c1, v1);
                        assert_int_equal(r0, r1);
                        assert_int_equal(c0, c1);
                        assert_true(v0[0] == v1[0] && v0[1] == v1[1]);
                    }
                }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ties_settle_on_the_current_curve),
        cmocka_unit_test(test_empty_frames_do_not_vote),
        cmocka_unit_test(test_empty_frames_keep_the_curve_settled),
        cmocka_unit_test(test_the_better_curve_takes_over),
        cmocka_unit_test(test_a_tie_between_holds_the_current_curve),
        cmocka_unit_test(test_a_configured_curve_is_the_only_one),
        cmocka_unit_test(test_the_other_formation_is_always_at_hand),
        cmocka_unit_test(test_a_decided_read_votes_as_the_whole_read),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
