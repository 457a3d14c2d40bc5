/* sim_report: a `make sim` run judged against the simulator's truth, from
 * ringloc-aria-fuse's logs. The pose log has a line per control tick (a
 * server information packet with a fused pose): "t fx fy fyaw ax ay ayaw
 * sigma tx ty tyaw wp" (s; m, rad; the fused pose, ARIA's, the fused
 * sigma, the truth, the waypoint being driven to or -1). The route log has
 * a line per waypoint reached: "i gx gy t ax ay tx ty".
 *
 * The truth comes in whole millimetres and degrees (AMRISim's SIMSTAT), so
 * the error at a tick is judged at that resolution: the fused pose is
 * rounded to whole millimetres and degrees before it is compared.
 *
 *   sim_run r;
 *   sim_report_defaults(&r);                 // no cut, no push
 *   if (sim_report_load(&r, "poses.log", "route.log", err, sizeof err) == 0) {
 *       sim_report_judge(&r);
 *       use(r.rms_mm, r.worst_waypoint_mm);
 *   }
 *   sim_report_free(&r);
 */
#ifndef SIM_REPORT_H
#define SIM_REPORT_H

#include <stddef.h>

typedef struct {
    double t, fx, fy, fyaw, ax, ay, ayaw, sigma, tx, ty, tyaw;
    int wp;
} sim_tick;

typedef struct {
    int i;
    double gx, gy, t, ax, ay, tx, ty;
} sim_reached;

typedef struct {
    /* in: the disturbances, in s of the log's clock after the route's start (< 0: none) */
    double cut_at, cut_for, push_at;
    double slow;           /* the simulation ran this many times slower than the log's clock (1) */
    double recovered_mm;   /* the error under which the pose counts as recovered (10 mm) */
    /* loaded */
    sim_tick *tick;
    size_t n;
    sim_reached *reached;
    size_t nreached;
    /* judged, over the route's ticks (wp >= 0 ... the last waypoint reached) */
    double start;          /* the route's start (s) */
    size_t judged;         /* ticks judged */
    double rms_mm, p95_mm, max_mm, yaw_rms_deg, max_yaw_deg;
    double worst_waypoint_mm;  /* the truth's distance to its waypoint, the worst */
    double cut_max_mm;     /* during the cut and 2 simulated s after it */
    double recovery_s;     /* after the push: until the error stays under recovered_mm (-1: never) */
    size_t excluded;       /* ticks left out of the RMS: the push to its recovery */
} sim_run;

void sim_report_defaults(sim_run *r);

/* Read both logs (the route log may be NULL). 0, or -1 with one line in
 * err naming the file and line. */
int sim_report_load(sim_run *r, const char *poses, const char *route, char *err, size_t errlen);

/* the error at one tick, judged at the truth's resolution (mm; degrees) */
double sim_report_error_mm(const sim_tick *k);
double sim_report_yaw_error_deg(const sim_tick *k);

/* The figures above. */
void sim_report_judge(sim_run *r);

void sim_report_free(sim_run *r);

#endif
