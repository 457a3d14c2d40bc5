/* rl_shape: the ellipse a round landmark projects to (rl_shape.h). */
#include <math.h>
#include "rl_shape.h"

rl_shape rl_shape_circle(void)
{
    rl_shape s;
    s.a = s.c = 1.0;
    s.b = 0.0;
    return s;
}

int rl_shape_is_circle(const rl_shape *s)
{
    return s->a == 1.0 && s->b == 0.0 && s->c == 1.0;
}

rl_shape rl_shape_from_moments(double cxx, double cxy, double cyy)
{
    double det = cxx * cyy - cxy * cxy, tr = cxx + cyy, disc, l1, l2, root;
    rl_shape s = rl_shape_circle();
    if (!(det > 0) || !(tr > 0))
        return s;
    disc = sqrt(fmax(0.0, 0.25 * tr * tr - det));
    l1 = 0.5 * tr + disc;
    l2 = 0.5 * tr - disc;
    if (!(l2 > 0) || sqrt(l2 / l1) > 0.97)
        return s;
    /* the inverse covariance, scaled to determinant 1 */
    root = sqrt(det);
    s.a = cyy / root;
    s.b = -cxy / root;
    s.c = cxx / root;
    return s;
}

double rl_shape_step(const rl_shape *sh, double c, double s)
{
    return 1.0 / sqrt(sh->a * c * c + 2 * sh->b * c * s + sh->c * s * s);
}
