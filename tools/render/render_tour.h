/* render_tour: robot poses over a large site's map (ringloc-render
 * --site-map): uniformly random ones, and a drive (a "tour") that wanders
 * over the whole site at a steady speed, steering away from its edges,
 * and is carried elsewhere halfway (a kidnapped robot). Deterministic
 * from the seed; independent of the frames' random numbers.
 *
 *   render_area a = {0.3, 0.3, 59.7, 39.7};
 *   render_pose p[300];
 *   render_tour(&a, 7, 300, 0.1, p);   // 0.1 m per frame
 *   use(p[150].x, p[150].jumped);       // where it was carried
 */
#ifndef RENDER_TOUR_H
#define RENDER_TOUR_H

typedef struct {
    double x0, y0, x1, y1; /* where the robot may be, m */
} render_area;

typedef struct {
    double x, y, yaw;
    int jumped; /* 1: carried here from the previous frame's place */
} render_pose;

/* n random poses, uniform over the area and in heading. */
void render_random_poses(const render_area *a, unsigned long seed, int n, render_pose *out);

/* n poses of a drive, step metres apart, carried to a random place at n / 2. */
void render_tour(const render_area *a, unsigned long seed, int n, double step, render_pose *out);

/* n poses of a drive past the site's edge, step metres apart: from 1 m
 * inside its lower edge (y0) out to 0.75 m beyond it, then along it
 * weaving, so that frames show one row of two to four landmarks. */
void render_edge(const render_area *a, unsigned long seed, int n, double step, render_pose *out);

/* n poses of a drive round the site's lower right corner, step metres
 * apart: from 1 m inside its lower edge out to 0.75 m beyond it, along it
 * weaving, then round the corner and up 0.75 m beyond the right edge (x1):
 * one row in view, then the corner taken briskly (up to 0.8 rad a frame). */
void render_corner(const render_area *a, unsigned long seed, int n, double step, render_pose *out);

#endif
