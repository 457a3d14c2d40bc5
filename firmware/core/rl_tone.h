/* rl_tone: the camera's tone curve, undone for identification (internal).
 *
 * A camera's grey level is not proportional to light: sensors count
 * light, and the camera maps it to grey through a tone curve (sRGB-like,
 * g = 255 (E / E_white)^(1 / gamma) with gamma near 2.2) that lifts the
 * dark end. Blur and motion mix light, not grey levels, so in grey levels
 * a blurred edge is no longer the symmetric step the templates hold: dark
 * zones shrink and white ones swell by about a pixel at a robot's blur,
 * which reads a landmark's radius short and turns a black first code zone
 * into a white one (its zone twin). Identification therefore works on
 * light: every grey level it reads goes through these tables first, in
 * RL_TONE_MAX steps (a landmark in a dark corner still spans many). The
 * regions (thresholds, labels) are found on grey levels: an increasing
 * map keeps their order, and their thresholds are placed halfway in light.
 *
 *   rl_tone t;
 *   rl_tone_init(&t, 2.2);     // t.light[128] == 224.5,
 *                              // t.packed[128] == RL_TONE_PACK_COUNT + 798 (darkness 798)
 *   double span = rl_tone_light(&t, 180.0) - rl_tone_light(&t, 40.0);
 */
#ifndef RL_TONE_H
#define RL_TONE_H

#include <stdint.h>

/* Light of the white point (grey 255). */
#define RL_TONE_MAX 1023

/* A pixel's count in rl_tone.packed: the word's high half. */
#define RL_TONE_PACK_COUNT (1ull << 32)

typedef struct {
    float light[256];   /* light of each grey level, 0 .. RL_TONE_MAX */
    uint64_t packed[256]; /* RL_TONE_PACK_COUNT + darkness (RL_TONE_MAX - light, rounded,
                             what the profiles sum): one pixel's (count, darkness) in one
                             word, what rl_profile adds into a bin (made once a curve,
                             not once a gather) */
} rl_tone;

/* The tables for a tone curve of exponent gamma (1: a linear camera),
 * both. */
void rl_tone_init(rl_tone *t, double gamma);

/* Light of a grey level between the table's entries (linear in between);
 * levels outside 0 .. 255 are clamped. */
double rl_tone_light(const rl_tone *t, double grey);

/* The grey level where light is halfway between that of grey levels g0
 * and g1: the threshold that splits a blurred edge between them where a
 * symmetric blur leaves the printed edge (pixels below it are the darker
 * side). Found by halving: t's light must never fall as the grey level
 * rises (true of every curve rl_tone_init makes with a gamma over 0). */
int rl_tone_midway(const rl_tone *t, double g0, double g1);

#endif
