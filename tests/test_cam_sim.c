/* The simulation camera (hal/cam_sim.c): a frame's capture time is the
 * time on its line (the rendered pose's), not when it was read; the
 * pixels are the file's; a malformed line or a missing file is skipped
 * with an error naming the device and line; the end of the stream ends
 * the frames. Frames are made here, their pixels known by construction. */
#include "rl_test.h"
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "rl_cam.h"
#include "rl_png.h"

static void write_frame(const char *dir, const char *name, uint8_t value)
{
    static uint8_t px[32 * 24];
    char path[512], err[256];
    rl_image img = rl_image_view(32, 24, 32, px);
    memset(px, value, sizeof px);
    px[0] = (uint8_t)(value + 1);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    assert_int_equal(rl_png_write_gray(path, &img, err, sizeof err), RL_OK);
}

static void open_stream(rl_cam *c, const char *list, const char *text)
{
    rl_cam_config cc;
    char err[256];
    FILE *f = fopen(list, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    rl_cam_defaults(&cc);
    cc.backend = "sim";
    cc.device = list;
    memset(c, 0, sizeof *c);
    assert_int_equal(rl_cam_open(c, &cc, err, sizeof err), RL_OK);
}

static void capture_time_is_the_poses(void **state)
{
    char dir[256], list[320];
    rl_cam c;
    rl_cam_frame f;
    (void)state;
    rl_test_path(dir, sizeof dir, "cam_sim");
    snprintf(list, sizeof list, "%s/frames", dir);
    (void)mkdir(dir, 0777);
    write_frame(dir, "a.png", 40);
    write_frame(dir, "b.png", 90);
    /* times far from this process's clock: 1 s and 1.25 s of simulated time */
    open_stream(&c, list, "1000000 a.png\n1250000 b.png\n");
    assert_int_equal(rl_cam_grab(&c, 1000, &f), RL_OK);
    assert_int_equal(f.t_us, 1000000);
    assert_int_equal(f.img.width, 32);
    assert_int_equal(f.img.data[0], 41);
    assert_int_equal(f.img.data[5], 40);
    rl_cam_release(&c, &f);
    assert_int_equal(rl_cam_grab(&c, 1000, &f), RL_OK);
    assert_int_equal(f.t_us, 1250000);
    assert_int_equal(f.img.data[5], 90);
    rl_cam_release(&c, &f);
    assert_int_equal(rl_cam_grab(&c, 1000, &f), RL_ENOTFOUND);
    rl_cam_close(&c);
}

static void bad_lines_are_skipped_and_named(void **state)
{
    char dir[256], list[320];
    rl_cam c;
    rl_cam_frame f;
    (void)state;
    rl_test_path(dir, sizeof dir, "cam_sim");
    snprintf(list, sizeof list, "%s/bad", dir);
    (void)mkdir(dir, 0777);
    write_frame(dir, "a.png", 40);
    open_stream(&c, list, "a.png\n-5 a.png\n7 missing.png\n9 a.png");
    assert_int_equal(rl_cam_grab(&c, 1000, &f), RL_EFORMAT);
    assert_non_null(strstr(c.error, "bad:1: not 'T_US FILE'"));
    assert_int_equal(rl_cam_grab(&c, 1000, &f), RL_EFORMAT);
    assert_non_null(strstr(c.error, "bad:2:"));
    assert_int_equal(rl_cam_grab(&c, 1000, &f), RL_EFORMAT);
    assert_non_null(strstr(c.error, "missing.png"));
    assert_int_equal(rl_cam_grab(&c, 1000, &f), RL_OK); /* the last line, without its newline */
    assert_int_equal(f.t_us, 9);
    rl_cam_release(&c, &f);
    assert_int_equal(rl_cam_grab(&c, 1000, &f), RL_ENOTFOUND);
    rl_cam_close(&c);
}

static void missing_device_is_named(void **state)
{
    rl_cam_config cc;
    rl_cam c;
    char err[256];
    (void)state;
    rl_cam_defaults(&cc);
    cc.backend = "sim";
    cc.device = "/nonexistent/frames";
    memset(&c, 0, sizeof c);
    assert_int_equal(rl_cam_open(&c, &cc, err, sizeof err), RL_ENOTFOUND);
    assert_non_null(strstr(err, "/nonexistent/frames"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(capture_time_is_the_poses),
        cmocka_unit_test(bad_lines_are_skipped_and_named),
        cmocka_unit_test(missing_device_is_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
