/* rl_yaml: small helpers over libyaml's document API for ringloc's files.
 *
 * Every failure leaves one line in `err` naming the file, the key and the
 * line: "map.yaml:7: landmarks[2].id: expected an integer, got 'x'".
 *
 *   rl_yaml doc;
 *   yaml_node_t *root;
 *   double diameter;
 *   char err[256];
 *   if (rl_yaml_load(&doc, "map.yaml", err, sizeof err) != RL_OK)
 *       return;                               // err says why, naming the file
 *   root = rl_yaml_root(&doc);
 *   if (rl_yaml_double(&doc, root, "diameter", NULL, 1, &diameter, err, sizeof err) == RL_OK)
 *       use(diameter);
 *   rl_yaml_free(&doc);
 */
#ifndef RL_YAML_H
#define RL_YAML_H

#include <stddef.h>
#include <yaml.h>
#include "rl_error.h"

typedef struct {
    yaml_document_t doc;
    const char *path;
    int loaded;
} rl_yaml;

/* Parse `path` (the first document). RL_ENOTFOUND/RL_EIO if unreadable,
 * RL_EFORMAT if not YAML or empty. The path string must outlive doc. */
RL_CHECK rl_err rl_yaml_load(rl_yaml *y, const char *path, char *err, size_t errlen);
void rl_yaml_free(rl_yaml *y);

/* The root node, or NULL for an empty document. */
yaml_node_t *rl_yaml_root(rl_yaml *y);

/* Value node of `key` in mapping `map`, or NULL (not a mapping or no key). */
yaml_node_t *rl_yaml_get(rl_yaml *y, yaml_node_t *map, const char *key);

/* Item i of a sequence, or NULL. */
yaml_node_t *rl_yaml_item(rl_yaml *y, yaml_node_t *seq, int i);
int rl_yaml_len(yaml_node_t *seq); /* items of a sequence, -1 if not one */

/* Scalar text of a node, or NULL if it is not a scalar. */
/* The text of a plain scalar (unquoted, untagged), the only kind read as
 * a number; NULL for any other node. */
const char *rl_yaml_number_text(yaml_node_t *node);
const char *rl_yaml_text(yaml_node_t *node);

/* Format an error about `node` (may be NULL) and key name into err;
 * returns `code`. */
rl_err rl_yaml_fail(rl_yaml *y, yaml_node_t *node, const char *key, rl_err code, char *err,
                    size_t errlen, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 7, 8)))
#endif
    ;

/* Typed lookups of `key` in `map`: with required = 0 a missing key leaves
 * *out unchanged and returns RL_OK. `label` names the key in errors (e.g.
 * "landmarks[2].id"); NULL means `key`. */
RL_CHECK rl_err rl_yaml_double(rl_yaml *y, yaml_node_t *map, const char *key,
                               const char *label, int required, double *out, char *err,
                               size_t errlen);
/* The same, the number also within [lo, hi] (RL_ERANGE naming the range). */
RL_CHECK rl_err rl_yaml_double_in(rl_yaml *y, yaml_node_t *map, const char *key,
                                  const char *label, int required, double lo, double hi,
                                  double *out, char *err, size_t errlen);
RL_CHECK rl_err rl_yaml_int(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                            int required, int *out, char *err, size_t errlen);
RL_CHECK rl_err rl_yaml_string(rl_yaml *y, yaml_node_t *map, const char *key,
                               const char *label, int required, const char **out, char *err,
                               size_t errlen);

/* true/false (also yes/no, on/off) into *out as 1/0. */
RL_CHECK rl_err rl_yaml_bool(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                             int required, int *out, char *err, size_t errlen);

/* Every key of mapping `map` is one of `keys` (NULL-terminated), so a
 * misspelt key is an error, not a default: RL_EFORMAT naming the first
 * other key ("prefix.key", prefix may be NULL) and the known ones. A
 * node that is not a mapping is left to the typed lookups (RL_OK). */
RL_CHECK rl_err rl_yaml_only(rl_yaml *y, yaml_node_t *map, const char *prefix,
                             const char *const *keys, char *err, size_t errlen);

/* Parse a scalar as a number; 1 on success. */
int rl_yaml_parse_double(const char *s, double *out);

#endif
