/* rl_twins_lead: how far a landmark's id leads its rivals (its zone
 * twins, or every other id for a local read) read through one tone
 * curve, at its radius and a few percent either side (rl_twins_lead.c
 * says which scales and why). Internal: rl_twins_check's rules weigh
 * these leads.
 *
 *   int rv[RL_MAX_IDS], n = rl_twins_rivals(rec, &res.landmarks[0], rv);
 *   double fit, lead = rl_twins_lead(rec, &img, rec->tone, &res.landmarks[0], rv, n, 0, -1, &fit);
 */
#ifndef RL_TWINS_LEAD_H
#define RL_TWINS_LEAD_H

#include "rl_recog_state.h"

/* The ids d is judged against into out (RL_MAX_IDS of room): its zone
 * twins; for a local read (sector by sector, the centre searched) every
 * other id of rec's table. Returns how many. */
int rl_twins_rivals(const rl_recog *rec, const rl_detection *d, int *out);

/* How far d's id leads its best rival of rv[0 .. n) through tone: its
 * best score over 0.97 .. 1.03 of d's radius (into *fit) less the best
 * rival's there (with far, over 0.91 .. 1.09).
 * Gathered about d's centre from every other row of the ring, or, with
 * axis >= 0 (an rl_motion axis), from that axis's pixels alone. */
double rl_twins_lead(const rl_recog *rec, const rl_image *img, const rl_tone *tone, const rl_detection *d,
                     const int *rv, int n, int far, int axis, double *fit);

/* rec->led_scale made: the bin moves rl_twins_led_read rebins by (once,
 * at init). */
void rl_twins_led_init(rl_recog *rec);

/* 1 when m, the match of every id on p (a profile gathered at d's radius
 * through its curve: the global pass's read d), leads every other id by
 * RL_TWINS_CLEAR and its id leads its twins in code zones 1 and 2 (next
 * to the outer ring: rl_match_twins) at 0.97 of that radius too (read
 * from p, no pixel gathered again): its best score there and at
 * the radius (m->score) over theirs there. At the radius itself no twin
 * scored over m->second. 0 without a look for a small read (under
 * RL_TWINS_FAR_ZONE_PX's radius), which rl_twins checks whatever this
 * says. */
int rl_twins_led_read(const rl_recog *rec, const rl_profile *p, const rl_match *m, const rl_detection *d);

/* !(rl_twins_lead(rec, img, tone, d, rv, n, 1, -1, &fit) > 0): whether a
 * rival reaches d's id at 0.91 .. 1.09 of its radius through tone, the
 * same scores read, stopping at the first scale past the id's own three
 * where one does (rl_twins_steep asks it of a few reads, and a rival that
 * reaches the id is what it looks for). */
int rl_twins_lead_reached(const rl_recog *rec, const rl_image *img, const rl_tone *tone, const rl_detection *d,
                          const int *rv, int n);

#endif
