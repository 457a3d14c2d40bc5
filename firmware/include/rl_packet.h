/* rl_packet: pose and status frames on the wire, in ARCOS framing.
 *
 * The framing of the Pioneer's own packets, so an ARIA-based controller
 * can parse them with its packet receiver:
 *   0xFA 0xFB, count N (bytes after it: payload + 2 checksum bytes),
 *   payload, checksum (16-bit sum of big-endian byte pairs from the
 *   payload start, a leftover odd byte XORed in, sent high byte first).
 * Payload integers are little-endian.
 *
 * Pose, version 2, 34-byte payload: u8 0x50, u8 version 2, u16 seq, u32
 *   time (ms, monotonic capture time), i32 x (mm), i32 y (mm), i16 yaw
 *   (1e-4 rad), u8 landmarks used, u8 flags (bit 0: local pass used, bit
 *   1: tilt solved), u16 residual (0.1 mm), u16 latency capture -> send
 *   (0.1 ms), u16 sigma x (0.1 mm), u16 sigma y (0.1 mm), u16 sigma yaw
 *   (1e-4 rad), i16 camera roll, i16 camera pitch (1e-4 rad, from
 *   vertical). Version 1 (24 bytes) is the same without the last five
 *   fields; the decoder reads both.
 * Status, 12-byte payload: u8 0x53, u8 version 1, u16 seq, u32 time,
 *   u8 reason (rl_status_reason), u8 landmarks identified, u8 candidates,
 *   u8 0.
 *
 *   uint8_t buf[RL_PACKET_MAX];
 *   rl_msg pose, got;
 *   rl_decoder dec;
 *   size_t k, len;
 *   memset(&pose, 0, sizeof pose);
 *   pose.type = RL_PACKET_POSE;
 *   pose.x_mm = 1500;
 *   len = rl_packet_encode(&pose, buf);             // bytes to send
 *   rl_decoder_init(&dec);
 *   for (k = 0; k < len; k++)                      // bytes as they arrive
 *       if (rl_decoder_push(&dec, buf[k], &got))
 *           use(got.type, got.x_mm);
 */
#ifndef RL_PACKET_H
#define RL_PACKET_H

#include <stddef.h>
#include <stdint.h>


#ifdef __cplusplus
extern "C" {
#endif

#define RL_PACKET_POSE 0x50
#define RL_PACKET_STATUS 0x53
#define RL_PACKET_VERSION 2      /* of pose frames; status frames are version 1 */
#define RL_POSE_PAYLOAD 34
#define RL_POSE_V1_PAYLOAD 24
#define RL_STATUS_PAYLOAD 12
/* Largest frame: header 2 + count 1 + payload 34 + checksum 2. */
#define RL_PACKET_MAX 39

typedef enum {
    RL_STATUS_TOO_FEW = 1,       /* fewer landmarks than a pose needs */
    RL_STATUS_CAMERA_ERROR = 2,  /* the camera failed; reopening */
    RL_STATUS_CAMERA_TIMEOUT = 3,/* no frame in time */
    RL_STATUS_CONFIG_ERROR = 4,  /* the configuration cannot give a pose */
    RL_STATUS_AMBIGUOUS = 5      /* the landmarks fit several places of a map that repeats ids */
} rl_status_reason;

typedef struct {
    int type;           /* RL_PACKET_POSE or RL_PACKET_STATUS */
    uint16_t seq;
    uint32_t time_ms;
    /* pose */
    int32_t x_mm, y_mm;
    int16_t yaw_e4;     /* 1e-4 rad */
    uint8_t used;
    uint8_t flags;      /* bit 0: local pass used */
    uint16_t residual_e4; /* 0.1 mm */
    uint16_t latency_e4;  /* 0.1 ms */
    uint8_t version;      /* of a pose frame: 2 (0 encodes as 2), or 1 without these: */
    uint16_t sigma_x_e4, sigma_y_e4; /* 0.1 mm */
    uint16_t sigma_yaw_e4;           /* 1e-4 rad */
    int16_t roll_e4, pitch_e4;       /* 1e-4 rad */
    /* status */
    uint8_t reason;
    uint8_t identified;
    uint8_t candidates;
} rl_msg;

/* ARCOS checksum of n bytes. */
uint16_t rl_packet_checksum(const uint8_t *p, size_t n);

/* Encode a message into buf (RL_PACKET_MAX bytes); returns the frame's
 * length. The fields already have the wire's integer types, so they are
 * written as they are: whoever fills them from real values clamps into
 * range (rl_run.c does for poses). */
size_t rl_packet_encode(const rl_msg *m, uint8_t *buf);

/* A byte-at-a-time decoder that never allocates and resynchronises after
 * garbage, a wrong count, an unknown type or a bad checksum. */
typedef struct {
    uint8_t buf[RL_PACKET_MAX];
    size_t len;       /* bytes held */
    unsigned long bad;/* frames rejected (checksum, count, type) */
} rl_decoder;

void rl_decoder_init(rl_decoder *d);

/* Feed one byte; 1 when it completes a valid frame (decoded into *m). */
int rl_decoder_push(rl_decoder *d, uint8_t byte, rl_msg *m);

#ifdef __cplusplus
}
#endif

#endif
