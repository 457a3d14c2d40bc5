#include "rl_print.h"

#include <cairo-pdf.h>
#include <errno.h>
#include <cairo-svg.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rl_outfile.h"

#define MM_TO_PT (72.0 / 25.4)

static const rl_paper papers[] = {
    {"a4", 210.0, 297.0},
    {"letter", 215.9, 279.4},
    {"a3", 297.0, 420.0},
    {"tabloid", 279.4, 431.8},
};

const rl_paper *rl_paper_find(const char *name)
{
    size_t i;
    for (i = 0; name && i < sizeof papers / sizeof papers[0]; i++)
        if (strcmp(papers[i].name, name) == 0)
            return &papers[i];
    return NULL;
}

int rl_paper_parse(const char *s, rl_paper *out)
{
    const rl_paper *p = rl_paper_find(s);
    double w, h;
    char tail;
    if (p != NULL) {
        *out = *p;
        return 1;
    }
    if (s == NULL || sscanf(s, "%lfx%lf%c", &w, &h, &tail) != 2 || !(w >= 10 && w <= 2000) ||
        !(h >= 10 && h <= 2000))
        return 0;
    out->name = "custom";
    out->w_mm = w;
    out->h_mm = h;
    return 1;
}

const char *rl_paper_names(void)
{
    return "a4, letter, a3, tabloid";
}

double rl_print_max_diameter(const rl_paper *paper, double margin_mm)
{
    double side = paper->w_mm < paper->h_mm ? paper->w_mm : paper->h_mm;
    /* the crop marks lie inside the disk's bounding square; whole
     * millimetres, with a quarter millimetre a side for the printer's
     * (and a rasterizer's) rounding */
    return floor(side - 2 * margin_mm - 0.5) / 1000.0;
}

const rl_paper *rl_paper_fitting(double diameter, double margin_mm)
{
    size_t i;
    for (i = 0; i < sizeof papers / sizeof papers[0]; i++)
        if (diameter <= rl_print_max_diameter(&papers[i], margin_mm) + 1e-9)
            return &papers[i];
    return NULL;
}

void rl_print_landmark(cairo_t *cr, const rl_family *fam, int id, double cx, double cy, double R)
{
    double r[RL_MAX_BITS + 2];
    int z, n = fam->bits;
    rl_family_radii(fam, r);
    cairo_save(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    /* Zone z spans r[z] (outer) .. r[z+1] (inner); z = 0 is the outer ring,
     * z = k is code zone k. Merge runs of black zones into one annulus. */
    z = 0;
    while (z <= n) {
        int start, dark = z == 0 || rl_family_bit(fam, id, z);
        if (!dark) {
            z++;
            continue;
        }
        start = z;
        while (z + 1 <= n && rl_family_bit(fam, id, z + 1))
            z++;
        cairo_new_path(cr);
        cairo_arc(cr, cx, cy, r[start] * R, 0, 2 * M_PI);
        cairo_close_path(cr);
        if (r[z + 1] > 0) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, cx, cy, r[z + 1] * R, 0, 2 * M_PI);
            cairo_close_path(cr);
        }
        cairo_fill(cr);
        z++;
    }
    cairo_restore(cr);
}

/* Crop marks: an L in each corner of the landmark's bounding square,
 * along its edges and inside it (the disk touches the square only at the
 * middle of each side), so they are on the page whenever the disk is. */
static void crop_marks(cairo_t *cr, double cx, double cy, double half)
{
    double len = (half < 30 * MM_TO_PT ? 0.2 * half : 6 * MM_TO_PT), w = 0.25;
    int sx, sy;
    cairo_save(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, w);
    for (sx = -1; sx <= 1; sx += 2)
        for (sy = -1; sy <= 1; sy += 2) {
            /* the corner, moved in by half the line so the ink stays inside */
            double x = cx + sx * (half - w / 2), y = cy + sy * (half - w / 2);
            cairo_move_to(cr, x - sx * len, y);
            cairo_line_to(cr, x, y);
            cairo_line_to(cr, x, y - sy * len);
        }
    cairo_stroke(cr);
    cairo_restore(cr);
}

static void page(cairo_t *cr, const rl_paper *paper, const rl_family *fam, int id,
                 const rl_map_landmark *pos, double diameter)
{
    double W = paper->w_mm * MM_TO_PT, H = paper->h_mm * MM_TO_PT;
    double R = diameter * 1000.0 * MM_TO_PT / 2, cx = W / 2, cy = H / 2;
    char code[RL_MAX_BITS + 1], label[160];
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    rl_print_landmark(cr, fam, id, cx, cy, R);
    crop_marks(cr, cx, cy, R);
    if (rl_family_code(fam, id, code, sizeof code) != RL_OK)
        code[0] = '\0';
    if (pos != NULL)
        snprintf(label, sizeof label, "ringloc ring%d  id %d  code %s  diameter %.0f mm  at x %.3f m, y %.3f m",
                 fam->bits, id, code, diameter * 1000.0, pos->x, pos->y);
    else
        snprintf(label, sizeof label, "ringloc ring%d  id %d  code %s  diameter %.0f mm  (image top = robot forward)",
                 fam->bits, id, code, diameter * 1000.0);
    /* Small grey type near the bottom edge, outside the quiet zone
     * (1.25 R) whenever the paper leaves room for it. */
    cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 7.0);
    cairo_move_to(cr, 12 * MM_TO_PT, H - 8 * MM_TO_PT);
    cairo_show_text(cr, label);
}

static rl_err surface_status(cairo_surface_t *s, const char *path, char *err, size_t errlen)
{
    cairo_status_t st = cairo_surface_status(s);
    if (st == CAIRO_STATUS_SUCCESS)
        return RL_OK;
    snprintf(err, errlen, "%s: %s", path, cairo_status_to_string(st));
    return RL_EIO;
}

/* cairo's stream callback: into the temporary file (the first write error
 * is kept with its errno, so the line says why, not cairo's "error while
 * writing to output stream"). */
static cairo_status_t to_outfile(void *closure, const unsigned char *data, unsigned int length)
{
    return rl_outfile_write((rl_outfile *)closure, data, length) == 0 ? CAIRO_STATUS_SUCCESS
                                                                       : CAIRO_STATUS_WRITE_ERROR;
}

/* After drawing: cairo's own status (the context's, then the surface's
 * once finished) joins the file's, which is committed or removed. */
static rl_err finish(cairo_t *cr, cairo_surface_t *s, rl_outfile *o, char *err, size_t errlen)
{
    cairo_status_t st = cr ? cairo_status(cr) : CAIRO_STATUS_SUCCESS;
    if (cr)
        cairo_destroy(cr);
    cairo_surface_finish(s);
    if (st == CAIRO_STATUS_SUCCESS)
        st = cairo_surface_status(s);
    cairo_surface_destroy(s);
    if (st != CAIRO_STATUS_SUCCESS && o->errnum == 0) {
        rl_outfile_abort(o);
        snprintf(err, errlen, "%s: %s", o->path, cairo_status_to_string(st));
        return RL_EIO;
    }
    if (st != CAIRO_STATUS_SUCCESS)
        rl_outfile_set_error(o, EIO);
    return rl_outfile_commit(o, err, errlen);
}

/* A PDF or SVG surface of the paper's size writing into a new outfile. */
static rl_err vector_surface(int svg, const char *path, const rl_paper *paper, rl_outfile *o,
                             cairo_surface_t **s, char *err, size_t errlen)
{
    double w = paper->w_mm * MM_TO_PT, h = paper->h_mm * MM_TO_PT;
    rl_err e;
    if ((e = rl_outfile_open(o, path, err, errlen)) != RL_OK)
        return e;
    *s = svg ? cairo_svg_surface_create_for_stream(to_outfile, o, w, h)
             : cairo_pdf_surface_create_for_stream(to_outfile, o, w, h);
    if ((e = surface_status(*s, path, err, errlen)) != RL_OK) {
        cairo_surface_destroy(*s);
        rl_outfile_abort(o);
    }
    return e;
}

rl_err rl_print_pdf(const char *path, const rl_paper *paper, const rl_family *fam,
                    const int *ids, const rl_map_landmark *pos, int n, double diameter,
                    char *err, size_t errlen)
{
    cairo_surface_t *s;
    cairo_t *cr;
    rl_outfile o;
    int i;
    rl_err e;
    if ((e = vector_surface(0, path, paper, &o, &s, err, errlen)) != RL_OK)
        return e;
    cr = cairo_create(s);
    for (i = 0; i < n; i++) {
        page(cr, paper, fam, ids[i], pos ? &pos[i] : NULL, diameter);
        cairo_show_page(cr);
    }
    return finish(cr, s, &o, err, errlen);
}

rl_err rl_print_svg(const char *path, const rl_paper *paper, const rl_family *fam, int id,
                    const rl_map_landmark *pos, double diameter, char *err, size_t errlen)
{
    cairo_surface_t *s;
    cairo_t *cr;
    rl_outfile o;
    rl_err e;
    if ((e = vector_surface(1, path, paper, &o, &s, err, errlen)) != RL_OK)
        return e;
    cairo_svg_surface_set_document_unit(s, CAIRO_SVG_UNIT_MM);
    cr = cairo_create(s);
    page(cr, paper, fam, id, pos, diameter);
    return finish(cr, s, &o, err, errlen);
}

int rl_print_png_side(int px)
{
    int margin = (int)ceil(0.15 * px) + 2; /* covers the 1.25 R quiet zone */
    return px + 2 * margin;
}

rl_err rl_print_png(const char *path, const rl_family *fam, int id, int px, char *err,
                    size_t errlen)
{
    int side = rl_print_png_side(px);
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, side, side);
    cairo_t *cr;
    rl_err e;
    if ((e = surface_status(s, path, err, errlen)) != RL_OK) {
        cairo_surface_destroy(s);
        return e;
    }
    cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    /* cairo's pixel (i, j) spans [i, i+1): its centre is i + 0.5, which is
     * pixel coordinate i in the spec's convention. */
    rl_print_landmark(cr, fam, id, side / 2.0, side / 2.0, px / 2.0);
    cairo_destroy(cr);
    return rl_print_surface_png(s, path, err, errlen);
}

rl_err rl_print_surface_png(cairo_surface_t *s, const char *path, char *err, size_t errlen)
{
    rl_outfile o;
    rl_err e;
    cairo_status_t st;
    cairo_surface_flush(s);
    if ((e = rl_outfile_open(&o, path, err, errlen)) != RL_OK) {
        cairo_surface_destroy(s);
        return e;
    }
    st = cairo_surface_write_to_png_stream(s, to_outfile, &o);
    if (st != CAIRO_STATUS_SUCCESS && o.errnum == 0) {
        cairo_surface_destroy(s);
        rl_outfile_abort(&o);
        snprintf(err, errlen, "%s: cannot write PNG (%s)", path, cairo_status_to_string(st));
        return RL_EIO;
    }
    return finish(NULL, s, &o, err, errlen);
}
