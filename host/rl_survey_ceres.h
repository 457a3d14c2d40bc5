/* The survey's solver module (ringloc-ceres.so, built from
 * rl_survey_adjust.cpp with Ceres Solver): its entry point, which
 * rl_survey_adjust (rl_survey_adjust_load.c) loads on first use. Nothing
 * else of the module is visible.
 *
 *   static rl_survey sv;
 *   if (rl_survey_adjust_ceres(&sv) == RL_OK)   // in the module
 *       use(sv.n_lm);
 */
#ifndef RL_SURVEY_CERES_H
#define RL_SURVEY_CERES_H

#include "rl_module.h"
#include "rl_survey.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RL_SURVEY_CERES_ABI RL_MODULE_ABI(sizeof(rl_survey), sizeof(rl_survey_config))
#define RL_SURVEY_CERES_MODULE                                                                            \
    {"ringloc-ceres.so", "the survey's solver (package ringloc-tools)", RL_SURVEY_CERES_ABI}

RL_MODULE_EXPORT unsigned long rl_module_abi(void);
RL_MODULE_EXPORT rl_err rl_survey_adjust_ceres(rl_survey *sv);

#ifdef __cplusplus
}
#endif

#endif
