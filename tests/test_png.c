/* PNG input: every colour type and depth to 8-bit luminance, and broken
 * files giving one error that names the file. Test files are written here
 * with libpng directly, independently of the reader under test. */
#include "rl_test.h"
#include "rl_png.h"
#include <png.h>

static char path[512];

/* Write a PNG with libpng from packed rows of the given format. */
static void write_raw(const char *p, int w, int h, int depth, int color, const uint8_t *data,
                      size_t rowbytes, int interlace, const png_color *pal, int npal)
{
    FILE *f = fopen(p, "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    int y, pass, passes;
    assert_non_null(f);
    if (setjmp(png_jmpbuf(png)))
        fail_msg("libpng failed writing a test file");
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, depth, color,
                 interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (pal)
        png_set_PLTE(png, info, pal, npal);
    png_write_info(png, info);
    if (depth == 16)
        png_set_swap(png); /* test data is little-endian host order */
    passes = interlace ? png_set_interlace_handling(png) : 1;
    for (pass = 0; pass < passes; pass++)
        for (y = 0; y < h; y++)
            png_write_row(png, data + (size_t)y * rowbytes);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    fclose(f);
}

static uint8_t luma(int r, int g, int b)
{
    /* BT.601: pure red 76, green 150, blue 29 (OpenCV's RGB2GRAY values) */
    double y = 0.299 * r + 0.587 * g + 0.114 * b;
    return (uint8_t)(y + 0.5);
}

/* Read with rl_png_read_gray, and into a block of exactly
 * rl_png_block_size: both give the same pixels. */
static void read_ok(const char *p, int w, int h, rl_image *img)
{
    static uint8_t block[1 << 20];
    char err[256] = "";
    rl_image into;
    int y;
    rl_err e = rl_png_read_gray(p, img, err, sizeof err);
    if (e != RL_OK)
        fail_msg("%s", err);
    assert_int_equal(img->width, w);
    assert_int_equal(img->height, h);
    assert_true(img->stride >= w);
    assert_true(rl_png_block_size(w, h) <= sizeof block);
    e = rl_png_read_gray_into(p, block, rl_png_block_size(w, h), &into, err, sizeof err);
    if (e != RL_OK)
        fail_msg("into a block: %s", err);
    assert_int_equal(into.width, w);
    assert_int_equal(into.height, h);
    assert_true((uint8_t *)into.data >= block && (uint8_t *)into.data + (size_t)w * h <= block + sizeof block);
    for (y = 0; y < h; y++)
        assert_memory_equal(into.data + (size_t)y * into.stride, img->data + (size_t)y * img->stride, (size_t)w);
}

/* A block sized for a smaller frame refuses a larger one, naming it; the
 * size comes from the header alone. */
static void test_block_too_small(void **state)
{
    static uint8_t px[640 * 480], block[4 << 20];
    char err[256] = "";
    rl_image img;
    int w = 0, h = 0;
    (void)state;
    memset(px, 90, sizeof px);
    rl_test_path(path, sizeof path, "block.png");
    write_raw(path, 640, 480, 8, PNG_COLOR_TYPE_GRAY, px, 640, 1, NULL, 0);
    assert_int_equal(rl_png_size(path, &w, &h, err, sizeof err), RL_OK);
    assert_int_equal(w, 640);
    assert_int_equal(h, 480);
    assert_int_equal(rl_png_read_gray_into(path, block, rl_png_block_size(32, 24), &img, err, sizeof err),
                     RL_ELIMIT);
    assert_non_null(strstr(err, path));
    assert_true(rl_png_block_size(640, 480) <= sizeof block);
    assert_int_equal(rl_png_read_gray_into(path, block, rl_png_block_size(640, 480), &img, err, sizeof err),
                     RL_OK);
    assert_int_equal(img.data[640 * 479 + 639], 90);
    {
        /* the widest pixel, interlaced: 16-bit RGBA fits the block too */
        static uint16_t rgba[640 * 480 * 4];
        int i;
        for (i = 0; i < 640 * 480 * 4; i++)
            rgba[i] = (uint16_t)(i % 4 == 3 ? 65535 : 40000);
        write_raw(path, 640, 480, 16, PNG_COLOR_TYPE_RGBA, (const uint8_t *)rgba, 640 * 8, 1, NULL, 0);
        assert_int_equal(rl_png_read_gray_into(path, block, rl_png_block_size(640, 480), &img, err,
                                               sizeof err), RL_OK);
        assert_int_equal(img.data[640 * 240 + 320], luma(156, 156, 156)); /* 40000 / 257 = 155.6 */
    }
}

static void test_gray8_and_interlaced(void **state)
{
    uint8_t px[5 * 4];
    int i, il;
    rl_image img;
    (void)state;
    for (i = 0; i < 20; i++)
        px[i] = (uint8_t)(i * 13);
    for (il = 0; il < 2; il++) {
        rl_test_path(path, sizeof path, il ? "gray8i.png" : "gray8.png");
        write_raw(path, 5, 4, 8, PNG_COLOR_TYPE_GRAY, px, 5, il, NULL, 0);
        read_ok(path, 5, 4, &img);
        for (i = 0; i < 20; i++)
            assert_int_equal(rl_image_at(&img, i % 5, i / 5), i * 13);
        rl_png_free(&img);
        assert_null(img.data);
    }
}

static void test_gray16_and_gray1(void **state)
{
    uint16_t px16[4] = {0, 257 * 10, 257 * 200, 65535};
    uint8_t px1[2] = {0xA0, 0x50}; /* 1-bit rows: 1010 / 0101 */
    rl_image img;
    (void)state;
    rl_test_path(path, sizeof path, "gray16.png");
    write_raw(path, 4, 1, 16, PNG_COLOR_TYPE_GRAY, (const uint8_t *)px16, 8, 0, NULL, 0);
    read_ok(path, 4, 1, &img);
    assert_int_equal(rl_image_at(&img, 0, 0), 0);
    assert_int_equal(rl_image_at(&img, 1, 0), 10);
    assert_int_equal(rl_image_at(&img, 2, 0), 200);
    assert_int_equal(rl_image_at(&img, 3, 0), 255);
    rl_png_free(&img);

    rl_test_path(path, sizeof path, "gray1.png");
    write_raw(path, 4, 2, 1, PNG_COLOR_TYPE_GRAY, px1, 1, 0, NULL, 0);
    read_ok(path, 4, 2, &img);
    assert_int_equal(rl_image_at(&img, 0, 0), 255);
    assert_int_equal(rl_image_at(&img, 1, 0), 0);
    assert_int_equal(rl_image_at(&img, 0, 1), 0);
    assert_int_equal(rl_image_at(&img, 3, 1), 255);
    rl_png_free(&img);
}

static void test_rgb_rgba_palette_grayalpha(void **state)
{
    const uint8_t rgb[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 200, 77};
    const uint8_t rgba[] = {255, 0, 0, 0, 0, 255, 0, 128, 0, 0, 255, 255, 10, 200, 77, 3};
    const uint8_t ga[] = {17, 0, 240, 255};
    const png_color pal[3] = {{255, 0, 0}, {12, 34, 56}, {255, 255, 255}};
    const uint8_t idx[] = {2, 1, 0};
    uint16_t rgb16[3];
    rl_image img;
    (void)state;

    rl_test_path(path, sizeof path, "rgb.png");
    write_raw(path, 4, 1, 8, PNG_COLOR_TYPE_RGB, rgb, 12, 0, NULL, 0);
    read_ok(path, 4, 1, &img);
    assert_int_equal(rl_image_at(&img, 0, 0), 76);
    assert_int_equal(rl_image_at(&img, 1, 0), 150);
    assert_int_equal(rl_image_at(&img, 2, 0), 29);
    assert_int_equal(rl_image_at(&img, 3, 0), luma(10, 200, 77));
    rl_png_free(&img);

    rl_test_path(path, sizeof path, "rgba.png");
    write_raw(path, 4, 1, 8, PNG_COLOR_TYPE_RGBA, rgba, 16, 0, NULL, 0);
    read_ok(path, 4, 1, &img);
    assert_int_equal(rl_image_at(&img, 0, 0), 76); /* alpha 0 is dropped, not composited */
    assert_int_equal(rl_image_at(&img, 3, 0), luma(10, 200, 77));
    rl_png_free(&img);

    rl_test_path(path, sizeof path, "palette.png");
    write_raw(path, 3, 1, 8, PNG_COLOR_TYPE_PALETTE, idx, 3, 0, pal, 3);
    read_ok(path, 3, 1, &img);
    assert_int_equal(rl_image_at(&img, 0, 0), 255);
    assert_int_equal(rl_image_at(&img, 1, 0), luma(12, 34, 56));
    assert_int_equal(rl_image_at(&img, 2, 0), 76);
    rl_png_free(&img);

    rl_test_path(path, sizeof path, "grayalpha.png");
    write_raw(path, 2, 1, 8, PNG_COLOR_TYPE_GRAY_ALPHA, ga, 4, 0, NULL, 0);
    read_ok(path, 2, 1, &img);
    assert_int_equal(rl_image_at(&img, 0, 0), 17);
    assert_int_equal(rl_image_at(&img, 1, 0), 240);
    rl_png_free(&img);

    rgb16[0] = 257 * 10;
    rgb16[1] = 257 * 200;
    rgb16[2] = 257 * 77;
    rl_test_path(path, sizeof path, "rgb16.png");
    write_raw(path, 1, 1, 16, PNG_COLOR_TYPE_RGB, (const uint8_t *)rgb16, 6, 0, NULL, 0);
    read_ok(path, 1, 1, &img);
    assert_int_equal(rl_image_at(&img, 0, 0), luma(10, 200, 77));
    rl_png_free(&img);
}

static void test_write_then_read(void **state)
{
    uint8_t px[6 * 3], rgb[2 * 2 * 3];
    rl_image src = rl_image_view(4, 3, 6, px), back;
    char err[256];
    int x, y;
    (void)state;
    for (y = 0; y < 3; y++)
        for (x = 0; x < 6; x++)
            px[y * 6 + x] = (uint8_t)(x < 4 ? 40 * y + x : 0xEE);
    rl_test_path(path, sizeof path, "written.png");
    assert_int_equal(rl_png_write_gray(path, &src, err, sizeof err), RL_OK);
    read_ok(path, 4, 3, &back);
    for (y = 0; y < 3; y++)
        for (x = 0; x < 4; x++)
            assert_int_equal(rl_image_at(&back, x, y), 40 * y + x);
    rl_png_free(&back);
    memset(rgb, 0, sizeof rgb);
    rgb[0] = 255;
    rl_test_path(path, sizeof path, "written_rgb.png");
    assert_int_equal(rl_png_write_rgb(path, 2, 2, rgb, err, sizeof err), RL_OK);
    read_ok(path, 2, 2, &back);
    assert_int_equal(rl_image_at(&back, 0, 0), 76);
    rl_png_free(&back);
    assert_int_equal(rl_png_write_gray("/nonexistent-dir/x.png", &src, err, sizeof err), RL_EIO);
    assert_non_null(strstr(err, "/nonexistent-dir/x.png"));
}

/* Expect a failure with `code` and an error line naming the file. */
static void expect_fail(const char *p, rl_err code, const char *words)
{
    rl_image img;
    char err[256] = "";
    rl_err e = rl_png_read_gray(p, &img, err, sizeof err);
    assert_int_equal(e, code);
    assert_null(img.data);
    assert_non_null(strstr(err, p));
    assert_null(strchr(err, '\n'));
    if (words && strstr(err, words) == NULL)
        fail_msg("error '%s' does not say '%s'", err, words);
}

static long file_bytes(const char *p, uint8_t *buf, long cap)
{
    FILE *f = fopen(p, "rb");
    long n;
    assert_non_null(f);
    n = (long)fread(buf, 1, (size_t)cap, f);
    fclose(f);
    return n;
}

static void put_bytes(const char *p, const uint8_t *buf, long n)
{
    FILE *f = fopen(p, "wb");
    assert_non_null(f);
    if (n > 0)
        assert_int_equal(fwrite(buf, 1, (size_t)n, f), (size_t)n);
    fclose(f);
}

static void test_broken_files(void **state)
{
    static uint8_t px[64 * 64], buf[1 << 16];
    char good[512], bad[512];
    long n, i;
    (void)state;
    for (i = 0; i < 64 * 64; i++)
        px[i] = (uint8_t)((i * 7919) >> 3);
    rl_test_path(good, sizeof good, "good.png");
    write_raw(good, 64, 64, 8, PNG_COLOR_TYPE_GRAY, px, 64, 0, NULL, 0);
    n = file_bytes(good, buf, sizeof buf);
    assert_true(n > 100);

    expect_fail("/no/such/file.png", RL_ENOTFOUND, "No such file");

    rl_test_path(bad, sizeof bad, "empty.png");
    put_bytes(bad, buf, 0);
    expect_fail(bad, RL_EFORMAT, "empty");

    rl_test_path(bad, sizeof bad, "text.png");
    put_bytes(bad, (const uint8_t *)"hello, not a png at all", 23);
    expect_fail(bad, RL_EFORMAT, "not a PNG");

    rl_test_path(bad, sizeof bad, "short.png");
    put_bytes(bad, buf, 5);
    expect_fail(bad, RL_EFORMAT, "not a PNG");

    rl_test_path(bad, sizeof bad, "truncated.png");
    put_bytes(bad, buf, n / 2);
    expect_fail(bad, RL_EFORMAT, "corrupt or truncated");

    rl_test_path(bad, sizeof bad, "header_only.png");
    put_bytes(bad, buf, 33);
    expect_fail(bad, RL_EFORMAT, "corrupt or truncated");

    rl_test_path(bad, sizeof bad, "crc.png");
    buf[n - 20] ^= 0x5A; /* inside the IDAT data: CRC mismatch */
    put_bytes(bad, buf, n);
    buf[n - 20] ^= 0x5A;
    expect_fail(bad, RL_EFORMAT, "corrupt or truncated");
}

static void test_oversized_refused_from_header(void **state)
{
    char bad[512];
    FILE *f;
    png_structp png;
    png_infop info;
    (void)state;
    rl_test_path(bad, sizeof bad, "huge.png");
    f = fopen(bad, "wb");
    assert_non_null(f);
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, RL_PNG_MAX_DIM + 1, 16, 8, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info); /* the header only: the reader must stop there */
    png_destroy_write_struct(&png, &info);
    fclose(f);
    expect_fail(bad, RL_ELIMIT, "limit");
}

static void test_random_corruption_never_crashes(void **state)
{
    static uint8_t orig[1 << 16], buf[1 << 16];
    uint8_t px[40 * 30 * 3];
    char good[512], bad[512];
    long n, i;
    int trial, ok = 0, failed = 0;
    unsigned seed = 12345;
    (void)state;
    for (i = 0; i < (long)sizeof px; i++)
        px[i] = (uint8_t)(i * 31 + (i >> 5));
    rl_test_path(good, sizeof good, "fuzz_src.png");
    write_raw(good, 40, 30, 8, PNG_COLOR_TYPE_RGB, px, 120, 0, NULL, 0);
    n = file_bytes(good, orig, sizeof orig);
    rl_test_path(bad, sizeof bad, "fuzz.png");
    for (trial = 0; trial < 300; trial++) {
        rl_image img;
        char err[256];
        int flips = 1 + trial % 4, k;
        memcpy(buf, orig, (size_t)n);
        for (k = 0; k < flips; k++) {
            seed = seed * 1103515245u + 12345u;
            buf[8 + (seed >> 8) % (unsigned)(n - 8)] ^= (uint8_t)(1u << ((seed >> 4) & 7));
        }
        put_bytes(bad, buf, trial % 5 == 0 ? n - (long)(seed % 50) : n);
        if (rl_png_read_gray(bad, &img, err, sizeof err) == RL_OK) {
            static uint8_t block[1 << 20];
            rl_image into;
            ok++;
            /* what one reader accepts, the other reads the same */
            assert_int_equal(rl_png_read_gray_into(bad, block, sizeof block, &into, err, sizeof err), RL_OK);
            assert_memory_equal(into.data, img.data, (size_t)img.width * (size_t)img.height);
            rl_png_free(&img);
        } else {
            failed++;
            assert_non_null(strstr(err, bad));
        }
    }
    assert_int_equal(ok + failed, 300);
    assert_true(failed > 100); /* most single flips hit a CRC */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gray8_and_interlaced),
        cmocka_unit_test(test_block_too_small),
        cmocka_unit_test(test_gray16_and_gray1),
        cmocka_unit_test(test_rgb_rgba_palette_grayalpha),
        cmocka_unit_test(test_write_then_read),
        cmocka_unit_test(test_broken_files),
        cmocka_unit_test(test_oversized_refused_from_header),
        cmocka_unit_test(test_random_corruption_never_crashes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
