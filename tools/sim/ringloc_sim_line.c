/* ringloc-sim-line: a serial line between two pseudo-terminals, for
 * `make sim`: ringloc-fw writes its pose frames to one (FROM), the robot's
 * controller reads them from the other (TO), each frame arriving its time
 * on the wire at BAUD after ringloc-fw wrote it, plus a delay uniform in
 * 0 .. --transport s (what a USB adapter, a polling reader, a loaded
 * kernel add: outside the frame's latency field). Order is kept, as on a
 * line. Bytes that are not whole ARCOS packets are dropped and counted. */
#define _XOPEN_SOURCE 600
#include <errno.h>
#include <getopt.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "line_delay.h"
#include "rl_arcos.h"
#include "rl_cli.h"
#include "rl_clock.h"
#include "rl_outfile.h"
#include "rl_ptylink.h"
#include "rl_stop.h"

#define P "ringloc-sim-line"

static const char *help =
    "usage: ringloc-sim-line --from LINK --to LINK [--baud 115200] [--transport MAX] [--seed N]\n"
    "                        [--record FILE] [--force]\n\n"
    "A serial line between two pseudo-terminals: ringloc-fw writes its pose frames to the\n"
    "one LINK --from points to (its serial device), the controller reads them from --to's,\n"
    "each frame its bytes' time at BAUD (10 bits a byte) after it was written, plus a delay\n"
    "uniform in 0 .. MAX s (default 0.1) that the frame's latency field does not carry;\n"
    "in order, as on a line. Runs until SIGINT or SIGTERM, then one line of counts.\n"
    "  --from, --to LINK  new, or a link left to a pseudo-terminal that is gone; anything\n"
    "                     else there is refused (kept), unless --force (not a folder)\n"
    "  --seed N           the delays' random sequence (default 1)\n"
    "  --record FILE      the frames' bytes as ringloc-fw wrote them (for ringloc monitor),\n"
    "                     written whole at the end or not at all\n";

/* the delays: a 64-bit LCG's top bits, uniform in [0, 1) */
static double uniform(unsigned long long *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / 9007199254740992.0;
}

typedef struct {
    rl_ptylink from, to;
    rl_arcos_reader rd;
    line_delay q;
    double transport, byte_time;
    unsigned long long rng;
    unsigned long frames;
    rl_outfile *rec; /* --record (NULL: none) */
} sim_line;

/* what ringloc-fw wrote: whole packets queued to arrive */
static void take(sim_line *l, const uint8_t *buf, size_t n, double now)
{
    uint8_t payload[RL_ARCOS_MAX], pkt[RL_ARCOS_MAX];
    size_t i, len;
    for (i = 0; i < n; i++)
        if (rl_arcos_reader_push(&l->rd, buf[i], payload, &len)) {
            size_t k = rl_arcos_packet(pkt, payload, len);
            double wire = (double)k * l->byte_time;
            l->frames++;
            if (l->rec)
                rl_outfile_write(l->rec, pkt, k);
            line_delay_push(&l->q, pkt, k, now + wire + l->transport * uniform(&l->rng), wire);
        }
}

static void run(sim_line *l)
{
    while (!rl_stop_requested()) {
        struct pollfd p = {l->from.fd, POLLIN, 0};
        uint8_t buf[512];
        int wait = l->q.n > 0 ? (int)((l->q.when[0] - rl_clock_now_s()) * 1000) + 1 : 100;
        if (poll(&p, 1, wait < 0 ? 0 : wait > 100 ? 100 : wait) > 0 && (p.revents & POLLIN)) {
            ssize_t got = read(l->from.fd, buf, sizeof buf);
            if (got > 0)
                take(l, buf, (size_t)got, rl_clock_now_s());
        } else if (p.revents & POLLHUP)
            usleep(20000); /* the writer has not opened it yet, or closed it */
        line_delay_due(&l->q, l->to.fd, rl_clock_now_s());
    }
}

int main(int argc, char **argv)
{
    static const struct option opts[] = {
        {"from", required_argument, 0, 'f'},      {"to", required_argument, 0, 't'},
        {"baud", required_argument, 0, 'b'},      {"transport", required_argument, 0, 'T'},
        {"seed", required_argument, 0, 'S'},      {"force", no_argument, 0, 'F'},
        {"record", required_argument, 0, 'r'},    {"help", no_argument, 0, 'h'},
        {0, 0, 0, 0}};
    static sim_line l;
    const char *from = NULL, *to = NULL, *record = NULL;
    rl_outfile rec;
    int c, baud = 115200, seed = 1, force = 0;
    char err[1200];
    rl_cli_start(P);
    l.transport = 0.1;
    while ((c = rl_cli_getopt(NULL, argc, argv, opts)) != -1) {
        int ok = 1;
        switch (c) {
        case 'f': from = optarg; break;
        case 't': to = optarg; break;
        case 'b': ok = rl_cli_int(NULL, "--baud", optarg, 300, 4000000, &baud); break;
        case 'T': ok = rl_cli_double(NULL, "--transport", optarg, 0, 10, &l.transport); break;
        case 'S': ok = rl_cli_int(NULL, "--seed", optarg, 0, 1000000000, &seed); break;
        case 'F': force = 1; break;
        case 'r': record = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: return RL_EXIT_USAGE;
        }
        if (!ok)
            return RL_EXIT_USAGE;
    }
    if (optind != argc)
        return rl_cli_fail(NULL, RL_EXIT_USAGE, "unexpected argument '%s' (see --help)", argv[optind]);
    if (!from || !to)
        return rl_cli_fail(NULL, RL_EXIT_USAGE, "--from and --to are needed (see --help)");
    l.byte_time = 10.0 / baud;
    l.rng = (unsigned long long)seed * 2654435761ULL + 1;
    rl_arcos_reader_init(&l.rd);
    line_delay_init(&l.q);
    if (rl_ptylink_open(&l.from, from, force, 1, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "%s", err);
    if (rl_ptylink_open(&l.to, to, force, 1, err, sizeof err) != RL_OK) {
        rl_ptylink_close(&l.from);
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "%s", err);
    }
    if (record && rl_outfile_open(&rec, record, err, sizeof err) != RL_OK) {
        rl_ptylink_close(&l.from);
        rl_ptylink_close(&l.to);
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "%s", err);
    }
    l.rec = record ? &rec : NULL;
    rl_stop_on_signals(RL_STOP_NO_SIGPIPE);
    fprintf(stderr, P ": %s -> %s, %d baud, up to %.3f s more\n", from, to, baud, l.transport);
    run(&l);
    rl_ptylink_close(&l.from);
    rl_ptylink_close(&l.to);
    fprintf(stderr, P ": %lu frames in, %lu passed, %lu dropped, %lu with a bad count or checksum skipped\n",
            l.frames, l.q.sent, l.q.dropped, l.rd.bad);
    if (record && rl_outfile_commit(&rec, err, sizeof err) != RL_OK)
        return rl_cli_fail(NULL, RL_EXIT_FAIL, "%s", err);
    return 0;
}
