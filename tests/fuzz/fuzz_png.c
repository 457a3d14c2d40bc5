/* The PNG reader on arbitrary bytes: an image or an error, never a crash,
 * and an image's size within the limits. */
#include <stdlib.h>
#include "fuzz_file.h"
#include "rl_config.h"
#include "rl_png.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rl_image img;
    char err[512];
    if (rl_png_read_gray(fuzz_file(data, size, ".png"), &img, err, sizeof err) == RL_OK) {
        if (img.width <= 0 || img.height <= 0 || img.width > RL_MAX_IMAGE_DIM ||
            img.height > RL_MAX_IMAGE_DIM)
            abort();
        rl_png_free(&img);
    } else if (err[0] == '\0') {
        abort(); /* an error names what went wrong */
    }
    return 0;
}
