#include "rl_packet.h"

#include <string.h>

uint16_t rl_packet_checksum(const uint8_t *p, size_t n)
{
    uint32_t sum = 0;
    size_t i;
    for (i = 0; i + 1 < n; i += 2)
        sum = (sum + ((uint32_t)p[i] << 8 | p[i + 1])) & 0xFFFFu;
    if (n & 1)
        sum ^= p[n - 1];
    return (uint16_t)sum;
}

static void put16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static void put32(uint8_t *p, uint32_t v)
{
    put16(p, (uint16_t)v);
    put16(p + 2, (uint16_t)(v >> 16));
}

static uint16_t get16(const uint8_t *p)
{
    return (uint16_t)(p[0] | p[1] << 8);
}

static uint32_t get32(const uint8_t *p)
{
    return get16(p) | (uint32_t)get16(p + 2) << 16;
}

size_t rl_packet_encode(const rl_msg *m, uint8_t *buf)
{
    uint8_t *pl = buf + 3;
    int v1 = m->type == RL_PACKET_POSE && m->version == 1;
    size_t n = m->type == RL_PACKET_POSE ? (v1 ? RL_POSE_V1_PAYLOAD : RL_POSE_PAYLOAD) : RL_STATUS_PAYLOAD;
    uint16_t sum;
    buf[0] = 0xFA;
    buf[1] = 0xFB;
    buf[2] = (uint8_t)(n + 2);
    memset(pl, 0, n);
    pl[0] = m->type == RL_PACKET_POSE ? RL_PACKET_POSE : RL_PACKET_STATUS;
    pl[1] = m->type == RL_PACKET_POSE && !v1 ? RL_PACKET_VERSION : 1;
    put16(pl + 2, m->seq);
    put32(pl + 4, m->time_ms);
    if (m->type == RL_PACKET_POSE) {
        put32(pl + 8, (uint32_t)m->x_mm);
        put32(pl + 12, (uint32_t)m->y_mm);
        put16(pl + 16, (uint16_t)m->yaw_e4);
        pl[18] = m->used;
        pl[19] = m->flags;
        put16(pl + 20, m->residual_e4);
        put16(pl + 22, m->latency_e4);
        if (!v1) {
            put16(pl + 24, m->sigma_x_e4);
            put16(pl + 26, m->sigma_y_e4);
            put16(pl + 28, m->sigma_yaw_e4);
            put16(pl + 30, (uint16_t)m->roll_e4);
            put16(pl + 32, (uint16_t)m->pitch_e4);
        }
    } else {
        pl[8] = m->reason;
        pl[9] = m->identified;
        pl[10] = m->candidates;
    }
    sum = rl_packet_checksum(pl, n);
    pl[n] = (uint8_t)(sum >> 8);
    pl[n + 1] = (uint8_t)sum;
    return n + 5;
}

void rl_decoder_init(rl_decoder *d)
{
    d->len = 0;
    d->bad = 0;
}

/* A held prefix that failed: drop its first byte and look for the next
 * header inside what is held, so a frame that starts within garbage is
 * still found. */
static void resync(rl_decoder *d)
{
    size_t i;
    for (i = 1; i < d->len; i++)
        if (d->buf[i] == 0xFA && (i + 1 == d->len || d->buf[i + 1] == 0xFB))
            break;
    memmove(d->buf, d->buf + i, d->len - i);
    d->len -= i;
}

/* Check the held bytes as far as they go: 0 ok so far, -1 invalid. */
static int plausible(const rl_decoder *d)
{
    if (d->len >= 1 && d->buf[0] != 0xFA)
        return -1;
    if (d->len >= 2 && d->buf[1] != 0xFB)
        return -1;
    if (d->len >= 3 && d->buf[2] != RL_POSE_PAYLOAD + 2 && d->buf[2] != RL_POSE_V1_PAYLOAD + 2 &&
        d->buf[2] != RL_STATUS_PAYLOAD + 2)
        return -1;
    if (d->len >= 4) {
        uint8_t want = d->buf[2] == RL_STATUS_PAYLOAD + 2 ? RL_PACKET_STATUS : RL_PACKET_POSE;
        if (d->buf[3] != want)
            return -1;
    }
    /* the count says the version: 36 a version 2 pose, 26 version 1 */
    if (d->len >= 5 && d->buf[4] != (d->buf[2] == RL_POSE_PAYLOAD + 2 ? RL_PACKET_VERSION : 1))
        return -1;
    return 0;
}

int rl_decoder_push(rl_decoder *d, uint8_t byte, rl_msg *m)
{
    d->buf[d->len++] = byte;
    for (;;) {
        const uint8_t *pl;
        size_t total, n;
        uint16_t sum;
        while (d->len > 0 && plausible(d) != 0) {
            if (d->len > 2)
                d->bad++;
            resync(d);
        }
        if (d->len < 3)
            return 0;
        total = (size_t)d->buf[2] + 3;
        if (d->len < total)
            return 0;
        pl = d->buf + 3;
        n = total - 5;
        sum = rl_packet_checksum(pl, n);
        if (pl[n] != (uint8_t)(sum >> 8) || pl[n + 1] != (uint8_t)sum) {
            /* not a frame: the next one may start inside what is held */
            d->bad++;
            resync(d);
            continue;
        }
        memset(m, 0, sizeof *m);
        m->type = pl[0];
        m->seq = get16(pl + 2);
        m->time_ms = get32(pl + 4);
        if (m->type == RL_PACKET_POSE) {
            m->x_mm = (int32_t)get32(pl + 8);
            m->y_mm = (int32_t)get32(pl + 12);
            m->yaw_e4 = (int16_t)get16(pl + 16);
            m->used = pl[18];
            m->flags = pl[19];
            m->residual_e4 = get16(pl + 20);
            m->latency_e4 = get16(pl + 22);
            m->version = pl[1];
            if (m->version == RL_PACKET_VERSION) {
                m->sigma_x_e4 = get16(pl + 24);
                m->sigma_y_e4 = get16(pl + 26);
                m->sigma_yaw_e4 = get16(pl + 28);
                m->roll_e4 = (int16_t)get16(pl + 30);
                m->pitch_e4 = (int16_t)get16(pl + 32);
            }
        } else {
            m->reason = pl[8];
            m->identified = pl[9];
            m->candidates = pl[10];
        }
        /* keep what follows the frame: the start of the next one */
        memmove(d->buf, d->buf + total, d->len - total);
        d->len -= total;
        return 1;
    }
}
