/* The pose solver on arbitrary detections, calibrations, maps and mounts
 * (raw doubles from the input): RL_OK only with every number finite. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fuzz_take.h"
#include "rl_calib.h"
#include "rl_map.h"
#include "rl_pose.h"

static rl_map map;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rl_calib cam;
    rl_mount mount;
    rl_detection det[8];
    rl_pose pose;
    int i, nd, nm;
    if (size < 2)
        return 0;
    nd = data[0] % 9;
    nm = 1 + data[1] % 8;
    data += 2;
    size -= 2;
    rl_calib_defaults(&cam, 640, 480, 1.2);
    cam.model = (rl_dist_model)(size > 0 ? data[0] % 3 : 0);
    cam.fx = fuzz_take(&data, &size);
    cam.fy = fuzz_take(&data, &size);
    cam.cx = fuzz_take(&data, &size);
    cam.cy = fuzz_take(&data, &size);
    for (i = 0; i < 8; i++)
        cam.k[i] = fuzz_take(&data, &size);
    mount.x = fuzz_take(&data, &size);
    mount.y = fuzz_take(&data, &size);
    mount.z = fuzz_take(&data, &size);
    mount.yaw = fuzz_take(&data, &size);
    mount.roll = fuzz_take(&data, &size) * 1e-3; /* mostly within the 0.5 rad a mount may have */
    mount.pitch = fuzz_take(&data, &size) * 1e-3;
    mount.rocking = fuzz_take(&data, &size) * 1e-3; /* mostly within 0 .. RL_POSE_ROCKING_MAX, some not */
    memset(&map, 0, sizeof map);
    map.family.bits = 5;
    map.diameter = 0.21;
    map.ceiling_height = fuzz_take(&data, &size);
    map.count = nm;
    for (i = 0; i < nm; i++) {
        map.lm[i].id = i + 1;
        map.lm[i].x = fuzz_take(&data, &size);
        map.lm[i].y = fuzz_take(&data, &size);
    }
    memset(det, 0, sizeof det);
    for (i = 0; i < nd; i++) {
        det[i].id = 1 + i % 9;
        det[i].u = fuzz_take(&data, &size);
        det[i].v = fuzz_take(&data, &size);
        det[i].radius = 25;
    }
    if (rl_pose_solve(&cam, &map, &mount, det, nd, NULL, &pose) == RL_OK &&
        !(isfinite(pose.x) && isfinite(pose.y) && isfinite(pose.yaw) && isfinite(pose.residual)))
        abort();
    return 0;
}
