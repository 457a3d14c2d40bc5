/* render_look: each set's looks (render_look.h). */
#include "render_look.h"

#include <math.h>
#include "render_random.h"
#include "rl_print.h"

/* The scene's sheets: paper `name` (a paper rl_paper_find knows). */
static void use_sheet(render_scene *s, const char *name)
{
    const rl_paper *p = rl_paper_find(name);
    s->sheet_w = p->w_mm / 1000.0;
    s->sheet_h = p->h_mm / 1000.0;
}

/* A camera moving in dim light: ranges its frames are drawn from. */
typedef struct {
    double blur[2], defocus[2]; /* optics, px */
    double motion_px[2], turn;  /* travel during the exposure, px; turn, rad either way */
    double gain[2];             /* exposure */
    double full_well[2], read_noise[2], vignette[2];
    double ceiling[2];          /* the ceiling's brightness, times the default tile's */
    render_tone tone;
    int adc_bits;
} moving_look;

/* The development set: blur on the light, motion of any direction and a
 * turn, short exposures on sensors of several sizes, on ceilings darker
 * and lighter than paper (the sheets: every paper, drawn per frame). */
static const moving_look moving = {{0.6, 1.4}, {0, 0}, {1.0, 6.0}, 0.015, {0.25, 0.7},
                                   {2500, 9000}, {1.5, 4.0}, {0.1, 0.4}, {0.55, 1.3}, RENDER_TONE_GAMMA22, 10};
/* The set nothing is tuned on: another optics (a defocus disk), another
 * tone curve (sRGB), 12-bit raw values, the paper's letter sheets (3 mm
 * beside a 0.21 m landmark). Its figures are read, never worked towards. */
static const moving_look heldout = {{0.3, 0.8}, {0.5, 1.3}, {2.0, 6.0}, 0.015, {0.3, 0.5},
                                    {3000, 6000}, {2.0, 4.0}, {0.2, 0.45}, {0.6, 1.25}, RENDER_TONE_SRGB, 12};

static void moving_effects(render_scene *s, const moving_look *m)
{
    s->se.tone = m->tone;
    s->se.adc_bits = m->adc_bits;
    s->se.blur = render_random_uniform(m->blur[0], m->blur[1]);
    s->se.defocus = m->defocus[1] > 0 ? render_random_uniform(m->defocus[0], m->defocus[1]) : 0;
    s->motion = render_random_uniform(m->motion_px[0], m->motion_px[1]) / s->cam.fx * s->distance;
    s->motion_dir = render_random_uniform(0, 2 * M_PI);
    s->motion_turn = render_random_uniform(-m->turn, m->turn);
    s->gain = render_random_uniform(m->gain[0], m->gain[1]);
    s->se.full_well = render_random_uniform(m->full_well[0], m->full_well[1]);
    s->se.read_noise = render_random_uniform(m->read_noise[0], m->read_noise[1]);
    s->vignette = render_random_uniform(m->vignette[0], m->vignette[1]);
    s->ceiling = render_random_uniform(m->ceiling[0], m->ceiling[1]);
}

void render_look_apply(render_scene *s, render_set kind)
{
    s->gain = 1.0;
    s->vignette = 0.15;
    render_sensor_defaults(&s->se);
    s->se.blur = 0.5;
    s->se.read_noise = 1.5;
    s->motion = 0;
    s->motion_turn = 0;
    s->sheet_w = s->sheet_h = 0;
    s->ceiling = 1.0;
    s->halo_amp = render_random_uniform(0.3, 0.7);
    s->halo_sigma = render_random_uniform(0.03, 0.07);
    s->ink = RENDER_INK;
    s->ramp = s->shadow = 0;
    switch (kind) {
    case RENDER_SET_CLEAN: s->vignette = 0.1; s->se.read_noise = 1.0; break;
    case RENDER_SET_CLUTTERED: s->vignette = render_random_uniform(0.1, 0.4); s->se.blur = render_random_uniform(0.4, 1.0); s->se.read_noise = render_random_uniform(1, 3); s->gain = render_random_uniform(0.7, 1.1); break;
    case RENDER_SET_GLARE: s->halo_amp = render_random_uniform(0.5, 0.9); s->halo_sigma = render_random_uniform(0.04, 0.07); break;
    case RENDER_SET_BORDER: s->vignette = 0.3; break;
    case RENDER_SET_CLUTTER_ONLY: s->se.blur = render_random_uniform(0.4, 1.0); s->se.read_noise = 2; break;
    case RENDER_SET_DIM: s->gain = render_random_uniform(0.25, 0.4); s->se.read_noise = 2.5; s->vignette = 0.35; break;
    case RENDER_SET_BLUR: s->se.blur = render_random_uniform(1.2, 1.8); break;
    case RENDER_SET_MOTION: s->motion = render_random_uniform(0.015, 0.03); s->motion_dir = render_random_uniform(0, 2 * M_PI); break;
    case RENDER_SET_ILLUM:
        /* what real ceilings do to a frame: lens vignetting as strong as a
         * wide-angle's, light falling off across the frame, a shadow on
         * one side (a wall), ink that is dark grey rather than black */
        s->vignette = render_random_uniform(0.45, 0.6);
        s->ramp = render_random_uniform(0.2, 0.5);
        s->ramp_dir = render_random_uniform(0, 2 * M_PI);
        s->shadow = render_random_uniform(0.3, 0.6);
        s->shadow_at = render_random_uniform(0.4, 0.8);
        s->shadow_dir = render_random_uniform(0, 2 * M_PI);
        s->ink = render_random_uniform(0.06, 0.2);
        s->se.blur = render_random_uniform(0.5, 1.0);
        s->se.read_noise = render_random_uniform(1.5, 3);
        break;
    case RENDER_SET_DEGRADED:
        /* blur 1.1 px, 4 px of motion, 0.35 of the exposure on a sensor:
         * photon noise (4,500 e- at the white point) and read noise 3 DN
         * before the tone curve */
        s->se.blur = 1.1;
        s->motion = 4.0 / s->cam.fx * s->distance;
        s->motion_dir = render_random_uniform(0, 2 * M_PI);
        s->gain = 0.35;
        s->se.full_well = 4500;
        s->se.read_noise = 3.0;
        break;
    case RENDER_SET_MOVING: {
        static const char *papers[] = {"letter", "a4", "a3"};
        int k = (int)(render_random_next() % 4);
        moving_effects(s, &moving);
        if (k < 3)
            use_sheet(s, papers[k]);
        break;
    }
    case RENDER_SET_HELDOUT:
        moving_effects(s, &heldout);
        use_sheet(s, "letter");
        break;
    case RENDER_SET_LENS:
        /* a wide-angle M12 lens (3.6 mm class) as on the real photos:
         * strong barrel distortion, so landmarks towards the border are
         * ellipses (flattened radially, to about 0.8 at the edge) and
         * smaller, with the vignetting such lenses have */
        s->cam.k[0] = -0.22;
        s->cam.k[1] = 0.04;
        s->vignette = render_random_uniform(0.35, 0.55);
        s->se.blur = render_random_uniform(0.5, 0.9);
        s->se.read_noise = render_random_uniform(1.5, 2.5);
        break;
    case RENDER_SET_REPEATS: s->vignette = render_random_uniform(0.1, 0.3); break;
    case RENDER_SET_PATH:
    case RENDER_SET_COUNT: break;
    }
}
