/* rl_match: identification by Pearson's correlation against the radial
 * templates, the paper's identification step (internal).
 *
 * Every pixel of a candidate within 1.2 R of its centre is compared with
 * every template: Pearson's r between the pixels' darkness (255 - I) and
 * the template's darkness at the same radius, computed from a profile's
 * per-bin sums (rl_profile.h) in one pass over the bins per block of
 * columns (rl_match_kernel.h). r is invariant to gain and offset, so no
 * binary image is needed; the fitted gain is reported as the contrast.
 *
 *   rl_match m;
 *   static rl_match_list ls;
 *   rl_match_all(&tt, &p, &m);                      // m.id, m.score, m.second
 *   rl_match_list_make(&tt, ids, 3, m.blur, &ls);   // a short list, made once
 *   rl_match_list_score(&ls, &p, &m);               // scored for many profiles
 */
#ifndef RL_MATCH_H
#define RL_MATCH_H

#include <stdint.h>
#include "rl_profile.h"
#include "rl_templates.h"

typedef struct {
    int id;          /* best template's id, or -1 */
    double score;    /* its Pearson correlation */
    double second;   /* best correlation of any other id */
    double contrast; /* fitted darkness difference between the template's black
                        and white, grey levels */
    int blur;        /* blur level of the best template */
} rl_match;

/* Up to RL_MATCH_BLOCK (id, blur) columns copied out of a table into one
 * block, for scoring the same few templates against many profiles. */
typedef struct {
    float table[RL_PROFILE_BINS * RL_MATCH_BLOCK]; /* bin-major, unused columns 0 */
    int id[RL_MATCH_BLOCK], blur[RL_MATCH_BLOCK];
    int n;
} rl_match_list;

/* Score every template against a profile. */
void rl_match_all(const rl_templates *tt, const rl_profile *p, rl_match *m);

/* Every column's sums against one profile (the columns of the table,
 * padded to whole blocks), kept by rl_match_all_kept so that single ids
 * can be scored again from them (rl_match_kept_ids) without a walk over
 * the bins. The three arrays are the caller's memory, carved from a
 * workspace by rl_match_kept_init for one table's columns (its stride:
 * 3 x 4 bytes a column); a table wider than that keeps none and
 * rl_match_kept_ids reads the profile. */
enum { RL_MATCH_KEPT_FLAT, RL_MATCH_KEPT_SUMS, RL_MATCH_KEPT_NONE };
typedef struct {
    int state;            /* RL_MATCH_KEPT_*: a flat profile, the sums, none kept */
    int columns;          /* room: the columns each array holds */
    double n, sx, ivx;    /* the profile's pixels, their sum, 1 / sqrt(variance term) */
    float *st, *stt, *sxt;
} rl_match_kept;

/* Bytes rl_match_kept_init takes from a workspace for a table of
 * `columns` columns (its stride), the rl_match_kept included. */
size_t rl_match_kept_bytes(int columns);

/* An rl_match_kept with room for tt's columns, carved from ws into *out
 * (NULL while ws is sizing); none kept yet. RL_ENOMEM when ws is too
 * small. */
RL_CHECK rl_err rl_match_kept_init(rl_match_kept **out, rl_ws *ws, const rl_templates *tt);

/* rl_match_all, each column's sums kept into *keep (the same match, bit
 * for bit). */
void rl_match_all_kept(const rl_templates *tt, const rl_profile *p, rl_match *m, rl_match_kept *keep);

/* rl_match_all_kept for a read that wants only id, at a blur up to
 * max_blur, as the winner: 1 and the same match and sums, bit for bit;
 * 0 where it is none of them (no column of theirs scores, or another
 * column, of any id or of id blurrier, scores over all of them: the
 * walk over the table stops there), m then no match to use and keep
 * holding none (state NONE). */
int rl_match_all_kept_as(const rl_templates *tt, const rl_profile *p, int id, int max_blur, rl_match *m,
                         rl_match_kept *keep);

/* rl_match_ids(tt, p, ids, n, -1, m), the same bits, from the sums
 * rl_match_all_kept kept of p into *keep (p is read again only where
 * none were kept). */
void rl_match_kept_ids(const rl_templates *tt, const rl_profile *p, const rl_match_kept *keep, const int *ids,
                       int n, rl_match *m);

/* Score only the templates of the given ids, at one blur level
 * (0 .. RL_BLUR_LEVELS - 1) or at all of them (blur < 0). Ids the table
 * does not hold are skipped. */
void rl_match_ids(const rl_templates *tt, const rl_profile *p, const int *ids, int n, int blur,
                  rl_match *m);

/* rl_match_ids for id alone into *own and for ids into *m, on one
 * profile: its terms worked out once (the zone twins' check scores an id
 * and its rivals at each radius). own and m must be two matches. */
void rl_match_id_and_ids(const rl_templates *tt, const rl_profile *p, int id, const int *ids, int n,
                         int blur, rl_match *own, rl_match *m);

/* rl_match_id_and_ids for id and every other id of the table (in table
 * order), at every blur, in one walk over the table (the match of every
 * id's columns, wide blocks at a time): id's columns kept into *own, the
 * rest into *rest, the same bits as rl_match_id_and_ids with ids every
 * other id of a table that holds each id once (the zone twins' check of
 * a local read, rl_twins). own and rest must be two matches. */
void rl_match_id_and_rest(const rl_templates *tt, const rl_profile *p, int id, rl_match *own, rl_match *rest);

/* Each id's best score over its templates at every blur, into best[j]
 * (-2 for an id the table does not hold, or a profile that correlates
 * with nothing): rl_match_ids on each id alone, the profile's terms
 * worked out once. */
void rl_match_ids_each(const rl_templates *tt, const rl_profile *p, const int *ids, int n,
                       double *best);

/* A list of the templates of n ids at one blur level (every level when
 * blur < 0); columns past RL_MATCH_BLOCK, and ids not in the table, are
 * left out. */
void rl_match_list_make(const rl_templates *tt, const int *ids, int n, int blur,
                        rl_match_list *ls);

/* Score a list's templates against a profile. */
void rl_match_list_score(const rl_match_list *ls, const rl_profile *p, rl_match *m);

/* Pearson's correlation of a and b over the cells where mask != 0 (all
 * when NULL); 0 when either side is constant. The direct formula, for
 * tests and tools. */
/* The zone twins of id: the valid codes that differ from it in code zone
 * 1 or 2, the zones next to the outer ring, which a radius error or blur
 * confuses most (at most 2, into twins); their count. */
int rl_match_twins(const rl_templates *tt, int id, int *twins);

double rl_match_pearson(const uint8_t *a, const uint8_t *b, const uint8_t *mask, int n);

#endif
