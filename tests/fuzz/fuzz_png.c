/* The PNG reader on arbitrary bytes: an image or an error, never a crash,
 * and an image's size within the limits. The camera's reader (into a
 * block for 640x480 frames) reads what fits the same, or refuses it. */
#include <stdlib.h>
#include <string.h>
#include "fuzz_file.h"
#include "rl_config.h"
#include "rl_png.h"

static unsigned char block[8 << 20];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rl_image img, into;
    char err[512];
    const char *path = fuzz_file(data, size, ".png");
    size_t cap = rl_png_block_size(640, 480);
    rl_err e;
    if (cap > sizeof block)
        abort();
    e = rl_png_read_gray_into(path, block, cap, &into, err, sizeof err);
    if (e != RL_OK && err[0] == '\0')
        abort();
    if (rl_png_read_gray(path, &img, err, sizeof err) == RL_OK) {
        int y;
        if (img.width <= 0 || img.height <= 0 || img.width > RL_MAX_IMAGE_DIM ||
            img.height > RL_MAX_IMAGE_DIM)
            abort();
        if (e == RL_OK) {
            if (into.width != img.width || into.height != img.height)
                abort();
            for (y = 0; y < img.height; y++)
                if (memcmp(into.data + (size_t)y * into.stride, img.data + (size_t)y * img.stride,
                           (size_t)img.width) != 0)
                    abort();
        } else if (e != RL_ELIMIT) {
            abort(); /* the block reader refuses only for want of room */
        }
        rl_png_free(&img);
    } else if (err[0] == '\0') {
        abort(); /* an error names what went wrong */
    } else if (e == RL_OK) {
        abort(); /* the block reader accepted what the other refused */
    }
    return 0;
}
