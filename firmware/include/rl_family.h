/* rl_family: landmark families ringN, ids, codes and zone radii.
 *
 * The contract is docs/landmark-spec.md: a landmark of radius R has a
 * black outer ring 0.8R..R and N code zones of equal area inside it; zone
 * k = 1 touches the outer ring, zone N is the central disk. The code
 * c_1..c_N (outer to inner) read as binary with c_1 most significant is
 * the id; valid ids are 1 .. 2^N - 2.
 *
 *   rl_family fam;
 *   char code[RL_MAX_BITS + 1];
 *   if (rl_family_parse("ring5", &fam) == RL_OK &&
 *       rl_family_code(&fam, 25, code, sizeof code) == RL_OK)
 *       use(code);                                            // "11001"
 */
#ifndef RL_FAMILY_H
#define RL_FAMILY_H

#include <stddef.h>
#include "rl_config.h"
#include "rl_error.h"

#define RL_FAMILY_MIN_BITS 2
#define RL_OUTER_RING_INNER 0.8 /* inner radius of the outer ring, in R */

typedef struct {
    int bits; /* N, code zones: RL_FAMILY_MIN_BITS .. RL_MAX_BITS */
} rl_family;

/* A family of N code zones; RL_ERANGE outside 2..RL_MAX_BITS. */
RL_CHECK rl_err rl_family_init(rl_family *fam, int bits);

/* Parse a family name "ringN"; RL_EFORMAT if not of that form, RL_ERANGE
 * for N out of range. */
RL_CHECK rl_err rl_family_parse(const char *name, rl_family *fam);

/* Number of valid ids, 2^N - 2. */
int rl_family_count(const rl_family *fam);

/* 1 if id is valid in the family (1 .. 2^N - 2). */
int rl_family_valid(const rl_family *fam, int id);

/* The valid ids one code zone from id, in any zone, into out (room for
 * RL_MAX_BITS); their count. The landmark contract's zone twins are the
 * two of them that differ in c_1 or c_2 (rl_match_twins). */
int rl_family_zone_twins(const rl_family *fam, int id, int *out);

/* Bit c_k (k = 1..N) of a code: 1 black, 0 white. */
int rl_family_bit(const rl_family *fam, int id, int k);

/* Write the code string of `id` (N chars + NUL) into buf; RL_ERANGE for an
 * invalid id, RL_ENOMEM if len < N + 1. */
RL_CHECK rl_err rl_family_code(const rl_family *fam, int id, char *buf, size_t len);

/* The id of a code string of exactly N '0'/'1' chars; RL_EFORMAT for a
 * wrong length or character, RL_ERANGE for all-white or all-black. */
RL_CHECK rl_err rl_family_id(const rl_family *fam, const char *code, int *id);

/* Zone boundary radii as fractions of R, outermost first: r[0] = 1 (outer
 * edge), r[1] = 0.8 (inside of the outer ring), r[1 + k] = inner radius of
 * code zone k, so r[N + 1] = 0. `r` holds N + 2 values. */
void rl_family_radii(const rl_family *fam, double *r);

/* The inner radius (in R) of the id's outermost black band (the outer
 * ring and the black code zones just inside it) when its inner edge is
 * clear: the white inside at least RL_FAMILY_BAND_WHITE R wide; else 0. */
#define RL_FAMILY_BAND_WHITE 0.12
double rl_family_band_inner(const rl_family *fam, int id);

/* Colour of a point at normalized radius rho = distance / R: 1 black,
 * 0 white (outside the landmark is white). */
int rl_family_dark_at(const rl_family *fam, int id, double rho);

#endif
