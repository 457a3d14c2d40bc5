/* The firmware loop under fault injection: a mock camera that fails,
 * times out and comes back, a mock serial line that fails, a fake clock.
 * Every frame the loop sends is decoded and checked: poses against the
 * renderer's truth, status frames for what happened. Heap allocations are
 * counted (the test is linked with --wrap=malloc) and must be zero once
 * the loop runs. */
#include "rl_test.h"
#include <math.h>
#include "alloc_count.h"
#include "fixture_eval.h"
#include "rl_packet_sink.h"
#include "rl_png.h"
#include "rl_run.h"
#include "rl_run_view.h"
#include "rl_site.h"

/* ---- a scripted camera ---- */
enum { OK, FAIL_OPEN, GRAB_EIO, GRAB_TIMEOUT, WRONG_SIZE, DAMAGED, END };
typedef struct {
    const int *script; /* what each grab (or open) does */
    int pos, opens, closes, is_open;
    rl_image img, small;
} mock_cam;

/* The double is a frame source: the loop opens, grabs, releases and
 * closes it through rl_run_io like the camera. */
static char cam_error_text[256];
static rl_err cam_grab(void *ctx, int timeout_ms, rl_cam_frame *f)
{
    mock_cam *c = ctx;
    int what = c->script[c->pos];
    (void)timeout_ms;
    assert_true(c->is_open);
    cam_error_text[0] = '\0';
    if (what == END)
        return RL_ENOTFOUND;
    c->pos++;
    if (what == GRAB_EIO)
        return RL_EIO;
    if (what == GRAB_TIMEOUT)
        return RL_ETIMEOUT;
    if (what == DAMAGED) {
        snprintf(cam_error_text, sizeof cam_error_text, "/dev/video9: frame %d is flagged damaged by the driver; dropped", c->pos);
        return RL_EFORMAT;
    }
    f->img = what == WRONG_SIZE ? c->small : c->img;
    f->t_us = 1000000u + (uint64_t)c->pos * 100000u;
    f->index = c->pos;
    f->slot = 0;
    f->name = NULL;
    return RL_OK;
}
static void cam_release(void *ctx, rl_cam_frame *f) { (void)ctx; (void)f; }
static void cam_close(void *ctx) { mock_cam *c = ctx; c->closes++; c->is_open = 0; }
static const char *cam_error(void *ctx) { (void)ctx; return cam_error_text; }
static rl_err cam_open(void *ctx, char *err, size_t errlen)
{
    mock_cam *c = ctx;
    if (c->script[c->pos] == FAIL_OPEN) {
        c->pos++;
        snprintf(err, errlen, "/dev/video9: no such device");
        return RL_ENODEV;
    }
    c->opens++;
    c->is_open = 1;
    return RL_OK;
}

/* ---- a serial line that decodes what it is given ---- */
typedef struct {
    rl_decoder d;
    rl_msg msgs[4096];
    int n, fail_writes, opens;
} mock_out;
static rl_err out_open(void *ctx, char *err, size_t errlen) { (void)err; (void)errlen; ((mock_out *)ctx)->opens++; return RL_OK; }
static rl_err out_write(void *ctx, const uint8_t *p, size_t n)
{
    mock_out *o = ctx;
    size_t i;
    if (o->fail_writes > 0) {
        o->fail_writes--;
        return RL_ENODEV;
    }
    for (i = 0; i < n; i++)
        if (rl_decoder_push(&o->d, p[i], &o->msgs[o->n]) && o->n < 4095)
            o->n++;
    return RL_OK;
}
static void out_close(void *ctx) { (void)ctx; }

static uint64_t fake_now;
static uint64_t now_us(void *ctx) { (void)ctx; return fake_now += 1000; }
static void sleep_us(void *ctx, uint64_t us) { (void)ctx; fake_now += us; }
static int log_lines;
static void log_line(void *ctx, const char *l) { (void)ctx; (void)l; log_lines++; }

/* ---- the scene: a golden fixture and a map made from its truth ---- */
static truth tr;
static rl_site site;
static rl_result res;
static mock_cam cam;
static mock_out out;
static rl_runner runner;
static uint8_t small_px[64 * 48];

static int setup(void **state)
{
    char path[1024], err[512];
    const char *src = getenv("RL_SOURCE_DIR");
    rl_recog_config cfg;
    rl_site_files files;
    int i;
    (void)state;
    snprintf(path, sizeof path, "%s/tests/fixtures/clean_000.yaml", src);
    assert_int_equal(truth_load(path, &tr), 0);
    snprintf(path, sizeof path, "%s/tests/fixtures/camera.yaml", src);
    rl_site_files_init(&files);
    files.calibration = path;
    if (rl_site_load(&site, &files, err, sizeof err) != RL_OK) fail_msg("%s", err);
    snprintf(path, sizeof path, "%s/tests/fixtures/clean_000.png", src);
    if (rl_png_read_gray(path, &cam.img, err, sizeof err) != RL_OK) fail_msg("%s", err);
    cam.small = rl_image_view(64, 48, 64, small_px);
    /* the map from the fixture's truth, the camera 1.87 m below the ceiling */
    site.map.family.bits = 5;
    site.map.diameter = 0.21;
    site.map.ceiling_height = 2.75;
    for (i = 0; i < tr.n; i++) {
        site.map.lm[i].id = tr.lm[i].id;
        site.map.lm[i].x = tr.lm[i].x;
        site.map.lm[i].y = tr.lm[i].y;
    }
    site.map.count = tr.n;
    site.has_map = 1;
    rl_mount_defaults(&site.mount, 2.75 - 1.87);
    site.has_mount = 1;
    rl_recog_defaults(&cfg);
    assert_int_equal(rl_site_prepare(&site, &cfg, err, sizeof err), RL_OK);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    rl_png_free(&cam.img);
    rl_site_free(&site);
    return 0;
}

static rl_packet_sink packets;

static void start_on(const int *script, rl_site *on)
{
    rl_run_io io;
    rl_run_config cfg;
    rl_packet_line line;
    memset(&io, 0, sizeof io);
    io.source.open = cam_open; io.source.grab = cam_grab; io.source.release = cam_release;
    io.source.close = cam_close; io.source.error = cam_error; io.source.ctx = &cam;
    memset(&line, 0, sizeof line);
    line.open = out_open; line.write = out_write; line.close = out_close; line.ctx = &out;
    io.sink = rl_packet_sink_make(&packets, &line);
    io.clock.now_us = now_us; io.clock.sleep_us = sleep_us; io.log = log_line;
    cam.script = script;
    cam.pos = cam.opens = cam.closes = cam.is_open = 0;
    memset(&out, 0, sizeof out);
    rl_decoder_init(&out.d);
    rl_run_defaults(&cfg);
    rl_run_init(&runner, &cfg, &io, on, &res);
}

static void start(const int *script)
{
    start_on(script, &site);
}

static void run_to_end(void)
{
    int guard = 0;
    while (rl_run_step(&runner) != RL_ENOTFOUND)
        assert_true(++guard < 3000);
}

static void assert_pose_right(const rl_msg *m)
{
    assert_int_equal(m->type, RL_PACKET_POSE);
    if (hypot(m->x_mm / 1000.0 - tr.robot_x, m->y_mm / 1000.0 - tr.robot_y) > 0.005)
        fail_msg("pose (%d, %d) mm, truth (%.0f, %.0f) mm", m->x_mm, m->y_mm, tr.robot_x * 1000, tr.robot_y * 1000);
    assert_true(fabs(remainder(m->yaw_e4 / 1e4 - tr.robot_yaw, 2 * M_PI)) < 0.005);
    assert_true(m->used >= 2);
}

static void test_frames_become_poses_without_allocating(void **state)
{
    static const int script[] = {OK, OK, OK, OK, OK, END};
    long before;
    int i;
    (void)state;
    start(script);
    assert_int_equal(rl_run_step(&runner), RL_OK); /* opens the camera */
    before = alloc_count();
    assert_true(before > 0); /* the counter works: setup's malloc was seen */
    run_to_end();
    assert_int_equal(alloc_count() - before, 0);
    assert_int_equal(out.n, 5);
    for (i = 0; i < 5; i++) {
        assert_pose_right(&out.msgs[i]);
        assert_int_equal(out.msgs[i].seq, i);
        assert_int_equal(out.msgs[i].time_ms, (1000000u + (uint32_t)(i + 1) * 100000u) / 1000u);
    }
}

/* With the web view's observer on (issue 29), the loop still makes no heap
 * call and sends the same pose frames, and the view's snapshot is the last
 * frame's: its image, and its pose as sent. */
static void test_view_observer_without_allocating(void **state)
{
    static const int script[] = {OK, OK, OK, OK, OK, END};
    static rl_view view;
    static rl_view_snap snap;
    static rl_run_view rv;
    rl_view_config vc;
    void *vmem, *smem;
    long before;
    int i;
    (void)state;
    rl_view_defaults(&vc);
    vc.width = site.calib.width;
    vc.height = site.calib.height;
    vc.max_rate = 1000; /* every frame of the fake clock's 10 a second */
    vmem = malloc(rl_view_size(&vc));
    smem = malloc(rl_view_size(&vc));
    assert_int_equal(rl_view_init(&view, &vc, vmem, rl_view_size(&vc)), RL_OK);
    assert_int_equal(rl_view_snap_init(&snap, &vc, smem, rl_view_size(&vc)), RL_OK);
    start(script);
    rl_run_view_init(&rv, &view, &runner, "tty", NULL);
    runner.io.observe = rl_run_view_report;
    runner.io.observe_ctx = &rv;
    assert_int_equal(rl_run_step(&runner), RL_OK); /* opens the camera */
    before = alloc_count();
    run_to_end();
    assert_int_equal(alloc_count() - before, 0);
    assert_int_equal(out.n, 5);
    for (i = 0; i < 5; i++)
        assert_pose_right(&out.msgs[i]);
    assert_int_equal(rl_view_take(&view, &snap), 1);
    assert_int_equal(snap.counts.frames, 5);
    assert_true(snap.have_pose && snap.have_image && snap.have_result);
    assert_int_equal((int)lround(snap.pose.x * 1000.0), out.msgs[4].x_mm);
    assert_int_equal((int)lround(snap.pose.y * 1000.0), out.msgs[4].y_mm);
    assert_int_equal(snap.image[1234], cam.img.data[(1234 / cam.img.width) * cam.img.stride + 1234 % cam.img.width]);
    assert_true(snap.res->n_landmarks >= 2);
    rl_view_destroy(&view);
    free(vmem);
    free(smem);
}

static void test_camera_fails_then_comes_back(void **state)
{
    static const int script[] = {FAIL_OPEN, FAIL_OPEN, OK, GRAB_EIO, OK, OK, END};
    int i, camera_errors = 0, poses = 0;
    (void)state;
    start(script);
    run_to_end();
    for (i = 0; i < out.n; i++) {
        if (out.msgs[i].type == RL_PACKET_STATUS) {
            assert_int_equal(out.msgs[i].reason, RL_STATUS_CAMERA_ERROR);
            camera_errors++;
        } else {
            assert_pose_right(&out.msgs[i]);
            poses++;
        }
        assert_int_equal(out.msgs[i].seq, i); /* one counter across both */
    }
    assert_int_equal(poses, 3);
    assert_true(camera_errors >= 3);   /* two failed opens and a failed grab */
    assert_int_equal(cam.opens, 2);    /* opened, failed, reopened */
    /* the backoff grew while opening failed, and a good open reset it */
    assert_int_equal(runner.src_backoff, runner.cfg.backoff_min_us);
}

static void test_timeouts_reopen_the_camera(void **state)
{
    static const int script[] = {OK, GRAB_TIMEOUT, GRAB_TIMEOUT, GRAB_TIMEOUT, OK, GRAB_TIMEOUT, OK, END};
    int i, timeouts = 0, poses = 0;
    (void)state;
    start(script);
    run_to_end();
    for (i = 0; i < out.n; i++) {
        if (out.msgs[i].type == RL_PACKET_STATUS) {
            assert_int_equal(out.msgs[i].reason, RL_STATUS_CAMERA_TIMEOUT);
            timeouts++;
        } else {
            poses++;
        }
    }
    assert_int_equal(timeouts, 4);
    assert_int_equal(poses, 3);
    assert_int_equal(cam.opens, 2); /* three timeouts in a row: reopened once */
    assert_int_equal(rl_run_counts_of(&runner)->camera_timeouts, 4);
}

static void test_serial_write_fails_and_recovers(void **state)
{
    static const int script[] = {OK, OK, OK, OK, OK, END};
    int i;
    (void)state;
    start(script);
    assert_int_equal(rl_run_step(&runner), RL_OK);
    assert_int_equal(rl_run_step(&runner), RL_OK); /* frame 0 sent */
    out.fail_writes = 1;
    assert_int_equal(rl_run_step(&runner), RL_OK); /* frame 1 lost: line reopened later */
    fake_now += 10 * runner.cfg.backoff_max_us;
    run_to_end();
    assert_int_equal(rl_run_counts_of(&runner)->sink_errors, 1);
    assert_int_equal(out.opens, 2);
    assert_int_equal(out.n, 4);
    assert_int_equal(out.msgs[0].seq, 0);
    assert_int_equal(out.msgs[1].seq, 2); /* the gap says a frame was lost */
    for (i = 0; i < out.n; i++)
        assert_pose_right(&out.msgs[i]);
}

static void test_bad_frame_does_not_stop_the_loop(void **state)
{
    static const int script[] = {OK, WRONG_SIZE, OK, END};
    (void)state;
    start(script);
    run_to_end();
    assert_int_equal(out.n, 3);
    assert_pose_right(&out.msgs[0]);
    assert_int_equal(out.msgs[1].type, RL_PACKET_STATUS);
    assert_int_equal(out.msgs[1].reason, RL_STATUS_CONFIG_ERROR);
    assert_pose_right(&out.msgs[2]);
}

/* A frame the camera could not give whole is skipped: counted, a
 * status frame (camera error), and no reopening. */
static void test_damaged_frame_is_skipped(void **state)
{
    static const int script[] = {OK, DAMAGED, DAMAGED, OK, END};
    (void)state;
    start(script);
    run_to_end();
    assert_int_equal(out.n, 4);
    assert_pose_right(&out.msgs[0]);
    assert_int_equal(out.msgs[1].type, RL_PACKET_STATUS);
    assert_int_equal(out.msgs[1].reason, RL_STATUS_CAMERA_ERROR);
    assert_int_equal(out.msgs[2].reason, RL_STATUS_CAMERA_ERROR);
    assert_pose_right(&out.msgs[3]);
    assert_int_equal(rl_run_counts_of(&runner)->bad_frames, 2);
    assert_int_equal(rl_run_counts_of(&runner)->camera_errors, 0);
    assert_int_equal(cam.opens, 1);
}

static void test_logs_are_rate_limited(void **state)
{
    static int script[64];
    int i;
    (void)state;
    for (i = 0; i < 40; i++)
        script[i] = FAIL_OPEN;
    script[40] = OK;
    script[41] = END;
    log_lines = 0;
    start(script);
    run_to_end();
    /* 40 failed opens within a few simulated seconds: a handful of lines */
    assert_true(rl_run_counts_of(&runner)->camera_errors == 40);
    assert_true(log_lines < 40 / 2);
}

/* Issue 16: a map that holds the frame's constellation twice (the same
 * ids again 10 m away). With no prior every frame is ambiguous: status
 * frames, reason 5, no pose. With the last pose known (0.1 s before the
 * first frame) each frame is placed near it, tracked, and right. Nothing
 * is allocated while the loop runs. */
static void test_repeated_ids_ambiguous_then_tracked(void **state)
{
    static const int script[] = {OK, OK, OK, END};
    static rl_site twice;
    rl_recog_config cfg;
    rl_pose last;
    char err[256];
    long before;
    int i;
    (void)state;
    twice = site;
    memset(&twice.recog, 0, sizeof twice.recog);
    memset(&twice.place, 0, sizeof twice.place);
    for (i = 0; i < site.map.count; i++) {
        twice.map.lm[site.map.count + i] = site.map.lm[i];
        twice.map.lm[site.map.count + i].x += 10.0;
    }
    twice.map.count = 2 * site.map.count;
    rl_recog_defaults(&cfg);
    assert_int_equal(rl_site_prepare(&twice, &cfg, err, sizeof err), RL_OK);
    assert_non_null(twice.place.pl); /* ids repeat: places */
    start_on(script, &twice);
    assert_int_equal(rl_run_step(&runner), RL_OK);
    before = alloc_count();
    run_to_end();
    assert_int_equal(alloc_count() - before, 0);
    assert_int_equal(out.n, 3);
    for (i = 0; i < 3; i++) {
        assert_int_equal(out.msgs[i].type, RL_PACKET_STATUS);
        assert_int_equal(out.msgs[i].reason, RL_STATUS_AMBIGUOUS);
    }
    assert_int_equal(rl_run_counts_of(&runner)->ambiguous, 3);
    start_on(script, &twice);
    memset(&last, 0, sizeof last);
    last.x = tr.robot_x + 0.05;
    last.y = tr.robot_y - 0.05;
    last.yaw = tr.robot_yaw + 0.05;
    rl_run_start_at(&runner, &last, 1000000u); /* the first frame is at 1.1 s */
    run_to_end();
    assert_int_equal(out.n, 3);
    for (i = 0; i < 3; i++)
        assert_pose_right(&out.msgs[i]);
    assert_int_equal(rl_run_counts_of(&runner)->tracked, 3);
    rl_site_free(&twice);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_frames_become_poses_without_allocating),
        cmocka_unit_test(test_view_observer_without_allocating),
        cmocka_unit_test(test_camera_fails_then_comes_back),
        cmocka_unit_test(test_timeouts_reopen_the_camera),
        cmocka_unit_test(test_serial_write_fails_and_recovers),
        cmocka_unit_test(test_bad_frame_does_not_stop_the_loop),
        cmocka_unit_test(test_damaged_frame_is_skipped),
        cmocka_unit_test(test_logs_are_rate_limited),
        cmocka_unit_test(test_repeated_ids_ambiguous_then_tracked),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
