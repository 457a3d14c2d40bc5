#include "rl_module.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* The module's symbol, or NULL with why (the loader's words). */
static void *find(void *h, const char *symbol, const char **why)
{
    void *sym;
    dlerror();
    sym = dlsym(h, symbol);
    if (sym == NULL)
        *why = dlerror();
    return sym;
}

/* The running program's folder into path (/proc/self/exe, links
 * resolved); 0 if it cannot be read or does not fit. */
static int program_folder(char *path, size_t len)
{
    ssize_t n = readlink("/proc/self/exe", path, len - 1);
    char *slash;
    if (n <= 0 || (size_t)n >= len - 1)
        return 0;
    path[n] = 0;
    if ((slash = strrchr(path, '/')) == NULL)
        return 0;
    *slash = 0;
    return 1;
}

rl_err rl_module_symbol(const rl_module *m, const char *symbol, void (**fn)(void), char *err, size_t errlen)
{
    char path[1024];
    const char *why = NULL;
    void *h, *sym;
    rl_module_abi_fn abi;
    *fn = NULL;
    /* the program's own folder, links resolved (not ld.so's $ORIGIN, which
     * is the caller's: a sanitizer runtime that wraps dlopen is in /usr/lib) */
    if (!program_folder(path, sizeof path) ||
        (size_t)snprintf(path + strlen(path), sizeof path - strlen(path), "/../lib/ringloc/%s", m->file) >=
            sizeof path - strlen(path)) {
        snprintf(err, errlen, "%s cannot be loaded: the program's own folder is not known", m->what);
        return RL_EUNSUPPORTED;
    }
    if ((h = dlopen(path, RTLD_NOW | RTLD_LOCAL)) == NULL) {
        why = dlerror();
        snprintf(err, errlen, "%s cannot be loaded from lib/ringloc/%s next to the program's folder: %s", m->what,
                 m->file, why ? why : "unknown reason");
        return RL_EUNSUPPORTED;
    }
    if ((sym = find(h, "rl_module_abi", &why)) == NULL) {
        snprintf(err, errlen, "%s (lib/ringloc/%s) is not a ringloc module: %s", m->what, m->file,
                 why ? why : "no rl_module_abi");
        return RL_EUNSUPPORTED;
    }
    memcpy(&abi, &sym, sizeof sym); /* POSIX: dlsym's address read as a function's */
    if (abi() != m->abi) {
        snprintf(err, errlen, "%s (lib/ringloc/%s) was built for another version or layout of ringloc: install "
                              "it and the program from one build", m->what, m->file);
        return RL_EUNSUPPORTED;
    }
    if ((sym = find(h, symbol, &why)) == NULL) {
        snprintf(err, errlen, "%s (lib/ringloc/%s) has no %s: %s", m->what, m->file, symbol,
                 why ? why : "no such symbol");
        return RL_EUNSUPPORTED;
    }
    memcpy(fn, &sym, sizeof sym);
    return RL_OK;
}
