/* The renderer's camera after the lens: from the light that reaches each
 * pixel to the 8-bit frame a camera delivers.
 *
 * In the order light takes (the first renderer applied the tone curve
 * first and blurred and added noise to grey levels, which no camera does,
 * and recognition learned that): the optics' blur (a Gaussian, and a defocus disk) on linear light; the
 * sensor counts photo-electrons (Poisson: the noise grows with the
 * signal), adds read noise, clips at its full well and quantizes; then
 * the tone curve (gamma 2.2 or sRGB), which stretches the dark end, noise
 * included. Dim light and short exposures are what make a frame noisy
 * there: a fraction of the full well reaches the paper, a few tens of
 * electrons the ink.
 *
 *   render_sensor se;
 *   render_sensor_defaults(&se);          // 6000 e-, 1.5 DN, 10 bits, gamma 2.2
 *   se.blur = 1.1;
 *   render_sensor_develop(&se, lin, W, H, rng, out);   // lin: linear light, 1 = full scale
 */
#ifndef RENDER_SENSOR_H
#define RENDER_SENSOR_H

#include <stdint.h>

typedef enum { RENDER_TONE_GAMMA22, RENDER_TONE_SRGB } render_tone;

typedef struct {
    double blur;         /* optics: Gaussian sigma, px */
    double defocus;      /* optics: radius of a defocus disk, px (0: none) */
    double full_well;    /* photo-electrons at linear 1.0 (the white point) */
    double read_noise;   /* read noise, DN of an 8-bit linear scale */
    int adc_bits;        /* the raw values' bits (8 .. 16) */
    render_tone tone;    /* the tone curve to 8 bits */
} render_sensor;

/* Normal and uniform random numbers, the renderer's own (reproducible). */
typedef struct {
    double (*normal)(void);  /* N(0, 1) */
    double (*uniform)(void); /* [0, 1) */
} render_rng;

void render_sensor_defaults(render_sensor *se);

/* A separable Gaussian blur of a W x H double image, in place (edges
 * clamped); nothing for sigma <= 0.05. 0, or -1 out of memory. */
int render_blur_gauss(double *img, int W, int H, double sigma);

/* lin (W x H, linear light, 1 = the white point) developed into out as
 * the sensor model says; lin is overwritten. 0, or -1 out of memory. */
int render_sensor_develop(const render_sensor *se, double *lin, int W, int H, const render_rng *rng,
                          uint8_t *out);

#endif
