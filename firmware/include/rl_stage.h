/* rl_stage: the recognizer's stages, in the order a frame runs through
 * them, named once for the code and for whoever times them.
 *
 * The core knows no clock. A caller that wants the cost of each stage puts
 * a hook in rl_recog_config.stage_hook: the recognizer calls it as each
 * stage begins (and with RL_STAGE_DONE when the frame is read), so the
 * time between two calls belongs to the stage named by the first. Two
 * stages come back: the local pass resumes after each read across the
 * motion, and the tone reads' zone twins' check runs after the local pass;
 * a frame with nothing dark ends after the histogram. The pose and the
 * place are the caller's own calls, timed by it under the same names.
 * A frame read by tracking windows (rl_track_read) runs the window
 * stages, each window's in their order, then the frame's, and ends with
 * RL_STAGE_DONE too; a frame it then reads in full runs the frame's
 * stages after that. (The plan, rl_track_plan, runs before the hook's
 * first call.)
 *
 *   rl_recog_defaults(&cfg);                   // no hook: no calls
 *   cfg.stage_hook.ctx = &res;                 // whatever the hook keeps its times in
 *   cfg.stage_hook.enter = NULL;               // a void (*)(void *ctx, rl_stage) that reads a clock
 *   rl_stage_enter(&cfg.stage_hook, RL_STAGE_HIST);
 *   use(rl_stage_name(RL_STAGE_LOCAL));        // "local pass"
 */
#ifndef RL_STAGE_H
#define RL_STAGE_H

#include <stddef.h>

typedef enum {
    RL_STAGE_HIST = 0, /* histogram analysis: levels, light sources */
    RL_STAGE_LABEL,    /* the ceiling's light across the frame, dark regions labelled */
    RL_STAGE_CLR,      /* candidate landmark regions; regions marked for second labellings */
    RL_STAGE_GLOBAL,   /* global pass: the candidates read through the frame's tone curve */
    RL_STAGE_TONES,    /* while the curve is open: the candidates read through the other
                          curve */
    RL_STAGE_SECOND,   /* second labellings of the marked tiles, their new candidates read */
    RL_STAGE_LOCAL,    /* local pass: candidates near lights or cut by the border */
    RL_STAGE_ACROSS,   /* reads across the motion (within the local pass) */
    RL_STAGE_TWINS,    /* landmarks not clear of their zone twins read through the other
                          image formation (rl_twins.h) */
    RL_STAGE_POSE,     /* the pose from the frame's landmarks (the caller's) */
    RL_STAGE_PLACE,    /* the place on a map that repeats ids (the caller's) */
    /* a frame read by tracking windows (rl_track_read), window by window: */
    RL_STAGE_WIN_CENTRE,  /* a window's centre drawn to its ink, or fitted to its edge by the border */
    RL_STAGE_WIN_PROFILE, /* its profile gathered */
    RL_STAGE_WIN_ID,      /* its id judged: its own columns, its rivals or every id, the ring's edge */
    RL_STAGE_WIN_TWINS,   /* its zone twins held against it at every radius */
    RL_STAGE_WIN_RING,    /* not a code ring of a larger landmark (rl_inner_enclosed) */
    RL_STAGE_WIN_COSTLY,  /* a window verification did not take: its edge, box and local reads
                             (the local reads' own stages inside) */
    RL_STAGE_WIN_FRAME,   /* the frame's zone twins' check and the rest of the frame's reads */
    RL_STAGE_DONE         /* not a stage: the count, and the call that ends a frame */
} rl_stage;

typedef struct {
    void (*enter)(void *ctx, rl_stage stage); /* NULL (default): no calls */
    void *ctx;
} rl_stage_hook;

/* The stage's name ("histogram", "local pass"...), "?" for none. */
const char *rl_stage_name(rl_stage stage);

/* Call hook's enter with stage, when it has one. */
static inline void rl_stage_enter(const rl_stage_hook *hook, rl_stage stage)
{
    if (hook->enter != NULL)
        hook->enter(hook->ctx, stage);
}

#endif
