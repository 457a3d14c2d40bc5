/* rl_http's configuration defaults (rl_http.h), the same whether the
 * server is built in (rl_http.c) or not (rl_http_none.c). */
#include "rl_http.h"

#include <string.h>

void rl_http_defaults(rl_http_config *c)
{
    memset(c, 0, sizeof *c);
    c->token = "";
    c->max_clients = 32;
    c->max_per_client = 8;
    c->timeout_s = 10;
    c->max_request = 8192;
}
