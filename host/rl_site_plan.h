/* rl_site_plan: ids for a large site from a small family, every view unique.
 *
 * A square grid over the area, centred in it. A view is the set of grid points whose whole landmark
 * the camera sees: those inside its footprint on the ceiling less the
 * diameter, at camera positions over the area (a third of a pitch apart)
 * and headings (7.5 degrees apart). A view of at least K landmarks is
 * unique when every other placement of it on the grid (any grid
 * translation and quarter turn, the only motions that put three grid
 * points on grid points) shows at least two different ids, or lands off
 * the site: a single misread never makes it another place. Candidate
 * placements come from the view's first three landmarks (a placement that
 * differs in at most one id agrees on two of them): pairs of the site with
 * the same two ids and the same offset. Ids are drawn at random, never
 * repeating within `gap` of each other; then in stages, views of 8 or
 * more landmarks first, then 7, ... down to min_view, a failing view has
 * an id that agrees with the other placement redrawn until a round finds
 * none. A stage that does not converge (max_rounds, or four rounds without
 * fewer failing views than before) is undone and
 * planning stops: the smallest views (a few landmarks at the walls) may be
 * beyond a small family, and k_achieved says which views are unique.
 *
 *   rl_site_plan_input in;
 *   rl_site_plan_result out;
 *   static int grid_ids[100 * 70];
 *   rl_site_plan_defaults(&in);
 *   in.width = 60; in.height = 40; in.pitch = 0.61; in.view_w = 2.62; in.view_h = 1.96;
 *   in.diameter = 0.195; in.n_ids = 30;
 *   if (rl_site_plan(&in, grid_ids, 100 * 70, &out) == RL_OK)
 *       use(out.cols, out.rows, out.k_achieved);
 */
#ifndef RL_SITE_PLAN_H
#define RL_SITE_PLAN_H

#include "rl_error.h"

typedef struct {
    double width, height;  /* the area, m */
    double pitch;          /* grid pitch, m */
    double view_w, view_h; /* the camera's footprint on the ceiling, m */
    double diameter;       /* printed landmark diameter, m */
    double clearance;      /* the camera comes no nearer the area's edge than this, m (0.3:
                              a Pioneer 3-DX's half width and a little) */
    int n_ids;             /* the family's ids: 1 .. n_ids */
    int bits;              /* its code zones (for even_parity) */
    int even_parity;       /* only ids of even parity: any two differ in two zones */
    int min_view;          /* K: views of this many landmarks or more must be unique (3) */
    double gap;            /* no id twice closer than this, m (0: two pitches) */
    unsigned long seed;    /* random ids (1) */
    int max_rounds;        /* repair rounds per stage (12) */
    void (*progress)(void *ctx, int stage, long failing); /* after each round (NULL: quiet) */
    void *progress_ctx;
} rl_site_plan_input;

typedef struct {
    int cols, rows;
    double x0, y0;        /* landmark (0, 0)'s place; (i, j) is at x0 + i pitch, y0 + j pitch */
    int ids_used;         /* distinct ids on the site */
    int k_achieved;       /* smallest K with every view of K or more unique */
    long views;           /* views checked in the last round */
    long failing;         /* views of min_view or more that are not unique (0: all are) */
    int smallest_view;    /* fewest whole landmarks of a view (not counting views under 3) */
    int rounds;           /* in all stages */
    long redrawn;         /* ids redrawn */
    double seconds;
} rl_site_plan_result;

void rl_site_plan_defaults(rl_site_plan_input *in);

/* Plan the ids into ids[row * cols + col] (room for max). RL_EINVAL for
 * bad inputs, RL_ENOMEM when the grid needs more than max or memory runs
 * out, RL_ERANGE when no id fits the gap (too few ids), RL_ELIMIT when
 * views of min_view still fail after max_rounds (out says how many). */
RL_CHECK rl_err rl_site_plan(const rl_site_plan_input *in, int *ids, int max, rl_site_plan_result *out);

#endif
