/* rl_survey_input: a survey's frames from files: PNG images (recognized
 * here), folders of them (in name order), or JSON-lines files of
 * `ringloc detect` output (a survey redone without recognizing again).
 * Each frame's identified landmarks become survey observations through
 * the camera's calibration (rl_calib_centre, rl_calib_radius); a
 * landmark the border cuts keeps its centre, with 4 times the noise. The
 * scale comes only from radii the recognizer measured across both edges
 * of the outer black band (rl_family_band_inner) within
 * RL_SURVEY_RADIUS_FIELD of the optical axis (normalized): elsewhere the
 * radius is some tenths of a per cent off.
 *
 *   static rl_survey sv;
 *   rl_survey_input in;
 *   rl_survey_input_init(&in, &cam, &fam, &sv, NULL);
 *   if (rl_survey_input_path(&in, "recording/") != RL_OK)
 *       use(in.err);
 *   use(in.frames, in.unreadable);
 */
#ifndef RL_SURVEY_INPUT_H
#define RL_SURVEY_INPUT_H

#include "rl_calib.h"
#include "rl_family.h"
#include "rl_site.h"
#include "rl_survey.h"

#define RL_SURVEY_RADIUS_FIELD 0.25

typedef struct {
    const rl_calib *cam;
    const rl_family *fam;
    rl_survey *sv;
    rl_site *site;     /* its recognizer reads PNG frames; NULL: JSON lines only */
    int frames;        /* frames read */
    int unreadable;    /* PNG frames that could not be read or were the wrong size (said on stderr) */
    int progress;      /* 1: a progress line on stderr (a terminal) */
    int failed;        /* a frame could not be kept (err says why) */
    char err[600];
} rl_survey_input;

void rl_survey_input_init(rl_survey_input *in, const rl_calib *cam, const rl_family *fam, rl_survey *sv,
                          rl_site *site);

/* One FRAME argument: a folder, a .json/.jsonl/.ndjson file, or a PNG.
 * RL_EFORMAT for a malformed JSON line, an id outside the family or a
 * frame of another size in a JSON file (err names file and line);
 * RL_ENOTFOUND for a missing path or a folder with no PNG; RL_ENOMEM. An
 * unreadable PNG is said on stderr and counted, and the run goes on. */
RL_CHECK rl_err rl_survey_input_path(rl_survey_input *in, const char *path);

#endif
