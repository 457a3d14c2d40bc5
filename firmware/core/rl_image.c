#include "rl_image.h"

rl_image rl_image_view(int width, int height, int stride, uint8_t *data)
{
    rl_image img;
    img.width = width;
    img.height = height;
    img.stride = stride;
    img.data = data;
    return img;
}

int rl_image_valid(const rl_image *img)
{
    return img != NULL && img->data != NULL && img->width > 0 &&
           img->height > 0 && img->stride >= img->width;
}

rl_err rl_image_sub(const rl_image *img, int x, int y, int w, int h, rl_image *out)
{
    if (!rl_image_valid(img) || out == NULL || w <= 0 || h <= 0 || x < 0 || y < 0 ||
        x > img->width - w || y > img->height - h)
        return RL_EINVAL;
    *out = rl_image_view(w, h, img->stride,
                         img->data + (size_t)y * (size_t)img->stride + (size_t)x);
    return RL_OK;
}
