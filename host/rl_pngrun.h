/* rl_pngrun: a command's frames, the PNG files it names, through the one
 * loop (rl_run) with the PNG camera as its source.
 *
 * `detect`, `locate`, `calibrate-offsets`, `calibrate-mount` and the
 * survey's frame reading are this loop with a sink of their own: each
 * recognized (and, on a full site, localized) frame is handed to put; a
 * file that cannot be read or used gets one error line naming it and is
 * counted. Files are taken in the order given, each at its own size
 * unless the site has a calibration.
 *
 *   static rl_site site;             // loaded and prepared (rl_site.h)
 *   static char *files[] = {"a.png", "b.png"};
 *   rl_pngrun pr;
 *   rl_pngrun_defaults(&pr, "detect");
 *   pr.put = NULL;                   // each frame's (ctx, const rl_run_report *)
 *   if (rl_pngrun_files(&pr, &site, files, 2) > 0)
 *       use(pr.cmd);                 // some files failed, each said why
 */
#ifndef RL_PNGRUN_H
#define RL_PNGRUN_H

#include "rl_run.h"
#include "rl_site.h"

typedef struct {
    const char *cmd;            /* names error lines: "ringloc CMD: ..." */
    rl_run_config run;          /* the loop's settings (frame_interval, alone) */
    rl_err (*put)(void *ctx, const rl_run_report *rep); /* each recognized frame */
    void *ctx;
    int quiet;                  /* 1: no error line for a bad file (the sink says it) */
    const char *bad_suffix;     /* appended to a bad file's error line ("; left out"), or NULL */
} rl_pngrun;

void rl_pngrun_defaults(rl_pngrun *pr, const char *cmd);

/* Run the files through the loop; the number that failed (0: all read). */
long rl_pngrun_files(const rl_pngrun *pr, rl_site *site, char *const *files, int n);

#endif
