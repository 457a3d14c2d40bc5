/* rl_arcos: the Pioneer's own packets (ARCOS), both ways, for the stand-in
 * robot and its checks: command packets a client sends (SYNC0..2, OPEN,
 * VEL, RVEL, ...), any packet a server sends (the SYNC replies, the
 * standard server information packet), and a reader that takes bytes as
 * they come. The framing and checksum are rl_packet's (the same ARCOS
 * framing ringloc's pose frames use): 0xFA 0xFB, count (payload + 2),
 * payload, checksum high byte first. A command's payload: its number,
 * then for an integer argument 0x3B (>= 0) or 0x1B (< 0) and the
 * magnitude as two bytes, low first.
 *
 *   uint8_t buf[RL_ARCOS_MAX], payload[RL_ARCOS_MAX];
 *   size_t n = rl_arcos_command_int(buf, RL_ARCOS_VEL, -300), k, len;
 *   rl_arcos_reader r;
 *   rl_arcos_reader_init(&r);
 *   for (k = 0; k < n; k++)
 *       if (rl_arcos_reader_push(&r, buf[k], payload, &len))
 *           use(payload[0], rl_arcos_int_arg(payload, len));   // 11, -300
 */
#ifndef RL_ARCOS_H
#define RL_ARCOS_H

#include <stddef.h>
#include <stdint.h>

#define RL_ARCOS_MAX 207 /* header 2 + count 1 + payload up to 202 + checksum 2 */

/* the commands the stand-in knows (ARIA's ArCommands numbers) */
enum {
    RL_ARCOS_PULSE = 0, RL_ARCOS_OPEN = 1, RL_ARCOS_CLOSE = 2, RL_ARCOS_ENABLE = 4,
    RL_ARCOS_SETO = 7, RL_ARCOS_ROTATE = 9, RL_ARCOS_VEL = 11, RL_ARCOS_CONFIG = 18,
    RL_ARCOS_RVEL = 21, RL_ARCOS_STOP = 29, RL_ARCOS_ESTOP = 55
};
#define RL_ARCOS_SIP_STOPPED 0x32
#define RL_ARCOS_SIP_MOVING 0x33

/* a packet around payload (n bytes, 1 .. 202) into buf; its length */
size_t rl_arcos_packet(uint8_t *buf, const uint8_t *payload, size_t n);

/* a command without argument / with an integer argument (|arg| < 65536) */
size_t rl_arcos_command(uint8_t *buf, int cmd);
size_t rl_arcos_command_int(uint8_t *buf, int cmd, int arg);

/* a command payload's integer argument (0 when it has none) */
int rl_arcos_int_arg(const uint8_t *payload, size_t n);

typedef struct {
    uint8_t buf[RL_ARCOS_MAX];
    size_t len;
    unsigned long bad; /* packets with a bad count or checksum, skipped */
} rl_arcos_reader;

void rl_arcos_reader_init(rl_arcos_reader *r);

/* Feed one byte; 1 when it completes a packet whose checksum holds (its
 * payload, *n bytes, into payload, RL_ARCOS_MAX bytes). */
int rl_arcos_reader_push(rl_arcos_reader *r, uint8_t byte, uint8_t *payload, size_t *n);

#endif
