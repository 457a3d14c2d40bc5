/* rl_offsetsfile: the paper's pixel-to-offset polynomials, as YAML.
 *
 *   type: ringloc_offsets
 *   degree: 2
 *   u0: 319.5, v0: 239.5, scale: 320     # pixel normalization
 *   distance: 1.870                      # camera to ceiling at calibration, m
 *   forward: [c0, c1, ...]               # forward offset = sum c_i t_i(u, v)
 *   left: [c0, c1, ...]
 *
 *   rl_offsets o;
 *   char err[256];
 *   if (rl_offsetsfile_load("offsets.yaml", &o, err, sizeof err) == RL_OK)
 *       use(o.degree);
 */
#ifndef RL_OFFSETSFILE_H
#define RL_OFFSETSFILE_H

#include <stddef.h>
#include "rl_pose.h"

RL_CHECK rl_err rl_offsetsfile_load(const char *path, rl_offsets *o, char *err, size_t errlen);
RL_CHECK rl_err rl_offsetsfile_save(const char *path, const rl_offsets *o, char *err,
                                    size_t errlen);

/* Least-squares fit of o's coefficients (degree, u0, v0, scale set by the
 * caller) to n pixel -> (forward, left) samples. RL_ETOOFEW with fewer
 * samples than terms + 2; RL_ERANGE for a singular layout. */
RL_CHECK rl_err rl_offsets_fit(rl_offsets *o, const double *u, const double *v,
                               const double *fwd, const double *left, int n);

#endif
