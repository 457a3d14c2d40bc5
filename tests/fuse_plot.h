/* fuse_plot: the picture of one fused drive (PNG, cairo): the path from
 * above (truth, reset-on-arrival, fused), then the x and y errors over
 * time, reset-on-arrival beside the fused pose and its 3-sigma band, the
 * stretch without landmarks shaded.
 *
 *   static fs_result r;
 *   if (fuse_plot_write("fuse.png", &r, "circle, 1 m/s") != 0)
 *       fprintf(stderr, "fuse.png: not written\n");
 */
#ifndef FUSE_PLOT_H
#define FUSE_PLOT_H

#include "fuse_sim.h"

/* 0, or -1 with a line on stderr naming the file */
int fuse_plot_write(const char *path, const fs_result *r, const char *title);

#endif
