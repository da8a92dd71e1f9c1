/* SUNDIALS IDAS's adjoint on the LC ladder of `cargo bench -p dirac-benches --bench adjoint`, the peer of its
 * adjoint gradients: the gradient of G = ∫_0^T ½ |q|² dt with respect to every cell's
 * inductance and capacitance (N_θ = 2N), in the same formulation as dirac's composite
 * (y = (q, v, p, λ), F = M y' − f(t, y) = 0, M = diag(I, 0, I, 0), the algebraic variables out
 * of the error test), as ida_ladder.c writes it, with each cell's l_j and c_j.
 *
 * The forward run is IDASolveF with checkpoints every CHECKPOINT steps and Hermite
 * interpolation; the backward problem is the adjoint DAE M λ' − F_yᵀ λ + g_yᵀ = 0 from
 * λ(T) = 0 (IDAS user guide, §2.6 for a quadrature objective; it is index 2 as the forward
 * one is), with the analytic sparse Jacobian −F_yᵀ + c_jB M and KLU on both sides, and the
 * gradient the backward quadrature of λᵀ F_θ. The forward run also integrates G as a
 * quadrature. One tolerance TOL for all of them, forward and backward.
 *
 * Reads from DIR (written by `cargo bench -p dirac-benches --bench adjoint -- peers setup DIR`):
 * y0.txt and yp0.txt (dirac's consistent start and its derivative), l.txt and c.txt (the
 * cells), reference.txt (G and the reference gradient, l_j c_j per line). Prints one
 * work-precision CSV line, problem,tol,error,seconds,steps: problem ladder<cells>, error the
 * largest difference from the reference gradient over its largest entry, seconds the median
 * of REPEATS gradients, steps the forward run's; the backward run's steps and G on stderr.
 * Used by adjoint.sh; not part of CI. */
#include <idas/idas.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <time.h>

#define CHECKPOINT 100
#define REPEATS 5
static double TOL;
#define T_END 5.0

static long N, NQ, NC, NY;
static double *L, *C;

/* Slots in y: q at 0, v at NQ, p at 2 NQ, λ at 3 NQ. Coordinates: g = 0, a_j = 1 + 2j, b_j = 2 + 2j. */
#define A_(j) (1 + 2 * (j))
#define B_(j) (2 + 2 * (j))

static int res(realtype t, N_Vector yy, N_Vector yp, N_Vector rr, void *data) {
  double *y = N_VGetArrayPointer(yy), *d = N_VGetArrayPointer(yp), *r = N_VGetArrayPointer(rr);
  const double *q = y, *v = y + NQ, *p = y + 2 * NQ, *lam = y + 3 * NQ;
  const double *dq = d, *dp = d + 2 * NQ;
  double *rq = r, *rv = r + NQ, *rp = r + 2 * NQ, *rl = r + 3 * NQ;
  for (long i = 0; i < NQ; i++) {
    rq[i] = dq[i] - v[i];
    rv[i] = -p[i];
    rp[i] = dp[i];
  }
  for (long j = 0; j < N; j++) {
    double f = (q[B_(j)] - q[A_(j)]) / L[j];
    rv[B_(j)] += C[j] * v[B_(j)];
    rp[A_(j)] -= f;
    rp[B_(j)] += f;
  }
  rp[0] -= lam[0] + lam[1];
  rp[A_(0)] += lam[1];
  rl[0] = -v[0];
  rl[1] = -(v[0] - v[A_(0)]);
  for (long j = 0; j + 1 < N; j++) {
    rp[B_(j)] -= lam[2 + j];
    rp[A_(j + 1)] += lam[2 + j];
    rl[2 + j] = -(v[B_(j)] - v[A_(j + 1)]);
  }
  return 0;
}

/* G's integrand. */
static int quad(realtype t, N_Vector yy, N_Vector yp, N_Vector rq, void *data) {
  const double *q = N_VGetArrayPointer(yy);
  double g = 0;
  for (long i = 0; i < NQ; i++) g += 0.5 * q[i] * q[i];
  N_VGetArrayPointer(rq)[0] = g;
  return 0;
}

/* Every entry (row, col, value) of F_y, without the c_j M of the iteration matrix. */
typedef void (*Emit)(long row, long col, double val, void *to);
static void each_entry(Emit emit, void *to) {
  long v0 = NQ, p0 = 2 * NQ, l0 = 3 * NQ;
  for (long i = 0; i < NQ; i++) {
    emit(i, v0 + i, -1.0, to);
    emit(v0 + i, p0 + i, -1.0, to);
  }
  for (long j = 0; j < N; j++) {
    emit(v0 + B_(j), v0 + B_(j), C[j], to);
    emit(p0 + A_(j), A_(j), 1.0 / L[j], to);
    emit(p0 + A_(j), B_(j), -1.0 / L[j], to);
    emit(p0 + B_(j), B_(j), 1.0 / L[j], to);
    emit(p0 + B_(j), A_(j), -1.0 / L[j], to);
  }
  emit(p0 + 0, l0 + 0, -1.0, to);
  emit(p0 + 0, l0 + 1, -1.0, to);
  emit(p0 + A_(0), l0 + 1, 1.0, to);
  emit(l0 + 0, v0 + 0, -1.0, to);
  emit(l0 + 1, v0 + 0, -1.0, to);
  emit(l0 + 1, v0 + A_(0), 1.0, to);
  for (long j = 0; j + 1 < N; j++) {
    emit(p0 + B_(j), l0 + 2 + j, -1.0, to);
    emit(p0 + A_(j + 1), l0 + 2 + j, 1.0, to);
    emit(l0 + 2 + j, v0 + B_(j), -1.0, to);
    emit(l0 + 2 + j, v0 + A_(j + 1), 1.0, to);
  }
}

typedef struct { long row, col; double val; } Entry;
typedef struct { Entry *entries; long count; int transpose; } Gather;
static Entry *scratch;

static void gather(long row, long col, double val, void *to) {
  Gather *g = to;
  g->entries[g->count++] = g->transpose ? (Entry){col, row, -val} : (Entry){row, col, val};
}

/* The compressed-column pattern of one matrix (forward or transposed), found on its first
 * fill: the gathering order never changes, so each gathered entry keeps its slot, duplicates
 * (a diagonal entry of F_y beside c_j M) sharing one. IDAS zeroes the whole sparse matrix,
 * indices included, before it asks for a Jacobian, so every fill copies the kept indices. */
typedef struct { long nnz, *slot; sunindextype *colptrs, *rowvals; } Pattern;
static Pattern patterns[2] = {{-1}, {-1}};
static const Entry *sorting;

static int by_column(const void *a, const void *b) {
  const Entry *x = &sorting[*(const long *)a], *y = &sorting[*(const long *)b];
  if (x->col != y->col) return (x->col > y->col) - (x->col < y->col);
  return (x->row > y->row) - (x->row < y->row);
}

static void keep_pattern(Pattern *p, const Gather *g) {
  long *order = malloc(g->count * sizeof(long));
  for (long k = 0; k < g->count; k++) order[k] = k;
  sorting = g->entries;
  qsort(order, g->count, sizeof(long), by_column);
  p->slot = malloc(g->count * sizeof(long));
  p->colptrs = malloc((NY + 1) * sizeof(sunindextype));
  p->rowvals = malloc(g->count * sizeof(sunindextype));
  long k = 0, out = 0;
  for (long c = 0; c < NY; c++) {
    p->colptrs[c] = out;
    while (k < g->count && g->entries[order[k]].col == c) {
      p->rowvals[out] = g->entries[order[k]].row;
      p->slot[order[k++]] = out;
      while (k < g->count && g->entries[order[k]].col == c && g->entries[order[k]].row == p->rowvals[out])
        p->slot[order[k++]] = out;
      out++;
    }
  }
  p->colptrs[NY] = out;
  p->nnz = out;
  free(order);
}

/* F_y + cj M (forward) or −F_yᵀ + cj M (backward) in compressed columns. */
static void fill(SUNMatrix J, double cj, int transpose) {
  Gather g = {scratch, 0, transpose};
  for (long i = 0; i < NQ; i++) {
    gather(i, i, transpose ? -cj : cj, &g);
    gather(2 * NQ + i, 2 * NQ + i, transpose ? -cj : cj, &g);
  }
  each_entry(gather, &g);
  Pattern *p = &patterns[transpose];
  if (p->nnz < 0) keep_pattern(p, &g);
  memcpy(SUNSparseMatrix_IndexPointers(J), p->colptrs, (NY + 1) * sizeof(sunindextype));
  memcpy(SUNSparseMatrix_IndexValues(J), p->rowvals, p->nnz * sizeof(sunindextype));
  double *vals = SUNSparseMatrix_Data(J);
  memset(vals, 0, p->nnz * sizeof(double));
  for (long k = 0; k < g.count; k++) vals[p->slot[k]] += g.entries[k].val;
}

static int jac(realtype t, realtype cj, N_Vector yy, N_Vector yp, N_Vector rr, SUNMatrix J, void *data,
               N_Vector t1, N_Vector t2, N_Vector t3) {
  fill(J, cj, 0);
  return 0;
}

static int jacB(realtype t, realtype cjB, N_Vector yy, N_Vector yp, N_Vector yyB, N_Vector ypB, N_Vector rrB,
                SUNMatrix J, void *data, N_Vector t1, N_Vector t2, N_Vector t3) {
  fill(J, cjB, 1);
  return 0;
}

/* rrB = M λ' − F_yᵀ λ + g_yᵀ. */
typedef struct { const double *lam; double *r; } Transposed;
static void subtract_transposed(long row, long col, double val, void *to) {
  Transposed *t = to;
  t->r[col] -= val * t->lam[row];
}

static int resB(realtype t, N_Vector yy, N_Vector yp, N_Vector yyB, N_Vector ypB, N_Vector rrB, void *data) {
  const double *q = N_VGetArrayPointer(yy), *lam = N_VGetArrayPointer(yyB), *dlam = N_VGetArrayPointer(ypB);
  double *r = N_VGetArrayPointer(rrB);
  for (long i = 0; i < NY; i++) r[i] = 0.0;
  for (long i = 0; i < NQ; i++) {
    r[i] = dlam[i] + q[i];
    r[2 * NQ + i] = dlam[2 * NQ + i];
  }
  Transposed to = {lam, r};
  each_entry(subtract_transposed, &to);
  return 0;
}

/* λᵀ F_θ for θ = (l_0, c_0, l_1, c_1, …). */
static int quadB(realtype t, N_Vector yy, N_Vector yp, N_Vector yyB, N_Vector ypB, N_Vector qdot, void *data) {
  const double *y = N_VGetArrayPointer(yy), *lam = N_VGetArrayPointer(yyB);
  const double *q = y, *v = y + NQ, *lv = lam + NQ, *lp = lam + 2 * NQ;
  double *out = N_VGetArrayPointer(qdot);
  for (long j = 0; j < N; j++) {
    double df = -(q[B_(j)] - q[A_(j)]) / (L[j] * L[j]); /* ∂f/∂l_j, f = (q_b − q_a)/l_j */
    out[2 * j] = lp[A_(j)] * (-df) + lp[B_(j)] * df;
    out[2 * j + 1] = lv[B_(j)] * v[B_(j)];
  }
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

static double *read_file(const char *dir, const char *name, long n) {
  char path[4096];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = fopen(path, "r");
  if (!f) { fprintf(stderr, "cannot read %s\n", path); exit(2); }
  double *x = malloc(n * sizeof(double));
  for (long i = 0; i < n; i++)
    if (fscanf(f, "%lf", &x[i]) != 1) { fprintf(stderr, "%s: expected %ld numbers\n", path, n); exit(2); }
  fclose(f);
  return x;
}

static void check(int flag, const char *what) {
  if (flag < 0) { fprintf(stderr, "%s failed: %d\n", what, flag); exit(1); }
}

/* One gradient: the forward run with checkpoints, then the backward run. */
static void gradient(SUNContext ctx, const double *y0, const double *yp0, const double *id, double *g_value,
                     double *grad, long *steps_f, long *steps_b) {
  long nnz = 2 * (4 * NQ + 5 * N + 6 + 4 * (N - 1));
  N_Vector y = N_VNew_Serial(NY, ctx), yp = N_VNew_Serial(NY, ctx), ids = N_VNew_Serial(NY, ctx);
  N_Vector qf = N_VNew_Serial(1, ctx);
  memcpy(N_VGetArrayPointer(y), y0, NY * sizeof(double));
  memcpy(N_VGetArrayPointer(yp), yp0, NY * sizeof(double));
  memcpy(N_VGetArrayPointer(ids), id, NY * sizeof(double));
  N_VConst(0.0, qf);
  void *mem = IDACreate(ctx);
  check(IDAInit(mem, res, 0.0, y, yp), "IDAInit");
  check(IDASStolerances(mem, TOL, TOL), "IDASStolerances");
  SUNMatrix A = SUNSparseMatrix(NY, NY, nnz, CSC_MAT, ctx);
  SUNLinearSolver LS = SUNLinSol_KLU(y, A, ctx);
  check(IDASetLinearSolver(mem, LS, A), "IDASetLinearSolver");
  check(IDASetJacFn(mem, jac), "IDASetJacFn");
  check(IDASetId(mem, ids), "IDASetId");
  check(IDASetSuppressAlg(mem, SUNTRUE), "IDASetSuppressAlg");
  check(IDASetMaxNumSteps(mem, 1000000), "IDASetMaxNumSteps");
  check(IDASetStopTime(mem, T_END), "IDASetStopTime");
  check(IDAQuadInit(mem, quad, qf), "IDAQuadInit");
  check(IDAAdjInit(mem, CHECKPOINT, IDA_HERMITE), "IDAAdjInit");
  double t;
  int ncheck;
  check(IDASolveF(mem, T_END, &t, y, yp, IDA_NORMAL, &ncheck), "IDASolveF");
  IDAGetNumSteps(mem, steps_f);
  IDAGetQuad(mem, &t, qf);
  *g_value = N_VGetArrayPointer(qf)[0];

  int which;
  N_Vector yB = N_VNew_Serial(NY, ctx), ypB = N_VNew_Serial(NY, ctx), qB = N_VNew_Serial(2 * N, ctx);
  N_VConst(0.0, yB);
  N_VConst(0.0, ypB);
  N_VConst(0.0, qB);
  /* λ(T) = 0 and M λ'(T) = −g_yᵀ: λ_q' = −q(T). */
  const double *qT = N_VGetArrayPointer(y);
  for (long i = 0; i < NQ; i++) N_VGetArrayPointer(ypB)[i] = -qT[i];
  check(IDACreateB(mem, &which), "IDACreateB");
  check(IDAInitB(mem, which, resB, T_END, yB, ypB), "IDAInitB");
  check(IDASStolerancesB(mem, which, TOL, TOL), "IDASStolerancesB");
  SUNMatrix AB = SUNSparseMatrix(NY, NY, nnz, CSC_MAT, ctx);
  SUNLinearSolver LSB = SUNLinSol_KLU(yB, AB, ctx);
  check(IDASetLinearSolverB(mem, which, LSB, AB), "IDASetLinearSolverB");
  check(IDASetJacFnB(mem, which, jacB), "IDASetJacFnB");
  check(IDASetIdB(mem, which, ids), "IDASetIdB");
  check(IDASetSuppressAlgB(mem, which, SUNTRUE), "IDASetSuppressAlgB");
  check(IDASetMaxNumStepsB(mem, which, 1000000), "IDASetMaxNumStepsB");
  check(IDAQuadInitB(mem, which, quadB, qB), "IDAQuadInitB");
  check(IDAQuadSStolerancesB(mem, which, TOL, TOL), "IDAQuadSStolerancesB");
  check(IDASolveB(mem, 0.0, IDA_NORMAL), "IDASolveB");
  check(IDAGetQuadB(mem, which, &t, qB), "IDAGetQuadB");
  IDAGetNumSteps(IDAGetAdjIDABmem(mem, which), steps_b);
  memcpy(grad, N_VGetArrayPointer(qB), 2 * N * sizeof(double));

  IDAFree(&mem);
  SUNLinSolFree(LS);
  SUNLinSolFree(LSB);
  SUNMatDestroy(A);
  SUNMatDestroy(AB);
  N_VDestroy(y); N_VDestroy(yp); N_VDestroy(ids); N_VDestroy(qf);
  N_VDestroy(yB); N_VDestroy(ypB); N_VDestroy(qB);
}

int main(int argc, char **argv) {
  if (argc != 4) { fprintf(stderr, "usage: idas_adjoint CELLS DIR TOL\n"); return 2; }
  N = atol(argv[1]);
  TOL = atof(argv[3]);
  NQ = 2 * N + 1;
  NC = N + 1;
  NY = 3 * NQ + NC;
  scratch = malloc(2 * (4 * NQ + 5 * N + 6 + 4 * (N - 1)) * sizeof(Entry));
  double *y0 = read_file(argv[2], "y0.txt", NY), *yp0 = read_file(argv[2], "yp0.txt", NY);
  L = read_file(argv[2], "l.txt", N);
  C = read_file(argv[2], "c.txt", N);
  double *reference = read_file(argv[2], "reference.txt", 1 + 2 * N);
  double *id = malloc(NY * sizeof(double));
  for (long i = 0; i < NY; i++) id[i] = (i < NQ || (i >= 2 * NQ && i < 3 * NQ)) ? 1.0 : 0.0;
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  double times[REPEATS], g_value = 0, *grad = malloc(2 * N * sizeof(double));
  long steps_f = 0, steps_b = 0;
  for (int r = 0; r < REPEATS; r++) {
    double t0 = now();
    gradient(ctx, y0, yp0, id, &g_value, grad, &steps_f, &steps_b);
    times[r] = now() - t0;
  }
  qsort(times, REPEATS, sizeof(double), cmp);
  double scale = 0, worst = 0;
  for (long k = 0; k < 2 * N; k++) scale = fmax(scale, fabs(reference[1 + k]));
  for (long k = 0; k < 2 * N; k++) worst = fmax(worst, fabs(grad[k] - reference[1 + k]) / scale);
  printf("ladder%ld,%g,%.3e,%.6e,%ld\n", N, TOL, worst, times[REPEATS / 2], steps_f);
  fprintf(stderr, "IDAS, %ld cells, tol %g: %ld forward and %ld backward steps, G = %.10e (reference %.10e)\n",
          N, TOL, steps_f, steps_b, g_value, reference[0]);
  SUNContext_Free(&ctx);
  return 0;
}
