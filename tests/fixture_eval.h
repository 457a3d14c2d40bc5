/* Fixture evaluation against the renderer's ground truth: recognition
 * results are matched to true landmarks by position, and counted. */
#ifndef FIXTURE_EVAL_H
#define FIXTURE_EVAL_H

#include <stdio.h>
#include "rl_recog.h"

#define EVAL_MAX_TRUTH 64

typedef struct {
    int id;
    double x, y;       /* map position */
    double u, v;       /* projected centre */
    double radius, visible, light_gap_radii;
} truth_landmark;

typedef struct {
    char image[512];
    int width, height, n;
    double robot_x, robot_y, robot_yaw;
    truth_landmark lm[EVAL_MAX_TRUTH];
} truth;

typedef struct {
    int complete, complete_found, complete_ident;   /* landmarks fully in view */
    int glare, glare_ident;                          /* within one radius of a light */
    int border, border_ident;                        /* 50% .. <100% visible */
    int identified, wrong_id, invented;              /* over all reports */
    double centre_err_sum;                           /* complete, identified: px */
    int centre_n;
    int local_found;
    int id_complete[RL_MAX_IDS], id_ident[RL_MAX_IDS]; /* complete landmarks per id */
    int twin, twin_ident; /* complete landmarks whose id another one in the frame holds too */
} eval_counts;

/* Load NAME.yaml next to NAME.png; 0 on success, else prints why. */
int truth_load(const char *yaml, truth *t);

/* Frame k of SET in DIR (DIR/SET_NNN.yaml): 1 loaded, 0 when there is no
 * such frame (a set's end), -1 when its YAML does not load. */
int truth_load_frame(const char *dir, const char *set, int k, truth *t);

/* A test's frames: DIR and its SET names (the arguments DIR SET...). */
typedef struct {
    const char *dir;
    const char *const *sets;
    int n;
} fixture_sets;

/* *fs from a test's arguments; 0, with a usage line naming prog on
 * stderr, when there are not a DIR and a SET. */
int fixture_sets_args(int argc, char **argv, const char *prog, fixture_sets *fs);

/* The next frame of fs into *t, from set *s frame *k on (both 0 at
 * first): 1 (*s the set it is of), 0 after the last set's last frame, -1
 * when a frame's YAML does not load. */
int fixture_sets_next(const fixture_sets *fs, int *s, int *k, truth *t);

/* The complete landmarks of each id seen, and how many identified, as
 * one line ("  per id: 1 12/12, 2 9/10 ..."); the worst id's rate (1
 * when none was seen), its id in *worst. */
double eval_per_id(const eval_counts *c, FILE *out, int *worst);

/* Match one result to its truth and add to the counts. */
void eval_frame(const truth *t, const rl_result *res, eval_counts *c, int verbose);

#endif
