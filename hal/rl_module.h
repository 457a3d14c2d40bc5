/* rl_module: a part built as a loadable module, loaded the first time it
 * is used.
 *
 * What links a large library stack is a module beside the programs
 * (lib/ringloc/ in the package; the build's lib/ringloc/), so every other
 * start of `ringloc` or `ringloc-fw` does not load and relocate it:
 * libcamera (the camera backend, with its tracer) and Ceres Solver (the
 * survey's adjustment) were 60-70% of a start. The programs' run path
 * names the directory; a module is never unloaded.
 *
 *   void (*fn)(void);
 *   char err[256];
 *   if (rl_module_symbol("ringloc-ceres.so", "rl_survey_adjust_ceres", &fn, err, sizeof err) == RL_OK)
 *       use(fn);                    // cast to the entry point's own type, then called
 */
#ifndef RL_MODULE_H
#define RL_MODULE_H

#include <stddef.h>
#include "rl_error.h"

/* A module's entry point (the only symbols it makes visible). */
#define RL_MODULE_EXPORT __attribute__((visibility("default")))

/* *fn = the function symbol of module file, or RL_EUNSUPPORTED with err
 * naming the module, the symbol and the loader's reason. */
RL_CHECK rl_err rl_module_symbol(const char *file, const char *symbol, void (**fn)(void), char *err,
                                 size_t errlen);

#endif
