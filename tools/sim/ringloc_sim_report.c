/* ringloc-sim-report: a `make sim` run judged against AMRISim's truth (see
 * sim_report.h for the logs and how the error is judged) and drawn. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include "rl_cli.h"
#include "sim_plot.h"
#include "sim_report.h"

#define P "ringloc-sim-report"
#define WAYPOINT_MM 30.0 /* issue 42's targets */
#define RMS_MM 5.0

static const char *help =
    "usage: ringloc-sim-report --poses FILE [--route FILE] [--plot PNG] [--cut-at S [--cut-for 3]]\n"
    "                          [--push-at S] [--slow K] [--title TEXT]\n\n"
    "Judges a `make sim` run from ringloc-aria-fuse's logs (-poseLog with a simulator's truth,\n"
    "-routeLog) against the simulator's truth, in whole millimetres and degrees (the truth's\n"
    "resolution): the fused pose's error at every control tick of the route (RMS, p95, max,\n"
    "yaw), each waypoint's distance from the truth where the robot stopped, the error during\n"
    "a cut of the frames (--cut-at S after the route's start, for --cut-for s, and 2 s after),\n"
    "and the time the fused pose took to come back under 10 mm after a push (--push-at S; the\n"
    "ticks until then are left out of the RMS and counted). --plot draws the run.\n"
    "--slow K: the simulation ran K times slower than the logs' clock; the times given and\n"
    "printed are the simulation's (the logs' divided by K).\n"
    "Exit: 0 the targets met (every waypoint within 30 mm, the RMS within 5 mm), 4 not met,\n"
    "1 a file could not be read or written, 2 a usage error.\n";

static void print(const sim_run *r)
{
    double k = r->slow;
    size_t i;
    printf("route: %zu waypoints reached\n", r->nreached);
    for (i = 0; i < r->nreached; i++) {
        const sim_reached *w = &r->reached[i];
        printf("  waypoint %d (%.3f, %.3f) at %.1f s: the truth (%.3f, %.3f), %.0f mm off; ARIA's pose %.1f mm off\n",
               w->i, w->gx, w->gy, (w->t - r->start) / k, w->tx, w->ty,
               1000 * sqrt((w->tx - w->gx) * (w->tx - w->gx) + (w->ty - w->gy) * (w->ty - w->gy)),
               1000 * sqrt((w->ax - w->gx) * (w->ax - w->gx) + (w->ay - w->gy) * (w->ay - w->gy)));
    }
    printf("the fused pose against the truth at %zu control ticks (whole mm and degrees, the truth's resolution):\n"
           "  %.2f mm RMS, p95 %.0f mm, max %.0f mm; yaw %.2f degrees RMS, max %.0f\n",
           r->judged, r->rms_mm, r->p95_mm, r->max_mm, r->yaw_rms_deg, r->max_yaw_deg);
    if (r->cut_at >= 0)
        printf("frames cut %.1f .. %.1f s: at most %.0f mm off then and in the 2 s after\n", r->cut_at / k,
               (r->cut_at + r->cut_for) / k, r->cut_max_mm);
    if (r->push_at >= 0 && r->recovery_s >= 0)
        printf("pushed at %.1f s: back under %.0f mm after %.2f s (%zu ticks left out of the RMS)\n", r->push_at / k,
               r->recovered_mm, r->recovery_s / k, r->excluded);
    else if (r->push_at >= 0)
        printf("pushed at %.1f s: not back under %.0f mm by the end\n", r->push_at / k, r->recovered_mm);
}

int main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"poses", required_argument, 0, 'p'},   {"route", required_argument, 0, 'r'},
        {"plot", required_argument, 0, 'o'},    {"cut-at", required_argument, 0, 'c'},
        {"cut-for", required_argument, 0, 'f'}, {"push-at", required_argument, 0, 'u'},
        {"title", required_argument, 0, 't'},   {"slow", required_argument, 0, 's'},
        {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    const char *poses = NULL, *route = NULL, *plot = NULL, *title = "make sim";
    sim_run r;
    char err[1200];
    int c, code;
    rl_cli_start(P);
    sim_report_defaults(&r);
    while ((c = rl_cli_getopt(NULL, argc, argv, opts)) != -1) {
        int ok = 1;
        switch (c) {
        case 'p': poses = optarg; break;
        case 'r': route = optarg; break;
        case 'o': plot = optarg; break;
        case 't': title = optarg; break;
        case 'c': ok = rl_cli_double(NULL, "--cut-at", optarg, 0, 1e6, &r.cut_at); break;
        case 'f': ok = rl_cli_double(NULL, "--cut-for", optarg, 0, 1e6, &r.cut_for); break;
        case 'u': ok = rl_cli_double(NULL, "--push-at", optarg, 0, 1e6, &r.push_at); break;
        case 's': ok = rl_cli_double(NULL, "--slow", optarg, 1, 1000, &r.slow); break;
        case 'h': fputs(help, stdout); return 0;
        default: return RL_EXIT_USAGE;
        }
        if (!ok)
            return RL_EXIT_USAGE;
    }
    if (optind != argc)
        return rl_cli_fail(NULL, RL_EXIT_USAGE, "unexpected argument '%s' (see --help)", argv[optind]);
    if (!poses)
        return rl_cli_fail(NULL, RL_EXIT_USAGE, "--poses is needed (see --help)");
    if (sim_report_load(&r, poses, route, err, sizeof err) != 0) {
        sim_report_free(&r);
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "%s", err);
    }
    if (r.cut_at >= 0) { /* given in simulated s */
        r.cut_at *= r.slow;
        r.cut_for *= r.slow;
    }
    if (r.push_at >= 0)
        r.push_at *= r.slow;
    sim_report_judge(&r);
    print(&r);
    code = r.worst_waypoint_mm <= WAYPOINT_MM && r.rms_mm <= RMS_MM && r.judged > 0 ? 0 : 4;
    printf("targets (every waypoint within %.0f mm, the fused pose within %.0f mm RMS): %s\n", WAYPOINT_MM, RMS_MM,
           code ? "NOT met" : "met");
    if (plot && sim_plot_write(plot, &r, title) != 0)
        code = RL_EXIT_FAIL;
    sim_report_free(&r);
    return rl_cli_finish(NULL, code);
}
