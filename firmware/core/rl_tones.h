/* rl_tones: the tone curve a frame is read through: the configured one,
 * or, when the configuration leaves it open (gamma 0, the default), the
 * one the landmarks read best through, learned frame by frame (internal).
 *
 * Cameras differ: the sRGB-like output of V4L2, libcamera and webcams
 * (gamma near 2.2) and the linear output of machine-vision cameras with
 * gamma off (1). Read through the wrong curve, blurred zones swell or
 * shrink and a few landmarks pass for their zone twins, so the curve is
 * not guessed: while unsettled, each frame's candidates are read through
 * both, and the curve that identifies more of them earns a vote (the
 * votes of past frames fade); where both identify as many, the current
 * curve earns it (a frame with no landmark votes for neither, nor fades
 * the votes: it says nothing). The current curve (2.2 at first) gives way
 * when the other leads it by more than two votes; a frame is read through the current
 * curve unless the other identifies two landmarks more there. Once one
 * curve leads by RL_TONES_SETTLE votes only it is read, and both again
 * every RL_TONES_RECHECK frames (a camera's settings can change).
 *
 *   rl_tones ts;
 *   int which[RL_TONES_MAX], n = 0, k;
 *   rl_tones_init(&ts, 0.0);                  // auto
 *   n = rl_tones_to_try(&ts, which);           // 2 at first
 *   for (k = 0; k < n; k++)
 *       use(&ts.tone[which[k]]);               // read the frame's candidates
 *   rl_tones_vote(&ts, which, n, (int[]){5, 3});
 *   use(rl_tones_current(&ts), rl_tones_gamma(&ts));
 */
#ifndef RL_TONES_H
#define RL_TONES_H

#include "rl_tone.h"

#define RL_TONES_MAX 2
#define RL_TONES_SETTLE 6.0
#define RL_TONES_RECHECK 16
/* The steepest tone curve a camera is taken to have (the held-out
 * cameras reach gamma 2.6): a frame read as linear is doubted against it
 * too (rl_tones_steep). */
#define RL_TONES_STEEP 2.6

typedef struct {
    rl_tone tone[RL_TONES_MAX];   /* both made, whether configured or not */
    uint16_t steep_dark[256];     /* RL_TONES_STEEP's darkness per grey level (rl_tone.packed's
                                     low words), made with them: 512 B where the whole curve is
                                     3 kB, made whole only where it is read (rl_tones_steep) */
    double gamma[RL_TONES_MAX];
    double votes[RL_TONES_MAX];
    int n;        /* curves to choose from: 1 when configured */
    int current;  /* the curve frames are read through now */
    unsigned frames;
} rl_tones;

/* gamma 1 .. 3: that curve only (and the other formation's for doubt,
 * rl_tones_other); 0: choose between 1 and 2.2. */
void rl_tones_init(rl_tones *ts, double gamma);

/* The curves to read this frame through (indices into ts->tone, the
 * current one first), their count. */
int rl_tones_to_try(const rl_tones *ts, int *which);

/* After a frame read through the n curves of which[] (the current one
 * first): identified[k] landmarks through which[k]. The votes and the current curve as above; the index into
 * which[] of the curve the frame is to be read through is returned. */
int rl_tones_vote(rl_tones *ts, const int *which, int n, const int *identified);

/* 1 when a frame's read through the other curve can stop: with `other`
 * of its candidates identified through it so far and `left` still to
 * read, and `current` identified through the current curve, no count the
 * rest could add changes what rl_tones_vote does (the other cannot
 * identify more than the current curve, whatever the rest: every such
 * count votes alike; or it already identifies CLEAR_LEAD more: the frame
 * is read through it). The count so far then stands for the whole read. */
int rl_tones_decided(int current, int other, int left);

const rl_tone *rl_tones_current(const rl_tones *ts);

/* The other curve while the choice is open (auto, not settled), else NULL:
 * what a frame read through `used` is to be doubted against. */
const rl_tone *rl_tones_doubt(const rl_tones *ts, const rl_tone *used);
/* The other image formation, always (configured or not): grey levels
 * mixed after the curve (gamma 1) for a frame read through a curve, the
 * sRGB-like curve (2.2) for one read as linear light. A landmark's id is
 * taken only if its zone twins do not read better there (rl_twins.h). */
const rl_tone *rl_tones_other(const rl_tones *ts, const rl_tone *used);

/* The steepest camera curve (RL_TONES_STEEP) into *t: the far end of the
 * formations a frame read as linear light could have come from, the
 * other (2.2) between (rl_twins.c: an id read as linear is taken only
 * where its rivals do not read better there either). t->packed is
 * rl_tone_init(t, RL_TONES_STEEP)'s, the same bits; t->light is its
 * darkness's complement (the light rounded to whole steps): the steep
 * curve is only gathered through (rl_profile reads packed alone). A
 * curve kept whole a frame would cost the workspace 3 kB, made here
 * from 512 B in 256 steps. */
void rl_tones_steep(const rl_tones *ts, rl_tone *t);

double rl_tones_gamma(const rl_tones *ts);

#endif
