/* sim_plot: see sim_plot.h. */
#include "sim_plot.h"
#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include "rl_outfile.h"

#define W 900
#define MAP_H 560
#define ERR_H 260
#define M 50

typedef struct {
    double x0, y0, sx, sy; /* data -> pixels: px = x0 + sx * x */
} scale;

static void text(cairo_t *cr, double x, double y, const char *s, double grey)
{
    cairo_set_source_rgb(cr, grey, grey, grey);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, s);
}

/* the site: waypoints, truth (grey, wide) and fused pose (blue) */
static void draw_map(cairo_t *cr, const sim_run *r)
{
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9, k;
    scale s;
    size_t i;
    for (i = 0; i < r->n; i++) {
        x0 = fmin(x0, r->tick[i].tx);
        x1 = fmax(x1, r->tick[i].tx);
        y0 = fmin(y0, r->tick[i].ty);
        y1 = fmax(y1, r->tick[i].ty);
    }
    k = fmin((W - 2 * M) / (x1 - x0 + 0.4), (MAP_H - 2 * M) / (y1 - y0 + 0.4));
    s.sx = k;
    s.sy = -k;
    s.x0 = W / 2.0 - k * (x0 + x1) / 2;
    s.y0 = MAP_H / 2.0 + 20 + k * (y0 + y1) / 2;
    cairo_set_line_width(cr, 6);
    cairo_set_source_rgb(cr, 0.78, 0.78, 0.78);
    cairo_new_path(cr); /* show_text leaves a current point */
    for (i = 0; i < r->n; i++)
        cairo_line_to(cr, s.x0 + s.sx * r->tick[i].tx, s.y0 + s.sy * r->tick[i].ty);
    cairo_stroke(cr);
    cairo_set_line_width(cr, 1);
    cairo_set_source_rgb(cr, 0.1, 0.2, 0.75);
    for (i = 0; i < r->n; i++)
        cairo_line_to(cr, s.x0 + s.sx * r->tick[i].fx, s.y0 + s.sy * r->tick[i].fy);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.85, 0.3, 0.1);
    for (i = 0; i < r->nreached; i++) {
        char n[16];
        cairo_new_path(cr);
        cairo_arc(cr, s.x0 + s.sx * r->reached[i].gx, s.y0 + s.sy * r->reached[i].gy, 5, 0, 2 * M_PI);
        cairo_stroke(cr);
        snprintf(n, sizeof n, "%d", r->reached[i].i);
        text(cr, s.x0 + s.sx * r->reached[i].gx + 7, s.y0 + s.sy * r->reached[i].gy - 7 - 12 * (i % 2), n, 0.4);
        cairo_set_source_rgb(cr, 0.85, 0.3, 0.1);
    }
}

/* the error against time, mm */
static void draw_errors(cairo_t *cr, const sim_run *r, double top)
{
    double t1 = r->n ? r->tick[r->n - 1].t - r->start : 1, lim = 10, bottom = top + ERR_H;
    scale s;
    size_t i;
    char l[128];
    lim = fmax(lim, 1.3 * r->max_mm); /* the push's errors above it are clipped */
    s.x0 = M;
    s.sx = (W - 2 * M) / fmax(t1, 1);
    s.y0 = bottom;
    s.sy = -ERR_H / lim;
    if (r->cut_at >= 0) {
        cairo_set_source_rgb(cr, 0.92, 0.92, 0.92);
        cairo_rectangle(cr, s.x0 + s.sx * r->cut_at, top, s.sx * r->cut_for, ERR_H);
        cairo_fill(cr);
    }
    if (r->push_at >= 0) {
        cairo_set_source_rgb(cr, 0.85, 0.3, 0.1);
        cairo_move_to(cr, s.x0 + s.sx * r->push_at, top);
        cairo_line_to(cr, s.x0 + s.sx * r->push_at, bottom);
        cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6); /* 5 mm */
    cairo_new_path(cr);
    cairo_move_to(cr, M, s.y0 + s.sy * 5);
    cairo_line_to(cr, W - M, s.y0 + s.sy * 5);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.2, 0.75);
    cairo_new_path(cr);
    for (i = 0; i < r->n; i++)
        if (r->tick[i].t >= r->start)
            cairo_line_to(cr, s.x0 + s.sx * (r->tick[i].t - r->start),
                          s.y0 + s.sy * fmin(lim, sim_report_error_mm(&r->tick[i])));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);
    cairo_rectangle(cr, M, top, W - 2 * M, ERR_H);
    cairo_stroke(cr);
    snprintf(l, sizeof l, "fused pose's error at each control tick, 0 .. %.0f mm (grey line: 5 mm), "
             "0 .. %.0f s of the route (simulated)", lim, t1 / r->slow);
    text(cr, M + 4, top + 14, l, 0.2);
}

static cairo_status_t to_outfile(void *o, const unsigned char *data, unsigned int len)
{
    return rl_outfile_write(o, data, len) == 0 ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

int sim_plot_write(const char *path, const sim_run *r, const char *title)
{
    cairo_surface_t *sf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, W, MAP_H + ERR_H + 30);
    cairo_t *cr = cairo_create(sf);
    rl_outfile o;
    char err[1200];
    int ok = r->n > 1;
    if (ok) {
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_paint(cr);
        cairo_set_font_size(cr, 12);
        text(cr, M, 20, title, 0);
        text(cr, M, 36, "wide grey: the truth (AMRISim)   blue: the fused pose   orange: the waypoints   "
             "shaded: frames cut   orange line: the push", 0.3);
        draw_map(cr, r);
        draw_errors(cr, r, MAP_H);
    }
    cairo_destroy(cr);
    if (ok && rl_outfile_open(&o, path, err, sizeof err) == 0) {
        if (cairo_surface_write_to_png_stream(sf, to_outfile, &o) != CAIRO_STATUS_SUCCESS)
            rl_outfile_set_error(&o, 0);
        ok = rl_outfile_commit(&o, err, sizeof err) == 0;
        if (!ok)
            fprintf(stderr, "ringloc-sim-report: %s\n", err);
    } else if (ok) {
        fprintf(stderr, "ringloc-sim-report: %s\n", err);
        ok = 0;
    } else
        fprintf(stderr, "ringloc-sim-report: %s: not drawn (fewer than 2 ticks)\n", path);
    cairo_surface_destroy(sf);
    return ok ? 0 : -1;
}
