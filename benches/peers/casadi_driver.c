/* Times a CasADi-generated residual+Jacobian function, compiled in its own translation unit
 * and called through a function pointer: prints the median ns per call of 21 rounds. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef long long casadi_int;
typedef int (*kernel)(const double **arg, double **res, casadi_int *iw, double *w, int mem);
typedef int (*work)(casadi_int *sz_arg, casadi_int *sz_res, casadi_int *sz_iw, casadi_int *sz_w);

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

double time_kernel(void *kp, void *wp, int ny, int nnz) {
  kernel k = (kernel)kp;
  work wk = (work)wp;
  casadi_int sa, sr, si, sw;
  wk(&sa, &sr, &si, &sw);
  double *y = malloc(ny * sizeof(double)), *f = malloc(ny * sizeof(double)), *j = malloc(nnz * sizeof(double));
  double *w = malloc((sw + 1) * sizeof(double));
  casadi_int *iw = malloc((si + 1) * sizeof(casadi_int));
  unsigned long long s = 7;
  for (int i = 0; i < ny; i++) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    y[i] = (double)(s >> 11) / (double)(1ULL << 53) - 0.5;
  }
  const double *arg[1] = {y};
  double *res[2] = {f, j};
  double rounds[21];
  long reps = 100000;
  volatile double sink = 0;
  for (int r = 0; r < 21; r++) {
    double t0 = now();
    for (long i = 0; i < reps; i++) {
      k(arg, res, iw, w, 0);
      sink += f[0];
    }
    rounds[r] = (now() - t0) / reps * 1e9;
  }
  qsort(rounds, 21, sizeof(double), cmp);
  free(y); free(f); free(j); free(w); free(iw);
  return rounds[10];
}
