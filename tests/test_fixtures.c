/* Recognition on rendered fixtures, judged by the renderer's ground truth.
 *
 *   test_fixtures golden DIR   one test per committed fixture (each DIR/NAME.yaml)
 *   test_fixtures stats DIR SET...   rates over a rendered set
 *
 * What each set must meet (issues 4 and 5):
 * - every set: no wrong id, no landmark invented where there is none;
 * - clean, cluttered: >= 99% of complete landmarks detected, >= 99.9% of
 *   those identified correctly; the golden files: every complete one;
 * - clutter_only: nothing identified.
 */
#include "rl_test.h"
#include <dirent.h>
#include <math.h>
#include "fixture_eval.h"
#include "rl_png.h"
#include "rl_report.h"
#include "rl_site.h"

static rl_heap_recog hr, hr_always;

/* The held-out set's guards (held out from tuning; seen once, by the eighth session's
 * zone-twin rule, narrowed to local reads for it: docs/results.md; first measured at 95.0%, 95.5%,
 * 76.2% (70.2% after the lead a cut landmark needs at a moving template) and 78.6% for the
 * worst id; with motion-broken rings closed and the read across the motion 97.0%, 95.5%,
 * 76.2% and 78.6%; with the cut landmarks' halves paired, corners read and small fits
 * read again at the frame's size 97.5%, 95.5%, 79.8%, 78.6%; with true axes and half
 * axes across the motion 98.1%, 96.6%, 82.1%, 78.6%; with the local levels from the
 * landmark's own square, large regions split and cut landmarks read where their box
 * puts them 99.2%, 98.9%, 92.9%, 85.7% (30 frames: 98.9%, 97.3%, 91.7%)). From then on
 * 150 frames (60 were too few for a rate per id: one miss was 7%): 99.7%, 99.6%, 93.3%
 * and 94.3% for the worst id (300 frames, measured once: 99.4%, 99.0%, 88.8%, 93.4%); with
 * cut candidates tried down to 0.4 in the frame 94.3% cut (300: 91.0%; 30: 91.7%). A
 * sanitizer build renders other frames (30: 98.9%, 94.6%, 89.8%), so the guards stay under
 * both. Since zone twins that read as well under the other image formation are
 * misses (issue 44): 150 frames 99.3%, 99.6%, 93.8%, worst id 91.4%; the sanitizer
 * build's 30 frames 97.7% (170 of 174), 94.6%, 89.8%. */
#define HELDOUT_COMPLETE 0.97
#define HELDOUT_GLARE 0.90
#define HELDOUT_BORDER 0.85
#define HELDOUT_PER_ID 0.90
/* Ids seen fewer times than this are not held to the held-out rate per
 * id (a sanitizer build's 30 frames hold 2-12 of each). */
#define HELDOUT_PER_ID_MIN 20
static rl_result res;

static const char *set_of(const char *image)
{
    static char set[64];
    const char *base = strrchr(image, '/');
    size_t n;
    base = base ? base + 1 : image;
    n = strcspn(base, "0123456789");
    if (n > 0 && base[n - 1] == '_')
        n--;
    snprintf(set, sizeof set, "%.*s", (int)n, base);
    return set;
}

static void run_frame(const char *yaml, truth *t, eval_counts *c, int verbose)
{
    char png[1024], err[512];
    const char *slash = strrchr(yaml, '/');
    rl_image img;
    double us;
    assert_int_equal(truth_load(yaml, t), 0);
    snprintf(png, sizeof png, "%.*s%s", slash ? (int)(slash - yaml + 1) : 0, yaml, t->image);
    if (rl_png_read_gray(png, &img, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    /* the glare and border sets test the local pass: run it always there */
    assert_int_equal(rl_report_run(getenv("RL_LOCAL_ALWAYS") || strncmp(t->image, "glare", 5) == 0 ||
                                               strncmp(t->image, "border", 6) == 0
                                           ? &hr_always
                                           : &hr,
                                       &img, &res, &us),
                     RL_OK);
    rl_png_free(&img);
    eval_frame(t, &res, c, verbose);
}

/* ---- golden: one test per fixture ---- */

static void golden_one(void **state)
{
    const char *yaml = (const char *)*state;
    truth t;
    eval_counts c;
    const char *set;
    memset(&c, 0, sizeof c);
    run_frame(yaml, &t, &c, 1);
    set = set_of(t.image);
    assert_int_equal(c.wrong_id, 0);
    assert_int_equal(c.invented, 0);
    if (strcmp(set, "clean") == 0 || strcmp(set, "cluttered") == 0) {
        assert_int_equal(c.complete_ident, c.complete);
        if (c.centre_n)
            assert_true(c.centre_err_sum / c.centre_n < 1.0);
    }
    if (strcmp(set, "clutter_only") == 0)
        assert_int_equal(c.identified, 0);
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* On the committed glare and border fixtures, the local pass identifies
 * landmarks that the global pass could not, on the same images, with the
 * right ids. */
static const char *golden_dir;

static void local_recovers_what_global_missed(void **state)
{
    static char *names[64];
    rl_recog_config cfg;
    rl_heap_recog never, always;
    static rl_result a, b;
    int recovered = 0, k, set;
    const char *sets[] = {"glare", "border"};
    (void)state;
    (void)names;
    rl_recog_defaults(&cfg);
    cfg.local = RL_LOCAL_NEVER;
    rl_heap_recog_init(&never, &cfg);
    cfg.local = RL_LOCAL_ALWAYS;
    rl_heap_recog_init(&always, &cfg);
    for (set = 0; set < 2; set++)
        for (k = 0; k < 100; k++) {
            char yaml[1024], png[1024], err[512];
            truth t;
            rl_image img;
            double us;
            int i, j;
            FILE *f;
            snprintf(yaml, sizeof yaml, "%s/%s_%03d.yaml", golden_dir, sets[set], k);
            if ((f = fopen(yaml, "r")) == NULL)
                break;
            fclose(f);
            assert_int_equal(truth_load(yaml, &t), 0);
            snprintf(png, sizeof png, "%s/%s", golden_dir, t.image);
            if (rl_png_read_gray(png, &img, err, sizeof err) != RL_OK)
                fail_msg("%s", err);
            assert_int_equal(rl_report_run(&never, &img, &a, &us), RL_OK);
            assert_int_equal(rl_report_run(&always, &img, &b, &us), RL_OK);
            rl_png_free(&img);
            for (i = 0; i < b.n_landmarks; i++) {
                const rl_detection *d = &b.landmarks[i];
                int in_global = 0;
                if (d->pass != RL_PASS_LOCAL)
                    continue;
                for (j = 0; j < a.n_landmarks; j++)
                    in_global |= a.landmarks[j].id == d->id;
                assert_false(in_global);
                for (j = 0; j < t.n; j++)
                    if (hypot(t.lm[j].u - d->u, t.lm[j].v - d->v) < 0.5 * t.lm[j].radius) {
                        assert_int_equal(t.lm[j].id, d->id);
                        recovered++;
                    }
            }
        }
    printf("  the local pass recovered %d landmarks the global pass missed\n", recovered);
    assert_true(recovered >= 3);
    rl_heap_recog_free(&never);
    rl_heap_recog_free(&always);
}

static int golden(const char *dir)
{
    static char *files[512];
    static struct CMUnitTest tests[513];
    int n = 0, i;
    DIR *d = opendir(dir);
    struct dirent *e;
    if (!d) {
        fprintf(stderr, "test_fixtures: %s: cannot open\n", dir);
        return 1;
    }
    while ((e = readdir(d)) != NULL && n < 511) {
        size_t len = strlen(e->d_name);
        if (len > 5 && strcmp(e->d_name + len - 5, ".yaml") == 0) {
            /* a fixture is NAME.yaml beside NAME.png; other YAML (the site
             * map, the camera) is not */
            char png[1024];
            FILE *f;
            snprintf(png, sizeof png, "%s/%.*s.png", dir, (int)(len - 5), e->d_name);
            if ((f = fopen(png, "rb")) == NULL)
                continue;
            fclose(f);
            files[n] = malloc(strlen(dir) + len + 2);
            sprintf(files[n], "%s/%s", dir, e->d_name);
            n++;
        }
    }
    closedir(d);
    qsort(files, (size_t)n, sizeof files[0], cmp_str); /* fixed order */
    for (i = 0; i < n; i++) {
        tests[i].name = strrchr(files[i], '/') + 1;
        tests[i].test_func = golden_one;
        tests[i].setup_func = NULL;
        tests[i].teardown_func = NULL;
        tests[i].initial_state = files[i];
    }
    if (n == 0) {
        fprintf(stderr, "test_fixtures: no fixtures in %s\n", dir);
        return 1;
    }
    golden_dir = dir;
    tests[n].name = "local_recovers_what_global_missed";
    tests[n].test_func = local_recovers_what_global_missed;
    tests[n].setup_func = tests[n].teardown_func = NULL;
    tests[n].initial_state = NULL;
    n++;
    return _cmocka_run_group_tests("golden fixtures", tests, (size_t)n, NULL, NULL);
}

/* ---- stats: rates over a rendered set ---- */

static const char *stats_dir;

/* Issue 26's guards on the moving, dim sets: regression guards a little
 * under what each set gave when it was settled (README: the figures); the
 * old recognizer read 44% of the degraded set's landmarks once its frames
 * had the physics, and ids with a black first code zone a third of the
 * time. */
static void moving_guards(const char *set, const eval_counts *c)
{
    /* border 0.78: the sanitizer build's 30 frames read 30 of 38 cut
     * landmarks once a cut landmark read through a curve keeps no id a zone
     * twin leads (issue 44, 2026-12-06: misses, not wrong ids; 31 before) */
    double complete = 0.96, glare = 0.93, border = 0.78, per_id = 0.75;
    int id, per_id_min = 8;
    if (strcmp(set, "degraded") == 0)
        return;
    if (strcmp(set, "heldout") == 0) {
        complete = HELDOUT_COMPLETE;
        glare = HELDOUT_GLARE;
        border = HELDOUT_BORDER;
        per_id = HELDOUT_PER_ID;
        per_id_min = HELDOUT_PER_ID_MIN;
    }
    assert_true(c->complete > 80 && c->glare > 20 && c->border > 20); /* 30 frames or more */
    assert_true(c->complete_ident >= complete * c->complete);
    assert_true(c->glare_ident >= glare * c->glare);
    assert_true(c->border_ident >= border * c->border);
    for (id = 1; id < RL_MAX_IDS; id++)
        if (c->id_complete[id] >= per_id_min && c->id_ident[id] < per_id * c->id_complete[id])
            fail_msg("%s: id %d identified %d of %d times", set, id, c->id_ident[id], c->id_complete[id]);
}

static void stats_set(void **state)
{
    const char *set = (const char *)*state;
    eval_counts c;
    truth t;
    char path[1024];
    int k, frames = 0;
    memset(&c, 0, sizeof c);
    for (k = 0; k < 1000; k++) {
        FILE *f;
        snprintf(path, sizeof path, "%s/%s_%03d.yaml", stats_dir, set, k);
        f = fopen(path, "r");
        if (!f)
            break;
        fclose(f);
        run_frame(path, &t, &c, getenv("RL_VERBOSE") != NULL);
        frames++;
    }
    if (frames == 0)
        fail_msg("no %s fixtures in %s", set, stats_dir);
    printf("  %-12s %3d frames: complete %d/%d detected, %d identified; glare %d/%d; border %d/%d; "
           "reports %d (local %d), wrong %d, invented %d; centre error %.3f px\n",
           set, frames, c.complete_found, c.complete, c.complete_ident, c.glare_ident, c.glare,
           c.border_ident, c.border, c.identified, c.local_found, c.wrong_id, c.invented,
           c.centre_n ? c.centre_err_sum / c.centre_n : 0.0);
    assert_int_equal(c.wrong_id, 0);
    assert_int_equal(c.invented, 0);
    if (strcmp(set, "clean") == 0 || strcmp(set, "cluttered") == 0) {
        assert_true(c.complete > 40);
        assert_true(c.complete_found >= 0.99 * c.complete);
        assert_true(c.complete_ident >= 0.999 * c.complete_found);
    }
    if (strcmp(set, "clutter_only") == 0)
        assert_int_equal(c.identified, 0);
    if (strcmp(set, "border") == 0) {
        /* issue 5: >= 90% of landmarks up to half outside the image */
        assert_true(c.border > 10);
        assert_true(c.border_ident >= 0.90 * c.border);
    }
    if (strcmp(set, "illum") == 0) {
        /* issue 14: vignetting, fall-off, a shadow and grey ink as real
         * ceilings have them: >= 97% of complete landmarks */
        assert_true(c.complete > 40);
        assert_true(c.complete_ident >= 0.97 * c.complete);
    }
    if (strcmp(set, "degraded") == 0) {
        /* issue 14: blur 1.1 px + 4 px motion + 0.35 exposure, photon noise
         * and read noise 3 DN before the tone curve (issue 26) together:
         * >= 98% of complete landmarks (and no wrong id, above) */
        assert_true(c.complete > 40);
        assert_true(c.complete_ident >= 0.98 * c.complete);
    }
    if (strcmp(set, "moving") == 0 || strcmp(set, "heldout") == 0 || strcmp(set, "degraded") == 0) {
        /* issue 26: a robot moving in dim light, every id: the worst id's
         * rate over the ids seen at least 8 times (fewer say little) */
        int worst;
        double low = eval_per_id(&c, stdout, &worst);
        printf("  worst id %d at %.1f%%\n", worst, 100 * low);
        moving_guards(set, &c);
    }
    if (strcmp(set, "motion") == 0) {
        /* issue 26: motion blur of 3.7-7.3 px on light (the old recognizer
         * read 72% of these once blur happened before the tone curve) */
        assert_true(c.complete > 40);
        assert_true(c.complete_ident >= 0.98 * c.complete);
    }
    if (strcmp(set, "repeats") == 0) {
        /* issue 26: one id two or three times in a frame, at different
         * places: each is reported (>= 95% of them) */
        printf("  landmarks whose id the frame holds twice: %d of %d identified\n", c.twin_ident, c.twin);
        assert_true(c.twin > 40);
        assert_true(c.twin_ident >= 0.95 * c.twin);
    }
    if (strcmp(set, "lens") == 0) {
        /* a wide-angle lens's barrel distortion: complete landmarks as
         * everywhere, and the cut ones, flattened towards the border, read
         * as ellipses; the previous recognizer read 16% of those (7 of 44
         * in CI's frames), this one 80%: guarded at 75%, short of the 90%
         * of round ones */
        assert_true(c.complete > 40 && c.border > 10);
        assert_true(c.complete_ident >= 0.99 * c.complete);
        assert_true(c.border_ident >= 0.75 * c.border);
    }
    if (strcmp(set, "glare") == 0) {
        /* issue 5: >= 97% of landmarks within one radius of a light; since
         * the frames carry a camera's physics (issue 26: halos and blur on
         * light, photon noise) 96.8-97.8% of CI's 30 frames (the renderer
         * built by clang or gcc): guarded at 95% */
        assert_true(c.glare > 20);
        assert_true(c.glare_ident >= 0.95 * c.glare);
    }
}

/* ---- paths: the pose against the renderer's truth ---- */

static const char *paths_dir;

static double wrap(double a)
{
    return atan2(sin(a), cos(a));
}

/* A map file through rl_site. */
static void load_map(const char *path, rl_map *map)
{
    static rl_site site;
    rl_site_files files;
    char err[768];
    rl_site_files_init(&files);
    files.map = path;
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK) fail_msg("%s", err);
    *map = site.map;
}

/* The folder's map, calibration and robot. */
static void load_site(rl_map *map, rl_calib *cam, rl_mount *mount)
{
    static rl_site site;
    static rl_site_folder held;
    rl_site_files files;
    char err[768];
    rl_site_files_folder(&files, &held, paths_dir);
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK) fail_msg("%s", err);
    *map = site.map;
    *cam = site.calib;
    *mount = site.mount;
}

/* Frame k of a drive recognized into res, its truth into t; 0 past the
 * last frame. */
static int recognize_frame(const char *kind, int k, truth *t)
{
    char path[1024], err[512];
    rl_image img;
    double us;
    FILE *f;
    snprintf(path, sizeof path, "%s/%s_%03d.yaml", paths_dir, kind, k);
    if ((f = fopen(path, "r")) == NULL)
        return 0;
    fclose(f);
    assert_int_equal(truth_load(path, t), 0);
    snprintf(path, sizeof path, "%s/%s", paths_dir, t->image);
    if (rl_png_read_gray(path, &img, err, sizeof err) != RL_OK) fail_msg("%s", err);
    assert_int_equal(rl_report_run(&hr, &img, &res, &us), RL_OK);
    rl_png_free(&img);
    return 1;
}

static void path_accuracy(void **state)
{
    const char *kind = (const char *)*state;
    static rl_map map;
    rl_calib cam;
    rl_mount mount;
    double pos = 0, yaw = 0, zx = 0, zy = 0, zyaw = 0;
    int k, frames = 0;
    truth t;
    load_site(&map, &cam, &mount);
    for (k = 0; recognize_frame(kind, k, &t); k++) {
        rl_pose pose;
        assert_int_equal(rl_pose_solve(&cam, &map, &mount, res.landmarks, res.n_landmarks, NULL, &pose), RL_OK);
        assert_int_equal(pose.n_dropped, 0);
        pos += hypot(pose.x - t.robot_x, pose.y - t.robot_y);
        yaw += fabs(wrap(pose.yaw - t.robot_yaw));
        /* the errors in units of the pose's own standard deviations */
        zx += pow((pose.x - t.robot_x) / pose.sigma_x, 2);
        zy += pow((pose.y - t.robot_y) / pose.sigma_y, 2);
        zyaw += pow(wrap(pose.yaw - t.robot_yaw) / pose.sigma_yaw, 2);
        if (k == 0) {
            /* a landmark moved since the map was made: the pose stays right
             * and says which landmark it dropped */
            static rl_map wrong;
            int victim = res.landmarks[res.n_landmarks / 2].id;
            rl_pose p2;
            wrong = map;
            wrong.lm[rl_map_find(&wrong, victim)].x += 0.3;
            assert_int_equal(rl_pose_solve(&cam, &wrong, &mount, res.landmarks, res.n_landmarks, NULL, &p2), RL_OK);
            assert_int_equal(p2.n_dropped, 1);
            assert_int_equal(p2.dropped[0], victim);
            assert_true(hypot(p2.x - t.robot_x, p2.y - t.robot_y) < 0.005);
        }
        frames++;
    }
    if (frames == 0)
        fail_msg("no %s frames in %s", kind, paths_dir);
    pos /= frames;
    yaw /= frames;
    zx = sqrt(zx / frames);
    zy = sqrt(zy / frames);
    zyaw = sqrt(zyaw / frames);
    printf("  %-8s %3d frames: mean position error %.2f mm, mean yaw error %.3f deg, RMS error/sigma "
           "x %.2f y %.2f yaw %.2f\n", kind, frames, 1000 * pos, yaw * 180 / M_PI, zx, zy, zyaw);
    /* issue 6: at most 5 mm and 0.1 degree (the paper: 20.2 mm, 0.5 degree),
     * tilted or not (issue 15); the sigmas consistent with the errors */
    assert_true(pos <= 0.005);
    assert_true(yaw * 180 / M_PI <= 0.1);
    assert_true(zx >= 0.5 && zx <= 2 && zy >= 0.5 && zy <= 2 && zyaw >= 0.5 && zyaw <= 2);
}

/* A camera mounted off vertical, its tilt from calibrate-mount (the
 * folder's robot.yaml): every frame's pose, and the pose from only the two
 * landmarks nearest the image centre (the vertical model with the mount's
 * tilt applied), both within 3 mm on average (issue 15). */
static void mount_accuracy(void **state)
{
    static const char *kinds[] = {"straight", "rect", "circle"};
    static rl_map map;
    rl_calib cam;
    rl_mount mount;
    double all = 0, two = 0;
    int k, q, frames = 0;
    truth t;
    (void)state;
    load_site(&map, &cam, &mount);
    assert_true(fabs(mount.roll) > 0.01 && fabs(mount.pitch) > 0.01); /* calibrated, not left at 0 */
    for (q = 0; q < 3; q++)
        for (k = 0; recognize_frame(kinds[q], k, &t); k++) {
            rl_pose pose;
            rl_detection pair[2];
            double best[2] = {1e9, 1e9};
            int j;
            assert_int_equal(rl_pose_solve(&cam, &map, &mount, res.landmarks, res.n_landmarks, NULL, &pose), RL_OK);
            all += hypot(pose.x - t.robot_x, pose.y - t.robot_y);
            for (j = 0; j < res.n_landmarks; j++) {
                double d = hypot(res.landmarks[j].u - cam.cx, res.landmarks[j].v - cam.cy);
                if (d < best[0]) {
                    best[1] = best[0];
                    pair[1] = pair[0];
                    best[0] = d;
                    pair[0] = res.landmarks[j];
                } else if (d < best[1]) {
                    best[1] = d;
                    pair[1] = res.landmarks[j];
                }
            }
            assert_int_equal(rl_pose_solve(&cam, &map, &mount, pair, 2, NULL, &pose), RL_OK);
            assert_false(pose.tilt_solved);
            two += hypot(pose.x - t.robot_x, pose.y - t.robot_y);
            frames++;
        }
    assert_true(frames > 0);
    all /= frames;
    two /= frames;
    printf("  mounted %.4f, %.4f rad off vertical, %d frames: mean position error %.2f mm, from two "
           "landmarks %.2f mm\n", mount.roll, mount.pitch, frames, 1000 * all, 1000 * two);
    assert_true(all <= 0.003);
    assert_true(two <= 0.003);
}

/* ---- survey: the map a drive made against the renderer's truth ---- */

static int survey_moved_id;

/* The true map (map.yaml) in the survey's frame: origin landmark at
 * (0, 0), the axis one on +x. */
static void truth_in_survey_frame(rl_map *real, int origin, int axis)
{
    int o = rl_map_find(real, origin), a = rl_map_find(real, axis), i;
    double ox, oy, th;
    assert_true(o >= 0 && a >= 0);
    ox = real->lm[o].x;
    oy = real->lm[o].y;
    th = atan2(real->lm[a].y - oy, real->lm[a].x - ox);
    for (i = 0; i < real->count; i++) {
        double x = real->lm[i].x - ox, y = real->lm[i].y - oy;
        real->lm[i].x = cos(th) * x + sin(th) * y;
        real->lm[i].y = -sin(th) * x + cos(th) * y;
    }
}

/* The least-squares similarity taking map a onto map b (same ids):
 * b = [s -t; t s] a + (tx, ty), as T = {s, t, tx, ty}. */
static void similarity(const rl_map *a, const rl_map *b, double *T)
{
    double ax = 0, ay = 0, bx = 0, by = 0, sa = 0, sb = 0, pp = 0;
    int i, n = 0;
    for (i = 0; i < a->count; i++) {
        int j = rl_map_find(b, a->lm[i].id);
        assert_true(j >= 0);
        ax += a->lm[i].x, ay += a->lm[i].y, bx += b->lm[j].x, by += b->lm[j].y;
        n++;
    }
    ax /= n, ay /= n, bx /= n, by /= n;
    for (i = 0; i < a->count; i++) {
        int j = rl_map_find(b, a->lm[i].id);
        double px = a->lm[i].x - ax, py = a->lm[i].y - ay, qx = b->lm[j].x - bx, qy = b->lm[j].y - by;
        sa += px * qx + py * qy;
        sb += px * qy - py * qx;
        pp += px * px + py * py;
    }
    T[0] = sa / pp;
    T[1] = sb / pp;
    T[2] = bx - (T[0] * ax - T[1] * ay);
    T[3] = by - (T[1] * ax + T[0] * ay);
}

/* Issue 19: every landmark within 2 mm RMS of the truth, the ceiling
 * within 5 mm. */
static void survey_map(void **state)
{
    static rl_map real, sv;
    rl_calib cam;
    rl_mount mount;
    char path[1024];
    double ss = 0, worst = 0;
    int i, origin = 0, axis = 0;
    (void)state;
    load_site(&real, &cam, &mount);
    snprintf(path, sizeof path, "%s/survey.yaml", paths_dir);
    load_map(path, &sv);
    assert_int_equal(sv.count, real.count);
    /* the survey's frame: its origin at (0, 0), its axis landmark on y = 0 */
    for (i = 0; i < sv.count; i++)
        if (sv.lm[i].x == 0 && sv.lm[i].y == 0)
            origin = sv.lm[i].id;
        else if (sv.lm[i].y == 0)
            axis = sv.lm[i].id;
    truth_in_survey_frame(&real, origin, axis);
    for (i = 0; i < sv.count; i++) {
        int j = rl_map_find(&real, sv.lm[i].id);
        double d;
        assert_true(j >= 0);
        d = hypot(sv.lm[i].x - real.lm[j].x, sv.lm[i].y - real.lm[j].y);
        ss += d * d;
        worst = fmax(worst, d);
        /* the origin is exact, the axis exact in y */
        assert_true(sv.lm[i].id == origin || (sv.lm[i].sigma_x > 0 && (sv.lm[i].id == axis || sv.lm[i].sigma_y > 0)));
    }
    printf("  survey: %d landmarks within %.2f mm RMS (worst %.2f mm) of the truth; ceiling %.4f m, truth %.4f m\n",
           sv.count, 1000 * sqrt(ss / sv.count), 1000 * worst, sv.ceiling_height, real.ceiling_height);
    assert_true(sqrt(ss / sv.count) <= 0.002);
    assert_true(fabs(sv.ceiling_height - real.ceiling_height) <= 0.005);
}

/* Issue 19: poses with the surveyed map within 1 mm of those with the
 * true map, on another drive (rect) than the survey's; the surveyed map's
 * frame taken onto the true one by the similarity that fits the maps. */
static void survey_poses(void **state)
{
    static rl_map real, sv;
    rl_calib cam;
    rl_mount mount;
    char path[1024];
    double T[4], worst = 0, sum = 0, yaw_worst = 0;
    int k, frames = 0;
    truth t;
    (void)state;
    load_site(&real, &cam, &mount);
    snprintf(path, sizeof path, "%s/survey.yaml", paths_dir);
    load_map(path, &sv);
    similarity(&sv, &real, T);
    for (k = 0; recognize_frame("rect", k, &t); k++) {
        rl_pose a, b;
        double x, y, d;
        assert_int_equal(rl_pose_solve(&cam, &real, &mount, res.landmarks, res.n_landmarks, NULL, &a), RL_OK);
        assert_int_equal(rl_pose_solve(&cam, &sv, &mount, res.landmarks, res.n_landmarks, NULL, &b), RL_OK);
        x = T[0] * b.x - T[1] * b.y + T[2];
        y = T[1] * b.x + T[0] * b.y + T[3];
        d = hypot(x - a.x, y - a.y);
        if (getenv("RL_VERBOSE"))
            printf("    frame %d: %.2f mm (tilt %d %d, used %d %d, truth err %.2f mm)\n", k, 1000 * d, a.tilt_solved,
                   b.tilt_solved, a.used, b.used, 1000 * hypot(a.x - t.robot_x, a.y - t.robot_y));
        worst = fmax(worst, d);
        sum += d;
        yaw_worst = fmax(yaw_worst, fabs(wrap(b.yaw + atan2(T[1], T[0]) - a.yaw)));
        frames++;
    }
    assert_true(frames > 0);
    printf("  survey: %d rect frames, poses with the surveyed map %.2f mm from those with the true map on average, "
           "worst %.2f mm, %.4f deg (map scale %.5f)\n", frames, 1000 * sum / frames, 1000 * worst,
           yaw_worst * 180 / M_PI, hypot(T[0], T[1]));
    /* on average within 1 mm; a single tilted fit moves by up to 2-3 mm
     * with the map's last half millimetre (its own error against the
     * truth is as large with the true map) */
    assert_true(sum / frames <= 0.001);
    assert_true(worst <= 0.003);
}

/* Issue 19: a second survey with --map names the moved landmark and no
 * other (moved.json, its JSON line). */
static void survey_moved(void **state)
{
    char path[1024], line[8192];
    const char *p;
    int ids[64], n = 0;
    FILE *f;
    (void)state;
    snprintf(path, sizeof path, "%s/moved.json", paths_dir);
    f = fopen(path, "r");
    if (f == NULL || fgets(line, sizeof line, f) == NULL) fail_msg("%s: no JSON line", path);
    fclose(f);
    p = strstr(line, "\"moved\": [");
    assert_non_null(p);
    p += strlen("\"moved\": [");
    while (*p == '{' && n < 64) {
        assert_int_equal(sscanf(p, "{\"id\": %d", &ids[n]), 1);
        n++;
        p = strchr(p, '}');
        assert_non_null(p);
        p += *(p + 1) == ',' ? 3 : 1;
    }
    printf("  survey: %d landmark(s) named as moved%s", n, n ? ":" : "");
    for (int i = 0; i < n; i++)
        printf(" %d", ids[i]);
    printf(" (moved: %d)\n", survey_moved_id);
    assert_int_equal(n, 1);
    assert_int_equal(ids[0], survey_moved_id);
}

int main(int argc, char **argv)
{
    rl_recog_config cfg;
    int rc;
    rl_recog_defaults(&cfg);
    rl_heap_recog_init(&hr, &cfg);
    cfg.local = RL_LOCAL_ALWAYS;
    rl_heap_recog_init(&hr_always, &cfg);
    if (argc >= 3 && strcmp(argv[1], "golden") == 0) {
        rc = golden(argv[2]);
    } else if (argc >= 4 && strcmp(argv[1], "stats") == 0) {
        static struct CMUnitTest tests[16];
        int i, n = 0;
        stats_dir = argv[2];
        for (i = 3; i < argc && n < 16; i++, n++) {
            tests[n].name = argv[i];
            tests[n].test_func = stats_set;
            tests[n].setup_func = tests[n].teardown_func = NULL;
            tests[n].initial_state = argv[i];
        }
        rc = _cmocka_run_group_tests("fixture sets", tests, (size_t)n, NULL, NULL);
    } else if (argc >= 3 && strcmp(argv[1], "paths") == 0) {
        const struct CMUnitTest tests[] = {
            cmocka_unit_test_prestate(path_accuracy, (void *)"straight"),
            cmocka_unit_test_prestate(path_accuracy, (void *)"rect"),
            cmocka_unit_test_prestate(path_accuracy, (void *)"circle"),
        };
        paths_dir = argv[2];
        rc = cmocka_run_group_tests(tests, NULL, NULL);
    } else if (argc >= 3 && strcmp(argv[1], "mount") == 0) {
        const struct CMUnitTest tests[] = {cmocka_unit_test(mount_accuracy)};
        paths_dir = argv[2];
        rc = cmocka_run_group_tests(tests, NULL, NULL);
    } else if (argc >= 4 && strcmp(argv[1], "survey") == 0) {
        const struct CMUnitTest tests[] = {cmocka_unit_test(survey_map), cmocka_unit_test(survey_poses),
                                           cmocka_unit_test(survey_moved)};
        paths_dir = argv[2];
        survey_moved_id = atoi(argv[3]);
        rc = cmocka_run_group_tests(tests, NULL, NULL);
    } else {
        fprintf(stderr, "usage: test_fixtures golden DIR | stats DIR SET... | paths DIR | mount DIR | "
                "survey DIR MOVED_ID\n");
        rc = 2;
    }
    rl_heap_recog_free(&hr);
    rl_heap_recog_free(&hr_always);
    return rc;
}
