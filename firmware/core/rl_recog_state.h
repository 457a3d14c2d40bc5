/* rl_recog_state: what a recognizer holds between frames (internal: the
 * public header keeps rl_recog opaque).
 *
 * A header of its own, below every pass: the passes (rl_global, rl_local,
 * rl_locate, rl_twins) include it, and rl_recog.c, the hub above them
 * that runs them in the order of rl_stage.h, includes theirs; nothing
 * below the hub calls into it.
 *
 * It lives at the start of the caller's block; every array it points to
 * follows it in the same block, carved by the one layout sequence that
 * rl_recog_workspace_size also runs.
 *
 *   const struct rl_recog *rec = NULL;
 *   if (rec != NULL)
 *       use(rec->width, rec->templates.n, rec->dark.n_regions);
 */
#ifndef RL_RECOG_STATE_H
#define RL_RECOG_STATE_H

#include "rl_illum.h"
#include "rl_label.h"
#include "rl_match.h"
#include "rl_polar.h"
#include "rl_recog.h"
#include "rl_rivals.h"
#include "rl_split.h"
#include "rl_templates.h"
#include "rl_tones.h"

/* A CLR's centre as the global pass placed it (rl_recog.placed). */
typedef struct {
    double u, v;
    int read; /* -1: no read (inner, or cut by the border), 0: not identified, 1: identified */
} rl_recog_placed;

struct rl_recog {
    rl_recog_config cfg;
    int width, height;
    int ids[RL_MAX_IDS]; /* copy of cfg.ids */
    rl_templates templates;        /* rendered at init */
    rl_rivals rivals;    /* each id's rivals, for a known window's read (rl_verify) */
    rl_profile_scale verify_scales[5]; /* the radii a window's profile is read at (rl_verify_init) */
    rl_profile_scale led_scale; /* where a clear global read's twins are met (rl_twins_led_init) */
    rl_tones tones; /* the camera's tone curve, configured or learned */
    const rl_tone *tone; /* the one this frame is read through (in tones) */
    rl_label dark;  /* ROI labelling: the frame, its second labellings (rl_split), then the
                       local pass's windows */
    rl_label light; /* light-source labelling */
    rl_illum illum; /* the ceiling's light across the frame: per-tile thresholds */
    rl_split split; /* the second labellings' thresholds */
    rl_polar *polar;/* a local-pass candidate in polar cells */
    rl_match_kept *kept; /* a local-pass match's column sums, for the ids one zone away and its twins (rl_search, rl_local) */
    /* the frame's CLRs as the global pass read them, for the tone reads:
     * each centre as placed (rl_global_read_placed), and whether a curve
     * may identify it (an outer CLR, rl_global_readable) and did;
     * RL_MAX_CANDIDATES */
    rl_recog_placed *placed;
};

#endif
