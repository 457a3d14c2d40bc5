/* standin_sim: see standin_sim.h. */
#include <math.h>
#include <string.h>
#include "standin_sim.h"

#define ANGLE_UNIT (2 * M_PI / 4096) /* ARCOS's heading unit (ARIA's AngleConvFactor 0.001534) */

static double wrap(double a)
{
    return atan2(sin(a), cos(a));
}

double standin_uniform(standin_robot *r)
{
    r->rng ^= r->rng << 13;
    r->rng ^= r->rng >> 7;
    r->rng ^= r->rng << 17;
    return ((r->rng >> 11) + 0.5) / 9007199254740992.0;
}

static double gauss(standin_robot *r)
{
    return sqrt(-2 * log(standin_uniform(r))) * cos(2 * M_PI * standin_uniform(r));
}

void standin_init(standin_robot *r, double x, double y, double yaw, unsigned seed)
{
    memset(r, 0, sizeof *r);
    r->tx = x;
    r->ty = y;
    r->tyaw = yaw;
    r->scale_err = 1.01;
    r->track_err = 1.02;
    r->track = 0.33;
    r->wheel_noise = 0.0002;
    r->frame_sxy = 0.0005;
    r->frame_syaw = 0.0003;
    r->rng = 0x9E3779B97F4A7C15ULL ^ (seed * 0x2545F4914F6CDD1DULL);
}

/* The wheels follow the odometry's command; what they really roll is the
 * wheel scale times that, plus noise; the truth turns by the true track. */
void standin_step(standin_robot *r, double dt)
{
    double d_o, a_o, dr, dl, d, a;
    if (!r->enabled)
        return;
    d_o = r->v_cmd * dt;
    a_o = r->w_cmd * dt;
    r->ox += d_o * cos(r->oyaw + a_o / 2);
    r->oy += d_o * sin(r->oyaw + a_o / 2);
    r->oyaw = wrap(r->oyaw + a_o);
    dr = r->scale_err * (d_o + a_o * r->track / 2);
    dl = r->scale_err * (d_o - a_o * r->track / 2);
    dr += r->wheel_noise * sqrt(fabs(dr)) * gauss(r);
    dl += r->wheel_noise * sqrt(fabs(dl)) * gauss(r);
    d = (dr + dl) / 2;
    a = (dr - dl) / (r->track * r->track_err);
    r->tx += d * cos(r->tyaw + a / 2);
    r->ty += d * sin(r->tyaw + a / 2);
    r->tyaw = wrap(r->tyaw + a);
}

static void put16(uint8_t *p, int v)
{
    p[0] = (uint8_t)(v & 0xFF);
    p[1] = (uint8_t)((v >> 8) & 0xFF);
}

size_t standin_sip(const standin_robot *r, uint8_t *buf)
{
    uint8_t p[20];
    int moving = r->enabled && (r->v_cmd != 0 || r->w_cmd != 0);
    double wheel = r->w_cmd * r->track / 2;
    memset(p, 0, sizeof p);
    p[0] = moving ? RL_ARCOS_SIP_MOVING : RL_ARCOS_SIP_STOPPED;
    put16(p + 1, (int)lround(r->ox * 1000) & 0x7FFF);         /* x, mm, 15 bits */
    put16(p + 3, (int)lround(r->oy * 1000) & 0x7FFF);         /* y */
    put16(p + 5, (int)lround(r->oyaw / ANGLE_UNIT));          /* heading */
    put16(p + 7, (int)lround((r->v_cmd - wheel) * 1000));     /* left wheel, mm/s */
    put16(p + 9, (int)lround((r->v_cmd + wheel) * 1000));     /* right wheel */
    p[11] = 130;                                              /* battery, 0.1 V */
    put16(p + 12, 0);                                         /* stall and bumpers */
    put16(p + 14, (int)lround(r->oyaw / ANGLE_UNIT));         /* control: the heading setpoint */
    put16(p + 16, r->enabled ? 1 : 0);                        /* flags: bit 0 motors on */
    p[18] = 0;                                                /* compass */
    p[19] = 0;                                                /* sonar readings */
    return rl_arcos_packet(buf, p, sizeof p);
}

size_t standin_frame(standin_robot *r, uint32_t time_ms, double latency, uint8_t *buf)
{
    rl_msg m;
    memset(&m, 0, sizeof m);
    m.type = RL_PACKET_POSE;
    m.version = 2;
    m.seq = r->seq++;
    m.time_ms = time_ms;
    m.x_mm = (int32_t)lround((r->tx + r->frame_sxy * gauss(r)) * 1000);
    m.y_mm = (int32_t)lround((r->ty + r->frame_sxy * gauss(r)) * 1000);
    m.yaw_e4 = (int16_t)lround(wrap(r->tyaw + r->frame_syaw * gauss(r)) * 1e4);
    m.used = 6;
    m.latency_e4 = (uint16_t)lround(latency * 1e4);
    m.sigma_x_e4 = m.sigma_y_e4 = (uint16_t)lround(r->frame_sxy * 1e4);
    m.sigma_yaw_e4 = (uint16_t)lround(r->frame_syaw * 1e4);
    return rl_packet_encode(&m, buf);
}
