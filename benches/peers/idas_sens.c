/* SUNDIALS IDAS forward sensitivities of the paper's chain, the peer of
 * `cargo bench -p dirac-benches --bench sensitivities` (its paper-chain row). The chain is written as
 * ida_driver.c writes it (y = (q, v, p, mu), M y' = f(t, y), the algebraic variables out of the
 * error test), with its six parameters (m1, m2, k1, k2, m3, k3) in user data, so that IDAS
 * forms the sensitivity residuals by its own difference quotients (IDASetSensParams) and solves
 * them by the staggered corrector with the state's Jacobian (IDA_STAGGERED), its sensitivities'
 * errors out of the step control as in dirac's default. Same consistent start (x1 = 0.1 at
 * rest), same span (20 s), same tolerance (1e-8), output every 0.1 s. Prints the median wall
 * time of 21 solves without and with the sensitivities, the steps, and the sensitivities of
 * x1(20) for comparison with dirac's. Run by sensitivities.sh; not part of CI. */
#include <idas/idas.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <time.h>

#define NY 13
#define NP 6

/* p = (m1, m2, k1, k2, m3, k3). */
static int chain_res(sunrealtype t, N_Vector yy, N_Vector yp, N_Vector rr, void *data) {
  const double *p = data;
  double m1 = p[0], m2 = p[1], k1 = p[2], k2 = p[3], m3 = p[4], k3 = p[5];
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

#define S(i, j, v) SM_ELEMENT_D(J, i, j) = (v)
static int chain_jac(sunrealtype t, sunrealtype cj, N_Vector yy, N_Vector yp, N_Vector rr, SUNMatrix J,
                     void *data, N_Vector t1, N_Vector t2, N_Vector t3) {
  const double *p = data;
  double m1 = p[0], m2 = p[1], k1 = p[2], k2 = p[3], m3 = p[4], k3 = p[5];
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

/* One solve from the consistent start to t = 20, output every 0.1 s, with the six parameter
 * sensitivities if `sens`; returns the steps and writes x1(20) and its sensitivities. */
static long solve(SUNContext ctx, int sens, double *x1, double *dx1) {
  double p[NP] = {1.0, 2.0, 4.0, 5.0, 3.0, 6.0}, pbar[NP];
  for (int i = 0; i < NP; i++) pbar[i] = p[i];
  double id[NY] = {1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 1, 0};
  N_Vector y = N_VNew_Serial(NY, ctx), yp = N_VNew_Serial(NY, ctx), ids = N_VNew_Serial(NY, ctx);
  N_VConst(0.0, y);
  N_VConst(0.0, yp);
  double *y0 = N_VGetArrayPointer(y), *yp0 = N_VGetArrayPointer(yp);
  y0[0] = 0.1;
  yp0[8] = -p[2] * 0.1 - p[3] * 0.1;
  yp0[9] = p[3] * 0.1;
  memcpy(N_VGetArrayPointer(ids), id, sizeof id);
  void *mem = IDACreate(ctx);
  IDAInit(mem, chain_res, 0.0, y, yp);
  IDASStolerances(mem, 1e-8, 1e-8);
  IDASetUserData(mem, p);
  SUNMatrix A = SUNDenseMatrix(NY, NY, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  IDASetLinearSolver(mem, LS, A);
  IDASetJacFn(mem, chain_jac);
  IDASetId(mem, ids);
  IDASetSuppressAlg(mem, SUNTRUE);
  IDASetMaxNumSteps(mem, 1000000);
  N_Vector *s = NULL, *sp = NULL;
  if (sens) {
    s = N_VCloneVectorArray(NP, y);
    sp = N_VCloneVectorArray(NP, y);
    for (int k = 0; k < NP; k++) { N_VConst(0.0, s[k]); N_VConst(0.0, sp[k]); }
    /* The start's derivative: p1' = -(k1 + k2) x1 and p2' = k2 x1 depend on k1 and k2. */
    N_VGetArrayPointer(sp[2])[8] = -0.1;
    N_VGetArrayPointer(sp[3])[8] = -0.1;
    N_VGetArrayPointer(sp[3])[9] = 0.1;
    IDASensInit(mem, NP, IDA_STAGGERED, NULL, s, sp);
    IDASensEEtolerances(mem);
    IDASetSensParams(mem, p, pbar, NULL);
    IDASetSensErrCon(mem, SUNFALSE);
  }
  double t = 0.0;
  for (int k = 1; k <= 200; k++) {
    double tout = 0.1 * k;
    if (IDASolve(mem, tout, &t, y, yp, IDA_NORMAL) < 0) return -1;
    if (sens) IDAGetSens(mem, &t, s);
  }
  long steps = 0;
  IDAGetNumSteps(mem, &steps);
  *x1 = N_VGetArrayPointer(y)[0];
  for (int k = 0; sens && k < NP; k++) dx1[k] = N_VGetArrayPointer(s[k])[0];
  if (sens) {
    N_VDestroyVectorArray(s, NP);
    N_VDestroyVectorArray(sp, NP);
  }
  IDAFree(&mem);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(y); N_VDestroy(yp); N_VDestroy(ids);
  return steps;
}

int main(void) {
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  double x1 = 0, dx1[NP] = {0}, times[2][21];
  long steps[2] = {0, 0};
  for (int sens = 0; sens < 2; sens++) {
    for (int r = 0; r < 21; r++) {
      double t0 = now();
      steps[sens] = solve(ctx, sens, &x1, dx1);
      times[sens][r] = now() - t0;
    }
    qsort(times[sens], 21, sizeof(double), cmp);
  }
  double plain = times[0][10], with = times[1][10];
  printf("IDAS, paper chain, 6 parameters: plain %.3f ms (%ld steps), with sensitivities %.3f ms (%ld steps), "
         "ratio %.2f\n", 1e3 * plain, steps[0], 1e3 * with, steps[1], with / plain);
  printf("IDAS x1(20) = %.10f, d x1(20)/d(m1, m2, k1, k2, m3, k3) =", x1);
  for (int k = 0; k < NP; k++) printf(" %.8f", dx1[k]);
  printf("\n");
  SUNContext_Free(&ctx);
  return 0;
}
