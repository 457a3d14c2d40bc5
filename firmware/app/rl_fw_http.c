#include "rl_fw_http.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

rl_err rl_fw_http_start(rl_fw_http *web, const char *listen, const char *token, int w, int h,
                        const rl_site *site, const rl_map *map, const rl_runner *runner, const char *serial,
                        const rl_record *rec, char *err, size_t errlen)
{
    rl_view_config vc;
    rl_http_config hc;
    rl_err e;
    size_t size;
    memset(web, 0, sizeof *web);
    rl_view_defaults(&vc);
    vc.width = w;
    vc.height = h;
    if (site != NULL) { /* what the recognizer accepts */
        vc.min_score = site->recog.cfg.min_score;
        vc.local_min_score = site->recog.cfg.local_min_score;
        vc.size_tolerance = site->recog.cfg.size_tolerance;
    }
    if ((size = rl_view_size(&vc)) == 0 || (web->mem = malloc(size)) == NULL) {
        snprintf(err, errlen, "http: no memory for the web view of %dx%d frames", w, h);
        return RL_ENOMEM;
    }
    if ((e = rl_view_init(&web->view, &vc, web->mem, size)) != RL_OK) {
        free(web->mem);
        snprintf(err, errlen, "http: the web view: %s", rl_strerror(e));
        return e;
    }
    rl_http_defaults(&hc);
    hc.listen = listen;
    hc.token = token;
    if (site != NULL && site->has_calib && site->has_mount && !site->has_offsets) {
        hc.calib = &site->calib; /* the pinhole model: the map drawn into the image */
        hc.mount = &site->mount;
    }
    if ((e = rl_http_start(&web->http, &hc, &web->view, map, err, errlen)) != RL_OK) {
        char why[256];
        snprintf(why, sizeof why, "%s", err);
        snprintf(err, errlen, "http: %s", why);
        rl_view_destroy(&web->view);
        free(web->mem);
        return e;
    }
    rl_run_view_init(&web->rv, &web->view, runner, serial, rec);
    web->on = 1;
    return RL_OK;
}

void rl_fw_http_stop(rl_fw_http *web, const char *prefix)
{
    rl_http_counts n;
    if (!web->on)
        return;
    rl_http_stop(web->http, &n);
    if (prefix != NULL)
        fprintf(stderr, "%s: web view: %ld requests served, %ld refused, %ld snapshots skipped while read\n",
                prefix, n.served, n.refused, web->view.loop.skipped);
    rl_view_destroy(&web->view);
    free(web->mem);
    web->on = 0;
}
