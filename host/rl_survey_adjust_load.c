#include "rl_module.h"
#include "rl_survey.h"

/* The adjustment, from its module (Ceres Solver) on first use. */
rl_err rl_survey_adjust(rl_survey *sv)
{
    void (*fn)(void);
    rl_survey_adjust_fn adjust;
    rl_err e = rl_module_symbol(RL_SURVEY_CERES_MODULE, "rl_survey_adjust_ceres", &fn, sv->err,
                                sizeof sv->err);
    if (e != RL_OK)
        return e;
    adjust = (rl_survey_adjust_fn)fn;
    return adjust(sv);
}
