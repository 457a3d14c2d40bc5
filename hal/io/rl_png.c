#include "rl_png.h"

#include <dirent.h>
#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <strings.h>

/* libpng reports through callbacks and longjmp; this carries the message
 * back to the caller so that the file name and libpng's reason reach the
 * user in one line. */
typedef struct {
    jmp_buf jmp;
    char msg[160];
} png_ctx;

static void on_error(png_structp png, png_const_charp msg)
{
    png_ctx *ctx = (png_ctx *)png_get_error_ptr(png);
    snprintf(ctx->msg, sizeof ctx->msg, "%s", msg);
    longjmp(ctx->jmp, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg; /* warnings (bad CRC in ancillary chunks, sRGB profiles) are not errors */
}

static rl_err fail(char *err, size_t errlen, rl_err code, const char *path, const char *what)
{
    if (err != NULL && errlen > 0)
        snprintf(err, errlen, "%s: %s", path, what);
    return code;
}

void rl_png_free(rl_image *img)
{
    if (img == NULL)
        return;
    free(img->data);
    memset(img, 0, sizeof *img);
}

/* One row of 1-4 channels (grey, grey + alpha, RGB, RGBA) to grey. */
static void to_grey(const uint8_t *s, int channels, png_uint_32 w, uint8_t *d)
{
    png_uint_32 x;
    if (channels <= 2) {
        for (x = 0; x < w; x++)
            d[x] = s[(size_t)x * (size_t)channels];
        return;
    }
    for (x = 0; x < w; x++) {
        const uint8_t *p = s + (size_t)x * (size_t)channels;
        /* BT.601 luma in fixed point, rounded: the same weights as
         * OpenCV's RGB2GRAY. */
        d[x] = (uint8_t)((299u * p[0] + 587u * p[1] + 114u * p[2] + 500u) / 1000u);
    }
}

rl_err rl_png_read_gray(const char *path, rl_image *out, char *err, size_t errlen)
{
    FILE *f;
    unsigned char sig[24];
    size_t got;
    png_structp png = NULL;
    png_infop info = NULL;
    png_ctx ctx;
    uint8_t *volatile raw = NULL;
    png_bytep *volatile rows = NULL;
    uint8_t *volatile gray = NULL;
    char what[220];
    png_uint_32 w, h, y;
    int channels, passes;
    size_t rowbytes;

    if (out == NULL || path == NULL)
        return RL_EINVAL;
    memset(out, 0, sizeof *out);
    f = fopen(path, "rb");
    if (f == NULL)
        return fail(err, errlen, errno == ENOENT ? RL_ENOTFOUND : RL_EIO, path,
                    strerror(errno));
    {
        struct stat st;
        if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
            fclose(f);
            return fail(err, errlen, RL_EFORMAT, path, "a folder, not a PNG image");
        }
    }
    got = fread(sig, 1, sizeof sig, f);
    if (got == 0) {
        fclose(f);
        return fail(err, errlen, RL_EFORMAT, path, "empty file, not a PNG image");
    }
    if (got < 8 || png_sig_cmp(sig, 0, 8) != 0) {
        fclose(f);
        return fail(err, errlen, RL_EFORMAT, path, "not a PNG file");
    }
    /* Refuse huge images from the IHDR chunk (always first) before libpng
     * reads further or any pixel buffer exists. */
    if (got == sizeof sig && memcmp(sig + 12, "IHDR", 4) == 0) {
        unsigned long iw = ((unsigned long)sig[16] << 24) | ((unsigned long)sig[17] << 16) |
                           ((unsigned long)sig[18] << 8) | sig[19];
        unsigned long ih = ((unsigned long)sig[20] << 24) | ((unsigned long)sig[21] << 16) |
                           ((unsigned long)sig[22] << 8) | sig[23];
        if (iw > RL_PNG_MAX_DIM || ih > RL_PNG_MAX_DIM) {
            fclose(f);
            snprintf(what, sizeof what, "image is %lux%lu, larger than the %dx%d limit", iw,
                     ih, RL_PNG_MAX_DIM, RL_PNG_MAX_DIM);
            return fail(err, errlen, RL_ELIMIT, path, what);
        }
    }
    if (fseek(f, 8, SEEK_SET) != 0) {
        fclose(f);
        return fail(err, errlen, RL_EIO, path, strerror(errno));
    }
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error, on_warning);
    if (png != NULL)
        info = png_create_info_struct(png);
    if (png == NULL || info == NULL) {
        png_destroy_read_struct(&png, NULL, NULL);
        fclose(f);
        return fail(err, errlen, RL_ENOMEM, path, "out of memory");
    }
    ctx.msg[0] = '\0';
    if (setjmp(ctx.jmp)) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        free(raw);
        free(rows);
        free(gray);
        snprintf(what, sizeof what, "corrupt or truncated PNG (%s)", ctx.msg);
        return fail(err, errlen, RL_EFORMAT, path, what);
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    w = png_get_image_width(png, info);
    h = png_get_image_height(png, info);
    if (w > RL_PNG_MAX_DIM || h > RL_PNG_MAX_DIM) /* IHDR was not where expected */
        longjmp(ctx.jmp, 1);

    png_set_palette_to_rgb(png);
    png_set_expand_gray_1_2_4_to_8(png);
#ifdef PNG_READ_SCALE_16_TO_8_SUPPORTED
    png_set_scale_16(png);
#else
    png_set_strip_16(png);
#endif
    passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    channels = png_get_channels(png, info);
    rowbytes = png_get_rowbytes(png, info);
    if (channels < 1 || channels > 4 || rowbytes != (size_t)w * (size_t)channels)
        longjmp(ctx.jmp, 1);

    /* an interlaced image needs all its rows at once; any other is read a
     * row at a time into one row's buffer (an 8192 x 8192 RGBA image takes
     * the grey frame and 32 kB, not 256 MB more) */
    raw = (uint8_t *)malloc(rowbytes * (passes > 1 ? h : 1));
    rows = (png_bytep *)malloc(sizeof(png_bytep) * (passes > 1 ? h : 1));
    gray = (uint8_t *)malloc((size_t)w * h);
    if (raw == NULL || rows == NULL || gray == NULL) {
        snprintf(ctx.msg, sizeof ctx.msg, "out of memory");
        longjmp(ctx.jmp, 1);
    }
    if (passes > 1) {
        for (y = 0; y < h; y++)
            rows[y] = raw + (size_t)y * rowbytes;
        png_read_image(png, rows);
    }
    for (y = 0; y < h; y++) {
        const uint8_t *s = passes > 1 ? rows[y] : raw;
        uint8_t *d = gray + (size_t)y * w;
        if (passes == 1)
            png_read_row(png, raw, NULL);
        to_grey(s, channels, w, d);
    }
    png_read_end(png, NULL);

    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    free(raw);
    free(rows);
    *out = rl_image_view((int)w, (int)h, (int)w, gray);
    return RL_OK;
}

static rl_err write_png(const char *path, int w, int h, int color_type, const uint8_t *data,
                        size_t stride, char *err, size_t errlen)
{
    FILE *f;
    png_structp png;
    png_infop info = NULL;
    png_ctx ctx;
    int y;
    char what[220];

    if (path == NULL || data == NULL || w <= 0 || h <= 0)
        return fail(err, errlen, RL_EINVAL, path ? path : "(null)", "nothing to write");
    f = fopen(path, "wb");
    if (f == NULL)
        return fail(err, errlen, RL_EIO, path, strerror(errno));
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error, on_warning);
    if (png != NULL)
        info = png_create_info_struct(png);
    if (png == NULL || info == NULL) {
        png_destroy_write_struct(&png, NULL);
        fclose(f);
        return fail(err, errlen, RL_ENOMEM, path, "out of memory");
    }
    ctx.msg[0] = '\0';
    if (setjmp(ctx.jmp)) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        snprintf(what, sizeof what, "cannot write PNG (%s)", ctx.msg);
        return fail(err, errlen, RL_EIO, path, what);
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, color_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < h; y++)
        png_write_row(png, (png_const_bytep)(data + (size_t)y * stride));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    if (fclose(f) != 0)
        return fail(err, errlen, RL_EIO, path, strerror(errno));
    return RL_OK;
}

rl_err rl_png_write_gray(const char *path, const rl_image *img, char *err, size_t errlen)
{
    if (!rl_image_valid(img))
        return fail(err, errlen, RL_EINVAL, path ? path : "(null)", "invalid image");
    return write_png(path, img->width, img->height, PNG_COLOR_TYPE_GRAY, img->data,
                     (size_t)img->stride, err, errlen);
}

rl_err rl_png_write_rgb(const char *path, int w, int h, const uint8_t *rgb, char *err,
                        size_t errlen)
{
    return write_png(path, w, h, PNG_COLOR_TYPE_RGB, rgb, (size_t)w * 3, err, errlen);
}

static int cmp_path(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int is_png_name(const char *name)
{
    size_t len = strlen(name);
    return len > 4 && strcasecmp(name + len - 4, ".png") == 0;
}

void rl_png_list_free(char **paths, int n)
{
    int i;
    for (i = 0; i < n; i++)
        free(paths[i]);
    free(paths);
}

rl_err rl_png_list(const char *dir, char ***paths, int *n, char *err, size_t errlen)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char **list = NULL;
    int cap = 0, k = 0;
    *paths = NULL;
    *n = 0;
    if (d == NULL) {
        snprintf(err, errlen, "%s: cannot open the folder (%s)", dir, strerror(errno));
        return RL_ENOTFOUND;
    }
    while ((e = readdir(d)) != NULL) {
        size_t len;
        if (!is_png_name(e->d_name))
            continue;
        if (k == cap) {
            char **more = realloc(list, sizeof *list * (size_t)(cap ? 2 * cap : 64));
            if (more == NULL)
                break;
            list = more;
            cap = cap ? 2 * cap : 64;
        }
        len = strlen(dir) + strlen(e->d_name) + 2;
        if ((list[k] = malloc(len)) == NULL)
            break;
        snprintf(list[k++], len, "%s/%s", dir, e->d_name);
    }
    closedir(d);
    if (e != NULL) { /* stopped short: out of memory */
        rl_png_list_free(list, k);
        snprintf(err, errlen, "%s: out of memory listing the folder", dir);
        return RL_ENOMEM;
    }
    if (k > 0)
        qsort(list, (size_t)k, sizeof *list, cmp_path);
    *paths = list;
    *n = k;
    return RL_OK;
}
