/* What the header examples may take as given (tests/header_examples.cmake
 * wraps each in a function): a frame and its recognition, a map, a
 * camera, a workspace, the internals' usual variables, and use() for
 * whatever they produce. Only compiled, never run. */
#ifndef EXAMPLE_PRELUDE_H
#define EXAMPLE_PRELUDE_H
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE 1
#endif
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "rl_calib.h"
#include "rl_image.h"
#include "rl_label.h"
#include "rl_map.h"
#include "rl_match.h"
#include "rl_polar.h"
#include "rl_recog.h"
#include "rl_tone.h"
#include "rl_workspace.h"

void example_use(int unused, ...);
#define use(...) example_use(0, __VA_ARGS__)

extern rl_image frame, img;          /* a camera frame */
extern rl_map map;
extern rl_calib cam;
extern rl_family fam;
extern rl_ws ws;
extern rl_recog_config cfg;
extern rl_recog *rec;
extern rl_result res;
extern rl_detection d;               /* one of its candidates */
extern rl_label lb;
extern rl_templates tt;
extern rl_profile p;
extern rl_polar *pol;
extern rl_tone tone;                 /* the camera's tone curve, undone */
extern double cx, cy, r;             /* a candidate's centre and radius */
extern int light;                    /* the frame's light threshold */
extern int W, H, i, n, ids[8];
#endif
