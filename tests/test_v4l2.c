/* The V4L2 camera against a fake device at its system-call seam
 * (rl_v4l2_sys): the real backend negotiates formats, maps buffers,
 * applies controls and streams from a device that offers what a test
 * tells it to, and fails the ways devices fail. Frames are a rendered
 * golden fixture put into each pixel format; the luminance the backend
 * gives must be the original's, byte for byte (MJPEG, made here with
 * libturbojpeg: the same landmarks as the original within JPEG's
 * tolerance). */
#include "rl_test.h"
#include <errno.h>
#include <linux/videodev2.h>
#include <math.h>
#include <sys/mman.h>
#include <turbojpeg.h>
#include "rl_cam.h"
#include "rl_heap_recog.h"
#include "rl_png.h"
#include "rl_v4l2_sys.h"

#define W 640
#define H 480
#define NBUF 4
#define BUFLEN ((2 * W + 128) * H + 4096)
#define FAKE_FD 77

/* what a DQBUF does */
enum { GOOD, FLAGGED, SHORT, BAD_INDEX, GONE, SILENT };

typedef struct {
    uint32_t formats[8];
    int nformats, sizes_listed; /* ENUM_FRAMESIZES answers (640x480 and 320x240) */
    int open_errno, sfmt_errno, qbuf_errno;
    long bpl;                   /* bytesperline the driver reports (-1: the natural one) */
    long buflen;                /* length of each buffer */
    uint32_t fourcc;
    int streaming, opened, closed;
    uint8_t *buf[NBUF];
    int queued[NBUF], nqueued_total;
    int script[32], nscript, at;
    int has_exposure, has_gain;
    int soe;                 /* stamps at the start of exposure (else the V4L2 default, end of frame) */
    int exp_auto, exposure, autogain, gain;
    uint64_t ts_us;
    const rl_image *src;
} fake;

static fake fk;
static rl_image src;
static unsigned char *jpeg; /* src as a JPEG, made with libturbojpeg */
static unsigned long jpeg_len;

static size_t natural_bpl(uint32_t f)
{
    return (f == V4L2_PIX_FMT_YUYV || f == V4L2_PIX_FMT_UYVY) ? 2 * W : f == V4L2_PIX_FMT_MJPEG ? 0 : W;
}

static size_t stride_of(uint32_t f)
{
    return fk.bpl >= 0 && fk.bpl != 0 ? (size_t)fk.bpl : natural_bpl(f);
}

/* the source frame in the current format; its size in bytes */
static size_t fill(uint8_t *b)
{
    size_t st = stride_of(fk.fourcc);
    int x, y;
    if (fk.fourcc == V4L2_PIX_FMT_MJPEG) {
        memcpy(b, jpeg, jpeg_len);
        return jpeg_len;
    }
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            uint8_t v = fk.src->data[(size_t)y * fk.src->stride + x];
            switch (fk.fourcc) {
            case V4L2_PIX_FMT_YUYV: b[y * st + 2 * x] = v; b[y * st + 2 * x + 1] = 128; break;
            case V4L2_PIX_FMT_UYVY: b[y * st + 2 * x + 1] = v; b[y * st + 2 * x] = 128; break;
            default: b[y * st + x] = v; break;
            }
        }
    if (fk.fourcc == V4L2_PIX_FMT_NV12 || fk.fourcc == V4L2_PIX_FMT_YUV420) {
        memset(b + st * H, 128, st * H / 2);
        return st * H * 3 / 2;
    }
    return st * H;
}

static int f_open(void *ctx, const char *path, int flags)
{
    (void)ctx; (void)flags;
    if (fk.open_errno) {
        errno = fk.open_errno;
        return -1;
    }
    assert_string_equal(path, "/dev/videoFAKE");
    fk.opened++;
    return FAKE_FD;
}

static int f_close(void *ctx, int fd)
{
    (void)ctx;
    assert_int_equal(fd, FAKE_FD);
    fk.closed++;
    return 0;
}

static int query_ctrl(struct v4l2_queryctrl *q)
{
    int known = (q->id == V4L2_CID_EXPOSURE_AUTO || q->id == V4L2_CID_EXPOSURE_ABSOLUTE) ? fk.has_exposure
              : (q->id == V4L2_CID_AUTOGAIN || q->id == V4L2_CID_GAIN) ? fk.has_gain : 0;
    if (q->id & V4L2_CTRL_FLAG_NEXT_CTRL) { /* the listing: exposure, then gain */
        uint32_t after = q->id & ~V4L2_CTRL_FLAG_NEXT_CTRL;
        if (after < V4L2_CID_GAIN && fk.has_gain) q->id = V4L2_CID_GAIN;
        else if (after < V4L2_CID_EXPOSURE_ABSOLUTE && fk.has_exposure) q->id = V4L2_CID_EXPOSURE_ABSOLUTE;
        else { errno = EINVAL; return -1; }
        known = 1;
    }
    if (!known) {
        errno = EINVAL;
        return -1;
    }
    q->flags = 0;
    q->type = V4L2_CTRL_TYPE_INTEGER;
    q->minimum = q->id == V4L2_CID_EXPOSURE_ABSOLUTE ? 3 : q->id == V4L2_CID_GAIN ? 0 : 0;
    q->maximum = q->id == V4L2_CID_EXPOSURE_ABSOLUTE ? 2047 : q->id == V4L2_CID_GAIN ? 255 : 3;
    q->step = 1;
    snprintf((char *)q->name, sizeof q->name, "%s", q->id == V4L2_CID_GAIN ? "Gain" : "Exposure Time, Absolute");
    return 0;
}

static int set_ctrl(const struct v4l2_control *c)
{
    switch (c->id) {
    case V4L2_CID_EXPOSURE_AUTO: if (!fk.has_exposure) break; fk.exp_auto = c->value; return 0;
    case V4L2_CID_EXPOSURE_ABSOLUTE: if (!fk.has_exposure) break; fk.exposure = c->value; return 0;
    case V4L2_CID_AUTOGAIN: if (!fk.has_gain) break; fk.autogain = c->value; return 0;
    case V4L2_CID_GAIN: if (!fk.has_gain) break; fk.gain = c->value; return 0;
    }
    errno = EINVAL;
    return -1;
}

static int dqbuf(struct v4l2_buffer *b)
{
    int what = fk.at < fk.nscript ? fk.script[fk.at] : GOOD, i;
    if (fk.at < fk.nscript)
        fk.at++;
    if (what == GONE) {
        errno = ENODEV;
        return -1;
    }
    for (i = 0; i < NBUF && !fk.queued[i]; i++)
        continue;
    if (i == NBUF) {
        errno = EAGAIN;
        return -1;
    }
    fk.queued[i] = 0;
    b->index = what == BAD_INDEX ? 9 : (unsigned)i;
    b->bytesused = (uint32_t)fill(fk.buf[i]);
    if (what == SHORT)
        b->bytesused /= 3;
    b->flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | (what == FLAGGED ? V4L2_BUF_FLAG_ERROR : 0) |
               (fk.soe ? V4L2_BUF_FLAG_TSTAMP_SRC_SOE : V4L2_BUF_FLAG_TSTAMP_SRC_EOF);
    fk.ts_us += 33333;
    b->timestamp.tv_sec = (time_t)(fk.ts_us / 1000000u);
    b->timestamp.tv_usec = (suseconds_t)(fk.ts_us % 1000000u);
    return 0;
}

static int f_ioctl(void *ctx, int fd, unsigned long req, void *arg)
{
    (void)ctx;
    assert_int_equal(fd, FAKE_FD);
    switch (req) {
    case VIDIOC_QUERYCAP: {
        struct v4l2_capability *c = arg;
        snprintf((char *)c->driver, sizeof c->driver, "fake");
        snprintf((char *)c->card, sizeof c->card, "Fake Camera");
        c->capabilities = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
        return 0;
    }
    case VIDIOC_ENUM_FMT: {
        struct v4l2_fmtdesc *d = arg;
        if (d->index >= (unsigned)fk.nformats) { errno = EINVAL; return -1; }
        d->pixelformat = fk.formats[d->index];
        snprintf((char *)d->description, sizeof d->description, "format %u", d->index);
        return 0;
    }
    case VIDIOC_ENUM_FRAMESIZES: {
        struct v4l2_frmsizeenum *s = arg;
        if (!fk.sizes_listed || s->index > 1) { errno = EINVAL; return -1; }
        s->type = V4L2_FRMSIZE_TYPE_DISCRETE;
        s->discrete.width = s->index == 0 ? W : 320;
        s->discrete.height = s->index == 0 ? H : 240;
        return 0;
    }
    case VIDIOC_S_FMT: {
        struct v4l2_format *f = arg;
        int i, offered = 0;
        if (fk.sfmt_errno) { errno = fk.sfmt_errno; return -1; }
        for (i = 0; i < fk.nformats; i++)
            offered |= fk.formats[i] == f->fmt.pix.pixelformat;
        if (!offered)
            f->fmt.pix.pixelformat = fk.formats[0]; /* drivers answer with what they have */
        fk.fourcc = f->fmt.pix.pixelformat;
        f->fmt.pix.width = W;
        f->fmt.pix.height = H;
        f->fmt.pix.bytesperline = fk.bpl >= 0 ? (uint32_t)fk.bpl : (uint32_t)natural_bpl(fk.fourcc);
        f->fmt.pix.sizeimage = fk.fourcc == V4L2_PIX_FMT_MJPEG ? (uint32_t)fk.buflen : (uint32_t)(stride_of(fk.fourcc) * H * 3 / 2);
        return 0;
    }
    case VIDIOC_S_PARM: return 0;
    case VIDIOC_QUERYCTRL: return query_ctrl(arg);
    case VIDIOC_S_CTRL: return set_ctrl(arg);
    case VIDIOC_G_CTRL: { struct v4l2_control *c = arg; c->value = 7; return 0; }
    case VIDIOC_REQBUFS: {
        struct v4l2_requestbuffers *r = arg;
        r->count = NBUF;
        return 0;
    }
    case VIDIOC_QUERYBUF: {
        struct v4l2_buffer *b = arg;
        if (b->index >= NBUF) { errno = EINVAL; return -1; }
        b->length = (uint32_t)fk.buflen;
        b->m.offset = b->index * 0x100000u;
        return 0;
    }
    case VIDIOC_QBUF: {
        struct v4l2_buffer *b = arg;
        if (fk.qbuf_errno) { errno = fk.qbuf_errno; return -1; }
        if (b->index >= NBUF || fk.queued[b->index]) { errno = EINVAL; return -1; }
        fk.queued[b->index] = 1;
        fk.nqueued_total++;
        return 0;
    }
    case VIDIOC_DQBUF: return dqbuf(arg);
    case VIDIOC_STREAMON: fk.streaming = 1; return 0;
    case VIDIOC_STREAMOFF: fk.streaming = 0; return 0;
    }
    errno = ENOTTY;
    return -1;
}

static void *f_mmap(void *ctx, size_t len, int fd, off_t offset)
{
    (void)ctx;
    assert_int_equal(fd, FAKE_FD);
    assert_true(len == (size_t)fk.buflen);
    return fk.buf[offset / 0x100000];
}

static int f_munmap(void *ctx, void *addr, size_t len) { (void)ctx; (void)addr; (void)len; return 0; }

static int f_poll(void *ctx, struct pollfd *p, int timeout_ms)
{
    int what = fk.at < fk.nscript ? fk.script[fk.at] : GOOD;
    (void)ctx; (void)timeout_ms;
    if (what == SILENT) {
        fk.at++;
        return 0;
    }
    p->revents = POLLIN;
    return 1;
}

static const rl_v4l2_sys fake_sys = {f_open, f_close, f_ioctl, f_mmap, f_munmap, f_poll, NULL};

/* a device offering these formats, with everything else as a good one */
static void device(const uint32_t *formats, int n)
{
    int i;
    for (i = 0; i < NBUF; i++)
        free(fk.buf[i]);
    memset(&fk, 0, sizeof fk);
    for (i = 0; i < n; i++)
        fk.formats[i] = formats[i];
    fk.nformats = n;
    fk.sizes_listed = 1;
    fk.bpl = -1;
    fk.buflen = BUFLEN;
    fk.has_exposure = fk.has_gain = 1;
    fk.exp_auto = fk.autogain = -1;
    fk.src = &src;
    fk.ts_us = 5000000;
    for (i = 0; i < NBUF; i++)
        fk.buf[i] = calloc(1, BUFLEN);
}

static rl_cam_config config(void)
{
    rl_cam_config cc;
    rl_cam_defaults(&cc);
    cc.backend = "v4l2";
    cc.device = "/dev/videoFAKE";
    cc.width = W;
    cc.height = H;
    cc.rate = 30;
    cc.v4l2_sys = &fake_sys;
    return cc;
}

static void open_ok(rl_cam *c, const rl_cam_config *cc)
{
    char err[512] = "";
    if (rl_cam_open(c, cc, err, sizeof err) != RL_OK)
        fail_msg("open: %s", err);
}

/* opening fails with code, and err names the device and says text */
static void open_fails(const rl_cam_config *cc, rl_err code, const char *text)
{
    rl_cam c;
    char err[512] = "";
    assert_int_equal(rl_cam_open(&c, cc, err, sizeof err), code);
    assert_non_null(strstr(err, "/dev/videoFAKE: "));
    if (strstr(err, text) == NULL)
        fail_msg("'%s' does not say '%s'", err, text);
}

static void assert_same_pixels(const rl_image *img)
{
    int y;
    assert_int_equal(img->width, W);
    assert_int_equal(img->height, H);
    for (y = 0; y < H; y++)
        assert_memory_equal(img->data + (size_t)y * img->stride, src.data + (size_t)y * src.stride, W);
}

static int setup(void **state)
{
    char path[1024], err[512];
    const char *dir = getenv("RL_SOURCE_DIR");
    tjhandle tj;
    (void)state;
    snprintf(path, sizeof path, "%s/tests/fixtures/clean_000.png", dir ? dir : ".");
    if (rl_png_read_gray(path, &src, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    assert_int_equal(src.width, W);
    tj = tjInitCompress();
    assert_non_null(tj);
    assert_int_equal(tjCompress2(tj, src.data, W, src.stride, H, TJPF_GRAY, &jpeg, &jpeg_len, TJSAMP_GRAY, 90, 0), 0);
    tjDestroy(tj);
    return 0;
}

static int teardown(void **state)
{
    int i;
    (void)state;
    for (i = 0; i < NBUF; i++)
        free(fk.buf[i]);
    tjFree(jpeg);
    rl_png_free(&src);
    return 0;
}

/* Every raw format gives the original's luminance; the plane formats lend
 * the driver's buffer itself, at the driver's stride. */
static void test_each_raw_format_gives_the_luminance(void **state)
{
    static const uint32_t raw[] = {V4L2_PIX_FMT_GREY, V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_YUV420,
                                   V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_UYVY};
    static const char *names[] = {"GREY", "NV12", "YU12", "YUYV", "UYVY"};
    int i, pad;
    (void)state;
    for (pad = 0; pad < 2; pad++)
        for (i = 0; i < 5; i++) {
            rl_cam c;
            rl_cam_config cc = config();
            rl_cam_frame f;
            device(&raw[i], 1);
                    if (pad)
                fk.bpl = (long)natural_bpl(raw[i]) + 64; /* rows padded by the driver */
            open_ok(&c, &cc);
            assert_non_null(strstr(c.info, names[i]));
            assert_int_equal(rl_cam_grab(&c, 100, &f), RL_OK);
            assert_same_pixels(&f.img);
            if (i < 3) /* lent as is */
                assert_ptr_equal(f.img.data, fk.buf[f.slot]);
            assert_int_equal((long)f.t_us, 5033333L); /* the driver's timestamp */
            rl_cam_release(&c, &f);
            rl_cam_close(&c);
            assert_int_equal(fk.closed, 1);
            assert_int_equal(fk.streaming, 0);
        }
}

/* A rolling shutter read in 20 ms with a 10 ms exposure: the frame's
 * time is the middle row's mid-exposure, 10 + 5 ms after the first row
 * began its exposure (a start-of-exposure stamp), 10 + 5 ms before the
 * last row was read (V4L2's default, end-of-frame stamp); told the driver
 * stamps the first row's read (camera.stamp: frame_start), 10 - 5 ms after
 * it. The driver's first stamp is 5.033333 s. */
static void test_stamps_moved_to_the_middle_row(void **state)
{
    static const uint32_t grey = V4L2_PIX_FMT_GREY;
    static const struct {
        int soe, stamp;
        long want;
    } cases[] = {{0, RL_CAM_STAMP_AUTO, 5018333L}, {1, RL_CAM_STAMP_AUTO, 5048333L},
                 {0, RL_CAM_STAMP_FRAME_START, 5038333L}};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rl_cam c;
        rl_cam_config cc = config();
        rl_cam_frame f;
        cc.readout_us = 20000;
        cc.exposure_us = 10000;
        cc.stamp = cases[i].stamp;
        device(&grey, 1);
        fk.soe = cases[i].soe;
        open_ok(&c, &cc);
        assert_int_equal(rl_cam_grab(&c, 100, &f), RL_OK);
        assert_int_equal((long)f.t_us, cases[i].want);
        rl_cam_release(&c, &f);
        rl_cam_close(&c);
    }
    /* each kind by hand (readout 20 ms, exposure 10 ms, stamp 1 s) */
    assert_int_equal((long)rl_cam_middle_time(1000000, RL_CAM_STAMP_MIDDLE, 20000, 10000), 1000000L);
    assert_int_equal((long)rl_cam_middle_time(1000000, RL_CAM_STAMP_EXPOSURE_START, 20000, 10000), 1015000L);
    assert_int_equal((long)rl_cam_middle_time(1000000, RL_CAM_STAMP_FRAME_START, 20000, 10000), 1005000L);
    assert_int_equal((long)rl_cam_middle_time(1000000, RL_CAM_STAMP_FRAME_END, 20000, 10000), 985000L);
    assert_int_equal((long)rl_cam_middle_time(1000, RL_CAM_STAMP_FRAME_END, 20000, 10000), 0L); /* not before 0 */
}

/* MJPEG frames decode to the same landmarks as the grey original. */
static void test_mjpeg_gives_the_same_landmarks(void **state)
{
    static const uint32_t mj[] = {V4L2_PIX_FMT_MJPEG};
    static rl_result a, b;
    rl_recog_config rc;
    rl_heap_recog hr;
    rl_cam c;
    rl_cam_config cc = config();
    rl_cam_frame f;
    int i, j;
    (void)state;
    device(mj, 1);
    open_ok(&c, &cc);
    assert_non_null(strstr(c.info, "MJPG"));
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_OK);
    rl_recog_defaults(&rc);
    rc.gamma = 2.2; /* one tone curve for both frames: a learned one may move between them */
    rl_heap_recog_init(&hr, &rc);
    assert_int_equal(rl_heap_recog_run(&hr, &src, &a), RL_OK);
    assert_int_equal(rl_heap_recog_run(&hr, &f.img, &b), RL_OK);
    assert_true(a.n_landmarks >= 3);
    assert_int_equal(a.n_landmarks, b.n_landmarks);
    for (i = 0; i < a.n_landmarks; i++) {
        int found = 0;
        for (j = 0; j < b.n_landmarks; j++)
            if (a.landmarks[i].id == b.landmarks[j].id &&
                hypot(a.landmarks[i].u - b.landmarks[j].u, a.landmarks[i].v - b.landmarks[j].v) < 0.5)
                found = 1;
        if (!found)
            fail_msg("landmark %d at (%.1f, %.1f) not found in the MJPEG frame", a.landmarks[i].id,
                     a.landmarks[i].u, a.landmarks[i].v);
    }
    rl_cam_release(&c, &f);
    rl_cam_close(&c);
    rl_heap_recog_free(&hr);
}

/* The best format offered at the size: a plane to lend before a packed
 * one to copy before a JPEG to decode; one not at the size is passed by. */
static void test_best_format_at_the_size(void **state)
{
    static const uint32_t offered[] = {V4L2_PIX_FMT_MJPEG, V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_RGB24};
    rl_cam c;
    rl_cam_config cc = config();
    (void)state;
    device(offered, 4);
    open_ok(&c, &cc);
    assert_non_null(strstr(c.info, "NV12"));
    rl_cam_close(&c);
    /* 1280x720 is offered by none: the error lists what the device has */
    device(offered, 4);
    cc.width = 1280;
    cc.height = 720;
    open_fails(&cc, RL_EUNSUPPORTED, "at 1280x720 (it has: MJPG YUYV NV12 RGB3)");
    /* only formats ringloc does not take */
    device(&offered[3], 1);
    cc = config();
    open_fails(&cc, RL_EUNSUPPORTED, "offers none of");
}

/* Each way a device fails at open has its own reason. */
static void test_open_failures_say_why(void **state)
{
    static const uint32_t grey[] = {V4L2_PIX_FMT_GREY};
    rl_cam c;
    rl_cam_config cc = config();
    (void)state;
    device(grey, 1);
    fk.open_errno = ENOENT;
    open_fails(&cc, RL_ENOTFOUND, "/dev/videoFAKE: no such device");
    device(grey, 1);
    fk.open_errno = EACCES;
    open_fails(&cc, RL_ENODEV, "permission denied");
    device(grey, 1);
    fk.sfmt_errno = EBUSY;
    open_fails(&cc, RL_ENODEV, "device busy");
    assert_int_equal(fk.closed, 1); /* nothing left open */
    device(grey, 1);
    fk.bpl = W / 2; /* a stride that cannot hold a row */
    open_fails(&cc, RL_EUNSUPPORTED, "bytes per line");
    device(grey, 1);
    fk.buflen = W * H / 2; /* buffers smaller than a frame */
    open_fails(&cc, RL_EUNSUPPORTED, "a frame needs 307200");
    device(grey, 1);
    fk.bpl = 0; /* drivers that leave bytesperline to us */
    open_ok(&c, &cc);
    rl_cam_close(&c);
}

/* Damaged, short and foreign buffers are dropped and given back; the
 * stream goes on. A vanished device and a silent one say so. */
static void test_bad_buffers_are_dropped(void **state)
{
    static const uint32_t grey[] = {V4L2_PIX_FMT_GREY};
    rl_cam c;
    rl_cam_config cc = config();
    rl_cam_frame f;
    int queued;
    (void)state;
    device(grey, 1);
    fk.script[0] = FLAGGED;
    fk.script[1] = SHORT;
    fk.script[2] = GOOD;
    fk.script[3] = BAD_INDEX;
    fk.script[4] = GOOD;
    fk.script[5] = SILENT;
    fk.script[6] = GONE;
    fk.nscript = 7;
    open_ok(&c, &cc);
    queued = fk.nqueued_total;
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_EFORMAT);
    assert_non_null(strstr(c.error, "flagged damaged"));
    assert_int_equal(fk.nqueued_total, queued + 1); /* given back */
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_EFORMAT);
    assert_non_null(strstr(c.error, "a GREY frame 307200"));
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_OK);
    assert_same_pixels(&f.img);
    rl_cam_release(&c, &f);
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_EFORMAT);
    assert_non_null(strstr(c.error, "buffer 9 of 4"));
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_OK);
    rl_cam_release(&c, &f);
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_ETIMEOUT);
    assert_non_null(strstr(c.error, "no frame in 100 ms"));
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_ENODEV);
    assert_non_null(strstr(c.error, "device gone"));
    rl_cam_close(&c);
    /* a buffer that cannot be queued again: the next grab says so */
    device(grey, 1);
    open_ok(&c, &cc);
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_OK);
    fk.qbuf_errno = ENODEV;
    rl_cam_release(&c, &f);
    assert_int_equal(rl_cam_grab(&c, 100, &f), RL_ENODEV);
    assert_non_null(strstr(c.error, "re-queueing"));
    rl_cam_close(&c);
}

/* exposure and gain: manual as configured, in the device's units, within
 * its range; a control the device lacks is an error, never ignored */
static void test_exposure_and_gain(void **state)
{
    static const uint32_t grey[] = {V4L2_PIX_FMT_GREY};
    rl_cam c;
    rl_cam_config cc = config();
    (void)state;
    device(grey, 1);
    open_ok(&c, &cc);
    assert_int_equal(fk.exp_auto, V4L2_EXPOSURE_AUTO);
    assert_int_equal(fk.autogain, 1);
    assert_non_null(strstr(c.info, "exposure auto, gain auto"));
    rl_cam_close(&c);
    device(grey, 1);
    cc.exposure_us = 10000;
    cc.gain = 4;
    open_ok(&c, &cc);
    assert_int_equal(fk.exp_auto, V4L2_EXPOSURE_MANUAL);
    assert_int_equal(fk.exposure, 100); /* 100 us units */
    assert_int_equal(fk.autogain, 0);
    assert_int_equal(fk.gain, 4);
    assert_non_null(strstr(c.info, "exposure 10000 us, gain 4"));
    rl_cam_close(&c);
    device(grey, 1);
    cc.exposure_us = 1000000; /* 10000 units: beyond the device's 2047 */
    open_fails(&cc, RL_EUNSUPPORTED, "outside the device's 3 .. 2047");
    device(grey, 1);
    fk.has_exposure = 0;
    cc.exposure_us = 10000;
    open_fails(&cc, RL_EUNSUPPORTED, "offers no exposure");
}

static char probe_text[4096];
static void probe_line(void *ctx, const char *t)
{
    (void)ctx;
    strncat(probe_text, t, sizeof probe_text - strlen(probe_text) - 2);
    strcat(probe_text, "\n");
}

/* --probe lists the formats with their sizes, the one chosen, the controls */
static void test_probe_lists_formats_and_controls(void **state)
{
    static const uint32_t offered[] = {V4L2_PIX_FMT_MJPEG, V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_RGB24};
    rl_cam_config cc = config();
    char err[256];
    (void)state;
    device(offered, 3);
    probe_text[0] = '\0';
    assert_int_equal(rl_cam_probe(&cc, probe_line, NULL, err, sizeof err), RL_OK);
    assert_non_null(strstr(probe_text, "Fake Camera (driver fake)"));
    assert_non_null(strstr(probe_text, "* MJPG"));
    assert_non_null(strstr(probe_text, "* YUYV"));
    assert_non_null(strstr(probe_text, "  RGB3"));
    assert_non_null(strstr(probe_text, "640x480 320x240"));
    assert_non_null(strstr(probe_text, "ringloc would stream YUYV"));
    assert_non_null(strstr(probe_text, "control Gain"));
    assert_non_null(strstr(probe_text, "control Exposure Time, Absolute"));
}

/* --probe names the format streaming takes, for devices offering any mix
 * (the choice is made in one place, v4l2_dev_choose) */
static void test_probe_and_streaming_agree(void **state)
{
    static const uint32_t offered[] = {V4L2_PIX_FMT_GREY, V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_UYVY,
                                       V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_MJPEG};
    char chosen[64] = "";
    char err[256], want[64];
    int first;
    (void)state;
    for (first = 0; first < 5; first++) {
        rl_cam_config cc = config();
        rl_cam c;
        const char *fmt;
        device(&offered[first], 5 - first);
        open_ok(&c, &cc);
        /* the info line starts with the format's name */
        fmt = strstr(c.info, "GREY") ? "GREY" : strstr(c.info, "NV12") ? "NV12" : strstr(c.info, "UYVY") ? "UYVY"
            : strstr(c.info, "YUYV") ? "YUYV" : "MJPG";
        rl_cam_close(&c);
        device(&offered[first], 5 - first);
        probe_text[0] = '\0';
        assert_int_equal(rl_cam_probe(&cc, probe_line, NULL, err, sizeof err), RL_OK);
        snprintf(want, sizeof want, "ringloc would stream %s", fmt);
        if (strstr(probe_text, want) == NULL)
            fail_msg("streaming took %s (%s), --probe said: %s", fmt, c.info, probe_text);
        strcat(chosen, fmt);
        strcat(chosen, " ");
    }
    /* each device's best in the table's order (GREY, NV12, YU12, YUYV,
     * UYVY, MJPG): a plane, then packed, then JPEG */
    assert_string_equal(chosen, "GREY NV12 YUYV YUYV MJPG ");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_each_raw_format_gives_the_luminance),
        cmocka_unit_test(test_stamps_moved_to_the_middle_row),
        cmocka_unit_test(test_mjpeg_gives_the_same_landmarks),
        cmocka_unit_test(test_best_format_at_the_size),
        cmocka_unit_test(test_open_failures_say_why),
        cmocka_unit_test(test_bad_buffers_are_dropped),
        cmocka_unit_test(test_exposure_and_gain),
        cmocka_unit_test(test_probe_lists_formats_and_controls),
        cmocka_unit_test(test_probe_and_streaming_agree),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
