/* rl_report: the JSON line every frame command prints, and a timed
 * recognition for it.
 *
 *   rl_heap_recog hr;
 *   double us;
 *   rl_heap_recog_init(&hr, &cfg);
 *   if (rl_report_run(&hr, &img, &res, &us) == RL_OK) {
 *       rl_report_json_open(stdout, "a.png", &res, &hr.cfg.family, us);
 *       fputs("}\n", stdout);
 *   }
 *   rl_heap_recog_free(&hr);
 */
#ifndef RL_REPORT_H
#define RL_REPORT_H

#include <stdio.h>
#include "rl_heap_recog.h"
#include "rl_recog.h"

/* rl_heap_recog_run, and *elapsed_us the time inside it (the one clock,
 * rl_clock.h). */
RL_CHECK rl_err rl_report_run(rl_heap_recog *hr, const rl_image *img, rl_result *res,
                              double *elapsed_us);

/* Print the fields of the detect JSON object without its closing brace:
 * {"image": ..., "landmarks": [...], "unidentified": N, "dropped": {...}
 * -- the caller adds more fields (or none) and "}\n". */
void rl_report_json_open(FILE *f, const char *image, const rl_result *res, const rl_family *fam,
                         double elapsed_us);

/* Print a JSON string literal (quotes and escapes). */
void rl_json_string(FILE *f, const char *s);

#endif
