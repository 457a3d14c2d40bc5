#include "rl_png.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <strings.h>
#include <unistd.h>
#include "rl_infile.h"
#include "rl_outfile.h"

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

/* ---- reading ----
 * One decoder for both kinds of caller: memory comes from the heap
 * (rl_png_read_gray) or from the caller's block, libpng's own included
 * (rl_png_read_gray_into); the file is read with read(2) through a
 * buffer, so no FILE is allocated either. */
typedef struct {
    png_ctx ctx;              /* first: libpng's error pointer */
    int fd;
    unsigned char buf[16384];
    size_t pos, len;
    uint8_t *block;           /* NULL: the heap */
    size_t cap, used;
    int short_of_block;
} png_reader;

/* Memory from the caller's block: 16-byte aligned, never freed until
 * the next read; NULL (and short_of_block set) when it is used up. */
static void *bump(png_reader *r, size_t n)
{
    size_t at = (r->used + 15u) & ~(size_t)15u;
    if (at > r->cap || n > r->cap - at) {
        r->short_of_block = 1;
        return NULL;
    }
    r->used = at + n;
    return r->block + at;
}

/* libpng's own allocations, in block mode */
static png_voidp block_malloc(png_structp png, png_alloc_size_t n)
{
    return bump((png_reader *)png_get_mem_ptr(png), n);
}

static void block_free(png_structp png, png_voidp p)
{
    (void)png;
    (void)p;
}

static void *take(png_reader *r, size_t n)
{
    return r->block == NULL ? malloc(n) : bump(r, n);
}

static int refill(png_reader *r)
{
    ssize_t got;
    do
        got = read(r->fd, r->buf, sizeof r->buf);
    while (got < 0 && errno == EINTR);
    r->pos = 0;
    r->len = got > 0 ? (size_t)got : 0;
    return got > 0;
}

static void on_read(png_structp png, png_bytep out, png_size_t n)
{
    png_reader *r = (png_reader *)png_get_io_ptr(png);
    while (n > 0) {
        size_t k;
        if (r->pos == r->len && !refill(r))
            png_error(png, "file ends early");
        k = r->len - r->pos < n ? r->len - r->pos : n;
        memcpy(out, r->buf + r->pos, k);
        r->pos += k;
        out += k;
        n -= k;
    }
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

/* Open path and check the signature; the image size from the IHDR chunk
 * (always first), refused before any pixel buffer exists when it is over
 * the limit. On success the reader's buffer holds the file's start. */
static rl_err open_png(png_reader *r, const char *path, png_uint_32 *w, png_uint_32 *h, char *err,
                       size_t errlen)
{
    char what[220];
    rl_err e;
    if ((r->fd = rl_infile_open(path, "a PNG image", &e, err, errlen)) < 0)
        return e;
    r->pos = r->len = 0;
    while (r->len < 24) {
        ssize_t got = read(r->fd, r->buf + r->len, 24 - r->len);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            return fail(err, errlen, RL_EIO, path, strerror(errno));
        if (got == 0)
            break;
        r->len += (size_t)got;
    }
    if (r->len == 0)
        return fail(err, errlen, RL_EFORMAT, path, "empty file, not a PNG image");
    if (r->len < 8 || png_sig_cmp(r->buf, 0, 8) != 0)
        return fail(err, errlen, RL_EFORMAT, path, "not a PNG file");
    if (r->len < 24 || memcmp(r->buf + 12, "IHDR", 4) != 0)
        return fail(err, errlen, RL_EFORMAT, path, "corrupt or truncated PNG (no IHDR chunk first)");
    *w = ((png_uint_32)r->buf[16] << 24) | ((png_uint_32)r->buf[17] << 16) |
         ((png_uint_32)r->buf[18] << 8) | r->buf[19];
    *h = ((png_uint_32)r->buf[20] << 24) | ((png_uint_32)r->buf[21] << 16) |
         ((png_uint_32)r->buf[22] << 8) | r->buf[23];
    if (*w > RL_PNG_MAX_DIM || *h > RL_PNG_MAX_DIM) {
        snprintf(what, sizeof what, "image is %lux%lu, larger than the %dx%d limit",
                 (unsigned long)*w, (unsigned long)*h, RL_PNG_MAX_DIM, RL_PNG_MAX_DIM);
        return fail(err, errlen, RL_ELIMIT, path, what);
    }
    r->pos = 8; /* libpng is told the signature was read */
    return RL_OK;
}

static void close_png(png_reader *r)
{
    if (r->fd >= 0)
        close(r->fd);
    r->fd = -1;
}

/* Decode the open file to grey in memory from take(); the reader's fd is
 * closed by the caller. */
static rl_err decode(png_reader *r, const char *path, rl_image *out, char *err, size_t errlen)
{
    png_structp png = NULL;
    png_infop info = NULL;
    uint8_t *volatile raw = NULL;
    png_bytep *volatile rows = NULL;
    uint8_t *volatile gray = NULL;
    char what[220];
    png_uint_32 w, h, y;
    int channels, passes;
    size_t rowbytes;

    if (r->block != NULL)
        png = png_create_read_struct_2(PNG_LIBPNG_VER_STRING, &r->ctx, on_error, on_warning, r,
                                       block_malloc, block_free);
    else
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r->ctx, on_error, on_warning);
    if (png != NULL)
        info = png_create_info_struct(png);
    if (png == NULL || info == NULL) {
        png_destroy_read_struct(&png, NULL, NULL);
        return fail(err, errlen, r->block ? RL_ELIMIT : RL_ENOMEM, path,
                    r->block ? "larger than the frame buffer" : "out of memory");
    }
    r->ctx.msg[0] = '\0';
    if (setjmp(r->ctx.jmp)) {
        png_destroy_read_struct(&png, &info, NULL);
        if (r->block == NULL) {
            free(raw);
            free(rows);
            free(gray);
        }
        if (r->short_of_block)
            return fail(err, errlen, RL_ELIMIT, path, "larger than the frame buffer");
        snprintf(what, sizeof what, "corrupt or truncated PNG (%s)", r->ctx.msg);
        return fail(err, errlen, RL_EFORMAT, path, what);
    }
    png_set_read_fn(png, r, on_read);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    w = png_get_image_width(png, info);
    h = png_get_image_height(png, info);
    if (w > RL_PNG_MAX_DIM || h > RL_PNG_MAX_DIM) /* IHDR was not where expected */
        longjmp(r->ctx.jmp, 1);

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
        longjmp(r->ctx.jmp, 1);

    /* an interlaced image needs all its rows at once; any other is read a
     * row at a time into one row's buffer (an 8192 x 8192 RGBA image takes
     * the grey frame and 32 kB, not 256 MB more) */
    gray = (uint8_t *)take(r, (size_t)w * h);
    raw = (uint8_t *)take(r, rowbytes * (passes > 1 ? h : 1));
    rows = (png_bytep *)take(r, sizeof(png_bytep) * (passes > 1 ? h : 1));
    if (raw == NULL || rows == NULL || gray == NULL) {
        snprintf(r->ctx.msg, sizeof r->ctx.msg, "out of memory");
        longjmp(r->ctx.jmp, 1);
    }
    if (passes > 1) {
        for (y = 0; y < h; y++)
            rows[y] = raw + (size_t)y * rowbytes;
        png_read_image(png, rows);
    }
    for (y = 0; y < h; y++) {
        const uint8_t *s = passes > 1 ? rows[y] : raw;
        if (passes == 1)
            png_read_row(png, raw, NULL);
        to_grey(s, channels, w, gray + (size_t)y * w);
    }
    png_read_end(png, NULL);

    png_destroy_read_struct(&png, &info, NULL);
    if (r->block == NULL) {
        free(raw);
        free(rows);
    }
    *out = rl_image_view((int)w, (int)h, (int)w, gray);
    return RL_OK;
}

static rl_err read_gray(png_reader *r, const char *path, rl_image *out, char *err, size_t errlen)
{
    png_uint_32 w, h;
    rl_err e;
    r->fd = -1;
    r->used = 0;
    r->short_of_block = 0;
    if ((e = open_png(r, path, &w, &h, err, errlen)) == RL_OK)
        e = decode(r, path, out, err, errlen);
    close_png(r);
    return e;
}

rl_err rl_png_read_gray(const char *path, rl_image *out, char *err, size_t errlen)
{
    png_reader *r;
    rl_err e;
    if (out == NULL || path == NULL)
        return RL_EINVAL;
    memset(out, 0, sizeof *out);
    if ((r = (png_reader *)malloc(sizeof *r)) == NULL)
        return fail(err, errlen, RL_ENOMEM, path, "out of memory");
    r->block = NULL;
    r->cap = 0;
    e = read_gray(r, path, out, err, errlen);
    free(r);
    return e;
}

/* libpng's own working memory for a frame w pixels wide: its structs,
 * zlib's state and 32 kB window, two rows of the widest pixel (16-bit
 * RGBA), and room for ancillary chunks. */
#define PNG_WORK_BYTES(w) ((size_t)256 * 1024 + (size_t)(w) * 32u)

size_t rl_png_block_size(int w, int h)
{
    size_t gray = (size_t)w * (size_t)h;
    /* the grey frame, the rows before conversion (all of them when
     * interlaced, 4 bytes a pixel at most), their pointers, libpng */
    return sizeof(png_reader) + 64 + gray + 4 * gray + sizeof(png_bytep) * (size_t)h + PNG_WORK_BYTES(w);
}

rl_err rl_png_read_gray_into(const char *path, void *block, size_t cap, rl_image *out, char *err,
                             size_t errlen)
{
    png_reader *r;
    uintptr_t a = ((uintptr_t)block + 15u) & ~(uintptr_t)15u;
    if (out == NULL || path == NULL || block == NULL)
        return RL_EINVAL;
    memset(out, 0, sizeof *out);
    if (cap < sizeof *r + 64)
        return fail(err, errlen, RL_ELIMIT, path, "larger than the frame buffer");
    r = (png_reader *)a;
    r->block = (uint8_t *)(r + 1);
    r->cap = cap - (size_t)((uint8_t *)r->block - (uint8_t *)block);
    return read_gray(r, path, out, err, errlen);
}

rl_err rl_png_size(const char *path, int *w, int *h, char *err, size_t errlen)
{
    png_reader *r;
    png_uint_32 pw = 0, ph = 0;
    rl_err e;
    if ((r = (png_reader *)malloc(sizeof *r)) == NULL)
        return fail(err, errlen, RL_ENOMEM, path, "out of memory");
    r->fd = -1;
    e = open_png(r, path, &pw, &ph, err, errlen);
    close_png(r);
    free(r);
    *w = (int)pw;
    *h = (int)ph;
    return e;
}

/* libpng's write callbacks: into the outfile, whose first failure (with
 * its errno) ends the write through libpng's error path. */
typedef struct {
    png_ctx ctx; /* first: libpng's error pointer */
    rl_outfile out;
} png_writer;

static void on_write(png_structp png, png_bytep data, png_size_t n)
{
    png_writer *pw = (png_writer *)png_get_io_ptr(png);
    if (rl_outfile_write(&pw->out, data, n) != 0)
        png_error(png, strerror(pw->out.errnum));
}

static void on_flush(png_structp png)
{
    (void)png; /* the commit flushes */
}

static void write_rows(png_structp png, png_infop info, int w, int h, int color_type,
                       const uint8_t *data, size_t stride)
{
    int y;
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, color_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < h; y++)
        png_write_row(png, (png_const_bytep)(data + (size_t)y * stride));
    png_write_end(png, info);
}

/* libpng's write and info structs with ctx for errors; 0 (nothing left
 * made) when out of memory. */
static int new_writer(png_ctx *ctx, png_structp *png, png_infop *info)
{
    *info = NULL;
    *png = png_create_write_struct(PNG_LIBPNG_VER_STRING, ctx, on_error, on_warning);
    if (*png != NULL)
        *info = png_create_info_struct(*png);
    if (*png == NULL || *info == NULL) {
        png_destroy_write_struct(png, NULL);
        return 0;
    }
    return 1;
}

static rl_err write_png(const char *path, int w, int h, int color_type, const uint8_t *data,
                        size_t stride, char *err, size_t errlen)
{
    png_structp png;
    png_infop info = NULL;
    png_writer pw;
    rl_err e;

    if (path == NULL || data == NULL || w <= 0 || h <= 0)
        return fail(err, errlen, RL_EINVAL, path ? path : "(null)", "nothing to write");
    if ((e = rl_outfile_open(&pw.out, path, err, errlen)) != RL_OK)
        return e;
    if (!new_writer(&pw.ctx, &png, &info)) {
        rl_outfile_abort(&pw.out);
        return fail(err, errlen, RL_ENOMEM, path, "out of memory");
    }
    pw.ctx.msg[0] = '\0';
    if (setjmp(pw.ctx.jmp)) {
        char what[220];
        png_destroy_write_struct(&png, &info);
        if (pw.out.errnum != 0) /* the system's reason, from the commit */
            return rl_outfile_commit(&pw.out, err, errlen);
        rl_outfile_abort(&pw.out);
        snprintf(what, sizeof what, "cannot write PNG (%s)", pw.ctx.msg);
        return fail(err, errlen, RL_EIO, path, what);
    }
    png_set_write_fn(png, &pw, on_write, on_flush);
    write_rows(png, info, w, h, color_type, data, stride);
    png_destroy_write_struct(&png, &info);
    return rl_outfile_commit(&pw.out, err, errlen);
}

rl_err rl_png_write_gray(const char *path, const rl_image *img, char *err, size_t errlen)
{
    if (!rl_image_valid(img))
        return fail(err, errlen, RL_EINVAL, path ? path : "(null)", "invalid image");
    return write_png(path, img->width, img->height, PNG_COLOR_TYPE_GRAY, img->data,
                     (size_t)img->stride, err, errlen);
}

/* libpng's write callback into a caller's buffer; past its end, libpng's
 * error path. */
typedef struct {
    png_ctx ctx; /* first: libpng's error pointer */
    uint8_t *buf;
    size_t cap, n;
} png_memwriter;

static void on_mem_write(png_structp png, png_bytep data, png_size_t n)
{
    png_memwriter *mw = (png_memwriter *)png_get_io_ptr(png);
    if (n > mw->cap - mw->n)
        png_error(png, "larger than the buffer");
    memcpy(mw->buf + mw->n, data, n);
    mw->n += n;
}

size_t rl_png_gray_max(int w, int h)
{
    /* zlib's stored blocks at worst: 5 bytes per 16 KB, a filter byte per
     * row, the chunks' headers and the IEND */
    size_t raw = (size_t)w * (size_t)h + (size_t)h;
    return w > 0 && h > 0 ? raw + raw / 16384 * 5 + 1024 : 0;
}

rl_err rl_png_encode_gray(const rl_image *img, uint8_t *buf, size_t cap, size_t *n)
{
    png_structp png;
    png_infop info = NULL;
    png_memwriter mw;
    *n = 0;
    if (!rl_image_valid(img) || buf == NULL)
        return RL_EINVAL;
    if (!new_writer(&mw.ctx, &png, &info))
        return RL_ENOMEM;
    mw.ctx.msg[0] = '\0';
    mw.buf = buf;
    mw.cap = cap;
    mw.n = 0;
    if (setjmp(mw.ctx.jmp)) {
        png_destroy_write_struct(&png, &info);
        return RL_ELIMIT;
    }
    png_set_write_fn(png, &mw, on_mem_write, on_flush);
    png_set_compression_level(png, 1); /* fast: it is served while the robot runs */
    write_rows(png, info, img->width, img->height, PNG_COLOR_TYPE_GRAY, img->data, (size_t)img->stride);
    png_destroy_write_struct(&png, &info);
    *n = mw.n;
    return RL_OK;
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
