/* stepwise_trace.h: writes a stepwise trace (JSONL, docs/trace-format.md) from C99 or C++, so that
 * `stepwise check FILE` can replay it against the reference algorithm step by step.
 * One header, no library: include it and call
 *
 *   sw_trace t;
 *   sw_trace_begin(&t, stdout, "dda-line", "double", "{\"p0\":[1.25,2.5],\"p1\":[12.75,7.25]}");
 *   sw_step(&t, 1, "init");  sw_real(&t, "dx", dx);  sw_real(&t, "dy", dy);  sw_segment(&t, x0, y0, x1, y1);
 *   ...
 *   sw_result_begin(&t);  sw_result_list_begin(&t, "pixels");  sw_result_pixel(&t, i, j); ...  sw_result_list_end(&t);
 *   return sw_trace_end(&t);   (0 when every write reached the file)
 *
 * What each step records (its line, kind, variables and geometry) is the algorithm's contract:
 * `stepwise list --contract ALG`. Variables and geometry of a step may be given in any order; the
 * step is written when the next one starts. Numbers: sw_real writes a double as %.17g (it reads
 * back as the same double; NaN and infinities as the strings the format uses), sw_exact a rational
 * "p/q", sw_int a JSON integer. Set t.geometry = 0 to leave out every step's "geo" (for
 * `check --decisions-only`). Not thread-safe; a write error is remembered, not reported at once.
 */
#ifndef STEPWISE_TRACE_H
#define STEPWISE_TRACE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A growable text buffer (a step's variables, or its geometry). */
typedef struct sw_text {
  char *data;
  size_t len, cap;
} sw_text;

typedef struct sw_trace {
  FILE *out;
  long long next_step; /* the index the next step gets */
  int in_step;         /* a step is being built (written when the next starts) */
  int in_result;       /* sw_result_begin was called */
  int result_items;    /* members (or list entries) written in the current result object or list */
  int geometry;        /* 1: every step has "geo" (default); 0: none has (check --decisions-only) */
  int failed;          /* a write or an allocation failed */
  sw_text head, vars, geo;
} sw_trace;

static inline void sw__grow(sw_trace *t, sw_text *b, size_t more) {
  size_t cap;
  char *p;
  if (t->failed || b->len + more + 1 <= b->cap) return;
  cap = b->cap ? b->cap : 256;
  while (cap < b->len + more + 1) cap *= 2;
  p = (char *)realloc(b->data, cap);
  if (!p) {
    t->failed = 1;
    return;
  }
  b->data = p;
  b->cap = cap;
}

static inline void sw__append(sw_trace *t, sw_text *b, const char *s, size_t n) {
  sw__grow(t, b, n);
  if (t->failed) return;
  memcpy(b->data + b->len, s, n);
  b->len += n;
  b->data[b->len] = '\0';
}

static inline void sw__cat(sw_trace *t, sw_text *b, const char *s) { sw__append(t, b, s, strlen(s)); }

/* A JSON string: quotes, backslashes and control characters escaped; other bytes (UTF-8) as they are. */
static inline void sw__cat_string(sw_trace *t, sw_text *b, const char *s) {
  char esc[8];
  sw__cat(t, b, "\"");
  for (; *s; ++s) {
    const unsigned char c = (unsigned char)*s;
    if (c == '"') sw__cat(t, b, "\\\"");
    else if (c == '\\') sw__cat(t, b, "\\\\");
    else if (c == '\n') sw__cat(t, b, "\\n");
    else if (c == '\t') sw__cat(t, b, "\\t");
    else if (c == '\r') sw__cat(t, b, "\\r");
    else if (c < 0x20) {
      snprintf(esc, sizeof esc, "\\u%04x", c);
      sw__cat(t, b, esc);
    } else sw__append(t, b, s, 1);
  }
  sw__cat(t, b, "\"");
}

/* A double: %.17g reads back as the same double; NaN and infinities are strings in the format. */
static inline void sw__cat_real(sw_trace *t, sw_text *b, double v) {
  char num[40];
  if (isnan(v)) sw__cat(t, b, "\"NaN\"");
  else if (isinf(v)) sw__cat(t, b, v > 0 ? "\"Infinity\"" : "\"-Infinity\"");
  else {
    snprintf(num, sizeof num, "%.17g", v);
    sw__cat(t, b, num);
  }
}

static inline void sw__cat_int(sw_trace *t, sw_text *b, long long v) {
  char num[32];
  snprintf(num, sizeof num, "%lld", v);
  sw__cat(t, b, num);
}

/* An exact rational as the format writes it: "p/q" (q > 0), or "p" when q is 1. */
static inline void sw__cat_exact(sw_trace *t, sw_text *b, long long p, long long q) {
  char num[64];
  if (q < 0) p = -p, q = -q;
  if (q == 1) snprintf(num, sizeof num, "\"%lld\"", p);
  else snprintf(num, sizeof num, "\"%lld/%lld\"", p, q);
  sw__cat(t, b, num);
}

static inline void sw__write(sw_trace *t, const char *s, size_t n) {
  if (!t->failed && n && fwrite(s, 1, n, t->out) != n) t->failed = 1;
}

/* Writes the step being built, if any. */
static inline void sw__flush_step(sw_trace *t) {
  if (!t->in_step) return;
  t->in_step = 0;
  sw__cat(t, &t->head, ",\"vars\":{");
  if (t->vars.len) sw__append(t, &t->head, t->vars.data, t->vars.len);
  sw__cat(t, &t->head, "}");
  if (t->geometry) {
    sw__cat(t, &t->head, ",\"geo\":[");
    if (t->geo.len) sw__append(t, &t->head, t->geo.data, t->geo.len);
    sw__cat(t, &t->head, "]");
  }
  sw__cat(t, &t->head, "}\n");
  if (!t->failed) sw__write(t, t->head.data, t->head.len);
}

/* The header line. input_json: the algorithm's input object as JSON text (its numbers as JSON
 * numbers or exact "p/q" strings); numeric: "float", "double", "int", "exact", ... */
static inline void sw_trace_begin(sw_trace *t, FILE *out, const char *algorithm, const char *numeric, const char *input_json) {
  memset(t, 0, sizeof *t);
  t->out = out;
  t->geometry = 1;
  sw__cat(t, &t->head, "{\"format\":\"stepwise-trace\",\"version\":2,\"algorithm\":");
  sw__cat_string(t, &t->head, algorithm);
  sw__cat(t, &t->head, ",\"numeric\":");
  sw__cat_string(t, &t->head, numeric);
  sw__cat(t, &t->head, ",\"input\":");
  sw__cat(t, &t->head, input_json);
  sw__cat(t, &t->head, "}\n");
  if (!t->failed) sw__write(t, t->head.data, t->head.len);
}

/* Starts a step of a nested call: its line is in the callee's listing ("in"); callee NULL: the
 * algorithm's own listing. */
static inline void sw_step_in(sw_trace *t, const char *callee, int line, const char *kind) {
  sw__flush_step(t);
  t->head.len = t->vars.len = t->geo.len = 0;
  sw__cat(t, &t->head, "{\"step\":");
  sw__cat_int(t, &t->head, t->next_step++);
  if (callee) {
    sw__cat(t, &t->head, ",\"in\":");
    sw__cat_string(t, &t->head, callee);
  }
  sw__cat(t, &t->head, ",\"line\":");
  sw__cat_int(t, &t->head, line);
  sw__cat(t, &t->head, ",\"kind\":");
  sw__cat_string(t, &t->head, kind);
  t->in_step = 1;
}

/* Starts a step: line (1-based, the contract's line number) and kind ("init", "decide", "plot", ...). */
static inline void sw_step(sw_trace *t, int line, const char *kind) { sw_step_in(t, NULL, line, kind); }

static inline void sw__var_name(sw_trace *t, const char *name) {
  if (t->vars.len) sw__cat(t, &t->vars, ",");
  sw__cat_string(t, &t->vars, name);
  sw__cat(t, &t->vars, ":");
}

/* Variables of the current step. */
static inline void sw_int(sw_trace *t, const char *name, long long v) { sw__var_name(t, name); sw__cat_int(t, &t->vars, v); }
static inline void sw_real(sw_trace *t, const char *name, double v) { sw__var_name(t, name); sw__cat_real(t, &t->vars, v); }
static inline void sw_exact(sw_trace *t, const char *name, long long p, long long q) { sw__var_name(t, name); sw__cat_exact(t, &t->vars, p, q); }
static inline void sw_vec2(sw_trace *t, const char *name, double x, double y) {
  sw__var_name(t, name);
  sw__cat(t, &t->vars, "[");
  sw__cat_real(t, &t->vars, x);
  sw__cat(t, &t->vars, ",");
  sw__cat_real(t, &t->vars, y);
  sw__cat(t, &t->vars, "]");
}

/* Geometry items of the current step, in the contract's order. kind: "point", "segment", ... with
 * n values (docs/trace-format.md, "Geometry"). */
static inline void sw_geo(sw_trace *t, const char *kind, int n, const double *values) {
  int k;
  if (t->geo.len) sw__cat(t, &t->geo, ",");
  sw__cat(t, &t->geo, "{");
  sw__cat_string(t, &t->geo, kind);
  sw__cat(t, &t->geo, ":[");
  for (k = 0; k < n; ++k) {
    if (k) sw__cat(t, &t->geo, ",");
    sw__cat_real(t, &t->geo, values[k]);
  }
  sw__cat(t, &t->geo, "]}");
}
static inline void sw_pixel(sw_trace *t, long long i, long long j) {
  if (t->geo.len) sw__cat(t, &t->geo, ",");
  sw__cat(t, &t->geo, "{\"pixel\":[");
  sw__cat_int(t, &t->geo, i);
  sw__cat(t, &t->geo, ",");
  sw__cat_int(t, &t->geo, j);
  sw__cat(t, &t->geo, "]}");
}
static inline void sw_point(sw_trace *t, double x, double y) {
  const double v[2] = {x, y};
  sw_geo(t, "point", 2, v);
}
static inline void sw_segment(sw_trace *t, double x0, double y0, double x1, double y1) {
  const double v[4] = {x0, y0, x1, y1};
  sw_geo(t, "segment", 4, v);
}
/* Labels the geometry item just added (optional: check compares a label only where one is given). */
static inline void sw_label(sw_trace *t, const char *label) {
  if (!t->geo.len) return;
  t->geo.len--; /* reopen the item's closing brace */
  sw__cat(t, &t->geo, ",\"label\":");
  sw__cat_string(t, &t->geo, label);
  sw__cat(t, &t->geo, "}");
}

/* The result line: {"result":{...}}, after the last step. */
static inline void sw_result_begin(sw_trace *t) {
  sw__flush_step(t);
  t->in_result = 1;
  t->result_items = 0;
  sw__write(t, "{\"result\":{", 11);
}
static inline void sw__result_key(sw_trace *t, const char *key) {
  t->head.len = 0;
  if (t->result_items++) sw__cat(t, &t->head, ",");
  sw__cat_string(t, &t->head, key);
  sw__cat(t, &t->head, ":");
}
static inline void sw_result_int(sw_trace *t, const char *key, long long v) {
  sw__result_key(t, key);
  sw__cat_int(t, &t->head, v);
  sw__write(t, t->head.data, t->head.len);
}
static inline void sw_result_real(sw_trace *t, const char *key, double v) {
  sw__result_key(t, key);
  sw__cat_real(t, &t->head, v);
  sw__write(t, t->head.data, t->head.len);
}
/* A list member ("pixels", "cells"): sw_result_pixel for each entry, then sw_result_list_end. */
static inline void sw_result_list_begin(sw_trace *t, const char *key) {
  sw__result_key(t, key);
  sw__cat(t, &t->head, "[");
  sw__write(t, t->head.data, t->head.len);
  t->result_items = 0;
}
static inline void sw_result_pixel(sw_trace *t, long long i, long long j) {
  t->head.len = 0;
  sw__cat(t, &t->head, t->result_items++ ? ",[" : "[");
  sw__cat_int(t, &t->head, i);
  sw__cat(t, &t->head, ",");
  sw__cat_int(t, &t->head, j);
  sw__cat(t, &t->head, "]");
  sw__write(t, t->head.data, t->head.len);
}
static inline void sw_result_list_end(sw_trace *t) {
  sw__write(t, "]", 1);
  t->result_items = 1; /* the list was a member: the next member needs a comma */
}

/* Ends the trace (closing the result) and frees the buffers. Returns 0 when every write succeeded. */
static inline int sw_trace_end(sw_trace *t) {
  int ok;
  sw__flush_step(t);
  if (t->in_result) sw__write(t, "}}\n", 3);
  if (!t->failed && fflush(t->out) != 0) t->failed = 1;
  ok = !t->failed && !ferror(t->out);
  free(t->head.data);
  free(t->vars.data);
  free(t->geo.data);
  t->head.data = t->vars.data = t->geo.data = NULL;
  return ok ? 0 : 1;
}

#ifdef __cplusplus
}
#endif

#endif /* STEPWISE_TRACE_H */
