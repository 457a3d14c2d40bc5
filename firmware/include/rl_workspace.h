/* rl_workspace: aligned slices of one caller-provided block of memory.
 *
 * The recognition core never allocates. The caller hands it one block; the
 * core carves it into slices with rl_ws_alloc and gives them all back at
 * once with rl_ws_reset (stack discipline: a mark taken before a step can
 * be restored after it). A workspace made with rl_ws_init_sizing
 * hands out no memory but counts what would be needed, so that a size
 * function can run the same allocation sequence it will use for real.
 *
 *   static uint8_t mem[1 << 20];
 *   rl_ws ws;
 *   rl_ws_init(&ws, mem, sizeof mem);
 *   int32_t *buf;
 *   if (rl_ws_alloc(&ws, 100 * sizeof *buf, RL_WS_ALIGN, (void **)&buf) == RL_OK)
 *       buf[99] = 1;
 */
#ifndef RL_WORKSPACE_H
#define RL_WORKSPACE_H

#include <stddef.h>
#include <stdint.h>
#include "rl_error.h"

/* Alignment that suits every type the core stores (double, int64_t). */
#define RL_WS_ALIGN 16

typedef struct {
    uint8_t *base;  /* start of the caller's block; NULL when sizing */
    size_t size;    /* bytes in the block */
    size_t used;    /* offset of the first free byte */
    size_t peak;    /* most bytes ever in use (for benchmarks and sizing) */
} rl_ws;

/* Start handing out slices of mem[0..size). mem may be unaligned. */
void rl_ws_init(rl_ws *ws, void *mem, size_t size);

/* A sizing workspace: every rl_ws_alloc succeeds with *out = NULL and only
 * the peak grows. */
void rl_ws_init_sizing(rl_ws *ws);

/* 1 if this workspace only counts. */
int rl_ws_is_sizing(const rl_ws *ws);

/* Hand out `bytes` bytes aligned to `align` (a power of two) in *out.
 * RL_ENOMEM when the block is too small (ws unchanged, *out = NULL);
 * RL_EINVAL for a bad alignment. */
RL_CHECK rl_err rl_ws_alloc(rl_ws *ws, size_t bytes, size_t align, void **out);

/* Position to come back to with rl_ws_reset. */
size_t rl_ws_mark(const rl_ws *ws);

/* Give back everything handed out since `mark`. */
void rl_ws_reset(rl_ws *ws, size_t mark);

/* Bytes still free (0 when sizing). */
size_t rl_ws_remaining(const rl_ws *ws);

#endif
