/* render_path: the robot's drives under the fixed 6 x 5 site
 * (ringloc-render --path): straight across it, a rectangle, a circle, and
 * a survey drive back and forth over the whole site, weaving. Pose k of n
 * is where the robot is at fraction k / (n - 1) of the drive (a closed
 * drive stops one step short of its start).
 *
 *   double x, y, yaw;
 *   if (render_path_pose("rect", 3, 16, &x, &y, &yaw) == 0)
 *       use(x, y, yaw);
 */
#ifndef RENDER_PATH_H
#define RENDER_PATH_H

/* Pose k of n of drive kind (metres, radians in -pi .. pi); -1 for an
 * unknown kind. */
int render_path_pose(const char *kind, double k, int n, double *x, double *y, double *yaw);

#endif
