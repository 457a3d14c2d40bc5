#include "rl_stage.h"

const char *rl_stage_name(rl_stage stage)
{
    static const char *const names[RL_STAGE_DONE] = {
        "histogram", "labelling", "CLRs", "global pass", "tone reads", "second labellings",
        "local pass", "reads across motion", "zone twins", "pose", "place",
    };
    return (unsigned)stage < RL_STAGE_DONE ? names[stage] : "?";
}
