/* render_path: the fixed site's drives (render_path.h). */
#include "render_path.h"

#include <math.h>
#include <string.h>

int render_path_pose(const char *kind, double k, int n, double *x, double *y, double *yaw)
{
    double t = n > 1 ? k / (n - 1) : 0;
    if (strcmp(kind, "straight") == 0) {
        *x = 0.6 + 2.4 * t;
        *y = 1.55;
        *yaw = 0.0;
    } else if (strcmp(kind, "circle") == 0) {
        double a = 2 * M_PI * t * (n - 1) / n;
        *x = 1.83 + 0.6 * cos(a);
        *y = 1.52 + 0.6 * sin(a);
        *yaw = a + M_PI / 2;
    } else if (strcmp(kind, "rect") == 0) {
        /* perimeter of (0.9, 0.9)-(2.7, 2.1), heading along each edge */
        double w = 1.8, h = 1.2, p = t * 2 * (w + h) * (n - 1) / n;
        if (p < w) { *x = 0.9 + p; *y = 0.9; *yaw = 0; }
        else if (p < w + h) { *x = 2.7; *y = 0.9 + p - w; *yaw = M_PI / 2; }
        else if (p < 2 * w + h) { *x = 2.7 - (p - w - h); *y = 2.1; *yaw = M_PI; }
        else { *x = 0.9; *y = 2.1 - (p - 2 * w - h); *yaw = -M_PI / 2; }
    } else if (strcmp(kind, "survey") == 0) {
        /* back and forth in three rows across the site, weaving */
        double row = 3.05, turn = 0.9, L = 3 * row + 2 * turn, p = t * L, w = 0.5 * sin(2 * M_PI * 7 * t);
        int r = (int)(p / (row + turn));
        double q = p - r * (row + turn);
        if (r > 2)
            r = 2, q = row;
        if (q < row) {
            *x = r % 2 ? 3.35 - q : 0.3 + q;
            *y = 0.6 + 0.9 * r;
            *yaw = (r % 2 ? M_PI : 0) + w;
        } else {
            *x = r % 2 ? 0.3 : 3.35;
            *y = 0.6 + 0.9 * r + (q - row);
            *yaw = M_PI / 2 + w;
        }
    } else {
        return -1;
    }
    *yaw = atan2(sin(*yaw), cos(*yaw));
    return 0;
}
