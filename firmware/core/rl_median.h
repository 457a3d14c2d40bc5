/* rl_median: the median of a few values (internal).
 *
 *   double v[3] = {3, 1, 2};
 *   double m = rl_median(v, 3);   // 2; v is now sorted
 */
#ifndef RL_MEDIAN_H
#define RL_MEDIAN_H

/* Sort v[0..n) ascending in place (insertion sort: a few dozen values at
 * most) and return v[n / 2], the upper median; 0 when n <= 0. */
double rl_median(double *v, int n);

#endif
