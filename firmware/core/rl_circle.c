#include "rl_circle.h"

#include <math.h>
#include <string.h>

void rl_circle_clear(rl_circle_fit *f)
{
    memset(f, 0, sizeof *f);
}

void rl_circle_add(rl_circle_fit *f, double x, double y)
{
    double v[3];
    int k, m;
    v[0] = x;
    v[1] = y;
    v[2] = 1.0;
    for (k = 0; k < 3; k++) {
        for (m = 0; m < 3; m++)
            f->s[k][m] += v[k] * v[m];
        f->s[k][3] -= v[k] * (x * x + y * y);
    }
    f->n++;
}

int rl_solve3(double A[3][4], double x[3])
{
    int k, m, c;
    for (k = 0; k < 3; k++) {
        int piv = k;
        for (m = k + 1; m < 3; m++)
            if (fabs(A[m][k]) > fabs(A[piv][k]))
                piv = m;
        if (fabs(A[piv][k]) < 1e-12)
            return 0;
        for (c = 0; c < 4; c++) {
            double t = A[k][c];
            A[k][c] = A[piv][c];
            A[piv][c] = t;
        }
        for (m = k + 1; m < 3; m++) {
            double q = A[m][k] / A[k][k];
            for (c = k; c < 4; c++)
                A[m][c] -= q * A[k][c];
        }
    }
    for (k = 2; k >= 0; k--) {
        double v = A[k][3];
        for (c = k + 1; c < 3; c++)
            v -= A[k][c] * x[c];
        x[k] = v / A[k][k];
    }
    return 1;
}

int rl_circle_solve(const rl_circle_fit *f, double *cx, double *cy, double *r)
{
    double a[3], s[3][4];
    memcpy(s, f->s, sizeof s);
    if (f->n < 5 || !rl_solve3(s, a))
        return 0;
    *cx = -a[0] / 2;
    *cy = -a[1] / 2;
    *r = *cx * *cx + *cy * *cy - a[2];
    if (!(*r > 0))
        return 0;
    *r = sqrt(*r);
    return 1;
}

void rl_circle_refine(const double *x, const double *y, int n, double *cx, double *cy, double *r)
{
    double ncx = *cx, ncy = *cy, nr = *r;
    int it, i;
    for (it = 0; it < 8; it++) {
        double A[3][4] = {{0}}, step[3];
        int k, m, used = 0;
        for (i = 0; i < n; i++) {
            double dx = x[i] - ncx, dy = y[i] - ncy, d = sqrt(dx * dx + dy * dy), J[3], res;
            if (d < 1e-9 || fabs(d - nr) > 1.5)
                continue;
            J[0] = -dx / d;
            J[1] = -dy / d;
            J[2] = -1.0;
            res = d - nr;
            for (k = 0; k < 3; k++) {
                for (m = 0; m < 3; m++)
                    A[k][m] += J[k] * J[m];
                A[k][3] -= J[k] * res;
            }
            used++;
        }
        if (used < 6 || !rl_solve3(A, step))
            break;
        ncx += step[0];
        ncy += step[1];
        nr += step[2];
        if (fabs(step[0]) + fabs(step[1]) + fabs(step[2]) < 1e-3)
            break;
    }
    *cx = ncx;
    *cy = ncy;
    *r = nr;
}
