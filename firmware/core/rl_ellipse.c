#include "rl_ellipse.h"

#include <math.h>
#include "rl_circle.h"

int rl_ellipse_fit(const double *x, const double *y, int n, double gx, double gy, double gr,
                   rl_ellipse *e)
{
    double A[5][6] = {{0}}, q[5], det, x0, y0, f, m11, m12, m22, k;
    int i, a, b;
    if (n < 6 || !(gr > 0))
        return 0;
    for (i = 0; i < n; i++) {
        double u = (x[i] - gx) / gr, v = (y[i] - gy) / gr, row[5];
        row[0] = u * u;
        row[1] = u * v;
        row[2] = v * v;
        row[3] = u;
        row[4] = v;
        for (a = 0; a < 5; a++) {
            for (b = 0; b < 5; b++)
                A[a][b] += row[a] * row[b];
            A[a][5] += row[a];
        }
    }
    if (!rl_solve(5, &A[0][0], q))
        return 0;
    /* A u^2 + B uv + C v^2 + D u + E v = 1: centre where the gradient is 0 */
    det = 4 * q[0] * q[2] - q[1] * q[1];
    if (!(det > 0))
        return 0;
    x0 = (q[1] * q[4] - 2 * q[2] * q[3]) / det;
    y0 = (q[1] * q[3] - 2 * q[0] * q[4]) / det;
    /* about the centre: [u v] M [u v]^T = 1 with M = Q / -f */
    f = q[0] * x0 * x0 + q[1] * x0 * y0 + q[2] * y0 * y0 + q[3] * x0 + q[4] * y0 - 1.0;
    if (!(f < 0) || !(q[0] > 0))
        return 0;
    m11 = q[0] / -f;
    m12 = 0.5 * q[1] / -f;
    m22 = q[2] / -f;
    k = sqrt(m11 * m22 - m12 * m12); /* the ellipse's area is pi / k */
    e->cx = gx + gr * x0;
    e->cy = gy + gr * y0;
    e->r = gr / sqrt(k);
    e->shape.a = m11 / k;
    e->shape.b = m12 / k;
    e->shape.c = m22 / k;
    return 1;
}

double rl_ellipse_aspect(const rl_shape *sh)
{
    /* the eigenvalues of the shape's matrix (determinant 1) are l and 1 / l;
     * the axes go as their inverse square roots */
    double tr = sh->a + sh->c, disc = sqrt(fmax(0.0, 0.25 * tr * tr - 1.0));
    double hi = 0.5 * tr + disc;
    return 1.0 / hi; /* sqrt(lo / hi) with lo = 1 / hi */
}
