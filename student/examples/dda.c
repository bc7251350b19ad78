/* A student's DDA line and grid walk in C (doubles), traced with stepwise_trace.h to the contract
 * of `stepwise list --contract dda-line` and `--contract dda-grid-walk` (docs/assignment-dda.md).
 *
 *   cc -std=c99 -I student student/examples/dda.c -lm -o dda
 *   ./dda dda-line 1.25 2.5 12.75 7.25 > line.jsonl && stepwise check line.jsonl
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "stepwise_trace.h"

/* A growable list of pixels: the result. */
typedef struct {
  long long *ij;
  size_t n, cap;
} pixels;

static void add_pixel(pixels *p, long long i, long long j) {
  if (p->n == p->cap) {
    p->cap = p->cap ? 2 * p->cap : 64;
    p->ij = (long long *)realloc(p->ij, 2 * p->cap * sizeof *p->ij);
    if (!p->ij) exit(2);
  }
  p->ij[2 * p->n] = i;
  p->ij[2 * p->n + 1] = j;
  p->n++;
}

static void write_result(sw_trace *t, const char *key, const pixels *p) {
  size_t k;
  sw_result_begin(t);
  sw_result_list_begin(t, key);
  for (k = 0; k < p->n; ++k) sw_result_pixel(t, p->ij[2 * k], p->ij[2 * k + 1]);
  sw_result_list_end(t);
}

/* round(v) = floor(v + 1/2): ties round up. */
static long long round_half(double v) { return (long long)floor(v + 0.5); }

/* The listing's lines (stepwise list --listing dda-line). */
enum { L_DELTA = 1, L_MAJOR, L_SWAP, L_EMPTY, L_SLOPE, L_OFFSET, L_TEST, L_PLOT, L_ADVANCE, L_DONE };

static void dda_line(sw_trace *t, double p0[2], double p1[2], pixels *out) {
  double d[2] = {p1[0] - p0[0], p1[1] - p0[1]}, dp[2], q[2], offset;
  int a, swapped;
  long long n, bound;
  sw_step(t, L_DELTA, "init");
  sw_real(t, "dx", d[0]);
  sw_real(t, "dy", d[1]);
  sw_segment(t, p0[0], p0[1], p1[0], p1[1]);

  a = fabs(d[0]) > fabs(d[1]) ? 0 : 1;
  sw_step(t, L_MAJOR, "decide");
  sw_int(t, "a", a);

  swapped = d[a] < 0;
  if (swapped) {
    double *tmp = p0;
    p0 = p1;
    p1 = tmp;
    d[0] = -d[0];
    d[1] = -d[1];
  }
  sw_step(t, L_SWAP, "decide");
  sw_int(t, "swapped", swapped);
  sw_real(t, "dx", d[0]);
  sw_real(t, "dy", d[1]);
  if (d[a] == 0) {
    sw_step(t, L_EMPTY, "done");
    return;
  }

  dp[a] = 1;
  dp[1 - a] = d[1 - a] / d[a];
  sw_step(t, L_SLOPE, "init");
  sw_real(t, "dpx", dp[0]);
  sw_real(t, "dpy", dp[1]);

  offset = ceil(p0[a]) - p0[a];
  q[0] = p0[0] + offset * dp[0];
  q[1] = p0[1] + offset * dp[1];
  sw_step(t, L_OFFSET, "init");
  sw_real(t, "dp0x", offset * dp[0]);
  sw_real(t, "dp0y", offset * dp[1]);
  sw_real(t, "qx", q[0]);
  sw_real(t, "qy", q[1]);
  sw_point(t, q[0], q[1]);

  /* One column per pass, and one more pass that stops the walk. */
  bound = (long long)ceil(p1[a]) - (long long)ceil(p0[a]) + 1;
  for (n = 0; n < bound; ++n) {
    long long i, j;
    if (!(q[a] < p1[a])) {
      sw_step(t, L_DONE, "done");
      sw_real(t, "qx", q[0]);
      sw_real(t, "qy", q[1]);
      sw_point(t, q[0], q[1]);
      return;
    }
    i = round_half(q[0]);
    j = round_half(q[1]);
    add_pixel(out, i, j);
    sw_step(t, L_PLOT, "plot");
    sw_real(t, "qx", q[0]);
    sw_real(t, "qy", q[1]);
    sw_int(t, "i", i);
    sw_int(t, "j", j);
    sw_pixel(t, i, j);
    sw_point(t, q[0], q[1]);

    q[0] += dp[0];
    q[1] += dp[1];
    sw_step(t, L_ADVANCE, "advance");
    sw_real(t, "qx", q[0]);
    sw_real(t, "qy", q[1]);
    sw_point(t, q[0], q[1]);
  }
  sw_step(t, L_DONE, "done");
  sw_real(t, "qx", q[0]);
  sw_real(t, "qy", q[1]);
  sw_int(t, "bound_hit", 1);
}

/* The grid walk's lines (stepwise list --listing dda-grid-walk). */
enum { G_DELTA = 1, G_START, G_SETUP, G_FIRST_EXIT, G_PICK, G_TEST, G_UP, G_VISIT_UP, G_DOWN, G_VISIT_DOWN, G_DONE };

static int sign(double v) { return (v > 0) - (v < 0); }

static void grid_walk(sw_trace *t, const double p0[2], const double p1[2], pixels *out) {
  const double d[2] = {p1[0] - p0[0], p1[1] - p0[1]};
  long long cell[2], last[2], n, bound = 4;
  int step[2], a, dir;
  double t_max[2] = {0, 0}, t_delta[2] = {0, 0};
  sw_step(t, G_DELTA, "init");
  sw_real(t, "dx", d[0]);
  sw_real(t, "dy", d[1]);
  sw_segment(t, p0[0], p0[1], p1[0], p1[1]);
  if (d[0] == 0 && d[1] == 0) {
    sw_step(t, G_DONE, "done");
    return;
  }
  cell[0] = round_half(p0[0]);
  cell[1] = round_half(p0[1]);
  last[0] = round_half(p1[0]);
  last[1] = round_half(p1[1]);
  add_pixel(out, cell[0], cell[1]);
  sw_step(t, G_START, "visit");
  sw_int(t, "i", cell[0]);
  sw_int(t, "j", cell[1]);
  sw_pixel(t, cell[0], cell[1]);
  sw_point(t, p0[0], p0[1]);

  for (a = 0; a < 2; ++a) {
    step[a] = sign(d[a]);
    if (step[a] == 0) continue;
    t_delta[a] = step[a] / d[a];
    t_max[a] = ((double)cell[a] + step[a] * 0.5 - p0[a]) / d[a];
    bound += (long long)floor(fabs(d[a])) + 2;
  }
  sw_step(t, G_SETUP, "init");
  sw_int(t, "step_x", step[0]);
  sw_int(t, "step_y", step[1]);
  sw_real(t, "tDelta_x", t_delta[0]);
  sw_real(t, "tDelta_y", t_delta[1]);
  sw_step(t, G_FIRST_EXIT, "init");
  sw_real(t, "tMax_x", t_max[0]);
  sw_real(t, "tMax_y", t_max[1]);

  for (n = 0; n < bound; ++n) {
    /* Which axes leave the cell first: x, y, or both at a corner. */
    const int x_first = step[1] == 0 || (step[0] != 0 && t_max[0] < t_max[1]);
    const int y_first = !x_first && (step[0] == 0 || t_max[1] < t_max[0]);
    const int hit[2] = {!y_first, !x_first};
    const double tt = hit[0] ? t_max[0] : t_max[1];
    int past, reached;
    sw_step(t, G_PICK, "decide");
    sw_real(t, "t", tt);
    sw_real(t, "tMax_x", t_max[0]);
    sw_real(t, "tMax_y", t_max[1]);
    sw_point(t, p0[0] + tt * d[0], p0[1] + tt * d[1]);

    past = (hit[0] && step[0] != 0 && (cell[0] + step[0] - last[0]) * step[0] > 0) ||
           (hit[1] && step[1] != 0 && (cell[1] + step[1] - last[1]) * step[1] > 0);
    reached = !(tt < 1);
    if (reached || past) {
      sw_step(t, G_TEST, "done");
      sw_real(t, "t", tt);
      sw_int(t, "past_p1", !reached);
      return;
    }
    /* Upward moves first: an upward boundary belongs to the new cell, a downward one to the old. */
    for (dir = 1; dir >= -1; dir -= 2) {
      int moved = 0;
      for (a = 0; a < 2; ++a) {
        if (!hit[a] || step[a] != dir) continue;
        cell[a] += dir;
        t_max[a] += t_delta[a];
        moved = 1;
      }
      if (!moved) continue;
      add_pixel(out, cell[0], cell[1]);
      sw_step(t, dir > 0 ? G_VISIT_UP : G_VISIT_DOWN, "visit");
      sw_int(t, "i", cell[0]);
      sw_int(t, "j", cell[1]);
      sw_real(t, "tMax_x", t_max[0]);
      sw_real(t, "tMax_y", t_max[1]);
      sw_pixel(t, cell[0], cell[1]);
    }
  }
  sw_step(t, G_DONE, "done");
  sw_int(t, "bound_hit", 1);
}

int main(int argc, char **argv) {
  double p0[2], p1[2];
  char input[200];
  pixels out = {NULL, 0, 0};
  sw_trace t;
  int k, line;
  if (argc != 6 || (strcmp(argv[1], "dda-line") != 0 && strcmp(argv[1], "dda-grid-walk") != 0)) {
    fprintf(stderr, "usage: %s dda-line|dda-grid-walk X0 Y0 X1 Y1\n", argv[0]);
    return 2;
  }
  for (k = 0; k < 4; ++k) (k < 2 ? p0 : p1)[k % 2] = strtod(argv[2 + k], NULL);
  snprintf(input, sizeof input, "{\"p0\":[%.17g,%.17g],\"p1\":[%.17g,%.17g]}", p0[0], p0[1], p1[0], p1[1]);
  line = strcmp(argv[1], "dda-line") == 0;
  sw_trace_begin(&t, stdout, argv[1], "double", input);
  if (line) dda_line(&t, p0, p1, &out);
  else grid_walk(&t, p0, p1, &out);
  write_result(&t, line ? "pixels" : "cells", &out);
  free(out.ij);
  return sw_trace_end(&t);
}
