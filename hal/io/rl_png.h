/* rl_png: PNG files in and out for the host build (libpng).
 *
 * Reading turns any PNG (1/2/4/8/16-bit gray, gray+alpha, RGB, RGBA,
 * palette) into an 8-bit luminance image, as the paper does with colour:
 * Y = 0.299 R + 0.587 G + 0.114 B, alpha dropped, 16-bit scaled to 8.
 * rl_png_read_gray allocates the pixels (free them with rl_png_free);
 * rl_png_read_gray_into decodes into the caller's block with nothing
 * allocated, libpng's own memory and the file's buffer included (the PNG
 * camera, a frame at a time). The core never sees this module.
 *
 *   rl_image img;
 *   char err[256];
 *   if (rl_png_read_gray("a.png", &img, err, sizeof err) != RL_OK) {
 *       fprintf(stderr, "ringloc: %s\n", err);  // "a.png: not a PNG file"
 *       return;
 *   }
 *   use(img.width, img.height);
 *   rl_png_free(&img);
 */
#ifndef RL_PNG_H
#define RL_PNG_H

#include <stddef.h>
#include <stdint.h>
#include "rl_config.h"
#include "rl_image.h"

/* Largest width or height read; bigger files are refused before decoding. */
#define RL_PNG_MAX_DIM RL_MAX_IMAGE_DIM

/* Read `path` as 8-bit luminance into a new buffer (stride = width).
 * On failure *out is zeroed and err holds one line naming the file:
 * RL_ENOTFOUND/RL_EIO (cannot open/read), RL_EFORMAT (empty, not PNG,
 * corrupt, truncated), RL_ELIMIT (larger than RL_PNG_MAX_DIM),
 * RL_ENOMEM (out of memory). */
RL_CHECK rl_err rl_png_read_gray(const char *path, rl_image *out, char *err, size_t errlen);

/* Bytes of the block rl_png_read_gray_into needs for frames up to w x h
 * (any colour type, interlaced or not). */
size_t rl_png_block_size(int w, int h);

/* As rl_png_read_gray, into block (cap bytes, from rl_png_block_size):
 * *out views the block until the next read into it. RL_ELIMIT when the
 * file needs more (a larger frame, a huge ancillary chunk). */
RL_CHECK rl_err rl_png_read_gray_into(const char *path, void *block, size_t cap, rl_image *out,
                                      char *err, size_t errlen);

/* The image size from the file's header, nothing decoded; the errors of
 * rl_png_read_gray. */
RL_CHECK rl_err rl_png_size(const char *path, int *w, int *h, char *err, size_t errlen);

/* Free pixels from rl_png_read_gray and zero the view. */
void rl_png_free(rl_image *img);

/* Write an 8-bit gray image (stride honoured). */
RL_CHECK rl_err rl_png_write_gray(const char *path, const rl_image *img, char *err,
                                  size_t errlen);

/* Bytes always enough for rl_png_encode_gray of a w x h image (0 for a
 * bad size). */
size_t rl_png_gray_max(int w, int h);

/* An 8-bit gray image as a PNG file's bytes into buf[0..cap) (the
 * caller's; rl_png_gray_max is enough), *n of them; lossless, fast
 * compression. RL_EINVAL for a bad image, RL_ELIMIT when it does not
 * fit, RL_ENOMEM. */
RL_CHECK rl_err rl_png_encode_gray(const rl_image *img, uint8_t *buf, size_t cap, size_t *n);

/* Write a packed 8-bit RGB image (3*w bytes per row). */
RL_CHECK rl_err rl_png_write_rgb(const char *path, int w, int h, const uint8_t *rgb,
                                 char *err, size_t errlen);

/* The PNG files of folder dir (name ending in .png, any case), as paths
 * "dir/name", sorted by name, into *paths (n of them, malloc'ed; free
 * with rl_png_list_free). RL_ENOTFOUND (with err naming the folder) when
 * it cannot be opened, RL_ENOMEM; an empty folder is 0 paths. */
RL_CHECK rl_err rl_png_list(const char *dir, char ***paths, int *n, char *err, size_t errlen);
void rl_png_list_free(char **paths, int n);

#endif
