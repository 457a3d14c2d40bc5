/* The survey's input and first map on arbitrary text as detect's JSON
 * lines (json-c, then the association and the level model; the Ceres fit
 * is not part of it): a frame read holds finite observations, a built map
 * finite positions, an error names the file. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_file.h"
#include "rl_survey_input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rl_calib cam;
    rl_family fam = {5};
    rl_survey_config cfg;
    rl_survey sv;
    rl_survey_input in;
    const char *path = fuzz_file(data, size, ".jsonl");
    rl_err e;
    int i;
    rl_calib_defaults(&cam, 640, 480, 70.0 * M_PI / 180.0);
    rl_survey_defaults(&cfg);
    cfg.origin_id = 1;
    cfg.axis_id = 6;
    cfg.pixel_scale = cam.fx;
    rl_survey_init(&sv, &cfg);
    rl_survey_input_init(&in, &cam, &fam, &sv, NULL);
    e = rl_survey_input_path(&in, path);
    if (e != RL_OK && strstr(in.err, "ringloc-fuzz-") == NULL)
        abort(); /* the error names the file */
    for (i = 0; i < sv.n_obs; i++)
        if (!isfinite(sv.obs[i].xn) || !isfinite(sv.obs[i].yn) || !(sv.obs[i].rn >= 0) ||
            !rl_family_valid(&fam, sv.obs[i].id))
            abort();
    if (e == RL_OK && rl_survey_build(&sv) == RL_OK)
        for (i = 0; i < sv.n_lm; i++)
            if (!isfinite(sv.lm[i].x) || !isfinite(sv.lm[i].y))
                abort();
    rl_survey_free(&sv);
    return 0;
}
