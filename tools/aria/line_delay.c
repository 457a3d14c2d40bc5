/* line_delay: see line_delay.h. */
#include "line_delay.h"
#include <math.h>
#include <string.h>
#include <unistd.h>

void line_delay_init(line_delay *q)
{
    memset(q, 0, sizeof *q);
}

int line_delay_push(line_delay *q, const uint8_t *pkt, size_t n, double when, double line_time)
{
    if (q->n >= LINE_DELAY_QUEUE || n > RL_ARCOS_MAX) {
        q->dropped++;
        return 0;
    }
    memcpy(q->pkt[q->n], pkt, n);
    q->len[q->n] = n;
    /* a line keeps its order: no packet overtakes the one ahead */
    q->when[q->n] = q->last = fmax(when, q->last + line_time);
    q->n++;
    return 1;
}

void line_delay_due(line_delay *q, int fd, double now)
{
    while (q->n > 0 && q->when[0] <= now) {
        if (write(fd, q->pkt[0], q->len[0]) == (ssize_t)q->len[0])
            q->sent++;
        else
            q->dropped++; /* no reader yet: the pty's buffer is full */
        q->n--;
        memmove(q->pkt[0], q->pkt[1], (size_t)q->n * sizeof q->pkt[0]);
        memmove(q->len, q->len + 1, (size_t)q->n * sizeof q->len[0]);
        memmove(q->when, q->when + 1, (size_t)q->n * sizeof q->when[0]);
    }
}
