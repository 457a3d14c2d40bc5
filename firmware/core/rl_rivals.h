/* rl_rivals: for each id, the ids whose landmark its templates can
 * score high on (internal).
 *
 * A tracked window over a landmark the track already knows verifies
 * only the expected id (rl_verify): it is taken when its templates score
 * at least RL_RIVALS_TAKEN on the window's profile and it leads, by the
 * global rule, the ids listed here for it; every other id is not scored.
 * That refuses another landmark in the window only if no id left out can
 * lift the expected id's score that high. So an id's rivals are its zone
 * twins (one zone apart: a blurred twin scores up to 0.999) and every id
 * on whose landmark the expected id's templates score RL_RIVALS_MIN or
 * more: the landmark modelled as its own templates at every blur, read
 * through tone curves 1, 2.2 and the inverse of 2.2, at its radius and
 * 5% and 10% either side (a prediction a few percent off, then the read's
 * own 5% search), over a uniform disk's pixels. Worked out once at init;
 * docs/tracking.md (eleventh session) has the table and its margin.
 *
 * Not the zone twins' check's rivals (rl_twins: the ids one zone apart
 * a read is compared with) nor the rank read's (design.md): these are
 * the ids a known window is matched against instead of every id.
 *
 *   rl_rivals rv;
 *   int ids[RL_MAX_IDS], n;
 *   if (rl_rivals_init(&rv, &ws, &tt) == RL_OK && rl_rivals_ready(&rv))
 *       n = rl_rivals_of(&rv, &tt, 17, ids);   // id 17's rivals
 */
#ifndef RL_RIVALS_H
#define RL_RIVALS_H

#include "rl_error.h"
#include "rl_templates.h"
#include "rl_workspace.h"

/* An id left out of the rivals scores under this on another landmark. */
#define RL_RIVALS_MIN 0.90
/* The expected id's score a known window's read needs (the margin over
 * RL_RIVALS_MIN: what the model leaves out, a gather from every third
 * row, noise, a rescaled rim). */
#define RL_RIVALS_TAKEN 0.94
/* Tables with more ids than this are not worked out (n^2 profiles): no
 * rivals, every window matches every id. */
#define RL_RIVALS_MAX_IDS 64

typedef struct {
    int n;               /* ids of the templates, 0: not worked out */
    unsigned char *near; /* n x n: near[i * n + j] 1 when ids[j] is a rival of ids[i] */
} rl_rivals;

/* Work out the rivals of every id of tt (rl_templates_init first) into
 * ws (n^2 bytes; nothing past RL_RIVALS_MAX_IDS ids). RL_ENOMEM when ws
 * is too small. */
RL_CHECK rl_err rl_rivals_init(rl_rivals *rv, rl_ws *ws, const rl_templates *tt);

/* No rivals (rl_rivals_ready 0: every id is matched); RL_OK. */
rl_err rl_rivals_none(rl_rivals *rv);

/* 1 when the rivals were worked out (rl_rivals_of answers). */
int rl_rivals_ready(const rl_rivals *rv);

/* The rivals of id into out (at most tt->n - 1); their count; -1 when
 * they were not worked out or tt does not hold id. */
int rl_rivals_of(const rl_rivals *rv, const rl_templates *tt, int id, int *out);

#endif
