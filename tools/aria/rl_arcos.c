/* rl_arcos: see rl_arcos.h. */
#include <string.h>
#include "rl_arcos.h"
#include "rl_packet.h"

size_t rl_arcos_packet(uint8_t *buf, const uint8_t *payload, size_t n)
{
    uint16_t sum = rl_packet_checksum(payload, n);
    buf[0] = 0xFA;
    buf[1] = 0xFB;
    buf[2] = (uint8_t)(n + 2);
    memcpy(buf + 3, payload, n);
    buf[3 + n] = (uint8_t)(sum >> 8);
    buf[4 + n] = (uint8_t)(sum & 0xFF);
    return n + 5;
}

size_t rl_arcos_command(uint8_t *buf, int cmd)
{
    uint8_t p[1];
    p[0] = (uint8_t)cmd;
    return rl_arcos_packet(buf, p, 1);
}

size_t rl_arcos_command_int(uint8_t *buf, int cmd, int arg)
{
    uint8_t p[4];
    unsigned mag = (unsigned)(arg < 0 ? -arg : arg);
    p[0] = (uint8_t)cmd;
    p[1] = arg < 0 ? 0x1B : 0x3B;
    p[2] = (uint8_t)(mag & 0xFF);
    p[3] = (uint8_t)((mag >> 8) & 0xFF);
    return rl_arcos_packet(buf, p, 4);
}

int rl_arcos_int_arg(const uint8_t *payload, size_t n)
{
    int mag;
    if (n < 4 || (payload[1] != 0x3B && payload[1] != 0x1B))
        return 0;
    mag = payload[2] | (payload[3] << 8);
    return payload[1] == 0x1B ? -mag : mag;
}

void rl_arcos_reader_init(rl_arcos_reader *r)
{
    memset(r, 0, sizeof *r);
}

/* drop the first byte held and look for a header again in the rest */
static void resync(rl_arcos_reader *r)
{
    size_t i;
    for (i = 1; i < r->len; i++)
        if (r->buf[i] == 0xFA)
            break;
    memmove(r->buf, r->buf + i, r->len - i);
    r->len -= i;
}

int rl_arcos_reader_push(rl_arcos_reader *r, uint8_t byte, uint8_t *payload, size_t *n)
{
    size_t count;
    r->buf[r->len++] = byte;
    if (r->buf[0] != 0xFA) {
        resync(r);
        return 0;
    }
    if (r->len < 3)
        return 0;
    if (r->buf[1] != 0xFB || r->buf[2] < 3 || r->buf[2] > RL_ARCOS_MAX - 3) {
        r->bad += r->buf[1] == 0xFB;
        resync(r);
        return 0;
    }
    count = r->buf[2];
    if (r->len < 3 + count)
        return 0;
    if (rl_packet_checksum(r->buf + 3, count - 2) ==
        (uint16_t)((r->buf[1 + count] << 8) | r->buf[2 + count])) {
        *n = count - 2;
        memcpy(payload, r->buf + 3, *n);
        r->len = 0;
        return 1;
    }
    r->bad++;
    resync(r);
    return 0;
}
