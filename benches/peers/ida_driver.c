/* SUNDIALS IDA on the same two problems as dirac's Radau, in the same formulation
 * (y = (q, v, p, lambda), M y' = f(t, y), M = diag(I, 0, I, 0)), with hand-written residual and
 * analytic Jacobian, algebraic variables excluded from the error test (IDASetSuppressAlg), and
 * the same consistent initial state. Prints, per tolerance: problem, tol, final state error
 * against the reference given on the command line, wall time per solve (median of repeats),
 * steps. Used by run.sh; not part of CI. */
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <math.h>
#include <time.h>

/* ---------------- pendulum: n = 2, m = 1, y = (x, y, vx, vy, px, py, lambda) ---------------- */
static const double M_ = 1.0, G_ = 9.81, L_ = 1.0;

static int pend_res(sunrealtype t, N_Vector yy, N_Vector yp, N_Vector rr, void *data) {
  double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp), *r = N_VGetArrayPointer(rr);
  double x = y[0], yy_ = y[1], vx = y[2], vy = y[3], px = y[4], py = y[5], lam = y[6];
  r[0] = d[0] - vx;
  r[1] = d[1] - vy;
  r[2] = -(px - M_ * vx);
  r[3] = -(py - M_ * vy);
  r[4] = d[4] - 2.0 * x * lam;
  r[5] = d[5] - (-M_ * G_ + 2.0 * yy_ * lam);
  r[6] = -(2.0 * x * vx + 2.0 * yy_ * vy);
  return 0;
}

static int pend_jac(sunrealtype t, sunrealtype cj, N_Vector yy, N_Vector yp, N_Vector rr, SUNMatrix J,
                    void *data, N_Vector t1, N_Vector t2, N_Vector t3) {
  double *y = N_VGetArrayPointer(yy);
  double x = y[0], yy_ = y[1], vx = y[2], vy = y[3], lam = y[6];
  SUNMatZero(J);
#define S(i, j, v) SM_ELEMENT_D(J, i, j) = (v)
  S(0, 0, cj); S(0, 2, -1.0);
  S(1, 1, cj); S(1, 3, -1.0);
  S(2, 2, M_); S(2, 4, -1.0);
  S(3, 3, M_); S(3, 5, -1.0);
  S(4, 4, cj); S(4, 0, -2.0 * lam); S(4, 6, -2.0 * x);
  S(5, 5, cj); S(5, 1, -2.0 * lam); S(5, 6, -2.0 * yy_);
  S(6, 0, -2.0 * vx); S(6, 1, -2.0 * vy); S(6, 2, -2.0 * x); S(6, 3, -2.0 * yy_);
  return 0;
}

/* ------------- the paper's torn chain: n = 4, m = 1, q = (x1, x2, x2bar, x3) ------------- */
static const double m1 = 1.0, m2 = 2.0, m3 = 3.0, k1 = 4.0, k2 = 5.0, k3 = 6.0;

static int chain_res(sunrealtype t, N_Vector yy, N_Vector yp, N_Vector rr, void *data) {
  double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp), *r = N_VGetArrayPointer(rr);
  double x1 = y[0], x2 = y[1], xb = y[2], x3 = y[3];
  double v1 = y[4], v2 = y[5], vb = y[6], v3 = y[7];
  double p1 = y[8], p2 = y[9], pb = y[10], p3 = y[11], mu = y[12];
  for (int i = 0; i < 4; i++) r[i] = d[i] - y[4 + i];
  r[4] = -(p1 - m1 * v1);
  r[5] = -(p2 - m2 * v2);
  r[6] = -(pb - 0.0);
  r[7] = -(p3 - m3 * v3);
  r[8] = d[8] - (-k1 * x1 + k2 * (x2 - x1));
  r[9] = d[9] - (-k2 * (x2 - x1) + mu);
  r[10] = d[10] - (k3 * (x3 - xb) - mu);
  r[11] = d[11] - (-k3 * (x3 - xb));
  r[12] = -(v2 - vb);
  return 0;
}

static int chain_jac(sunrealtype t, sunrealtype cj, N_Vector yy, N_Vector yp, N_Vector rr, SUNMatrix J,
                     void *data, N_Vector t1, N_Vector t2, N_Vector t3) {
  SUNMatZero(J);
  for (int i = 0; i < 4; i++) { S(i, i, cj); S(i, 4 + i, -1.0); S(4 + i, 8 + i, -1.0); S(8 + i, 8 + i, cj); }
  S(4, 4, m1); S(5, 5, m2); S(7, 7, m3);
  S(8, 0, k1 + k2); S(8, 1, -k2);
  S(9, 0, -k2); S(9, 1, k2); S(9, 12, -1.0);
  S(10, 2, k3); S(10, 3, -k3); S(10, 12, 1.0);
  S(11, 2, -k3); S(11, 3, k3);
  S(12, 5, -1.0); S(12, 6, 1.0);
  return 0;
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Solves once from y0, yp0 to t_end; returns steps and writes the final state. */
static long solve(SUNContext ctx, IDAResFn res, IDALsJacFn jac, int n, const double *y0, const double *yp0,
                  const double *id, double t_end, double tol, double *out) {
  N_Vector y = N_VNew_Serial(n, ctx), yp = N_VNew_Serial(n, ctx), ids = N_VNew_Serial(n, ctx);
  memcpy(N_VGetArrayPointer(y), y0, n * sizeof(double));
  memcpy(N_VGetArrayPointer(yp), yp0, n * sizeof(double));
  memcpy(N_VGetArrayPointer(ids), id, n * sizeof(double));
  void *mem = IDACreate(ctx);
  IDAInit(mem, res, 0.0, y, yp);
  IDASStolerances(mem, tol, tol);
  SUNMatrix A = SUNDenseMatrix(n, n, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  IDASetLinearSolver(mem, LS, A);
  IDASetJacFn(mem, jac);
  IDASetId(mem, ids);
  IDASetSuppressAlg(mem, SUNTRUE);
  IDASetMaxNumSteps(mem, 1000000);
  IDASetStopTime(mem, t_end);
  double t;
  int flag = IDASolve(mem, t_end, &t, y, yp, IDA_NORMAL);
  long steps = 0;
  IDAGetNumSteps(mem, &steps);
  if (flag < 0) steps = -1;
  memcpy(out, N_VGetArrayPointer(y), n * sizeof(double));
  IDAFree(&mem);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(y); N_VDestroy(yp); N_VDestroy(ids);
  return steps;
}

int main(int argc, char **argv) {
  /* argv: chain reference x1 x2 x3 at t = 20 (exact, computed by dirac's side) */
  if (argc != 4) { fprintf(stderr, "usage: ida_driver x1(20) x2(20) x3(20)\n"); return 2; }
  double chain_ref[3] = {atof(argv[1]), atof(argv[2]), atof(argv[3])};
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  const double tols[] = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  /* Pendulum released from rest at the horizontal: lambda = 0, p' = (0, -m g). */
  double py0[7] = {1, 0, 0, 0, 0, 0, 0}, pyp0[7] = {0, 0, 0, 0, 0, -M_ * G_, 0}, pid[7] = {1, 1, 0, 0, 1, 1, 0};
  /* Chain from x1 = 0.1 at rest: mu = k3 (x3 - x2bar) = 0, p1' = -k1 x1 - k2 x1. */
  double cy0[13] = {0.1}, cyp0[13] = {0}, cid[13] = {1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 1, 0};
  cyp0[8] = -k1 * 0.1 - k2 * 0.1;
  cyp0[9] = k2 * 0.1;
  printf("problem,tol,error,seconds,steps\n");
  for (int p = 0; p < 2; p++) {
    for (size_t k = 0; k < sizeof tols / sizeof tols[0]; k++) {
      double out[13], times[21];
      long steps = 0;
      int reps = 21;
      for (int r = 0; r < reps; r++) {
        double t0 = now();
        steps = p == 0 ? solve(ctx, pend_res, pend_jac, 7, py0, pyp0, pid, 1.0, tols[k], out)
                       : solve(ctx, chain_res, chain_jac, 13, cy0, cyp0, cid, 20.0, tols[k], out);
        times[r] = now() - t0;
      }
      qsort(times, reps, sizeof(double), cmp);
      double err;
      if (p == 0) {
        double ex = fabs(out[0] - -0.98629175113187531936), ey = fabs(out[1] - -0.16501085312554116875);
        err = ex > ey ? ex : ey;
      } else {
        err = 0;
        int idx[3] = {0, 1, 3};
        for (int i = 0; i < 3; i++) {
          double e = fabs(out[idx[i]] - chain_ref[i]);
          if (e > err) err = e;
        }
      }
      printf("%s,%g,%.3e,%.6e,%ld\n", p == 0 ? "pendulum" : "chain", tols[k], err, times[reps / 2], steps);
    }
  }
  SUNContext_Free(&ctx);
  return 0;
}
