/* rl_print: landmarks drawn with cairo for printing (PDF, SVG) and for
 * tests (PNG), exactly per docs/landmark-spec.md.
 *
 * Black zones are drawn as even-odd annuli, adjacent black zones merged,
 * so no edge is drawn twice and anti-aliasing is exact coverage.
 *
 *   const rl_paper *a4 = rl_paper_find("a4");
 *   int ids[] = {25};
 *   char err[256];
 *   if (rl_print_pdf("out.pdf", a4, &fam, ids, NULL, 1, 0.21, err, sizeof err) != RL_OK)
 *       fprintf(stderr, "ringloc: %s\n", err);
 */
#ifndef RL_PRINT_H
#define RL_PRINT_H

#include <cairo.h>
#include <stddef.h>
#include "rl_family.h"
#include "rl_map.h"

typedef struct {
    const char *name;
    double w_mm, h_mm; /* portrait */
} rl_paper;

/* Paper by name (a4, letter, a3, tabloid), or NULL. */
const rl_paper *rl_paper_find(const char *name);
/* A sheet by paper name, or as WxH in millimetres (10 .. 2000 each, as
 * "300x300"); 0 when s is neither. A WxH sheet's name is "custom". */
int rl_paper_parse(const char *s, rl_paper *out);
/* "a4, letter, a3, tabloid" for messages. */
const char *rl_paper_names(void);

/* Smallest printable diameter, metres, and the unprintable border every
 * printer leaves (default margin): nothing is drawn nearer an edge. */
#define RL_PRINT_MIN_DIAMETER 0.02
#define RL_PRINT_MARGIN_MM 5.0

/* Largest diameter (metres) whose disk and crop marks stay margin_mm from
 * every edge of the paper. */
double rl_print_max_diameter(const rl_paper *paper, double margin_mm);

/* The first paper of a4, letter, a3, tabloid that the diameter fits within
 * margin_mm, or NULL. */
const rl_paper *rl_paper_fitting(double diameter, double margin_mm);

/* Draw the black zones of landmark `id`, centre (cx, cy), radius R, in the
 * current user units of cr. */
void rl_print_landmark(cairo_t *cr, const rl_family *fam, int id, double cx, double cy, double R);

/* One page per landmark: centred at its printed diameter (metres), crop
 * marks inside the corners of its bounding square (on the page whenever
 * the disk is), a small label below. `pos` (may be NULL) gives map
 * positions for the labels. The caller checks the diameter against
 * rl_print_max_diameter. */
RL_CHECK rl_err rl_print_pdf(const char *path, const rl_paper *paper, const rl_family *fam,
                             const int *ids, const rl_map_landmark *pos, int n,
                             double diameter, char *err, size_t errlen);
RL_CHECK rl_err rl_print_svg(const char *path, const rl_paper *paper, const rl_family *fam,
                             int id, const rl_map_landmark *pos, double diameter, char *err,
                             size_t errlen);

/* Write a cairo image surface to a PNG and destroy it; err names the file. */
RL_CHECK rl_err rl_print_surface_png(cairo_surface_t *s, const char *path, char *err,
                                     size_t errlen);

/* A PNG with the landmark `px` pixels across, centred on a white square of
 * side rl_print_png_side(px) (room for the quiet zone). The centre is at
 * pixel coordinates ((side - 1) / 2, (side - 1) / 2). */
int rl_print_png_side(int px);
RL_CHECK rl_err rl_print_png(const char *path, const rl_family *fam, int id, int px, char *err,
                             size_t errlen);

#endif
