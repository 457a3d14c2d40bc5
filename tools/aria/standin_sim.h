/* standin_sim: the stand-in robot's body: a differential drive that does
 * what its odometry is told (VEL, RVEL) while the truth differs by a wheel
 * scale, a track width and wheel noise, as a Pioneer's does; its server
 * information packet; and the pose frames a ringloc camera would send
 * about it (the truth plus noise, captured every period, sent a delay
 * later).
 *
 *   standin_robot r;
 *   uint8_t sip[RL_ARCOS_MAX];
 *   standin_init(&r, 1.0, 2.0, 0.5, 7);
 *   r.enabled = 1;
 *   r.v_cmd = 0.5;
 *   standin_step(&r, 0.001);
 *   use(standin_sip(&r, sip));
 */
#ifndef STANDIN_SIM_H
#define STANDIN_SIM_H

#include <stddef.h>
#include <stdint.h>
#include "rl_arcos.h"
#include "rl_packet.h"

typedef struct {
    double tx, ty, tyaw;     /* the truth, m, rad (the map's frame) */
    double ox, oy, oyaw;     /* the odometry (its own frame, from where it started or SETO) */
    double v_cmd, w_cmd;     /* commanded: m/s, rad/s */
    int enabled;             /* motors on */
    double scale_err;        /* true travel / odometry's (1.01) */
    double track_err;        /* true track / nominal (1.02) */
    double track;            /* nominal, m (0.33) */
    double wheel_noise;      /* m per sqrt(m) (0.0002) */
    double frame_sxy, frame_syaw; /* noise of the pose frames (0.0005 m, 0.0003 rad) */
    unsigned long long rng;
    uint16_t seq;
} standin_robot;

void standin_init(standin_robot *r, double x, double y, double yaw, unsigned seed);

/* a number uniform in 0 .. 1 from the robot's generator */
double standin_uniform(standin_robot *r);

/* dt seconds of driving */
void standin_step(standin_robot *r, double dt);

/* the server information packet (0x32 stopped, 0x33 moving) into buf; its length */
size_t standin_sip(const standin_robot *r, uint8_t *buf);

/* a pose frame about the truth now (ARCOS-framed, rl_packet), its capture
 * time time_ms and its capture-to-send latency (s) given; its length */
size_t standin_frame(standin_robot *r, uint32_t time_ms, double latency, uint8_t *buf);

#endif
