#include "rl_survey_plot.h"

#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include "rl_print.h"

#define PLOT_W 1000
#define PLOT_H 760
#define MARGIN 60

typedef struct {
    double x0, y0, scale; /* map (x0, y0) at the plot's lower left margin; px per m */
} view;

static void to_px(const view *v, double x, double y, double *px, double *py)
{
    *px = MARGIN + (x - v->x0) * v->scale;
    *py = PLOT_H - MARGIN - (y - v->y0) * v->scale;
}

static void extend(double *b, double x, double y)
{
    b[0] = fmin(b[0], x);
    b[1] = fmin(b[1], y);
    b[2] = fmax(b[2], x);
    b[3] = fmax(b[3], y);
}

/* The ellipse of a 2x2 covariance at k sigma, enlarged by `mag`. */
static void ellipse(cairo_t *cr, const view *v, double x, double y, const double *cov, double k, double mag)
{
    double a = cov[0], b = cov[1], c = cov[2], t = 0.5 * (a + c), d = sqrt(fmax(0, 0.25 * (a - c) * (a - c) + b * b));
    double l1 = fmax(t + d, 0), l2 = fmax(t - d, 0), ang = 0.5 * atan2(2 * b, a - c), px, py;
    to_px(v, x, y, &px, &py);
    cairo_new_path(cr);
    cairo_save(cr);
    cairo_translate(cr, px, py);
    cairo_rotate(cr, -ang);
    cairo_scale(cr, fmax(k * sqrt(l1) * mag * v->scale, 0.5), fmax(k * sqrt(l2) * mag * v->scale, 0.5));
    cairo_arc(cr, 0, 0, 1, 0, 2 * M_PI);
    cairo_restore(cr);
}

static void drive(cairo_t *cr, const view *v, const rl_survey *sv)
{
    int i, pen = 0;
    cairo_set_source_rgb(cr, 0.35, 0.55, 0.85);
    cairo_set_line_width(cr, 1.2);
    for (i = 0; i < sv->n_fr; i++) {
        const rl_survey_frame *f = &sv->fr[i];
        double px, py;
        if (f->status != RL_SURVEY_USED) {
            pen = 0;
            continue;
        }
        to_px(v, f->x, f->y, &px, &py);
        if (pen)
            cairo_line_to(cr, px, py);
        else
            cairo_move_to(cr, px, py);
        pen = 1;
    }
    cairo_stroke(cr);
}

/* The view over the placed landmarks and the drive, with a margin; the
 * ellipses' enlargement into *mag: the largest 3-sigma ellipse drawn some
 * 30 px long, enlarged by 1, 2 or 5 times a power of ten. */
static void plot_view(const rl_survey *sv, view *v, double *mag)
{
    double b[4] = {1e30, 1e30, -1e30, -1e30}, smax = 0;
    int i;
    for (i = 0; i < sv->n_lm; i++)
        if (sv->lm[i].status == RL_SURVEY_PLACED) {
            extend(b, sv->lm[i].x, sv->lm[i].y);
            smax = fmax(smax, sqrt(fmax(sv->lm[i].cov[0], sv->lm[i].cov[2])));
        }
    for (i = 0; i < sv->n_fr; i++)
        if (sv->fr[i].status == RL_SURVEY_USED)
            extend(b, sv->fr[i].x, sv->fr[i].y);
    if (b[0] > b[2])
        b[0] = b[1] = 0, b[2] = b[3] = 1;
    b[0] -= 0.3, b[1] -= 0.3, b[2] += 0.3, b[3] += 0.3;
    v->scale = fmin((PLOT_W - 2 * MARGIN) / (b[2] - b[0]), (PLOT_H - 2 * MARGIN) / (b[3] - b[1]));
    v->x0 = b[0];
    v->y0 = b[1];
    *mag = 1;
    if (smax > 0) {
        double want = fmax(1, 15.0 / (3 * smax * v->scale)), p = pow(10, floor(log10(want)));
        *mag = want >= 5 * p ? 5 * p : want >= 2 * p ? 2 * p : p;
    }
}

/* Each placed landmark: its ellipse, centre and id (origin and axis
 * circled); the count of them. */
static int draw_landmarks(cairo_t *cr, const view *v, const rl_survey *sv, double mag)
{
    double px, py;
    char text[200];
    int i, placed = 0;
    for (i = 0; i < sv->n_lm; i++) {
        const rl_survey_landmark *l = &sv->lm[i];
        if (l->status != RL_SURVEY_PLACED)
            continue;
        placed++;
        ellipse(cr, v, l->x, l->y, l->cov, 3, mag);
        cairo_set_source_rgba(cr, 0.1, 0.6, 0.2, 0.35);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.05, 0.4, 0.1);
        cairo_set_line_width(cr, 1);
        cairo_stroke(cr);
        to_px(v, l->x, l->y, &px, &py);
        cairo_new_path(cr);
        cairo_arc(cr, px, py, 2, 0, 2 * M_PI);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_fill(cr);
        snprintf(text, sizeof text, "%d", l->id);
        cairo_move_to(cr, px + 5, py - 5);
        cairo_show_text(cr, text);
        if (l->id == sv->cfg.origin_id || l->id == sv->cfg.axis_id) {
            cairo_new_path(cr);
            cairo_arc(cr, px, py, 9, 0, 2 * M_PI);
            cairo_set_line_width(cr, 1.5);
            cairo_stroke(cr);
        }
    }
    return placed;
}

/* Each moved landmark: an arrow from where the map had it. */
static void draw_moves(cairo_t *cr, const view *v, const rl_survey_move *mv, int n_mv)
{
    double px, py;
    char text[200];
    int i;
    for (i = 0; i < n_mv; i++) {
        double ox, oy, a;
        to_px(v, mv[i].old_x, mv[i].old_y, &ox, &oy);
        to_px(v, mv[i].x, mv[i].y, &px, &py);
        cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
        cairo_set_line_width(cr, 2);
        cairo_new_path(cr);
        cairo_arc(cr, ox, oy, 5, 0, 2 * M_PI);
        cairo_stroke(cr);
        cairo_move_to(cr, ox, oy);
        cairo_line_to(cr, px, py);
        a = atan2(py - oy, px - ox);
        cairo_line_to(cr, px - 8 * cos(a - 0.4), py - 8 * sin(a - 0.4));
        cairo_move_to(cr, px, py);
        cairo_line_to(cr, px - 8 * cos(a + 0.4), py - 8 * sin(a + 0.4));
        cairo_stroke(cr);
        snprintf(text, sizeof text, "%d moved %.0f mm", mv[i].id, mv[i].distance * 1000);
        cairo_move_to(cr, px + 8, py + 14);
        cairo_show_text(cr, text);
    }
}

/* The scale bar and the legend. */
static void draw_legend(cairo_t *cr, const view *v, const rl_survey *sv, int placed, double mag)
{
    double bar = pow(10, floor(log10((PLOT_W - 2 * MARGIN) / v->scale / 3)));
    char text[200];
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 2);
    cairo_move_to(cr, MARGIN, PLOT_H - 25);
    cairo_line_to(cr, MARGIN + bar * v->scale, PLOT_H - 25);
    cairo_stroke(cr);
    snprintf(text, sizeof text, "%g m", bar);
    cairo_move_to(cr, MARGIN + bar * v->scale + 6, PLOT_H - 21);
    cairo_show_text(cr, text);
    cairo_set_font_size(cr, 13);
    snprintf(text, sizeof text, "ringloc survey: %d landmarks, %d frames, ceiling %.4f m; ellipses 3 sigma x %g; "
             "blue: the robot's drive; circled: origin %d, axis %d", placed, sv->frames_used, sv->height, mag,
             sv->cfg.origin_id, sv->cfg.axis_id);
    cairo_move_to(cr, MARGIN, 30);
    cairo_show_text(cr, text);
}

rl_err rl_survey_plot(const char *path, const rl_survey *sv, const rl_survey_move *mv, int n_mv, char *err,
                      size_t errlen)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, PLOT_W, PLOT_H);
    cairo_t *cr = cairo_create(s);
    double mag;
    view v;
    int placed;

    plot_view(sv, &v, &mag);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    drive(cr, &v, sv);
    cairo_set_font_size(cr, 11);
    placed = draw_landmarks(cr, &v, sv, mag);
    draw_moves(cr, &v, mv, n_mv);
    draw_legend(cr, &v, sv, placed, mag);
    cairo_destroy(cr);
    return rl_print_surface_png(s, path, err, errlen);
}
