/* rl_module: a part built as a loadable module, loaded the first time it
 * is used.
 *
 * What links a large library stack is a module in lib/ringloc/ next to the
 * programs' bin/ (the package's /usr/lib/ringloc; the build's lib/ringloc,
 * which its program folders reach as ../lib/ringloc), so no other start of
 * `ringloc` or `ringloc-fw` loads and relocates it: libcamera (the camera
 * backend, with its tracer) and Ceres Solver (the survey's adjustment)
 * were half of a start. A module is found from the program's own folder
 * only (/proc/self/exe; never the library path or the current folder),
 * must say it was built for this program's version and layout, and is
 * never unloaded.
 *
 *   static const rl_module solver = {"ringloc-ceres.so", "the survey's solver (package ringloc-tools)",
 *                                    RL_MODULE_ABI(sizeof(rl_map), sizeof(rl_calib))}; // its structures' sizes
 *   void (*fn)(void);
 *   char err[256];
 *   if (rl_module_symbol(&solver, "rl_survey_adjust_ceres", &fn, err, sizeof err) == RL_OK)
 *       use(fn);                    // cast to the entry point's own type, then called
 */
#ifndef RL_MODULE_H
#define RL_MODULE_H

#include <stddef.h>
#include "rl_error.h"

/* A module's entry point (the only symbols it makes visible). */
#define RL_MODULE_EXPORT __attribute__((visibility("default")))

/* The version and layout a module and its program must share: the
 * project's version (RL_VERSION_CODE) and the sizes of the structures its
 * entry points take. Every module exports rl_module_abi() returning its
 * own. */
#define RL_MODULE_ABI(size_a, size_b)                                                                      \
    ((unsigned long)RL_VERSION_CODE * 1000003UL + (unsigned long)(size_a) * 1009UL + (unsigned long)(size_b))
typedef unsigned long (*rl_module_abi_fn)(void);

typedef struct {
    const char *file;  /* in lib/ringloc: "ringloc-libcamera.so" */
    const char *what;  /* for the message: "the libcamera camera backend (package ringloc)" */
    unsigned long abi; /* RL_MODULE_ABI of what the program was built with */
} rl_module;

/* *fn = the function symbol of module m, or RL_EUNSUPPORTED with err one
 * line naming what the module is for, its path and the reason (not found,
 * not loadable, built for another version or layout, no such symbol). */
RL_CHECK rl_err rl_module_symbol(const rl_module *m, const char *symbol, void (**fn)(void), char *err,
                                 size_t errlen);

#endif
