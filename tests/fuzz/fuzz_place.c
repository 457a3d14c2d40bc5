/* The place finder on arbitrary maps that repeat ids, detections and
 * priors (raw doubles from the input): the index built in its own size,
 * RL_OK only with a finite pose and every match a landmark of the
 * detection's id. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_take.h"
#include "rl_calib.h"
#include "rl_map.h"
#include "rl_place.h"

static rl_map map;
static unsigned char mem[1 << 18];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rl_calib cam;
    rl_mount mount;
    rl_detection det[12];
    rl_place_config cfg;
    rl_place_prior prior;
    rl_place_found f;
    rl_place *pl;
    rl_pose pose;
    size_t need;
    int i, nd, nm, ids;
    if (size < 3)
        return 0;
    nd = data[0] % 13;
    nm = 2 + data[1] % 23;
    ids = 1 + data[2] % 6; /* few ids: they repeat */
    data += 3;
    size -= 3;
    rl_calib_defaults(&cam, 640, 480, 1.2);
    rl_mount_defaults(&mount, 0.88);
    memset(&map, 0, sizeof map);
    map.family.bits = 5;
    map.diameter = 0.2;
    map.ceiling_height = 2.75;
    map.count = nm;
    for (i = 0; i < nm; i++) {
        map.lm[i].id = 1 + i % ids;
        map.lm[i].x = fuzz_take(&data, &size);
        map.lm[i].y = fuzz_take(&data, &size);
    }
    rl_place_defaults(&cfg);
    cfg.reach = fabs(fuzz_take(&data, &size));
    cfg.gate = fabs(fuzz_take(&data, &size));
    need = rl_place_size(&map, &cfg);
    if (need == 0 || need > sizeof mem)
        return 0; /* a map or configuration it refuses, or too large here */
    if (rl_place_init(&pl, &map, &cfg, mem, need) != RL_OK)
        abort(); /* the size it asked for must do */
    memset(det, 0, sizeof det);
    for (i = 0; i < nd; i++) {
        double pick = fmod(fabs(fuzz_take(&data, &size)) * 7, 8.0);
        det[i].id = 1 + (isfinite(pick) ? (int)pick : 0);
        det[i].u = fuzz_take(&data, &size);
        det[i].v = fuzz_take(&data, &size);
        det[i].radius = 25;
        det[i].complete = i % 3 != 0;
    }
    prior.valid = nd % 2;
    prior.x = fuzz_take(&data, &size);
    prior.y = fuzz_take(&data, &size);
    prior.yaw = fuzz_take(&data, &size);
    prior.age = fuzz_take(&data, &size);
    if (rl_place_solve(pl, &cam, &mount, det, nd, NULL, &prior, &pose, &f) == RL_OK) {
        if (!(isfinite(pose.x) && isfinite(pose.y) && isfinite(pose.yaw)))
            abort();
        for (i = 0; i < nd; i++)
            if (f.match[i] >= nm || (f.match[i] >= 0 && map.lm[f.match[i]].id != det[i].id))
                abort();
    }
    return 0;
}
