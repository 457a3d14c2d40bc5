/* rl_pngrun: a command's PNG files through the one loop (rl_pngrun.h). */
#include "rl_pngrun.h"

#include <stdio.h>
#include <string.h>
#include "rl_cli.h"

void rl_pngrun_defaults(rl_pngrun *pr, const char *cmd)
{
    memset(pr, 0, sizeof *pr);
    pr->cmd = cmd;
    rl_run_defaults(&pr->run);
    pr->run.timeout_ms = -1; /* files: no rate, nothing to wait for */
    pr->run.track.full_every = 0; /* every file in full; locate tracks a drive */
}

typedef struct {
    const rl_pngrun *pr;
    long failed;
    int stop;       /* the files could not be opened at all */
} pngrun_state;

static rl_err pngrun_put(void *ctx, const rl_run_report *rep)
{
    pngrun_state *st = (pngrun_state *)ctx;
    if (rep->event == RL_RUN_FRAME)
        return st->pr->put ? st->pr->put(st->pr->ctx, rep) : RL_OK;
    if (rep->event == RL_RUN_NO_FRAME) { /* files have no down time: said once, the end */
        rl_cli_fail(st->pr->cmd, RL_EXIT_FAIL, "%s", rep->error ? rep->error : "no frames");
        st->stop = 1;
        return RL_OK;
    }
    st->failed++;
    if (!st->pr->quiet)
        rl_cli_fail(st->pr->cmd, RL_EXIT_FAIL, "%s%s", rep->error ? rep->error : "bad frame",
                    st->pr->bad_suffix ? st->pr->bad_suffix : "");
    return RL_OK;
}

long rl_pngrun_files(const rl_pngrun *pr, rl_site *site, char *const *files, int n)
{
    static rl_result res;
    static rl_runner runner;
    rl_run_camera cam;
    rl_cam_config cc;
    rl_run_io io;
    pngrun_state st;
    rl_cam_defaults(&cc);
    cc.backend = "png";
    cc.rate = 0; /* as fast as they decode */
    cc.files = (const char *const *)files;
    cc.n_files = n;
    memset(&io, 0, sizeof io);
    io.source = rl_run_camera_source(&cam, &cc);
    st.pr = pr;
    st.failed = 0;
    st.stop = 0;
    io.sink.name = pr->cmd;
    io.sink.put = pngrun_put;
    io.sink.ctx = &st;
    io.clock = rl_clock_system();
    rl_run_init(&runner, &pr->run, &io, site, &res);
    while (!st.stop && rl_run_step(&runner) != RL_ENOTFOUND)
        continue;
    rl_run_close(&runner);
    return st.stop ? n : st.failed;
}
