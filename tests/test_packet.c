/* Pose and status frames: golden bytes, independent ARCOS checksum
 * vectors, and a decoder that survives garbage, truncation and flipped
 * bits without ever producing a frame that was not sent. */
#include "rl_test.h"
#include "rl_packet.h"

static void test_checksum_vectors(void **state)
{
    /* ARCOS packets from the Pioneer manual's examples, written out:
     * SETO (command 7, no argument): FA FB 03 07 00 07
     * SYNC1: FA FB 03 01 00 01
     * ENABLE 1 (command 4, integer argument 0x3B, value 1): FA FB 06 04 3B 01 00 05 3B */
    const uint8_t seto[] = {0x07}, sync1[] = {0x01}, enable[] = {0x04, 0x3B, 0x01, 0x00};
    (void)state;
    assert_int_equal(rl_packet_checksum(seto, 1), 0x0007);
    assert_int_equal(rl_packet_checksum(sync1, 1), 0x0001);
    assert_int_equal(rl_packet_checksum(enable, 4), 0x053B);
    {
        const uint8_t odd[] = {0x12, 0x34, 0xAB};
        assert_int_equal(rl_packet_checksum(odd, 3), 0x1234 ^ 0xAB);
        const uint8_t wrap[] = {0xFF, 0xFF, 0x00, 0x02};
        assert_int_equal(rl_packet_checksum(wrap, 4), 0x0001); /* modulo 2^16 */
    }
}

/* The pose of the golden frames. */
static void golden_pose(rl_msg *m)
{
    memset(m, 0, sizeof *m);
    m->type = RL_PACKET_POSE;
    m->seq = 7;
    m->time_ms = 123456;
    m->x_mm = 1203;
    m->y_mm = -502;
    m->yaw_e4 = 3120;
    m->used = 4;
    m->flags = 1;
    m->residual_e4 = 21;
    m->latency_e4 = 85;
}

static void test_pose_golden_bytes(void **state)
{
    rl_msg m;
    uint8_t buf[RL_PACKET_MAX];
    /* written out by hand from the wire format */
    const uint8_t want[] = {0xFA, 0xFB, 26,
                            0x50, 0x01, 0x07, 0x00,             /* type, version, seq 7 */
                            0x40, 0xE2, 0x01, 0x00,             /* time 123456 ms */
                            0xB3, 0x04, 0x00, 0x00,             /* x 1203 mm */
                            0x0A, 0xFE, 0xFF, 0xFF,             /* y -502 mm */
                            0x30, 0x0C,                         /* yaw 3120 e-4 rad */
                            0x04, 0x01,                         /* used 4, flags 1 */
                            0x15, 0x00,                         /* residual 21 (2.1 mm) */
                            0x55, 0x00,                         /* latency 85 (8.5 ms) */
                            0x00, 0x00};
    uint8_t expect[sizeof want];
    uint16_t sum;
    (void)state;
    memcpy(expect, want, sizeof want);
    sum = rl_packet_checksum(expect + 3, 24);
    expect[27] = (uint8_t)(sum >> 8);
    expect[28] = (uint8_t)sum;
    /* and the checksum itself, summed here as big-endian pairs by hand */
    {
        uint32_t s = 0;
        int i;
        for (i = 0; i < 24; i += 2)
            s = (s + (uint32_t)(want[3 + i] << 8 | want[4 + i])) & 0xFFFF;
        assert_int_equal(sum, s);
    }
    golden_pose(&m);
    m.version = 1; /* the older frame, as firmware before issue 15 sent it */
    assert_int_equal(rl_packet_encode(&m, buf), 29);
    assert_memory_equal(buf, expect, 29);
}

/* Feed n bytes to the decoder: how many frames came out (the last in *m). */
static int push_all(rl_decoder *d, const uint8_t *p, size_t n, rl_msg *m)
{
    size_t i;
    int k = 0;
    for (i = 0; i < n; i++)
        k += rl_decoder_push(d, p[i], m);
    return k;
}

/* Version 2: the same fields, then the sigmas and the tilt; the decoder
 * reads both versions from one stream. */
static void test_pose_v2_golden_bytes_and_both_versions_decode(void **state)
{
    rl_msg m, got;
    rl_decoder d;
    uint8_t buf[RL_PACKET_MAX], v1[RL_PACKET_MAX];
    const uint8_t want[] = {0xFA, 0xFB, 36,
                            0x50, 0x02, 0x07, 0x00,             /* type, version 2, seq 7 */
                            0x40, 0xE2, 0x01, 0x00,             /* time 123456 ms */
                            0xB3, 0x04, 0x00, 0x00,             /* x 1203 mm */
                            0x0A, 0xFE, 0xFF, 0xFF,             /* y -502 mm */
                            0x30, 0x0C,                         /* yaw 3120 e-4 rad */
                            0x04, 0x03,                         /* used 4, flags: local, tilt solved */
                            0x15, 0x00,                         /* residual 21 (2.1 mm) */
                            0x55, 0x00,                         /* latency 85 (8.5 ms) */
                            0x0B, 0x00,                         /* sigma x 11 (1.1 mm) */
                            0x09, 0x00,                         /* sigma y 9 (0.9 mm) */
                            0x04, 0x00,                         /* sigma yaw 4 e-4 rad */
                            0x0C, 0x00,                         /* roll 12 e-4 rad */
                            0xCD, 0xFF,                         /* pitch -51 e-4 rad */
                            0x00, 0x00};
    uint8_t expect[sizeof want];
    uint32_t s = 0;
    size_t i, n1, n2;
    int k = 0;
    (void)state;
    memcpy(expect, want, sizeof want);
    for (i = 0; i < 34; i += 2)
        s = (s + (uint32_t)(want[3 + i] << 8 | want[4 + i])) & 0xFFFF;
    expect[37] = (uint8_t)(s >> 8);
    expect[38] = (uint8_t)s;
    golden_pose(&m);
    m.flags = 3;
    m.sigma_x_e4 = 11;
    m.sigma_y_e4 = 9;
    m.sigma_yaw_e4 = 4;
    m.roll_e4 = 12;
    m.pitch_e4 = -51;
    n2 = rl_packet_encode(&m, buf);
    assert_int_equal(n2, 39);
    assert_memory_equal(buf, expect, 39);
    m.version = 1;
    n1 = rl_packet_encode(&m, v1);
    assert_int_equal(n1, 29);
    rl_decoder_init(&d);
    k = push_all(&d, v1, n1, &got);
    assert_int_equal(k, 1);
    assert_int_equal(got.version, 1);
    assert_int_equal(got.x_mm, 1203);
    assert_int_equal(got.sigma_x_e4, 0);
    k += push_all(&d, buf, n2, &got);
    assert_int_equal(k, 2);
    assert_int_equal(got.version, 2);
    assert_int_equal(got.sigma_x_e4, 11);
    assert_int_equal(got.sigma_y_e4, 9);
    assert_int_equal(got.sigma_yaw_e4, 4);
    assert_int_equal(got.roll_e4, 12);
    assert_int_equal(got.pitch_e4, -51);
    assert_int_equal(d.bad, 0);
}

static void test_status_golden_bytes(void **state)
{
    rl_msg m;
    uint8_t buf[RL_PACKET_MAX];
    const uint8_t want[] = {0xFA, 0xFB, 14, 0x53, 0x01, 0x09, 0x00, 0x80, 0xE2, 0x01, 0x00,
                            0x01, 0x01, 0x03, 0x00,
                            /* checksum: 5301 + 0900 + 80E2 + 0100 + 0101 + 0300 = E1E4 */
                            0xE1, 0xE4};
    (void)state;
    memset(&m, 0, sizeof m);
    m.type = RL_PACKET_STATUS;
    m.seq = 9;
    m.time_ms = 123520;
    m.reason = RL_STATUS_TOO_FEW;
    m.identified = 1;
    m.candidates = 3;
    assert_int_equal(rl_packet_encode(&m, buf), 17);
    assert_memory_equal(buf, want, 17);
}

static unsigned rnd(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return *s >> 8;
}

static void make_msg(rl_msg *m, unsigned i)
{
    memset(m, 0, sizeof *m);
    m->type = i % 3 ? RL_PACKET_POSE : RL_PACKET_STATUS;
    m->seq = (uint16_t)i;
    m->time_ms = 1000u * i + 17;
    if (m->type == RL_PACKET_POSE) {
        m->x_mm = (int32_t)(i * 37) - 5000;
        m->y_mm = (int32_t)(i * 91) % 7000;
        m->yaw_e4 = (int16_t)(i * 13 % 31416);
        m->used = (uint8_t)(2 + i % 9);
        m->flags = (uint8_t)(i & 1);
        m->residual_e4 = (uint16_t)(i * 3);
        m->latency_e4 = (uint16_t)(i * 5);
        /* both versions in one stream */
        m->version = (uint8_t)(i % 5 == 1 ? 1 : RL_PACKET_VERSION);
        if (m->version == RL_PACKET_VERSION) {
            m->sigma_x_e4 = (uint16_t)(i * 7);
            m->sigma_y_e4 = (uint16_t)(i * 11);
            m->sigma_yaw_e4 = (uint16_t)(i % 100);
            m->roll_e4 = (int16_t)(i % 300) - 150;
            m->pitch_e4 = (int16_t)(i % 200) - 100;
        }
    } else {
        m->reason = (uint8_t)(1 + i % 4);
        m->identified = (uint8_t)(i % 2);
        m->candidates = (uint8_t)(i % 7);
    }
}

/* A stream of frames, some intact, some damaged (a flipped bit,
 * truncated), with random garbage between: every intact frame is decoded,
 * in order, and nothing else. */
static void test_decoder_survives_damage(void **state)
{
    static uint8_t stream[1 << 20];
    static int intact[20000];
    size_t n = 0, i;
    unsigned seed = 99, k, sent = 4000, got = 0, want = 0;
    rl_decoder d;
    rl_msg m, ref;
    (void)state;
    for (k = 0; k < sent; k++) {
        uint8_t buf[RL_PACKET_MAX];
        size_t len, g, garbage = rnd(&seed) % 12;
        unsigned what = rnd(&seed) % 10;
        for (g = 0; g < garbage; g++) /* garbage, with header bytes on purpose */
            stream[n++] = (uint8_t)(g % 3 == 0 ? 0xFA : g % 3 == 1 ? 0xFB : rnd(&seed));
        make_msg(&m, k);
        len = rl_packet_encode(&m, buf);
        intact[k] = 0;
        if (what == 0) {
            buf[3 + rnd(&seed) % (len - 3)] ^= (uint8_t)(1u << (rnd(&seed) % 8)); /* a flipped bit */
        } else if (what == 1) {
            len = 1 + rnd(&seed) % (len - 1); /* truncated */
        } else {
            intact[k] = 1;
            want++;
        }
        memcpy(stream + n, buf, len);
        n += len;
    }
    rl_decoder_init(&d);
    k = 0;
    for (i = 0; i < n; i++)
        if (rl_decoder_push(&d, stream[i], &m)) {
            /* the next intact frame at or after k must be this one */
            while (k < sent && !intact[k])
                k++;
            assert_true(k < sent);
            make_msg(&ref, k);
            if (memcmp(&m, &ref, sizeof m) != 0)
                fail_msg("decoded frame %u is not what was sent (seq %u)", got, m.seq);
            k++;
            got++;
        }
    assert_int_equal(got, want);
    assert_true(d.bad > 0);
}

static void test_decoder_random_garbage(void **state)
{
    rl_decoder d;
    rl_msg m;
    unsigned seed = 7, i, frames = 0;
    (void)state;
    rl_decoder_init(&d);
    for (i = 0; i < 2000000; i++) {
        /* bias towards header bytes to give false frames every chance */
        unsigned r = rnd(&seed);
        uint8_t b = (uint8_t)(r % 4 == 0 ? 0xFA : r % 4 == 1 ? 0xFB : rnd(&seed));
        frames += (unsigned)rl_decoder_push(&d, b, &m);
    }
    assert_int_equal(frames, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_checksum_vectors),
        cmocka_unit_test(test_pose_golden_bytes),
        cmocka_unit_test(test_pose_v2_golden_bytes_and_both_versions_decode),
        cmocka_unit_test(test_status_golden_bytes),
        cmocka_unit_test(test_decoder_survives_damage),
        cmocka_unit_test(test_decoder_random_garbage),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
