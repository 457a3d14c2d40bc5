/* render_isp: what a camera's image signal processor does to a frame
 * after its tone curve, in grey levels (the renderer's option --isp).
 *
 * Optics and motion mix light, before the curve (render_sensor); many
 * cameras then scale, bin, compress or sharpen the 8-bit frame, which
 * mixes or bends grey levels instead, and some change their exposure from
 * frame to frame. Stages, applied in the order given:
 *   blur:S      a Gaussian of sigma S px on grey levels (0.3 .. 3)
 *   scale:F     scaled down by F (area average) and back up (bilinear), as a
 *               scaler or binning after the curve does (1.2 .. 4)
 *   sharpen:A   an unsharp mask of sigma 1 px and amount A (0.1 .. 3)
 *   jpeg:Q      JPEG compression at quality Q (10 .. 100), decoded again
 *   scurve:K    a monotone S-curve of strength K on grey levels (0.05 .. 1)
 *   ae:STOPS    auto exposure: each frame's exposure off by up to STOPS stops
 *               (0.05 .. 2), another each frame (a gain on grey levels as a
 *               gamma-2.2 camera's would be)
 *
 *   render_isp isp;
 *   if (render_isp_parse("blur:0.8,jpeg:80", &isp, err, sizeof err) != 0)
 *       fail(err);
 *   render_isp_apply(&isp, px, W, H, frame_index);
 */
#ifndef RENDER_ISP_H
#define RENDER_ISP_H

#include <stddef.h>
#include <stdint.h>

#define RENDER_ISP_MAX 8

typedef enum {
    RENDER_ISP_BLUR,
    RENDER_ISP_SCALE,
    RENDER_ISP_SHARPEN,
    RENDER_ISP_JPEG,
    RENDER_ISP_SCURVE,
    RENDER_ISP_AE
} render_isp_kind;

typedef struct {
    render_isp_kind kind[RENDER_ISP_MAX];
    double value[RENDER_ISP_MAX];
    int n; /* 0: no stage (the frame as the sensor developed it) */
} render_isp;

/* A stage list ("NAME:VALUE,..."): 0, or -1 with why in err. */
int render_isp_parse(const char *spec, render_isp *isp, char *err, size_t len);

/* The stages applied to a W x H 8-bit frame in place; frame (its index)
 * sets the auto exposure's change. 0, or -1 out of memory or when JPEG
 * fails (the frame then as far as it got). */
int render_isp_apply(const render_isp *isp, uint8_t *px, int W, int H, int frame);

#endif
