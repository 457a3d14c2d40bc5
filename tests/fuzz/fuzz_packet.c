/* The frame decoder on arbitrary bytes, and encode -> decode of whatever
 * it accepts: the same message back. */
#include <stdlib.h>
#include <string.h>
#include "rl_packet.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rl_decoder d, d2;
    rl_msg m, back;
    uint8_t buf[RL_PACKET_MAX];
    size_t i, k, n;
    rl_decoder_init(&d);
    for (i = 0; i < size; i++) {
        if (!rl_decoder_push(&d, data[i], &m))
            continue;
        n = rl_packet_encode(&m, buf);
        if (n == 0 || n > RL_PACKET_MAX)
            abort();
        rl_decoder_init(&d2);
        for (k = 0; k < n; k++)
            if (rl_decoder_push(&d2, buf[k], &back))
                break;
        if (k != n - 1 || back.type != m.type || back.seq != m.seq)
            abort();
    }
    return 0;
}
