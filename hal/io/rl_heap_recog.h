/* rl_heap_recog: a recognizer whose workspace comes from the heap, made
 * for the size of the frames it is given (re-made when that changes).
 * The one place where recognizers are set up, for the firmware and the
 * host tools alike.
 *
 *   rl_recog_config cfg;
 *   rl_heap_recog hr;
 *   rl_recog_defaults(&cfg);
 *   rl_heap_recog_init(&hr, &cfg);
 *   if (rl_heap_recog_run(&hr, &img, &res) == RL_OK)
 *       use(res.n_landmarks, res.landmarks);
 *   rl_heap_recog_free(&hr);
 */
#ifndef RL_HEAP_RECOG_H
#define RL_HEAP_RECOG_H

#include <stddef.h>
#include "rl_recog.h"

typedef struct {
    rl_recog_config cfg;
    int ids[RL_MAX_IDS]; /* copy of cfg.ids */
    rl_recog *rec;                 /* NULL until prepared */
    void *mem;
    size_t size;
    int width, height;             /* size rec is ready for; 0 before */
} rl_heap_recog;

/* Keep a copy of cfg (and of its ids, clipped to RL_MAX_IDS:
 * rl_recog_init refuses more); nothing is allocated yet. */
void rl_heap_recog_init(rl_heap_recog *hr, const rl_recog_config *cfg);

/* The same for a map's landmarks: family and ids from it. */
void rl_heap_recog_init_map(rl_heap_recog *hr, const rl_recog_config *cfg, const rl_map *map);

/* Make the recognizer for w x h frames unless it is ready for them.
 * RL_ENOMEM, or rl_recog_init's error for the configuration. */
RL_CHECK rl_err rl_heap_recog_prepare(rl_heap_recog *hr, int w, int h);

/* Prepare for img's size, then recognize it. */
RL_CHECK rl_err rl_heap_recog_run(rl_heap_recog *hr, const rl_image *img, rl_result *res);

void rl_heap_recog_free(rl_heap_recog *hr);

#endif
