#include "rl_module.h"
#include "rl_survey.h"
#include "rl_survey_ceres.h"

/* The adjustment, from its module (Ceres Solver) on first use. */

static const rl_module module = RL_SURVEY_CERES_MODULE;

rl_err rl_survey_solver_check(char *err, size_t errlen)
{
    void (*fn)(void);
    return rl_module_symbol(&module, "rl_survey_adjust_ceres", &fn, err, errlen);
}

rl_err rl_survey_adjust(rl_survey *sv)
{
    void (*fn)(void);
    rl_survey_adjust_fn adjust;
    rl_err e = rl_module_symbol(&module, "rl_survey_adjust_ceres", &fn, sv->err, sizeof sv->err);
    if (e != RL_OK)
        return e;
    adjust = (rl_survey_adjust_fn)fn;
    return adjust(sv);
}
