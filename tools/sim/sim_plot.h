/* sim_plot: the picture of a `make sim` run (PNG, cairo): above, the route's
 * waypoints, the truth and the fused pose in the site; below, the fused
 * pose's error at every control tick (judged at the truth's resolution),
 * the frames' cut shaded and the push marked.
 *
 *   if (sim_plot_write("sim.png", &run, "make sim: ...") != 0) ...  // one line printed */
#ifndef SIM_PLOT_H
#define SIM_PLOT_H

#include "sim_report.h"

/* 0, or -1 with one line on stderr naming the file (nothing left there) */
int sim_plot_write(const char *path, const sim_run *r, const char *title);

#endif
