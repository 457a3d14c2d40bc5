/* bench_stats: the benchmarks' one median (sorts v in place; 0 for none).
 *
 *   double t[3] = {3.0, 1.0, 2.0};
 *   use(rl_bench_median(t, 3));   // 2.0
 */
#ifndef BENCH_STATS_H
#define BENCH_STATS_H

double rl_bench_median(double *v, int n);

#endif
