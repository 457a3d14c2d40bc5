/* fuse_plot: see fuse_plot.h. */
#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include "fuse_plot.h"
#include "rl_outfile.h"

#define W 900
#define PATH_H 420
#define ERR_H 230
#define M 50

typedef struct {
    double x0, y0, sx, sy; /* data -> pixels: px = x0 + sx * x */
} axis;

static void line_xy(cairo_t *cr, const axis *a, const fs_pose *p, int n, double r, double g, double b)
{
    int i;
    cairo_set_source_rgb(cr, r, g, b);
    for (i = 0; i < n; i++)
        cairo_line_to(cr, a->x0 + a->sx * p[i].x, a->y0 + a->sy * p[i].y);
    cairo_stroke(cr);
}

static void label(cairo_t *cr, double x, double y, const char *s, double r, double g, double b)
{
    cairo_set_source_rgb(cr, r, g, b);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, s);
}

/* one error panel (c: 0 for x, 1 for y), mm against seconds */
static void errors(cairo_t *cr, const fs_result *r, int c, double top)
{
    double lim = 0, t0 = r->t[0], t1 = r->t[r->n - 1];
    axis a;
    int i;
    for (i = 0; i < r->n; i++) /* the fused pose's scale, after the first second */
        if (r->t[i] > t0 + 1.0) {
            double s = 3 * sqrt(r->cov[i][c ? 2 : 0]);
            double e = fabs(c ? r->fused[i].y - r->truth[i].y : r->fused[i].x - r->truth[i].x);
            lim = fmax(lim, fmax(s, e));
        }
    lim = fmax(lim * 1.3, 0.002);
    a.x0 = M - (W - 2 * M) * t0 / (t1 - t0);
    a.sx = (W - 2 * M) / (t1 - t0);
    a.y0 = top + ERR_H / 2.0;
    a.sy = -(ERR_H / 2.0 - 10) / lim;
    for (i = 0; i < r->n; i++) /* the stretch without landmarks */
        if (r->in_gap[i]) {
            cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
            cairo_rectangle(cr, a.x0 + a.sx * r->t[i], top, a.sx * 0.01 + 0.5, ERR_H);
            cairo_fill(cr);
        }
    cairo_set_source_rgba(cr, 0.2, 0.4, 0.9, 0.25); /* the 3-sigma band */
    for (i = 0; i < r->n; i++)
        cairo_line_to(cr, a.x0 + a.sx * r->t[i], a.y0 + a.sy * fmin(lim, 3 * sqrt(r->cov[i][c ? 2 : 0])));
    for (i = r->n - 1; i >= 0; i--)
        cairo_line_to(cr, a.x0 + a.sx * r->t[i], a.y0 - a.sy * fmin(lim, 3 * sqrt(r->cov[i][c ? 2 : 0])));
    cairo_fill(cr);
    cairo_set_line_width(cr, 1.0);
    cairo_set_source_rgb(cr, 0.85, 0.3, 0.1);
    for (i = 0; i < r->n; i++) {
        double e = c ? r->reset[i].y - r->truth[i].y : r->reset[i].x - r->truth[i].x;
        cairo_line_to(cr, a.x0 + a.sx * r->t[i], a.y0 + a.sy * fmax(-lim, fmin(lim, e)));
    }
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.2, 0.7);
    for (i = 0; i < r->n; i++) {
        double e = c ? r->fused[i].y - r->truth[i].y : r->fused[i].x - r->truth[i].x;
        cairo_line_to(cr, a.x0 + a.sx * r->t[i], a.y0 + a.sy * fmax(-lim, fmin(lim, e)));
    }
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);
    cairo_rectangle(cr, M, top, W - 2 * M, ERR_H);
    cairo_stroke(cr);
    {
        char s[96];
        snprintf(s, sizeof s, "%s error (+-%.1f mm shown, reset-on-arrival clipped; time %.1f .. %.1f s)", c ? "y" : "x",
                 lim * 1e3, t0, t1);
        label(cr, M + 4, top + 14, s, 0.2, 0.2, 0.2);
    }
}

static void draw(cairo_t *cr, const fs_result *r, const char *title)
{
    double minx = 1e9, maxx = -1e9, miny = 1e9, maxy = -1e9, sc;
    axis a;
    int i;
    for (i = 0; i < r->n; i++) {
        minx = fmin(minx, r->truth[i].x);
        maxx = fmax(maxx, r->truth[i].x);
        miny = fmin(miny, r->truth[i].y);
        maxy = fmax(maxy, r->truth[i].y);
    }
    sc = fmin((W - 2 * M) / (maxx - minx + 0.2), (PATH_H - 2 * M) / (maxy - miny + 0.2));
    a.sx = sc;
    a.sy = -sc;
    a.x0 = W / 2.0 - sc * (minx + maxx) / 2;
    a.y0 = PATH_H / 2.0 + sc * (miny + maxy) / 2;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_font_size(cr, 12);
    cairo_set_line_width(cr, 3);
    line_xy(cr, &a, r->truth, r->n, 0.75, 0.75, 0.75);
    cairo_set_line_width(cr, 1);
    line_xy(cr, &a, r->reset, r->n, 0.85, 0.3, 0.1);
    line_xy(cr, &a, r->fused, r->n, 0.1, 0.2, 0.7);
    label(cr, M, 20, title, 0, 0, 0);
    label(cr, M, 36, "grey: truth   orange: reset on arrival (today's snippet)   blue: rl_fuse, "
          "band: its 3 sigma   shaded: no landmarks", 0.3, 0.3, 0.3);
    errors(cr, r, 0, PATH_H);
    errors(cr, r, 1, PATH_H + ERR_H + 10);
}

static cairo_status_t write_cb(void *closure, const unsigned char *data, unsigned int len)
{
    return rl_outfile_write(closure, data, len) == 0 ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

int fuse_plot_write(const char *path, const fs_result *r, const char *title)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, W, PATH_H + 2 * ERR_H + 20);
    cairo_t *cr = cairo_create(s);
    rl_outfile o;
    char err[1200];
    int ok = r->n > 1;
    if (ok)
        draw(cr, r, title);
    cairo_destroy(cr);
    if (ok && rl_outfile_open(&o, path, err, sizeof err) == RL_OK) {
        if (cairo_surface_write_to_png_stream(s, write_cb, &o) != CAIRO_STATUS_SUCCESS)
            rl_outfile_set_error(&o, 0);
        ok = rl_outfile_commit(&o, err, sizeof err) == RL_OK;
    } else
        ok = 0;
    cairo_surface_destroy(s);
    if (!ok)
        fprintf(stderr, "%s: the picture was not written\n", path);
    return ok ? 0 : -1;
}
