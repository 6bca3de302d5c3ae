/* Times GSL's gsl_sf_elljac_e (sn, cn, dn in one call) on the batch of
 * examples/bench_batch.rs, for scripts/bench_peers.py.
 *
 *   bench_gsl N REPEATS fixed|fresh [K]
 *
 * Batch: u_i = -10 + 20 (i + 0.5)/N; modulus k = K (default 0.8, "fixed") or
 * k_i = 0.05 + 0.94 frac(i phi) ("fresh", phi the golden ratio); GSL takes the
 * parameter m = k^2.  Prints the wall-clock time per evaluation (ns) of every batch.
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_elljac.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_ns(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e9 + t.tv_nsec;
}

int main(int argc, char **argv) {
  if (argc < 4) {
    fprintf(stderr, "usage: bench_gsl N REPEATS fixed|fresh [K]\n");
    return 2;
  }
  int n = atoi(argv[1]), reps = atoi(argv[2]);
  int fresh = strcmp(argv[3], "fresh") == 0;
  double kfix = argc > 4 ? atof(argv[4]) : 0.8;
  double *u = malloc(n * sizeof *u), *m = malloc(n * sizeof *m);
  const double phi = 0.6180339887498949;
  for (int i = 0; i < n; i++) {
    u[i] = -10.0 + 20.0 * (i + 0.5) / n;
    double k = fresh ? 0.05 + 0.94 * fmod(i * phi, 1.0) : kfix;
    m[i] = k * k;
  }
  gsl_set_error_handler_off();
  volatile double sink = 0;
  for (int r = 0; r < reps; r++) {
    double t0 = now_ns(), acc = 0;
    for (int i = 0; i < n; i++) {
      double sn, cn, dn;
      gsl_sf_elljac_e(u[i], m[i], &sn, &cn, &dn);
      acc += sn + cn + dn;
    }
    sink += acc;
    printf("%s%.3f", r ? " " : "", (now_ns() - t0) / n);
  }
  printf("\n");
  free(u);
  free(m);
  return sink == 12345.0;
}
