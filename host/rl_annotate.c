#include "rl_annotate.h"
#include "rl_print.h"

#include <cairo.h>
#include <math.h>
#include <stdio.h>

static void circle(cairo_t *cr, const rl_detection *d, double r, double g, double b)
{
    cairo_set_source_rgb(cr, r, g, b);
    cairo_set_line_width(cr, 1.5);
    cairo_new_path(cr);
    cairo_arc(cr, d->u + 0.5, d->v + 0.5, d->radius, 0, 2 * M_PI);
    cairo_stroke(cr);
}

rl_err rl_annotate_png(const char *path, const rl_image *img, const rl_result *res,
                       const rl_family *fam, const char *caption, char *err, size_t errlen)
{
    int W = img->width, H = img->height, x, y, i, stride;
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, W, H);
    cairo_t *cr;
    unsigned char *px;
    char text[64];
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errlen, "%s: %s", path, cairo_status_to_string(cairo_surface_status(s)));
        cairo_surface_destroy(s);
        return RL_ENOMEM;
    }
    cairo_surface_flush(s);
    px = cairo_image_surface_get_data(s);
    stride = cairo_image_surface_get_stride(s);
    for (y = 0; y < H; y++) {
        uint32_t *row = (uint32_t *)(void *)(px + (size_t)y * (size_t)stride);
        for (x = 0; x < W; x++) {
            uint32_t v = rl_image_at(img, x, y);
            if ((int)v >= res->levels.light) /* light source: yellow */
                row[x] = 0xFFFFD000u;
            else
                row[x] = 0xFF000000u | (v << 16) | (v << 8) | v;
        }
    }
    cairo_surface_mark_dirty(s);
    cr = cairo_create(s);
    cairo_set_line_width(cr, 1.0);
    for (i = 0; i < res->n_lights; i++) {
        const rl_box *b = &res->lights[i];
        cairo_set_source_rgb(cr, 1.0, 0.55, 0.0);
        cairo_rectangle(cr, b->x0, b->y0, b->x1 - b->x0 + 1, b->y1 - b->y0 + 1);
        cairo_stroke(cr);
    }
    for (i = 0; i < res->n_unidentified; i++)
        circle(cr, &res->unidentified[i], 0.95, 0.1, 0.1);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 12.0);
    for (i = 0; i < res->n_landmarks; i++) {
        const rl_detection *d = &res->landmarks[i];
        char code[RL_MAX_BITS + 1] = "";
        if (d->pass == RL_PASS_LOCAL)
            circle(cr, d, 0.0, 0.85, 1.0);
        else
            circle(cr, d, 0.1, 0.9, 0.1);
        cairo_set_source_rgb(cr, 1.0, 1.0, 0.0);
        cairo_new_path(cr);
        cairo_arc(cr, d->u + 0.5, d->v + 0.5, 2.0, 0, 2 * M_PI);
        cairo_fill(cr);
        if (fam == NULL || rl_family_code(fam, d->id, code, sizeof code) != RL_OK)
            snprintf(code, sizeof code, "?");
        snprintf(text, sizeof text, "%d %s%s", d->id, code, d->pass == RL_PASS_LOCAL ? " L" : "");
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, d->u + d->radius * 0.75 + 1, d->v - d->radius * 0.75 + 1);
        cairo_show_text(cr, text);
        cairo_set_source_rgb(cr, d->pass == RL_PASS_LOCAL ? 0.0 : 0.1, d->pass == RL_PASS_LOCAL ? 0.85 : 0.9,
                             d->pass == RL_PASS_LOCAL ? 1.0 : 0.1);
        cairo_move_to(cr, d->u + d->radius * 0.75, d->v - d->radius * 0.75);
        cairo_show_text(cr, text);
    }
    if (caption != NULL) {
        cairo_set_font_size(cr, 13.0);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, 7, 17);
        cairo_show_text(cr, caption);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_move_to(cr, 6, 16);
        cairo_show_text(cr, caption);
    }
    cairo_destroy(cr);
    return rl_print_surface_png(s, path, err, errlen);
}
