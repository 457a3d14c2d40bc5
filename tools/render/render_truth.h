/* render_truth: what a frame shows, written beside it (NAME.yaml): the
 * camera and robot pose, and for every landmark in view its id, place,
 * projected centre and radius, the fraction of it the camera sees (inside
 * the image, not under a light) and its gap to the nearest light; then
 * the frame's looks. Written to a temporary file and renamed.
 *
 *   if (render_truth_write("out/clean_000.yaml", "clean_000.png", &s, 4.1, 3.2, 0.7) != 0)
 *       use(1);                                // the error line is printed
 */
#ifndef RENDER_TRUTH_H
#define RENDER_TRUTH_H

#include "render_scene.h"

/* 0, or -1 with one line on stderr naming the file. */
int render_truth_write(const char *path, const char *image, const render_scene *s, double rx, double ry,
                       double ryaw);

#endif
