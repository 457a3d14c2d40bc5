#include "rl_yaml.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rl_infile.h"

/* Largest configuration file read; ringloc's files are a few kB. */
#define RL_YAML_MAX_BYTES (4L << 20)
/* Deepest nesting of mappings and lists; ringloc's files nest 3 deep.
 * (libyaml takes time quadratic in the depth: 40,000 levels, 3 s.) */
#define RL_YAML_MAX_DEPTH 64

/* 1 if no collection in the text nests deeper than RL_YAML_MAX_DEPTH;
 * else 0 with *line where it does (a malformed text passes: the full
 * parse reports it). The events stop at the first level too deep. */
static int depth_ok(const char *text, size_t n, unsigned long *line)
{
    yaml_parser_t parser;
    yaml_event_t ev;
    int depth = 0, ok = 1, done = 0;
    if (!yaml_parser_initialize(&parser))
        return 1;
    yaml_parser_set_input_string(&parser, (const unsigned char *)text, n);
    while (!done && ok) {
        if (!yaml_parser_parse(&parser, &ev))
            break;
        if (ev.type == YAML_SEQUENCE_START_EVENT || ev.type == YAML_MAPPING_START_EVENT) {
            if (++depth > RL_YAML_MAX_DEPTH) {
                ok = 0;
                *line = (unsigned long)ev.start_mark.line + 1;
            }
        } else if (ev.type == YAML_SEQUENCE_END_EVENT || ev.type == YAML_MAPPING_END_EVENT) {
            depth--;
        }
        done = ev.type == YAML_STREAM_END_EVENT;
        yaml_event_delete(&ev);
    }
    yaml_parser_delete(&parser);
    return ok;
}

/* The first key that a mapping of the document holds twice: 1 with both
 * nodes, else 0. */
static int duplicate_key(yaml_document_t *doc, yaml_node_t **first, yaml_node_t **again)
{
    yaml_node_t *node;
    for (node = doc->nodes.start; node < doc->nodes.top; node++) {
        yaml_node_pair_t *a, *b;
        if (node->type != YAML_MAPPING_NODE)
            continue;
        for (b = node->data.mapping.pairs.start; b < node->data.mapping.pairs.top; b++) {
            yaml_node_t *kb = yaml_document_get_node(doc, b->key);
            if (kb == NULL || kb->type != YAML_SCALAR_NODE)
                continue;
            for (a = node->data.mapping.pairs.start; a < b; a++) {
                yaml_node_t *ka = yaml_document_get_node(doc, a->key);
                if (ka && ka->type == YAML_SCALAR_NODE &&
                    strcmp((const char *)ka->data.scalar.value, (const char *)kb->data.scalar.value) == 0) {
                    *first = ka;
                    *again = kb;
                    return 1;
                }
            }
        }
    }
    return 0;
}

/* A file is one document: a second one (after "---" or text after
 * "..."), even a malformed one, is an error, never silently ignored. */
static int one_document(yaml_parser_t *parser, const char *path, char *err, size_t errlen)
{
    yaml_document_t next;
    int more;
    if (!yaml_parser_load(parser, &next)) {
        snprintf(err, errlen, "%s:%lu: a second YAML document, and malformed (ringloc files hold one)", path,
                 (unsigned long)parser->problem_mark.line + 1);
        return 0;
    }
    more = yaml_document_get_root_node(&next) != NULL;
    if (more)
        snprintf(err, errlen, "%s:%lu: a second YAML document (ringloc files hold one)", path,
                 (unsigned long)next.start_mark.line + 1);
    yaml_document_delete(&next);
    return !more;
}

/* A scalar with an explicit tag ("!!str 5", "!!float 1") is not a plain
 * number: it is marked as a quoted scalar, which no number reader takes.
 * libyaml gives untagged and !!str scalars the same tag, so the source
 * text (where the node starts with its properties) tells them apart. */
static void mark_tagged(yaml_document_t *doc, const char *text)
{
    yaml_node_t *n;
    for (n = doc->nodes.start; n < doc->nodes.top; n++)
        if (n->type == YAML_SCALAR_NODE && text[n->start_mark.index] == '!')
            n->data.scalar.style = YAML_SINGLE_QUOTED_SCALAR_STYLE;
}

rl_err rl_yaml_load(rl_yaml *y, const char *path, char *err, size_t errlen)
{
    FILE *f;
    yaml_parser_t parser;
    char *text;
    long n;
    int ok;
    memset(y, 0, sizeof *y);
    y->path = path;
    {
        rl_err e;
        if ((f = rl_infile_fopen(path, "a YAML file", &e, err, errlen)) == NULL)
            return e;
    }
    text = (char *)malloc(RL_YAML_MAX_BYTES + 1);
    if (text == NULL) {
        fclose(f);
        snprintf(err, errlen, "%s: out of memory", path);
        return RL_ENOMEM;
    }
    n = (long)fread(text, 1, RL_YAML_MAX_BYTES + 1, f);
    if (ferror(f) || n > RL_YAML_MAX_BYTES) {
        if (n > RL_YAML_MAX_BYTES)
            snprintf(err, errlen, "%s: larger than %ld MB: not a configuration file", path,
                     RL_YAML_MAX_BYTES >> 20);
        else
            snprintf(err, errlen, "%s: %s", path, strerror(errno));
        free(text);
        fclose(f);
        return RL_EIO;
    }
    fclose(f);
    text[n] = '\0';
    /* OpenCV FileStorage writes "%YAML:1.0", which is not a YAML 1.1
     * directive: blank that line so the rest parses as ordinary YAML. */
    if (strncmp(text, "%YAML:", 6) == 0) {
        long i;
        for (i = 0; i < n && text[i] != '\n'; i++)
            text[i] = ' ';
        text[0] = '#';
    }
    {
        unsigned long line = 0;
        if (!depth_ok(text, (size_t)n, &line)) {
            snprintf(err, errlen, "%s:%lu: nested more than %d levels deep: not a ringloc file", path,
                     line, RL_YAML_MAX_DEPTH);
            free(text);
            return RL_EFORMAT;
        }
    }
    if (!yaml_parser_initialize(&parser)) {
        free(text);
        snprintf(err, errlen, "%s: out of memory", path);
        return RL_ENOMEM;
    }
    yaml_parser_set_input_string(&parser, (const unsigned char *)text, (size_t)n);
    ok = yaml_parser_load(&parser, &y->doc);
    if (!ok) {
        snprintf(err, errlen, "%s:%lu: malformed YAML: %s", path,
                 (unsigned long)parser.problem_mark.line + 1,
                 parser.problem ? parser.problem : "parse error");
        yaml_parser_delete(&parser);
        free(text);
        return RL_EFORMAT;
    }
    y->loaded = 1;
    if (!one_document(&parser, path, err, errlen)) {
        yaml_parser_delete(&parser);
        free(text);
        rl_yaml_free(y);
        return RL_EFORMAT;
    }
    mark_tagged(&y->doc, text);
    yaml_parser_delete(&parser);
    free(text);
    if (yaml_document_get_root_node(&y->doc) == NULL) {
        snprintf(err, errlen, "%s: empty file, expected a YAML mapping", path);
        rl_yaml_free(y);
        return RL_EFORMAT;
    }
    {
        yaml_node_t *first, *again;
        if (duplicate_key(&y->doc, &first, &again)) {
            snprintf(err, errlen, "%s:%lu: %s: given twice (first at line %lu)", path,
                     (unsigned long)again->start_mark.line + 1, (const char *)again->data.scalar.value,
                     (unsigned long)first->start_mark.line + 1);
            rl_yaml_free(y);
            return RL_EFORMAT;
        }
    }
    return RL_OK;
}

void rl_yaml_free(rl_yaml *y)
{
    if (y->loaded)
        yaml_document_delete(&y->doc);
    y->loaded = 0;
}

yaml_node_t *rl_yaml_root(rl_yaml *y)
{
    return y->loaded ? yaml_document_get_root_node(&y->doc) : NULL;
}

yaml_node_t *rl_yaml_get(rl_yaml *y, yaml_node_t *map, const char *key)
{
    yaml_node_pair_t *p;
    if (map == NULL || map->type != YAML_MAPPING_NODE)
        return NULL;
    for (p = map->data.mapping.pairs.start; p < map->data.mapping.pairs.top; p++) {
        yaml_node_t *k = yaml_document_get_node(&y->doc, p->key);
        if (k && k->type == YAML_SCALAR_NODE && strcmp((const char *)k->data.scalar.value, key) == 0)
            return yaml_document_get_node(&y->doc, p->value);
    }
    return NULL;
}

int rl_yaml_len(yaml_node_t *seq)
{
    if (seq == NULL || seq->type != YAML_SEQUENCE_NODE)
        return -1;
    return (int)(seq->data.sequence.items.top - seq->data.sequence.items.start);
}

yaml_node_t *rl_yaml_item(rl_yaml *y, yaml_node_t *seq, int i)
{
    if (i < 0 || i >= rl_yaml_len(seq))
        return NULL;
    return yaml_document_get_node(&y->doc, seq->data.sequence.items.start[i]);
}

const char *rl_yaml_text(yaml_node_t *node)
{
    if (node == NULL || node->type != YAML_SCALAR_NODE)
        return NULL;
    return (const char *)node->data.scalar.value;
}

const char *rl_yaml_number_text(yaml_node_t *node)
{
    if (node == NULL || node->type != YAML_SCALAR_NODE || node->data.scalar.style != YAML_PLAIN_SCALAR_STYLE)
        return NULL; /* "5" and '5' are strings, as a YAML reader takes them */
    return (const char *)node->data.scalar.value;
}

rl_err rl_yaml_fail(rl_yaml *y, yaml_node_t *node, const char *key, rl_err code, char *err,
                    size_t errlen, const char *fmt, ...)
{
    char what[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (node != NULL)
        snprintf(err, errlen, "%s:%lu: %s: %s", y->path,
                 (unsigned long)node->start_mark.line + 1, key, what);
    else
        snprintf(err, errlen, "%s: %s: %s", y->path, key, what);
    return code;
}

rl_err rl_yaml_only(rl_yaml *y, yaml_node_t *map, const char *prefix, const char *const *keys,
                    char *err, size_t errlen)
{
    yaml_node_pair_t *p;
    if (map == NULL || map->type != YAML_MAPPING_NODE)
        return RL_OK;
    for (p = map->data.mapping.pairs.start; p < map->data.mapping.pairs.top; p++) {
        yaml_node_t *k = yaml_document_get_node(&y->doc, p->key);
        const char *name = k && k->type == YAML_SCALAR_NODE ? (const char *)k->data.scalar.value : "?";
        char label[128], known[256];
        size_t used = 0;
        int i, found = 0;
        for (i = 0; keys[i] != NULL && !found; i++)
            found = strcmp(keys[i], name) == 0;
        if (found)
            continue;
        known[0] = '\0';
        for (i = 0; keys[i] != NULL && used < sizeof known; i++) {
            int w = snprintf(known + used, sizeof known - used, "%s%s", i ? ", " : "", keys[i]);
            used += w > 0 ? (size_t)w : 0;
        }
        snprintf(label, sizeof label, "%s%s%s", prefix ? prefix : "", prefix ? "." : "", name);
        return rl_yaml_fail(y, k, label, RL_EFORMAT, err, errlen, "unknown key (expected %s)", known);
    }
    return RL_OK;
}

int rl_yaml_parse_double(const char *s, double *out)
{
    char *end;
    double v;
    if (s == NULL || *s == '\0')
        return 0;
    if (strpbrk(s, "xX") != NULL) /* strtod's hex floats are no YAML number */
        return 0;
    errno = 0;
    v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !isfinite(v))
        return 0;
    *out = v;
    return 1;
}

static yaml_node_t *lookup(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                           int required, rl_err *e, char *err, size_t errlen)
{
    yaml_node_t *n = rl_yaml_get(y, map, key);
    *e = RL_OK;
    if (n == NULL && required)
        *e = rl_yaml_fail(y, map, label, RL_EFORMAT, err, errlen, "missing key");
    return n;
}

rl_err rl_yaml_double(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                      int required, double *out, char *err, size_t errlen)
{
    rl_err e;
    yaml_node_t *n;
    label = label ? label : key;
    n = lookup(y, map, key, label, required, &e, err, errlen);
    if (n == NULL)
        return e;
    if (!rl_yaml_parse_double(rl_yaml_number_text(n), out))
        return rl_yaml_fail(y, n, label, RL_EFORMAT, err, errlen, "expected a number, got %s%s%s",
                            rl_yaml_text(n) ? "'" : "", rl_yaml_text(n) ? rl_yaml_text(n) : "a list or mapping",
                            rl_yaml_text(n) ? "'" : "");
    return RL_OK;
}

rl_err rl_yaml_double_in(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                         int required, double lo, double hi, double *out, char *err, size_t errlen)
{
    double v = *out;
    rl_err e = rl_yaml_double(y, map, key, label, required, &v, err, errlen);
    if (e != RL_OK)
        return e;
    if (rl_yaml_get(y, map, key) != NULL && !(v >= lo && v <= hi))
        return rl_yaml_fail(y, rl_yaml_get(y, map, key), label ? label : key, RL_ERANGE, err, errlen,
                            "%g is out of range (%g .. %g)", v, lo, hi);
    *out = v;
    return RL_OK;
}

rl_err rl_yaml_int(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                   int required, int *out, char *err, size_t errlen)
{
    rl_err e;
    yaml_node_t *n;
    const char *s;
    char *end;
    long v;
    label = label ? label : key;
    n = lookup(y, map, key, label, required, &e, err, errlen);
    if (n == NULL)
        return e;
    s = rl_yaml_number_text(n);
    errno = 0;
    v = s ? strtol(s, &end, 10) : 0;
    if (s == NULL || *s == '\0' || *end != '\0')
        return rl_yaml_fail(y, n, label, RL_EFORMAT, err, errlen,
                            "expected an integer, got %s%s%s", rl_yaml_text(n) ? "'" : "",
                            rl_yaml_text(n) ? rl_yaml_text(n) : "a list or mapping", rl_yaml_text(n) ? "'" : "");
    if (errno == ERANGE || v < -2147483647L || v > 2147483647L)
        return rl_yaml_fail(y, n, label, RL_ERANGE, err, errlen, "%s is out of range (-2147483647 .. 2147483647)", s);
    *out = (int)v;
    return RL_OK;
}

rl_err rl_yaml_string(rl_yaml *y, yaml_node_t *map, const char *key, const char *label,
                      int required, const char **out, char *err, size_t errlen)
{
    rl_err e;
    yaml_node_t *n;
    label = label ? label : key;
    n = lookup(y, map, key, label, required, &e, err, errlen);
    if (n == NULL)
        return e;
    if (rl_yaml_text(n) == NULL)
        return rl_yaml_fail(y, n, label, RL_EFORMAT, err, errlen,
                            "expected a text value, got a list or mapping");
    *out = rl_yaml_text(n);
    return RL_OK;
}

rl_err rl_yaml_bool(rl_yaml *y, yaml_node_t *map, const char *key, const char *label, int required,
                    int *out, char *err, size_t errlen)
{
    static const char *const yes[] = {"true", "True", "TRUE", "yes", "Yes", "on", NULL};
    static const char *const no[] = {"false", "False", "FALSE", "no", "No", "off", NULL};
    const char *s = NULL;
    int i;
    rl_err e = rl_yaml_string(y, map, key, label, required, &s, err, errlen);
    if (e != RL_OK || s == NULL)
        return e;
    for (i = 0; yes[i] != NULL; i++)
        if (strcmp(s, yes[i]) == 0)
            return *out = 1, RL_OK;
    for (i = 0; no[i] != NULL; i++)
        if (strcmp(s, no[i]) == 0)
            return *out = 0, RL_OK;
    return rl_yaml_fail(y, rl_yaml_get(y, map, key), label ? label : key, RL_EFORMAT, err, errlen,
                        "expected true or false, got '%s'", s);
}
