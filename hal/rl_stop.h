/* rl_stop: a program's request to stop, from a signal or from itself.
 *
 * SIGINT and SIGTERM (and SIGHUP where asked: a closed terminal, a
 * service reload) set it; the program's loop reads it and ends with its
 * summary. Where asked, SIGPIPE is ignored: a vanished reader is then a
 * write error the program handles, not a death.
 *
 *   rl_stop_on_signals(RL_STOP_HUP | RL_STOP_NO_SIGPIPE);
 *   while (!rl_stop_requested())
 *       use(n);                     // a step of the loop
 *   rl_stop_request();              // the same stop, from the program (its output gone)
 */
#ifndef RL_STOP_H
#define RL_STOP_H

#define RL_STOP_HUP 1        /* SIGHUP stops too */
#define RL_STOP_NO_SIGPIPE 2 /* SIGPIPE ignored */

/* Install the handlers (flags: 0 or those above). */
void rl_stop_on_signals(int flags);

/* 1 once a stop was requested. */
int rl_stop_requested(void);

/* Request the stop. */
void rl_stop_request(void);

#endif
