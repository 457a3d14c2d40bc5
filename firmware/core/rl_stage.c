#include "rl_stage.h"

const char *rl_stage_name(rl_stage stage)
{
    static const char *const names[RL_STAGE_DONE] = {
        "histogram", "labelling", "CLRs", "global pass", "tone reads", "second labellings",
        "local pass", "reads across motion", "zone twins", "pose", "place",
        "window centres", "window profiles", "window ids", "window twins", "window code rings",
        "window costly reads", "window frame's checks",
    };
    return (unsigned)stage < RL_STAGE_DONE ? names[stage] : "?";
}
