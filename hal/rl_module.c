#include "rl_module.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

rl_err rl_module_symbol(const char *file, const char *symbol, void (**fn)(void), char *err, size_t errlen)
{
    void *sym;
    void *h = dlopen(file, RTLD_NOW | RTLD_LOCAL);
    const char *why;
    *fn = NULL;
    if (h == NULL) {
        why = dlerror();
        snprintf(err, errlen, "cannot load the module %s (it is installed in lib/ringloc beside the "
                              "program): %s", file, why ? why : "unknown reason");
        return RL_EUNSUPPORTED;
    }
    dlerror();
    sym = dlsym(h, symbol);
    if (sym == NULL) {
        why = dlerror();
        snprintf(err, errlen, "module %s has no %s: %s", file, symbol, why ? why : "no such symbol");
        return RL_EUNSUPPORTED;
    }
    /* POSIX: a function's address from dlsym may be read as one */
    memcpy(fn, &sym, sizeof sym);
    return RL_OK;
}
