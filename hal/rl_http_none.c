/* rl_http without libmicrohttpd (a build where it was not found): the
 * web view is refused at start, with the reason. */
#include "rl_http.h"

#include <stdio.h>
#include <string.h>

rl_err rl_http_start(rl_http **h, const rl_http_config *c, rl_view *view, const rl_map *map, char *err,
                     size_t errlen)
{
    (void)c;
    (void)view;
    (void)map;
    *h = NULL;
    snprintf(err, errlen, "this build has no web view (libmicrohttpd was not found when it was built)");
    return RL_EUNSUPPORTED;
}

void rl_http_stop(rl_http *h, rl_http_counts *counts)
{
    (void)h;
    if (counts != NULL)
        memset(counts, 0, sizeof *counts);
}
