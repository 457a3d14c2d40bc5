/* Every YAML loader (map, camera, robot, offsets, run configuration) on
 * arbitrary text: the first byte picks the loader. A loaded file holds
 * numbers within their limits; an error names the file. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_file.h"
#include "rl_calibfile.h"
#include "rl_mapfile.h"
#include "rl_offsetsfile.h"
#include "rl_robotfile.h"
#include "rl_runcfg.h"

static rl_map map;
static rl_runcfg rc;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[512];
    const char *path;
    rl_err e = RL_OK;
    int i;
    if (size < 1)
        return 0;
    path = fuzz_file(data + 1, size - 1, ".yaml");
    err[0] = '\0';
    switch (data[0] % 5) {
    case 0:
        if ((e = rl_mapfile_load(path, &map, err, sizeof err)) == RL_OK) {
            int bad;
            if (rl_map_check(&map, &bad) != RL_OK)
                abort();
        }
        break;
    case 1: {
        rl_calib cam;
        if ((e = rl_calibfile_load(path, &cam, err, sizeof err)) == RL_OK && rl_calib_check(&cam) != RL_OK)
            abort();
        break;
    }
    case 2: {
        rl_mount m;
        if ((e = rl_robotfile_load(path, &m, err, sizeof err)) == RL_OK &&
            !(isfinite(m.x) && isfinite(m.y) && isfinite(m.z) && isfinite(m.yaw) && fabs(m.roll) <= 0.5 &&
              fabs(m.pitch) <= 0.5 && m.rocking >= 0 && m.rocking <= RL_POSE_ROCKING_MAX))
            abort();
        break;
    }
    case 3: {
        rl_offsets o;
        if ((e = rl_offsetsfile_load(path, &o, err, sizeof err)) == RL_OK)
            for (i = 0; i < RL_OFFSET_TERMS; i++)
                if (!isfinite(o.cx[i]) || !isfinite(o.cy[i]))
                    abort();
        break;
    }
    default:
        e = rl_runcfg_load(path, &rc, err, sizeof err);
        break;
    }
    if (e != RL_OK && strstr(err, path) == NULL)
        abort(); /* every error names the file */
    return 0;
}
