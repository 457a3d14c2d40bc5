/* render_scene: adding an object (render_scene.h). */
#include "render_scene.h"

#include <math.h>

int render_scene_add(render_scene *s, render_obj_kind k, double x, double y, double rot, double a, double b, int id)
{
    render_object *o;
    if (s->n == RENDER_MAX_OBJ)
        return -1;
    o = &s->obj[s->n++];
    o->kind = k; o->x = x; o->y = y; o->rot = rot; o->a = a; o->b = b; o->id = id; o->drop = 0;
    o->cr = cos(rot);
    o->sr = sin(rot);
    return 0;
}
