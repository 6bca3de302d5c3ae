/* Times GSL's gsl_sf_elljac_e (sn, cn, dn in one call) on the batch of
 * examples/bench_batch.rs, for scripts/bench_peers.py.
 *
 *   bench_gsl N REPEATS fixed|fresh [K] [E|Einc|Pi]
 *
 * With a last argument E, Einc or Pi the batch times GSL's elliptic integrals instead
 * (as examples/bench_batch.rs fn=ellipe|ellipeinc|ellippi): E(k_i) =
 * gsl_sf_ellint_Ecomp, E(u_i/4, k_i) = gsl_sf_ellint_E, Pi(0.3, u_i/8, k_i) =
 * gsl_sf_ellint_P with GSL's characteristic -0.3 (GSL integrates 1/(1 + n sin^2)).
 *
 * Batch: u_i = -10 + 20 (i + 0.5)/N; modulus k = K (default 0.8, "fixed") or
 * k_i = 0.05 + 0.94 frac(i phi) ("fresh", phi the golden ratio); GSL takes the
 * parameter m = k^2.  Prints the wall-clock time per evaluation (ns) of every batch.
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
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
    fprintf(stderr, "usage: bench_gsl N REPEATS fixed|fresh [K] [E|Einc|Pi]\n");
    return 2;
  }
  int n = atoi(argv[1]), reps = atoi(argv[2]);
  int fresh = strcmp(argv[3], "fresh") == 0;
  double kfix = argc > 4 ? atof(argv[4]) : 0.8;
  const char *fn = argc > 5 ? argv[5] : "";
  int which = strcmp(fn, "E") == 0 ? 1 : strcmp(fn, "Einc") == 0 ? 2 : strcmp(fn, "Pi") == 0 ? 3 : 0;
  double *u = malloc(n * sizeof *u), *m = malloc(n * sizeof *m);
  const double phi = 0.6180339887498949;
  for (int i = 0; i < n; i++) {
    u[i] = -10.0 + 20.0 * (i + 0.5) / n;
    double k = fresh ? 0.05 + 0.94 * fmod(i * phi, 1.0) : kfix;
    m[i] = which ? k : k * k; /* the integrals take the modulus */
  }
  gsl_set_error_handler_off();
  volatile double sink = 0;
  for (int r = 0; r < reps; r++) {
    double t0 = now_ns(), acc = 0;
    for (int i = 0; i < n; i++) {
      double sn, cn, dn;
      switch (which) {
      case 1: acc += gsl_sf_ellint_Ecomp(m[i], GSL_PREC_DOUBLE); break;
      case 2: acc += gsl_sf_ellint_E(u[i] / 4, m[i], GSL_PREC_DOUBLE); break;
      case 3: acc += gsl_sf_ellint_P(u[i] / 8, m[i], -0.3, GSL_PREC_DOUBLE); break;
      default:
        gsl_sf_elljac_e(u[i], m[i], &sn, &cn, &dn);
        acc += sn + cn + dn;
      }
    }
    sink += acc;
    printf("%s%.3f", r ? " " : "", (now_ns() - t0) / n);
  }
  printf("\n");
  free(u);
  free(m);
  return sink == 12345.0;
}
