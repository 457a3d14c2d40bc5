/* Fixture evaluation against the renderer's ground truth: recognition
 * results are matched to true landmarks by position, and counted. */
#ifndef FIXTURE_EVAL_H
#define FIXTURE_EVAL_H

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
} eval_counts;

/* Load NAME.yaml next to NAME.png; 0 on success, else prints why. */
int truth_load(const char *yaml, truth *t);

/* Match one result to its truth and add to the counts. */
void eval_frame(const truth *t, const rl_result *res, eval_counts *c, int verbose);

#endif
