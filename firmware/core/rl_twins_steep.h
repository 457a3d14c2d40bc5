/* rl_twins_steep: a frame read as linear light doubted against the
 * steepest camera curve (rl_tones_steep) too (internal: rl_twins_check's).
 *
 * Read as linear, the formations a frame could have come from run from
 * linear light to the steepest camera curve, the 2.2 curve between (the
 * other formation, rl_tones_other). A 2.2 camera whose processing after
 * its curve sharpens, clips (auto exposure) or compresses (JPEG) moves past
 * 2.2: a dark code zone the blur lifted reads light at 1 and at 2.2 both,
 * and only a steeper curve brings it back dark (sixteenth session: a cut 24
 * read as 16, a 24 as 16, a 17 as 1, a 21 as 1, their twins ahead through
 * 2.6; docs/results.md). A truly linear camera's right reads fall behind
 * their twins through 2.6 too (13% of its letter sheets' right reads), so the
 * steep curve is asked only where the frame says a curve is plausible:
 * its landmarks fit the 2.2 curve nearly as well as linear light or better.
 *
 *   int rv[RL_MAX_IDS], n = rl_twins_rivals(rec, &res.landmarks[0], rv), from[RL_MAX_LANDMARKS] = {0};
 *   unsigned char ask[RL_MAX_LANDMARKS] = {0};
 *   rl_tone steep;
 *   rl_tones_steep(&rec->tones, &steep);
 *   int doubted = rl_twins_steep_doubts(rec, &img, &steep, &res.landmarks[0], rv, n);
 *   ask[0] = (unsigned char)rl_twins_steep_asks(0.0);
 *   double far_fit[RL_MAX_LANDMARKS];
 *   far_fit[0] = NAN;                        // not read: the evidence reads it
 *   rl_twins_steep_settle(rec, &img, &res, ask, from, far_fit, NULL);
 */
#ifndef RL_TWINS_STEEP_H
#define RL_TWINS_STEEP_H

#include "rl_recog_state.h"
#include "rl_twins_lead.h"

/* The frame's evidence for a curve: the median over its identified
 * landmarks of (fit through the 2.2 curve - fit as linear), each the id's
 * best score at 0.97 .. 1.03 of its radius (rl_twins_lead's fit). Over
 * RL_TWINS_STEEP_FRAME a curve is plausible: linear cameras' frames
 * (the development photos' letter sheets at gamma 1) gave -0.005 or less,
 * 2.2 cameras read as linear -0.025 to 0.034, median 0.008; the frames of
 * the wrong reads caught 0.0013-0.017. */
#define RL_TWINS_STEEP_FRAME (-0.002)

/* A read whose lead through the 2.2 curve (rl_twins_check's `lead`) is
 * RL_TWINS_STEEP_ASK or more is not asked (the wrong reads had 0.012 or
 * less; the steep read then runs on the few reads it concerns). */
#define RL_TWINS_STEEP_ASK 0.02

/* Whether a read kept through the 2.2 curve's lead `lead` (rl_twins_check's)
 * is asked by rl_twins_steep_settle: lead under RL_TWINS_STEEP_ASK. */
#define rl_twins_steep_asks(lead) ((lead) < RL_TWINS_STEEP_ASK)

/* Whether d (its rivals rv, n of them: rl_twins_rivals) is doubted: d's id
 * not leading its rivals at 0.91 .. 1.09 of its radius through the
 * steepest camera curve, steep (rl_tones_steep; rl_twins_lead_reached). */
int rl_twins_steep_doubts(const rl_recog *rec, const rl_image *img, const rl_tone *steep, const rl_detection *d,
                          const int *rv, int n);

/* After rl_twins_check_known kept res->landmarks (read as linear; ask[k]:
 * landmark k kept by the leads with rl_twins_steep_asks): where any asked
 * one is doubted and the frame's evidence is over RL_TWINS_STEEP_FRAME,
 * the doubted ones are made unidentified (their kept[from[k]] cleared,
 * kept when not NULL). The same as asking every asked one, then the
 * evidence where any is doubted, but the evidence is weighed at the first
 * doubted one and, where it says linear, the rest are not asked.
 * far_fit[from[k]]: landmark k's id's fit at 0.97 .. 1.03 of its radius
 * through rl_tones_other from a gather at 1.09 (rl_twins_lead's far fit),
 * where rl_twins_check read it, else NAN (read here). */
void rl_twins_steep_settle(const rl_recog *rec, const rl_image *img, rl_result *res, const unsigned char *ask,
                           const int *from, const double *far_fit, unsigned char *kept);

#endif
