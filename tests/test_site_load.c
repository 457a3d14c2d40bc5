/* rl_site: a site's files read and checked together, with the error
 * lines made by hand here (files written by the test, expectations from
 * what each file says), and what rl_site_prepare builds from them. */
#include "rl_test.h"
#include "rl_outfile.h"
#include "rl_robotfile.h"
#include "rl_site.h"

static char cam_path[1024], map_path[1024], empty_path[1024], robot_path[1024], high_path[1024],
    rep_path[1024];

/* Written as every output is (a temporary renamed into place). */
static void write_file(const char *path, const char *text)
{
    rl_outfile o;
    char err[600];
    if (rl_outfile_open(&o, path, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    fputs(text, o.f);
    if (rl_outfile_commit(&o, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
}

static int setup(void **state)
{
    char src[1024];
    (void)state;
    snprintf(src, sizeof src, "%s/tests/fixtures/camera.yaml", getenv("RL_SOURCE_DIR"));
    snprintf(cam_path, sizeof cam_path, "%s", src); /* 640x480 */
    write_file(rl_test_path(map_path, sizeof map_path, "site_map.yaml"),
               "family: ring5\ndiameter: 0.21\nceiling_height: 2.75\nlandmarks:\n"
               "  - {id: 1, x: 0, y: 0}\n  - {id: 2, x: 0.6, y: 0}\n  - {id: 3, x: 0, y: 0.6}\n");
    write_file(rl_test_path(rep_path, sizeof rep_path, "site_repeats.yaml"),
               "family: ring5\ndiameter: 0.21\nceiling_height: 2.75\nlandmarks:\n"
               "  - {id: 1, x: 0, y: 0}\n  - {id: 2, x: 0.6, y: 0}\n  - {id: 1, x: 5, y: 0}\n"
               "  - {id: 2, x: 5.6, y: 0}\n");
    write_file(rl_test_path(empty_path, sizeof empty_path, "site_empty.yaml"),
               "family: ring5\ndiameter: 0.21\nceiling_height: 2.75\nlandmarks: []\n");
    write_file(rl_test_path(robot_path, sizeof robot_path, "site_robot.yaml"),
               "camera_mount: {x: 0.1, y: 0, z: 0.88, yaw: 0}\n");
    write_file(rl_test_path(high_path, sizeof high_path, "site_high.yaml"),
               "camera_mount: {x: 0, y: 0, z: 3.5, yaw: 0}\n");
    return 0;
}

static rl_err load(rl_site *s, const char *cal, const char *map, const char *robot, int w, int h, char *err,
                   size_t len)
{
    rl_site_files f;
    rl_site_files_init(&f);
    f.calibration = cal;
    f.map = map;
    f.robot = robot;
    f.width = w;
    f.height = h;
    f.size_from = "--size";
    return rl_site_load(s, &f, err, len);
}

/* A full site loads; what each file says is there. */
static void test_full_site(void **state)
{
    static rl_site s;
    rl_recog_config rc;
    char err[768] = "";
    int w, h;
    (void)state;
    assert_int_equal(load(&s, cam_path, map_path, robot_path, 0, 0, err, sizeof err), RL_OK);
    assert_true(s.has_calib && s.has_map && s.has_mount && !s.has_offsets);
    assert_int_equal(s.calib.width, 640);
    assert_int_equal(s.map.count, 3);
    assert_true(s.mount.x == 0.1 && s.mount.z == 0.88);
    assert_null(rl_site_offsets(&s));
    rl_recog_defaults(&rc);
    assert_int_equal(rl_site_prepare(&s, &rc, err, sizeof err), RL_OK);
    assert_non_null(s.recog.rec);            /* made for the calibration's size */
    rl_recog_frame_size(s.recog.rec, &w, &h);
    assert_int_equal(w, 640);
    assert_int_equal(h, 480);
    assert_int_equal(s.recog.cfg.n_ids, 3);  /* the map's ids only */
    assert_null(s.place.pl);                 /* ids unique: no place index */
    rl_site_free(&s);
}

/* A map that repeats ids gets the place index. */
static void test_repeated_ids_index(void **state)
{
    static rl_site s;
    rl_recog_config rc;
    char err[768] = "";
    (void)state;
    assert_int_equal(load(&s, NULL, rep_path, NULL, 0, 0, err, sizeof err), RL_OK);
    rl_recog_defaults(&rc);
    assert_int_equal(rl_site_prepare(&s, &rc, err, sizeof err), RL_OK);
    assert_non_null(s.place.pl);
    assert_null(s.recog.rec); /* no calibration: made for each frame's size */
    rl_site_free(&s);
}

/* Each check's one line names the files at fault. */
static void test_checks_name_the_files(void **state)
{
    static rl_site s;
    char err[768];
    (void)state;
    assert_int_equal(load(&s, NULL, empty_path, NULL, 0, 0, err, sizeof err), RL_EINVAL);
    assert_non_null(strstr(err, "site_empty.yaml: the map has no landmarks"));
    assert_int_equal(load(&s, NULL, map_path, high_path, 0, 0, err, sizeof err), RL_EINVAL);
    assert_non_null(strstr(err, "site_high.yaml: camera_mount.z 3.500 m is not below the ceiling"));
    assert_non_null(strstr(err, "site_map.yaml: ceiling_height 2.750 m"));
    assert_int_equal(load(&s, cam_path, NULL, NULL, 1280, 960, err, sizeof err), RL_EINVAL);
    assert_non_null(strstr(err, "--size: image is 1280x960 but"));
    assert_non_null(strstr(err, "is for 640x480"));
    assert_int_equal(load(&s, cam_path, NULL, NULL, 640, 480, err, sizeof err), RL_OK); /* the same size */
    assert_int_equal(load(&s, NULL, "/nonexistent/map.yaml", NULL, 0, 0, err, sizeof err), RL_ENOTFOUND);
    assert_non_null(strstr(err, "/nonexistent/map.yaml"));
}

/* A folder's files are its camera.yaml, map.yaml and robot.yaml. */
static void test_folder_names(void **state)
{
    rl_site_folder held;
    rl_site_files f;
    (void)state;
    rl_site_files_folder(&f, &held, "/data/site");
    assert_string_equal(f.calibration, "/data/site/camera.yaml");
    assert_string_equal(f.map, "/data/site/map.yaml");
    assert_string_equal(f.robot, "/data/site/robot.yaml");
    assert_null(f.offsets);
}

/* robot.yaml's rocking: absent is the default, written only where it is
 * not (a file an older ringloc reads too), and read back as written */
static void test_robot_rocking(void **state)
{
    rl_mount m, back;
    char err[600], path[1024], text[512];
    FILE *f;
    size_t n;
    (void)state;
    assert_int_equal(rl_robotfile_load(robot_path, &m, err, sizeof err), RL_OK);
    assert_true(m.rocking == RL_POSE_TILT_PRIOR && m.rocking == 0.005);
    rl_test_path(path, sizeof path, "robot_rocking.yaml");
    assert_int_equal(rl_robotfile_save(path, &m, err, sizeof err), RL_OK);
    f = fopen(path, "r");
    assert_non_null(f);
    n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = 0;
    assert_null(strstr(text, "rocking"));
    m.rocking = 0.0125;
    assert_int_equal(rl_robotfile_save(path, &m, err, sizeof err), RL_OK);
    assert_int_equal(rl_robotfile_load(path, &back, err, sizeof err), RL_OK);
    assert_true(back.rocking == 0.0125);
    m.rocking = 0;
    assert_int_equal(rl_robotfile_save(path, &m, err, sizeof err), RL_OK);
    assert_int_equal(rl_robotfile_load(path, &back, err, sizeof err), RL_OK);
    assert_true(back.rocking == 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_full_site),
        cmocka_unit_test(test_repeated_ids_index),
        cmocka_unit_test(test_checks_name_the_files),
        cmocka_unit_test(test_folder_names),
        cmocka_unit_test(test_robot_rocking),
    };
    return cmocka_run_group_tests(tests, setup, NULL);
}
