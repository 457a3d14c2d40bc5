/* rl_stop on POSIX signals (rl_stop.h). */
#include "rl_stop.h"

#include <signal.h>
#include <string.h>

static volatile sig_atomic_t stop_flag;

static void on_signal(int sig)
{
    (void)sig;
    stop_flag = 1;
}

void rl_stop_on_signals(int flags)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    if (flags & RL_STOP_HUP)
        sigaction(SIGHUP, &sa, NULL);
    if (flags & RL_STOP_NO_SIGPIPE)
        signal(SIGPIPE, SIG_IGN);
}

int rl_stop_requested(void)
{
    return stop_flag != 0;
}

void rl_stop_request(void)
{
    stop_flag = 1;
}
