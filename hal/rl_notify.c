/* rl_notify: the sd_notify protocol (rl_notify.h). */
#include "rl_notify.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

void rl_notify_open(rl_notify *n)
{
    const char *sock = getenv("NOTIFY_SOCKET"), *usec = getenv("WATCHDOG_USEC"), *pid = getenv("WATCHDOG_PID");
    size_t len;
    memset(n, 0, sizeof *n);
    n->fd = -1;
    if (sock == NULL || (sock[0] != '/' && sock[0] != '@') || (len = strlen(sock)) >= sizeof n->path)
        return;
    memcpy(n->path, sock, len);
    if (sock[0] == '@')
        n->path[0] = 0;
    n->path_len = (int)len;
    if ((n->fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0)) < 0)
        return;
    /* the watchdog is ours unless systemd named another process */
    if (usec != NULL && (pid == NULL || strtol(pid, NULL, 10) == (long)getpid()))
        n->watchdog_us = strtoull(usec, NULL, 10);
}

void rl_notify_send(rl_notify *n, const char *state)
{
    struct sockaddr_un a;
    if (n->fd < 0)
        return;
    memset(&a, 0, sizeof a);
    a.sun_family = AF_UNIX;
    memcpy(a.sun_path, n->path, (size_t)n->path_len);
    (void)sendto(n->fd, state, strlen(state), MSG_NOSIGNAL, (const struct sockaddr *)&a,
                 (socklen_t)(offsetof(struct sockaddr_un, sun_path) + (size_t)n->path_len));
}

void rl_notify_alive(rl_notify *n, uint64_t now_us)
{
    if (n->fd < 0 || n->watchdog_us == 0 || now_us < n->next_ping_us)
        return;
    rl_notify_send(n, "WATCHDOG=1");
    n->next_ping_us = now_us + n->watchdog_us / 2;
}

void rl_notify_close(rl_notify *n)
{
    if (n->fd >= 0)
        close(n->fd);
    n->fd = -1;
}
