/* rl_templates: the radial template table that identification scores
 * against (internal).
 *
 * For every id of the recognizer and every blur level, the landmark's mean
 * darkness (0 white .. 1 black) in each radial bin of a profile. A blur
 * level is a Gaussian (defocus) and a straight motion during the
 * exposure, as fractions of R, so a blurred or moving landmark matches a
 * blurred template instead of reading as another code. Motion smears a
 * landmark along one direction only; a profile averages every direction,
 * so the moving templates are that average too (the same for any
 * direction of motion). The table is bin-major:
 * for each bin, the value of every (id, blur) column side by side, padded
 * to whole blocks of RL_MATCH_BLOCK columns, so the matcher walks the
 * profile once and updates a block of columns together.
 *
 *   rl_templates t;
 *   if (rl_templates_init(&t, &ws, &fam, NULL, 0) == RL_OK)    // every id
 *       use(rl_templates_bin(&t, 0, 2, 10));                   // id t.ids[0], blur 2, bin 10
 */
#ifndef RL_TEMPLATES_H
#define RL_TEMPLATES_H

#include <stdint.h>
#include "rl_config.h"
#include "rl_error.h"
#include "rl_family.h"
#include "rl_profile.h"
#include "rl_workspace.h"

/* Template blur levels (Gaussian sigma and motion, in units of R),
 * ordered so that the last is the softest (rl_accept: the local pass
 * takes none there). */
#define RL_BLUR_LEVELS 7
/* Columns scored together by the matcher (rl_match_kernel.h). */
#define RL_MATCH_BLOCK 8

typedef struct {
    rl_family fam;
    int n;          /* ids */
    int *ids;       /* the ids */
    float *table;   /* RL_PROFILE_BINS x stride; column i * RL_BLUR_LEVELS + b is
                       id ids[i] at blur b, the rest pads (0) */
    int stride;     /* columns per bin, a multiple of RL_MATCH_BLOCK */
    int16_t at[1 << RL_MAX_BITS]; /* index of id among ids (its first), or -1 */
} rl_templates;
/* at[] holds an index of up to 2^RL_MAX_BITS - 2 ids in 16 bits, and sits
 * in rl_recog (512 bytes at 8 bits): a family of more than 15 bits would
 * wrap it. */
typedef char rl_templates_at_fits[RL_MAX_BITS <= 15 ? 1 : -1];

/* Bytes rl_templates_init takes from a workspace for n ids. */
size_t rl_templates_bytes(int n);

/* Compute the templates of `ids` (every id of the family when ids is NULL)
 * into ws. RL_ERANGE for an id outside the family (or past RL_MAX_BITS), RL_ENOMEM when ws is
 * too small. */
RL_CHECK rl_err rl_templates_init(rl_templates *tt, rl_ws *ws, const rl_family *fam,
                                  const int *ids, int n_ids);

/* Darkness of landmark `id` at normalized radius rho with Gaussian blur
 * sigma (units of R); 0 white .. 1 black. */
double rl_templates_value_at(const rl_family *fam, int id, double rho, double sigma);

/* Table value of the i-th id at a blur level in bin k. */
float rl_templates_bin(const rl_templates *tt, int i, int blur, int k);

/* 1 for a blur level with motion (its template averages every direction). */
int rl_templates_moving(int blur);

/* Index of `id` among tt->ids (its first place), or -1: a look-up, the
 * matcher asks it for every id it scores. */
int rl_templates_find(const rl_templates *tt, int id);

#endif
