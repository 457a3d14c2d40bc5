/* rl_plan_area: what `ringloc plan --area` plans with (host/cmd_plan_area.c).
 *
 *   rl_plan_area a = {0};
 *   a.width = 60; a.height = 40; a.pitch = 0.61; a.view_w = 2.62; a.view_h = 1.96;
 *   a.diameter = 0.195; a.ceiling = 2.75; a.min_view = 3; a.seed = 1; a.map_out = "site.yaml";
 *   if (rl_family_init(&a.family, 5) == RL_OK)
 *       use(rl_plan_area_run("plan", &a));   // exit code; JSON figures on stdout
 */
#ifndef RL_PLAN_AREA_H
#define RL_PLAN_AREA_H

#include "rl_family.h"
#include "rl_print.h"

typedef struct {
    double width, height, pitch;
    double view_w, view_h;   /* the camera's footprint on the ceiling, m */
    double diameter, ceiling;
    rl_family family;
    int even_parity, min_view;
    unsigned long seed;
    const char *map_out, *pdf; /* pdf may be NULL */
    const rl_paper *paper;
} rl_plan_area;

/* Plan, write the map (and PDF), print the figures as one JSON line;
 * the exit code (rl_cli.h). */
int rl_plan_area_run(const char *cmd, const rl_plan_area *a);

#endif
