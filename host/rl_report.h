/* rl_report: the host's recognizer (workspace from the heap, re-made when
 * the frame size changes) and the JSON line every frame command prints.
 *
 *   rl_host_recog hr;
 *   rl_host_recog_init(&hr, &cfg);
 *   if (rl_host_recog_run(&hr, &img, &res, &elapsed_us) == RL_OK)
 *       rl_report_json(stdout, "a.png", &res, &hr.cfg.family, elapsed_us, NULL);
 *   rl_host_recog_free(&hr);
 */
#ifndef RL_REPORT_H
#define RL_REPORT_H

#include <stdio.h>
#include "rl_recog.h"

typedef struct {
    rl_recog_config cfg;
    rl_recog rec;
    void *mem;
    size_t size;
    int width, height; /* size the recognizer is ready for; 0 before the first frame */
} rl_host_recog;

void rl_host_recog_init(rl_host_recog *hr, const rl_recog_config *cfg);
void rl_host_recog_free(rl_host_recog *hr);

/* Recognize one frame; *elapsed_us is the time inside rl_recog_run. */
RL_CHECK rl_err rl_host_recog_run(rl_host_recog *hr, const rl_image *img, rl_result *res,
                                  double *elapsed_us);

/* Monotonic clock in microseconds. */
double rl_now_us(void);

/* Print the fields of the detect JSON object without its closing brace:
 * {"image": ..., "landmarks": [...], "unidentified": N  -- the caller adds
 * more fields (or none) and "}\n". */
void rl_report_json_open(FILE *f, const char *image, const rl_result *res, const rl_family *fam,
                         double elapsed_us);

/* Print a JSON string literal (quotes and escapes). */
void rl_json_string(FILE *f, const char *s);

#endif
