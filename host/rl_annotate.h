/* rl_annotate: draw what recognition saw over the frame, like the paper's
 * figures: light-source pixels tinted yellow, unidentified candidates in
 * red, identified landmarks in green (global pass) or cyan (local pass)
 * with their centre as a yellow dot and their code next to them.
 *
 *   char err[256];
 *   if (rl_annotate_png("out.png", &img, &res, &fam, "frame 12", err, sizeof err) != RL_OK)
 *       fprintf(stderr, "ringloc: %s\n", err);
 */
#ifndef RL_ANNOTATE_H
#define RL_ANNOTATE_H

#include <stddef.h>
#include "rl_recog.h"

/* `caption` (may be NULL) is written in the top-left corner. */
RL_CHECK rl_err rl_annotate_png(const char *path, const rl_image *img, const rl_result *res,
                                const rl_family *fam, const char *caption, char *err,
                                size_t errlen);

#endif
