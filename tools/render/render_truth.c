/* render_truth: a frame's ground truth (render_truth.h). */
#include "render_truth.h"

#include <math.h>
#include <stdio.h>
#include "render_camera.h"
#include "render_ceiling.h"
#include "rl_outfile.h"

/* 1 if a light fixture drawn over the ceiling covers (X, Y). */
static int under_light(const render_scene *s, double X, double Y)
{
    int i;
    for (i = 0; i < s->n; i++) {
        const render_object *l = &s->obj[i];
        if (l->kind == RENDER_OBJ_LIGHT && render_ceiling_light_gap(l, X, Y) <= 0)
            return 1;
        if (l->kind == RENDER_OBJ_DOWNLIGHT && hypot(X - l->x, Y - l->y) <= l->a)
            return 1;
    }
    return 0;
}

/* 1 if an object hanging below (X, Y, drop below the ceiling) covers it
 * from the camera. */
static int hidden(const render_scene *s, double X, double Y, double drop)
{
    int i;
    for (i = 0; i < s->n; i++) {
        const render_object *h = &s->obj[i];
        double t, hx, hy;
        if (!(h->drop > drop))
            continue;
        /* where the ray from the camera to the point crosses h's plane */
        t = (s->ceiling_height - h->drop - s->cz) / (s->ceiling_height - drop - s->cz);
        hx = s->cx + t * (X - s->cx);
        hy = s->cy + t * (Y - s->cy);
        if (render_ceiling_object(s, h, hx, hy) >= 0)
            return 1;
    }
    return 0;
}

/* Fraction of the landmark's disk that the camera sees: inside the image
 * and not covered by a light fixture or by something hanging below it. */
static double visible_fraction(const render_scene *s, const render_object *o)
{
    int i, j, in = 0, n = 0;
    for (j = -20; j <= 20; j++)
        for (i = -20; i <= 20; i++) {
            double lx = i / 20.0 * o->a, ly = j / 20.0 * o->a, u, v;
            if (lx * lx + ly * ly > o->a * o->a)
                continue;
            n++;
            render_camera_to_pixel(s, o->x + lx, o->y + ly, o->drop, &u, &v);
            /* one that hangs below the ceiling hangs below its lights too */
            in += u >= -0.5 && v >= -0.5 && u <= s->cam.width - 0.5 && v <= s->cam.height - 0.5 &&
                  (o->drop > 0 || !under_light(s, o->x + lx, o->y + ly)) &&
                  !hidden(s, o->x + lx, o->y + ly, o->drop);
        }
    return (double)in / n;
}

static double light_gap(const render_scene *s, const render_object *o)
{
    double best = 1e9;
    int i, k;
    for (i = 0; i < s->n; i++) {
        const render_object *l = &s->obj[i];
        if (l->kind != RENDER_OBJ_LIGHT && l->kind != RENDER_OBJ_DOWNLIGHT)
            continue;
        for (k = 0; k < 72; k++) { /* landmark edge to light, sampled */
            double X = o->x + o->a * cos(k * M_PI / 36), Y = o->y + o->a * sin(k * M_PI / 36);
            double g = l->kind == RENDER_OBJ_LIGHT ? render_ceiling_light_gap(l, X, Y)
                                            : fmax(0, hypot(X - l->x, Y - l->y) - l->a);
            if (g < best)
                best = g;
        }
    }
    return best;
}

int render_truth_write(const char *path, const char *image, const render_scene *s, double rx, double ry,
                       double ryaw)
{
    rl_outfile out;
    FILE *f;
    char err[1200];
    int i, n = 0;
    if (rl_outfile_open(&out, path, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-render: %s\n", err), -1;
    f = out.f;
    fprintf(f, "image: %s\nwidth: %d\nheight: %d\nfamily: ring%d\ndiameter: %.4f\n", image,
            s->cam.width, s->cam.height, s->fam.bits, s->diameter);
    fprintf(f, "distance: %.4f\ncamera: {x: %.6f, y: %.6f, yaw: %.6f}\n", s->distance, s->cx, s->cy, s->yaw);
    fprintf(f, "robot: {x: %.6f, y: %.6f, yaw: %.6f}\n", rx, ry, ryaw);
    fprintf(f, "camera_tilt: {roll: %.6f, pitch: %.6f, z: %.6f}\n", s->roll, s->pitch, s->cz);
    fprintf(f, "twin: %s\nlandmarks:\n", s->twin ? "apriltag36h11" : "none");
    for (i = 0; i < s->n; i++) {
        const render_object *o = &s->obj[i];
        double u, v, vis, gap, dist = s->distance - o->drop; /* the camera's distance to it */
        if (o->kind != RENDER_OBJ_LANDMARK)
            continue;
        render_camera_to_pixel(s, o->x, o->y, o->drop, &u, &v);
        if (u < -3 * o->a / s->distance * s->cam.fx || v < -3 * o->a / s->distance * s->cam.fx ||
            u > s->cam.width * 1.5 || v > s->cam.height * 1.5)
            continue;
        vis = visible_fraction(s, o);
        if (vis <= 0)
            continue;
        gap = light_gap(s, o);
        fprintf(f, "  - {id: %d, x: %.6f, y: %.6f, u: %.4f, v: %.4f, radius: %.3f, visible: %.4f, light_gap: %.4f, light_gap_radii: %.3f",
                o->id, o->x, o->y, u, v, o->a / dist * s->cam.fx, vis, gap, gap / o->a);
        if (o->drop > 0)
            fprintf(f, ", drop: %.4f", o->drop);
        fprintf(f, "}\n");
        n++;
    }
    if (n == 0)
        fprintf(f, "  []\n");
    fprintf(f, "effects: {gain: %.3f, vignette: %.3f, blur: %.3f, noise: %.3f, motion: %.4f, halo: %.3f}\n",
            s->gain, s->vignette, s->se.blur, s->se.read_noise, s->motion, s->halo_amp);
    fprintf(f, "sensor: {full_well: %.0f, defocus: %.2f, tone: %s, adc_bits: %d, motion_px: %.2f, "
            "motion_turn: %.4f}\n",
            s->se.full_well, s->se.defocus, s->se.tone == RENDER_TONE_SRGB ? "srgb" : "gamma2.2",
            s->se.adc_bits, s->motion / s->distance * s->cam.fx, s->motion_turn);
    fprintf(f, "sheet: {width: %.4f, height: %.4f, ceiling: %.3f}\n", s->sheet_w, s->sheet_h, s->ceiling);
    if (rl_outfile_commit(&out, err, sizeof err) != RL_OK)
        return fprintf(stderr, "ringloc-render: %s\n", err), -1;
    return 0;
}
