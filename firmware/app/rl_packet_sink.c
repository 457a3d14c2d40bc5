/* rl_packet_sink: the loop's reports as pose and status packets (rl_packet_sink.h). */
#include "rl_packet_sink.h"

#include <math.h>
#include <string.h>

static int32_t clamp32(double v)
{
    return v > 2147483647.0 ? 2147483647 : v < -2147483647.0 ? -2147483647 : (int32_t)lround(v);
}

static uint16_t clampu16(double v)
{
    return v > 65535.0 ? 65535 : v < 0 ? 0 : (uint16_t)lround(v);
}

static int16_t clamp16(double v)
{
    return v > 32767.0 ? 32767 : v < -32767.0 ? -32767 : (int16_t)lround(v);
}

static uint8_t clamp8(int v)
{
    return (uint8_t)(v > 255 ? 255 : v < 0 ? 0 : v);
}

static void pose_msg(const rl_run_report *rep, rl_msg *m)
{
    const rl_pose *pose = rep->pose;
    m->type = RL_PACKET_POSE;
    m->x_mm = clamp32(pose->x * 1000.0);
    m->y_mm = clamp32(pose->y * 1000.0);
    m->yaw_e4 = (int16_t)lround(pose->yaw * 1e4); /* |yaw| <= pi fits */
    m->used = clamp8(pose->used);
    m->flags = (uint8_t)((rep->local_used ? 1 : 0) | (pose->tilt_solved ? 2 : 0));
    m->residual_e4 = clampu16(pose->residual * 1e4);
    m->latency_e4 = clampu16((double)(rep->sent_us > rep->t_us ? rep->sent_us - rep->t_us : 0) / 100.0);
    m->version = RL_PACKET_VERSION;
    m->sigma_x_e4 = clampu16(pose->sigma_x * 1e4);
    m->sigma_y_e4 = clampu16(pose->sigma_y * 1e4);
    m->sigma_yaw_e4 = clampu16(pose->sigma_yaw * 1e4);
    m->roll_e4 = clamp16(pose->roll * 1e4);
    m->pitch_e4 = clamp16(pose->pitch * 1e4);
}

void rl_packet_from_report(const rl_run_report *rep, rl_msg *m)
{
    memset(m, 0, sizeof *m);
    m->seq = (uint16_t)rep->seq;
    m->time_ms = (uint32_t)(rep->t_us / 1000u);
    if (rep->event == RL_RUN_FRAME && rep->pose_err == RL_OK) {
        pose_msg(rep, m);
        return;
    }
    m->type = RL_PACKET_STATUS;
    m->reason = (uint8_t)rep->status;
    /* a frame whose pose failed says what it saw */
    if (rep->event == RL_RUN_FRAME && rep->status != 0) {
        m->identified = clamp8(rep->res->n_landmarks);
        m->candidates = clamp8(rep->res->n_candidates);
    }
}

static rl_err sink_open(void *ctx, char *err, size_t errlen)
{
    rl_packet_sink *ps = (rl_packet_sink *)ctx;
    return ps->line.open ? ps->line.open(ps->line.ctx, err, errlen) : RL_OK;
}

static rl_err sink_put(void *ctx, const rl_run_report *rep)
{
    rl_packet_sink *ps = (rl_packet_sink *)ctx;
    uint8_t buf[RL_PACKET_MAX];
    rl_msg m;
    rl_packet_from_report(rep, &m);
    return ps->line.write(ps->line.ctx, buf, rl_packet_encode(&m, buf));
}

static void sink_close(void *ctx)
{
    rl_packet_sink *ps = (rl_packet_sink *)ctx;
    if (ps->line.close)
        ps->line.close(ps->line.ctx);
}

static const char *sink_why(void *ctx)
{
    rl_packet_sink *ps = (rl_packet_sink *)ctx;
    return ps->line.why ? ps->line.why(ps->line.ctx) : NULL;
}

rl_run_sink rl_packet_sink_make(rl_packet_sink *ps, const rl_packet_line *line)
{
    rl_run_sink s;
    ps->line = *line;
    s.name = "serial";
    s.open = sink_open;
    s.put = sink_put;
    s.close = sink_close;
    s.why = sink_why;
    s.ctx = ps;
    return s;
}
