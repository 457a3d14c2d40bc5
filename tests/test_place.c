/* rl_place: the index against brute force, the map's new rules, and the
 * finder's contract on small maps worked out by hand. */
#include "rl_test.h"
#include <math.h>
#include <stdlib.h>
#include "rl_place.h"
#include "rl_place_index.h"

static rl_map map;
static unsigned char mem[1 << 20];

/* A cols x rows grid at pitch p with ids from a fixed scramble of 1..30. */
static void grid(int cols, int rows, double p)
{
    int i, j;
    memset(&map, 0, sizeof map);
    assert_int_equal(rl_family_init(&map.family, 5), RL_OK);
    map.diameter = 0.2;
    map.ceiling_height = 2.75;
    for (j = 0; j < rows; j++)
        for (i = 0; i < cols; i++) {
            rl_map_landmark *lm = &map.lm[map.count++];
            lm->id = (int)(((unsigned)(j * 7 + i * 11 + i * j * 3)) % 30u) + 1;
            lm->x = i * p;
            lm->y = j * p;
        }
}

static rl_place *build(const rl_place_config *cfg)
{
    rl_place *pl;
    size_t need = rl_place_size(&map, cfg);
    assert_true(need > 0 && need <= sizeof mem);
    assert_int_equal(rl_place_init(&pl, &map, cfg, mem, need), RL_OK);
    assert_int_equal(rl_place_bytes(pl), need);
    return pl;
}

/* The pair count and every bucket against all pairs counted by hand. */
static void index_matches_brute_force(void **state)
{
    rl_place_config cfg;
    rl_place *pl;
    int a, b;
    long brute = 0, found = 0;
    (void)state;
    grid(17, 11, 0.61);
    rl_place_defaults(&cfg);
    cfg.reach = 1.3;
    pl = build(&cfg);
    for (a = 0; a < map.count; a++)
        for (b = a + 1; b < map.count; b++) {
            double d = hypot(map.lm[a].x - map.lm[b].x, map.lm[a].y - map.lm[b].y);
            const rl_place_pair *p, *end;
            int hit = 0;
            if (d > 1.3)
                continue;
            brute++;
            /* the pair is in its ids' bucket at its distance */
            rl_place_index_pairs(pl, map.lm[a].id, map.lm[b].id, d - 0.001, d + 0.001, &p, &end);
            for (; p < end; p++)
                hit += (p->a == a && p->b == b) || (p->a == b && p->b == a);
            assert_int_equal(hit, 1);
            found++;
        }
    assert_int_equal(rl_place_pairs(pl), brute);
    assert_int_equal(found, brute);
    /* 17 x 11 at 0.61 within 1.3 m: neighbours (0.61), diagonals (0.86) and two apart (1.22) */
    assert_int_equal(brute, (16 * 11 + 17 * 10) + 2 * 16 * 10 + (15 * 11 + 17 * 9));
}

static void near_matches_brute_force(void **state)
{
    rl_place_config cfg;
    rl_place *pl;
    int k;
    uint64_t s = 12345;
    (void)state;
    grid(9, 7, 0.61);
    rl_place_defaults(&cfg);
    pl = build(&cfg);
    for (k = 0; k < 2000; k++) {
        double x, y, best = 0.2;
        int i, want = -1, id = k % 3 == 0 ? 0 : (int)(k % 30) + 1;
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        x = -1 + 7 * (double)(s >> 11) / 9007199254740992.0;
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        y = -1 + 6 * (double)(s >> 11) / 9007199254740992.0;
        for (i = 0; i < map.count; i++) {
            double d = hypot(map.lm[i].x - x, map.lm[i].y - y);
            if (d <= best && (id == 0 || map.lm[i].id == id)) {
                best = d;
                want = i;
            }
        }
        assert_int_equal(rl_place_index_near(pl, x, y, 0.2, id), want);
    }
}

static void sizes_and_refusals(void **state)
{
    rl_place_config cfg;
    rl_place *pl;
    (void)state;
    grid(5, 5, 0.61);
    rl_place_defaults(&cfg);
    assert_int_equal(rl_place_init(&pl, &map, &cfg, mem, rl_place_size(&map, &cfg) - 1), RL_ENOMEM);
    cfg.margin = 0;
    assert_int_equal(rl_place_size(&map, &cfg), 0);
    assert_int_equal(rl_place_init(&pl, &map, &cfg, mem, sizeof mem), RL_EINVAL);
    rl_place_defaults(&cfg);
    map.lm[3].x = map.lm[2].x + 0.1; /* overlapping landmarks: a bad map */
    map.lm[3].y = map.lm[2].y;
    assert_int_equal(rl_place_size(&map, &cfg), 0);
}

/* The map's rules: ids may repeat, landmarks may not overlap. */
static void map_repeats_but_never_overlaps(void **state)
{
    int bad;
    (void)state;
    grid(3, 1, 0.61);
    map.lm[2].id = map.lm[0].id;
    assert_int_equal(rl_map_check(&map, &bad), RL_OK);
    assert_true(rl_map_repeats_ids(&map));
    map.lm[2].x = map.lm[1].x + 0.19; /* closer than the diameter 0.2 */
    assert_int_equal(rl_map_check(&map, &bad), RL_EFORMAT);
    assert_int_equal(bad, 2);
    assert_int_equal(rl_map_overlapped(&map, 2), 1);
    grid(3, 1, 0.61);
    map.lm[0].id = 1, map.lm[1].id = 2, map.lm[2].id = 3;
    assert_false(rl_map_repeats_ids(&map));
}

/* Detections a level camera (straight up, at the robot's centre) sees of
 * the map's landmarks at i: projected through a pinhole by hand. */
static int view(const rl_calib *cam, const rl_mount *mount, double x, double y, double yaw, const int *which,
                int n, rl_detection *d)
{
    int k;
    for (k = 0; k < n; k++) {
        const rl_map_landmark *lm = &map.lm[which[k]];
        double dx = lm->x - x, dy = lm->y - y, Z = rl_map_height(&map, which[k]) - mount->z; /* its own height */
        double fwd = cos(yaw) * dx + sin(yaw) * dy, left = -sin(yaw) * dx + cos(yaw) * dy;
        memset(&d[k], 0, sizeof d[k]);
        d[k].id = lm->id;
        d[k].u = cam->cx + cam->fx * left / Z; /* +u is left */
        d[k].v = cam->cy - cam->fy * fwd / Z;  /* image top is forward */
        d[k].radius = 20;
        d[k].complete = 1;
    }
    return n;
}

/* A map of two copies of ids 4 5 6, at (0,0) (0.61,0) (0,0.61) and again
 * 10 m away, and the n landmarks of `more` (id, x, y) after them. */
static void two_copies(const double (*more)[3], int n)
{
    int i;
    memset(&map, 0, sizeof map);
    assert_int_equal(rl_family_init(&map.family, 5), RL_OK);
    map.diameter = 0.2;
    map.ceiling_height = 2.75;
    for (i = 0; i < 6; i++) {
        map.lm[i].id = 4 + i % 3;
        map.lm[i].x = (i % 3 == 1 ? 0.61 : 0) + (i >= 3 ? 10 : 0);
        map.lm[i].y = i % 3 == 2 ? 0.61 : 0;
    }
    for (i = 0; i < n; i++) {
        map.lm[6 + i].id = (int)more[i][0];
        map.lm[6 + i].x = more[i][1];
        map.lm[6 + i].y = more[i][2];
    }
    map.count = 6 + n;
}

/* Two copies of the same three ids in the same shape: no prior cannot
 * tell them apart (ambiguous, no pose); a fourth landmark that only one
 * copy has settles it; the prior settles it with two. */
static void copies_are_ambiguous(void **state)
{
    rl_place_config cfg;
    rl_place *pl;
    rl_calib cam;
    rl_mount mount;
    rl_detection d[4];
    rl_place_found f;
    rl_place_prior prior = {1, 0.61, 0.0, 0.0, 0.1};
    rl_pose pose;
    int both[3] = {0, 1, 2}, with_fourth[4] = {0, 1, 2, 3}, two[2] = {0, 1}, i;
    static const double seventh[1][3] = {{7, 0.61, 0.61}}; /* beside the first copy */
    (void)state;
    two_copies(seventh, 1);
    rl_place_defaults(&cfg);
    pl = build(&cfg);
    rl_calib_defaults(&cam, 640, 480, 70 * M_PI / 180);
    rl_mount_defaults(&mount, 0.88);
    view(&cam, &mount, 0.3, 0.3, 0.4, both, 3, d);
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, 3, NULL, NULL, &pose, &f), RL_EAMBIGUOUS);
    assert_int_equal(f.status, RL_PLACE_AMBIGUOUS);
    assert_int_equal(f.verified, 3);
    assert_int_equal(f.runner_up, 3);
    /* the fourth, 7, is beside the first copy only */
    with_fourth[3] = 6;
    view(&cam, &mount, 0.3, 0.3, 0.4, with_fourth, 4, d);
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, 4, NULL, NULL, &pose, &f), RL_EAMBIGUOUS);
    assert_int_equal(f.verified, 4);
    assert_int_equal(f.runner_up, 3); /* a lead of one: the margin is two */
    cfg.margin = 1;
    pl = build(&cfg);
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, 4, NULL, NULL, &pose, &f), RL_OK);
    assert_true(hypot(pose.x - 0.3, pose.y - 0.3) < 0.01);
    for (i = 0; i < 4; i++)
        assert_int_equal(f.match[i], with_fourth[i]);
    /* two landmarks near the prior: the first copy, tracked */
    rl_place_defaults(&cfg);
    pl = build(&cfg);
    prior.x = 0.35;
    prior.y = 0.25;
    prior.yaw = 0.45;
    view(&cam, &mount, 0.3, 0.3, 0.4, two, 2, d);
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, 2, NULL, NULL, &pose, &f), RL_EAMBIGUOUS);
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, 2, NULL, &prior, &pose, &f), RL_OK);
    assert_int_equal(f.status, RL_PLACE_TRACKED);
    assert_true(hypot(pose.x - 0.3, pose.y - 0.3) < 0.01);
    /* the same prior too old to use */
    prior.age = 5;
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, 2, NULL, &prior, &pose, &f), RL_EAMBIGUOUS);
    /* one detection: too few */
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, 1, NULL, &prior, &pose, &f), RL_ETOOFEW);
}

/* Landmarks with their own heights (z) on a 7 x 7 grid whose ids repeat,
 * the robot at its middle, every landmark within 1 m in view (projected
 * by hand at its height): hung ones in view are matched and the pose is
 * exact; a map entry 0.2 m off where the landmark is (the gate is 0.15 m)
 * stays unverified whatever hangs elsewhere on the map (a landmark 0.3 m
 * lower, or 1.3 m lower, out of view: they widen the index's look-up, not
 * the gate); a landmark the map hangs below the camera is left out by
 * the pose. */
static void heights_in_the_place_search(void **state)
{
    rl_place_config cfg;
    rl_place *pl;
    rl_calib cam;
    rl_mount mount;
    rl_detection d[RL_MAX_LANDMARKS];
    rl_place_found f;
    rl_pose pose;
    int in[RL_MAX_LANDMARKS], n = 0, k, off = -1, far = -1;
    const double x = 1.83, y = 1.83;
    (void)state;
    grid(7, 7, 0.61);
    for (k = 0; k < map.count; k++) {
        double r = hypot(map.lm[k].x - x, map.lm[k].y - y);
        if (r < 1.0)
            in[n++] = k;
        else if (r > 2.5 && far < 0)
            far = k;
    }
    assert_true(n >= 8 && far >= 0);
    map.lm[in[1]].z = 2.45; /* two in view hung lower */
    map.lm[in[4]].z = 2.60;
    rl_place_defaults(&cfg);
    rl_calib_defaults(&cam, 640, 480, 70 * M_PI / 180);
    rl_mount_defaults(&mount, 0.88);
    pl = build(&cfg);
    view(&cam, &mount, x, y, 0.3, in, n, d);
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, n, NULL, NULL, &pose, &f), RL_OK);
    assert_int_equal(f.verified, n);
    for (k = 0; k < n; k++)
        assert_int_equal(f.match[k], in[k]);
    if (hypot(pose.x - x, pose.y - y) > 1e-3 || fabs(pose.yaw - 0.3) > 1e-3)
        fail_msg("pose (%g, %g, %g), truth (%g, %g, 0.3)", pose.x, pose.y, pose.yaw, x, y);
    /* one plane in view; a map entry 0.2 m off its landmark */
    map.lm[in[1]].z = map.lm[in[4]].z = 0;
    view(&cam, &mount, x, y, 0.3, in, n, d);
    off = in[2];
    map.lm[off].x += 0.2;
    for (k = 0; k < 3; k++) {
        map.lm[far].z = k == 0 ? 0 : k == 1 ? 2.45 : 1.45;
        pl = build(&cfg);
        if (rl_place_solve(pl, &cam, &mount, d, n, NULL, NULL, &pose, &f) != RL_OK || f.match[2] != -1 ||
            f.verified != n - 1)
            fail_msg("a landmark hung out of view at z %g: status %d, %d verified (want %d), the entry 0.2 m off "
                     "matched to %d (want -1)", map.lm[far].z, f.status, f.verified, n - 1, f.match[2]);
    }
    map.lm[off].x -= 0.2;
    /* a map that hangs a landmark below the camera (0.5 m; the frame seen
     * as if it were on the ceiling): the pose leaves it out */
    map.lm[far].z = 0;
    view(&cam, &mount, x, y, 0.3, in, n, d);
    map.lm[in[0]].z = 0.5;
    assert_int_equal(rl_pose_solve_matched(&cam, &map, &mount, d, n, in, NULL, &pose), RL_OK);
    assert_int_equal(pose.used, n - 1);
    if (hypot(pose.x - x, pose.y - y) > 1e-3)
        fail_msg("pose (%g, %g), truth (%g, %g)", pose.x, pose.y, x, y);
}

/* The place finder with its defaults over the map, and the camera and
 * mounting the detections are projected through (view). */
static rl_place *rig(rl_calib *cam, rl_mount *mount)
{
    rl_place_config cfg;
    rl_place_defaults(&cfg);
    rl_calib_defaults(cam, 640, 480, 70 * M_PI / 180);
    rl_mount_defaults(mount, 0.88);
    return build(&cfg);
}

/* The n detections d with the prior give a pose near (x, y), found with
 * `status` and `verified` landmarks verified. */
static void expect_place(rl_place *pl, const rl_calib *cam, const rl_mount *mount, const rl_detection *d,
                         int n, const rl_place_prior *prior, int status, int verified, double x, double y)
{
    rl_place_found f;
    rl_pose pose;
    assert_int_equal(rl_place_solve(pl, cam, mount, d, n, NULL, prior, &pose, &f), RL_OK);
    assert_int_equal(f.status, status);
    assert_int_equal(f.verified, verified);
    if (hypot(pose.x - x, pose.y - y) > 0.01)
        fail_msg("pose (%.3f, %.3f), truth (%.3f, %.3f)", pose.x, pose.y, x, y);
}

/* A robot carried from one copy of three ids to the other, with three
 * more landmarks in view there: near the last pose two of the frame's
 * five ids fit the first copy, but a place that leaves most of the frame
 * unverified is no tracked place; the search over the whole map finds the
 * second copy, all five verified. Truth: the pose the detections were
 * projected from. */
static void carried_robot_is_found_where_it_is(void **state)
{
    rl_place *pl;
    rl_calib cam;
    rl_mount mount;
    rl_detection d[5];
    rl_place_prior prior = {1, 0.35, 0.25, 0.45, 0.1};
    int seen[5] = {3, 4, 6, 7, 8}; /* ids 4 and 5 of the second copy, 8, 9 and 10 */
    static const double around_second[3][3] = {{8, 10.61, 0.61}, {9, 9.39, 0.0}, {10, 10.0, -0.61}};
    (void)state;
    two_copies(around_second, 3);
    pl = rig(&cam, &mount);
    view(&cam, &mount, 10.3, 0.3, 0.4, seen, 5, d);
    expect_place(pl, &cam, &mount, d, 5, &prior, RL_PLACE_FOUND, 5, 10.3, 0.3);
}

/* Near the last pose, two ids that verify and three the map does not
 * hold (landmarks left out of the survey): the whole map gives no clear
 * place (the two copies look alike there), so the tracked place is kept.
 * Truth: the pose the detections were projected from. */
static void unmapped_landmarks_keep_tracking(void **state)
{
    rl_place *pl;
    rl_calib cam;
    rl_mount mount;
    rl_detection d[5];
    rl_place_prior prior = {1, 0.35, 0.25, 0.45, 0.1};
    int two[2] = {0, 1}, k;
    (void)state;
    two_copies(NULL, 0);
    pl = rig(&cam, &mount);
    view(&cam, &mount, 0.3, 0.3, 0.4, two, 2, d);
    for (k = 2; k < 5; k++) {
        d[k] = d[0];
        d[k].id = 18 + k; /* 20, 21, 22: not in the map */
        d[k].u = 100.0 + 150.0 * (k - 2);
        d[k].v = 400.0;
    }
    expect_place(pl, &cam, &mount, d, 5, &prior, RL_PLACE_TRACKED, 2, 0.3, 0.3);
}

/* Ids falling along the detections' order (the nearest the image centre
 * first: 9, then 7, then 5): every pair is looked up with its higher id
 * first, and still proposes the place. */
static void ids_in_falling_order(void **state)
{
    rl_place_config cfg;
    rl_place *pl;
    rl_calib cam;
    rl_mount mount;
    rl_detection d[3];
    rl_place_found f;
    rl_pose pose;
    int three[3] = {0, 1, 2};
    (void)state;
    grid(6, 5, 0.61);
    map.lm[0].id = 9; /* at (0, 0), (0.61, 0), (1.22, 0) */
    map.lm[1].id = 7;
    map.lm[2].id = 5;
    rl_place_defaults(&cfg);
    pl = build(&cfg);
    rl_calib_defaults(&cam, 640, 480, 70 * M_PI / 180);
    rl_mount_defaults(&mount, 0.88);
    /* the camera over landmark 0, facing +x: 0 at the centre, 1 and 2 further up */
    view(&cam, &mount, 0.0, 0.05, 0.0, three, 3, d);
    assert_true(hypot(d[0].u - cam.cx, d[0].v - cam.cy) < hypot(d[1].u - cam.cx, d[1].v - cam.cy));
    assert_true(hypot(d[1].u - cam.cx, d[1].v - cam.cy) < hypot(d[2].u - cam.cx, d[2].v - cam.cy));
    assert_int_equal(rl_place_solve(pl, &cam, &mount, d, 3, NULL, NULL, &pose, &f), RL_OK);
    assert_int_equal(f.verified, 3);
    assert_true(hypot(pose.x - 0.0, pose.y - 0.05) < 0.01);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(index_matches_brute_force), cmocka_unit_test(near_matches_brute_force),
        cmocka_unit_test(sizes_and_refusals), cmocka_unit_test(map_repeats_but_never_overlaps),
        cmocka_unit_test(copies_are_ambiguous),
        cmocka_unit_test(carried_robot_is_found_where_it_is),
        cmocka_unit_test(unmapped_landmarks_keep_tracking), cmocka_unit_test(ids_in_falling_order),
        cmocka_unit_test(heights_in_the_place_search),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
