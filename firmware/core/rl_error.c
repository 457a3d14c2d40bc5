#include "rl_error.h"

const char *rl_strerror(rl_err e)
{
    switch (e) {
    case RL_OK: return "success";
    case RL_EINVAL: return "invalid argument";
    case RL_ENOMEM: return "workspace or buffer too small";
    case RL_ELIMIT: return "compile-time limit reached";
    case RL_ERANGE: return "value out of range";
    case RL_EFORMAT: return "malformed data";
    case RL_EIO: return "input/output error";
    case RL_ENOTFOUND: return "not found";
    case RL_ETIMEOUT: return "timed out";
    case RL_ENODEV: return "no such device";
    case RL_ETOOFEW: return "too few landmarks";
    case RL_EUNSUPPORTED: return "not supported";
    case RL_EAMBIGUOUS: return "ambiguous place";
    }
    return "unknown error";
}
