#include "rl_workspace.h"

void rl_ws_init(rl_ws *ws, void *mem, size_t size)
{
    ws->base = (uint8_t *)mem;
    ws->size = mem != NULL ? size : 0;
    ws->used = 0;
    ws->peak = 0;
}

void rl_ws_init_sizing(rl_ws *ws)
{
    ws->base = NULL;
    ws->size = (size_t)-1;
    ws->used = 0;
    ws->peak = 0;
}

int rl_ws_is_sizing(const rl_ws *ws)
{
    return ws->base == NULL && ws->size == (size_t)-1;
}

rl_err rl_ws_alloc(rl_ws *ws, size_t bytes, size_t align, void **out)
{
    size_t start, pad;
    if (out == NULL)
        return RL_EINVAL;
    *out = NULL;
    if (align == 0 || (align & (align - 1)) != 0)
        return RL_EINVAL;
    if (rl_ws_is_sizing(ws)) {
        /* Assume the worst padding so that a real block of the counted size
         * always suffices whatever its own alignment. */
        ws->used += bytes + align - 1;
        if (ws->used > ws->peak)
            ws->peak = ws->used;
        return RL_OK;
    }
    /* Align the address, not the offset: the block itself may be unaligned. */
    pad = (size_t)(-(uintptr_t)(ws->base + ws->used)) & (align - 1);
    start = ws->used + pad;
    if (start < ws->used || start > ws->size || bytes > ws->size - start)
        return RL_ENOMEM;
    ws->used = start + bytes;
    if (ws->used > ws->peak)
        ws->peak = ws->used;
    *out = ws->base + start;
    return RL_OK;
}

size_t rl_ws_mark(const rl_ws *ws)
{
    return ws->used;
}

void rl_ws_reset(rl_ws *ws, size_t mark)
{
    if (mark <= ws->used)
        ws->used = mark;
}

size_t rl_ws_remaining(const rl_ws *ws)
{
    return rl_ws_is_sizing(ws) ? 0 : ws->size - ws->used;
}
