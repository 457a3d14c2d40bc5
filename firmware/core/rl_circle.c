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

int rl_solve(int n, double *A, double *x)
{
    int k, m, c, w = n + 1;
    for (k = 0; k < n; k++) {
        int piv = k;
        for (m = k + 1; m < n; m++)
            if (fabs(A[m * w + k]) > fabs(A[piv * w + k]))
                piv = m;
        if (fabs(A[piv * w + k]) < 1e-12)
            return 0;
        for (c = 0; c < w; c++) {
            double t = A[k * w + c];
            A[k * w + c] = A[piv * w + c];
            A[piv * w + c] = t;
        }
        for (m = k + 1; m < n; m++) {
            double q = A[m * w + k] / A[k * w + k];
            for (c = k; c < w; c++)
                A[m * w + c] -= q * A[k * w + c];
        }
    }
    for (k = n - 1; k >= 0; k--) {
        double v = A[k * w + n];
        for (c = k + 1; c < n; c++)
            v -= A[k * w + c] * x[c];
        x[k] = v / A[k * w + k];
    }
    return 1;
}

int rl_solve3(double A[3][4], double x[3])
{
    return rl_solve(3, &A[0][0], x);
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
