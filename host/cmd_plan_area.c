/* ringloc plan --area: a large site's ids, every view unique (rl_site_plan). */
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <time.h>
#include "rl_cli.h"
#include "rl_mapfile.h"
#include "rl_outfile.h"
#include "rl_plan_area.h"
#include "rl_print.h"
#include "rl_site_plan.h"

static void progress(void *ctx, int stage, long failing)
{
    (void)ctx;
    fprintf(stderr, "ringloc plan: views of %d or more landmarks: %ld not unique%s\n", stage, failing,
            failing ? "; ids redrawn" : "");
}

/* Whether path can be written (its temporary made and removed: nothing
 * left behind, the target untouched). */
static int writable(const char *path, char *err, size_t errlen)
{
    rl_outfile o;
    if (rl_outfile_open(&o, path, err, errlen) != RL_OK)
        return 0;
    rl_outfile_abort(&o);
    return 1;
}

/* The planned grid as a map. */
static void to_map(const rl_plan_area *a, const rl_site_plan_result *r, const int *ids, rl_map *map)
{
    int i, j;
    map->family = a->family;
    map->diameter = a->diameter;
    map->ceiling_height = a->ceiling;
    map->count = 0;
    for (j = 0; j < r->rows; j++)
        for (i = 0; i < r->cols; i++) {
            rl_map_landmark *lm = &map->lm[map->count++];
            lm->id = ids[j * r->cols + i];
            lm->x = r->x0 + i * a->pitch;
            lm->y = r->y0 + j * a->pitch;
            lm->sigma_x = lm->sigma_y = 0;
        }
}

static void print_json(const rl_plan_area *a, const rl_site_plan_input *in, const rl_site_plan_result *r,
                       rl_err e)
{
    printf("{\"area\": [%.3f, %.3f], \"pitch\": %.4f, \"family\": \"ring%d\", \"diameter\": %.4f, "
           "\"view\": [%.3f, %.3f], \"cols\": %d, \"rows\": %d, \"landmarks\": %d, \"ids\": %d, "
           "\"even_parity\": %s, \"min_view\": %d, \"k_achieved\": %d, \"all_unique\": %s, "
           "\"views_checked\": %ld, \"views_not_unique\": %ld, \"smallest_view\": %d, \"rounds\": %d, "
           "\"redrawn\": %ld, \"gap\": %.3f, \"seed\": %lu, \"map\": \"%s\", \"pdf\": %s%s%s, "
           "\"seconds\": %.2f}\n",
           a->width, a->height, a->pitch, a->family.bits, a->diameter, in->view_w, in->view_h, r->cols,
           r->rows, r->cols * r->rows, r->ids_used, in->even_parity ? "true" : "false", in->min_view,
           r->k_achieved, e == RL_OK ? "true" : "false", r->views, r->failing, r->smallest_view, r->rounds,
           r->redrawn, in->gap, in->seed, a->map_out, a->pdf ? "\"" : "", a->pdf ? a->pdf : "null",
           a->pdf ? "\"" : "", r->seconds);
}

int rl_plan_area_run(const char *C, const rl_plan_area *a)
{
    static rl_map map;
    static int ids[RL_MAX_MAP_LANDMARKS];
    rl_site_plan_input in;
    rl_site_plan_result r;
    char err[512];
    rl_err e;
    long need = (long)(a->width / a->pitch + 1e-9) * (long)(a->height / a->pitch + 1e-9);
    if (need > RL_MAX_MAP_LANDMARKS)
        return rl_cli_fail(C, RL_EXIT_USAGE,
                           "--area %gx%g at pitch %g needs %ld landmarks, more than a map holds (%d)", a->width,
                           a->height, a->pitch, need, RL_MAX_MAP_LANDMARKS);
    rl_site_plan_defaults(&in);
    in.width = a->width;
    in.height = a->height;
    in.pitch = a->pitch;
    in.view_w = a->view_w;
    in.view_h = a->view_h;
    in.diameter = a->diameter;
    in.n_ids = rl_family_count(&a->family);
    in.bits = a->family.bits;
    in.even_parity = a->even_parity;
    in.min_view = a->min_view;
    in.seed = a->seed;
    in.gap = 2 * a->pitch;
    in.progress = progress;
    if (!(a->pitch > a->diameter))
        return rl_cli_fail(C, RL_EXIT_USAGE, "--pitch %g m: landmarks of %g m would overlap", a->pitch,
                           a->diameter);
    if (!(a->view_w - a->diameter > a->pitch) || !(a->view_h - a->diameter > a->pitch))
        return rl_cli_fail(C, RL_EXIT_USAGE,
                           "--pitch %g m: the camera's view (%.2f x %.2f m) holds too few whole landmarks "
                           "to tell places apart",
                           a->pitch, a->view_w, a->view_h);
    if (!writable(a->map_out, err, sizeof err) || (a->pdf && !writable(a->pdf, err, sizeof err)))
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err); /* before a minute of planning */
    e = rl_site_plan(&in, ids, RL_MAX_MAP_LANDMARKS, &r);
    if (e == RL_ERANGE)
        return rl_cli_fail(C, RL_EXIT_FAIL, "ring%d%s has too few ids to keep each id %.2f m from its repeats",
                           a->family.bits, a->even_parity ? " (even parity)" : "", in.gap);
    if (e != RL_OK && e != RL_ELIMIT)
        return rl_cli_fail(C, RL_EXIT_FAIL, "planning failed: %s", rl_strerror(e));
    to_map(a, &r, ids, &map);
    if (rl_mapfile_save(a->map_out, &map, err, sizeof err) != RL_OK)
        return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    if (a->pdf != NULL) {
        static int pdf_ids[RL_MAX_MAP_LANDMARKS];
        int i;
        for (i = 0; i < map.count; i++)
            pdf_ids[i] = map.lm[i].id;
        fprintf(stderr, "ringloc plan: writing %d pages to %s\n", map.count, a->pdf);
        if (rl_print_pdf(a->pdf, a->paper, &map.family, pdf_ids, map.lm, map.count, map.diameter, err,
                         sizeof err) != RL_OK)
            return rl_cli_fail(C, RL_EXIT_FAIL, "%s", err);
    }
    print_json(a, &in, &r, e);
    if (e == RL_ELIMIT)
        fprintf(stderr,
                "ringloc plan: note: every view of %d or more whole landmarks is unique; %ld views of %d .. %d "
                "(near the walls) are not, and a frame showing only those is found by tracking\n",
                r.k_achieved, r.failing, a->min_view, r.k_achieved - 1);
    return 0;
}
