#include "rl_median.h"

double rl_median(double *v, int n)
{
    int i, j;
    if (n <= 0)
        return 0.0;
    for (i = 1; i < n; i++) {
        double t = v[i];
        for (j = i; j > 0 && v[j - 1] > t; j--)
            v[j] = v[j - 1];
        v[j] = t;
    }
    return v[n / 2];
}
