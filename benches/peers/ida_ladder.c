/* SUNDIALS IDA with its sparse direct solver KLU on the LC ladder of dirac's test zoo, in the
 * same formulation as dirac's composite (y = (q, v, p, lambda), M y' = f(t, y),
 * M = diag(I, 0, I, 0)): ground coordinate g, then (a_j, b_j) per cell; rows: the ground's
 * holonomic row (index 2, through its velocity), connect0 (v_g - v_a0) and connect1[j]
 * (v_bj - v_a(j+1)). Hand-written residual and analytic sparse Jacobian (compressed sparse
 * columns), algebraic variables excluded from the error test. The initial state and the exact
 * solution come from dirac's side (benches/ladder_peers.rs setup), so both solvers start from
 * the same state and are judged by the same reference. Prints, per tolerance:
 * problem,tol,error,seconds,steps with the median of 3 solves. Used by ladder.sh; not in CI. */
#include <ida/ida.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <time.h>

static long N;     /* cells */
static long NQ, NC; /* coordinates 2N + 1, rows N + 1 */
static const double L_ = 1.0, C_ = 1.0;

/* Slots in y: q at 0, v at NQ, p at 2 NQ, lambda at 3 NQ. Coordinates: g = 0, a_j = 1 + 2j, b_j = 2 + 2j. */
#define A_(j) (1 + 2 * (j))
#define B_(j) (2 + 2 * (j))

static int res(sunrealtype t, N_Vector yy, N_Vector yp, N_Vector rr, void *data) {
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
    double f = (q[B_(j)] - q[A_(j)]) / L_;
    rv[B_(j)] += C_ * v[B_(j)];
    rp[A_(j)] -= f;
    rp[B_(j)] += f;
  }
  /* Constraint forces A^T lambda and rows A v. */
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

/* Entries (row, col, value) of dF/dy + cj dF/dy', gathered in a fixed order. The first call
 * sorts them by column into the compressed-column pattern and keeps, for each entry, its slot
 * in it (the pattern never changes: only cj moves the values); every call then scatters the
 * values into their slots and copies the kept pattern, since IDA zeroes the whole sparse
 * matrix, indices included, before it asks for the Jacobian. */
typedef struct { long row, col; double val; } Entry;
static Entry *entries;
static long count;
static long *slot, nnz_kept = -1;
static sunindextype *colptrs_kept, *rowvals_kept;
static void add(long row, long col, double val) { entries[count++] = (Entry){row, col, val}; }
static int by_column(const void *a, const void *b) {
  const Entry *x = &entries[*(const long *)a], *y = &entries[*(const long *)b];
  if (x->col != y->col) return (x->col > y->col) - (x->col < y->col);
  return (x->row > y->row) - (x->row < y->row);
}

/* The pattern of the gathered entries, once: colptrs_kept, rowvals_kept and slot. */
static void keep_pattern(long ny) {
  long *order = malloc(count * sizeof(long));
  for (long k = 0; k < count; k++) order[k] = k;
  qsort(order, count, sizeof(long), by_column);
  slot = malloc(count * sizeof(long));
  colptrs_kept = malloc((ny + 1) * sizeof(sunindextype));
  rowvals_kept = malloc(count * sizeof(sunindextype));
  long k = 0, out = 0;
  for (long c = 0; c < ny; c++) {
    colptrs_kept[c] = out;
    while (k < count && entries[order[k]].col == c) {
      rowvals_kept[out] = entries[order[k]].row;
      slot[order[k++]] = out;
      while (k < count && entries[order[k]].col == c && entries[order[k]].row == rowvals_kept[out]) slot[order[k++]] = out;
      out++;
    }
  }
  colptrs_kept[ny] = out;
  nnz_kept = out;
  free(order);
}

static int jac(sunrealtype t, sunrealtype cj, N_Vector yy, N_Vector yp, N_Vector rr, SUNMatrix J, void *data,
               N_Vector t1, N_Vector t2, N_Vector t3) {
  long v0 = NQ, p0 = 2 * NQ, l0 = 3 * NQ;
  count = 0;
  for (long i = 0; i < NQ; i++) {
    add(i, i, cj);
    add(i, v0 + i, -1.0);
    add(v0 + i, p0 + i, -1.0);
    add(p0 + i, p0 + i, cj);
  }
  for (long j = 0; j < N; j++) {
    add(v0 + B_(j), v0 + B_(j), C_);
    add(p0 + A_(j), A_(j), 1.0 / L_);
    add(p0 + A_(j), B_(j), -1.0 / L_);
    add(p0 + B_(j), B_(j), 1.0 / L_);
    add(p0 + B_(j), A_(j), -1.0 / L_);
  }
  add(p0 + 0, l0 + 0, -1.0);
  add(p0 + 0, l0 + 1, -1.0);
  add(p0 + A_(0), l0 + 1, 1.0);
  add(l0 + 0, v0 + 0, -1.0);
  add(l0 + 1, v0 + 0, -1.0);
  add(l0 + 1, v0 + A_(0), 1.0);
  for (long j = 0; j + 1 < N; j++) {
    add(p0 + B_(j), l0 + 2 + j, -1.0);
    add(p0 + A_(j + 1), l0 + 2 + j, 1.0);
    add(l0 + 2 + j, v0 + B_(j), -1.0);
    add(l0 + 2 + j, v0 + A_(j + 1), 1.0);
  }
  long ny = 3 * NQ + NC;
  if (nnz_kept < 0) keep_pattern(ny);
  memcpy(SUNSparseMatrix_IndexPointers(J), colptrs_kept, (ny + 1) * sizeof(sunindextype));
  memcpy(SUNSparseMatrix_IndexValues(J), rowvals_kept, nnz_kept * sizeof(sunindextype));
  double *vals = SUNSparseMatrix_Data(J);
  memset(vals, 0, nnz_kept * sizeof(double));
  for (long k = 0; k < count; k++) vals[slot[k]] += entries[k].val;
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

int main(int argc, char **argv) {
  if (argc != 3) { fprintf(stderr, "usage: ida_ladder CELLS DIR\n"); return 2; }
  N = atol(argv[1]);
  NQ = 2 * N + 1;
  NC = N + 1;
  long ny = 3 * NQ + NC, nnz = 4 * NQ + 5 * N + 6 + 4 * (N - 1);
  entries = malloc(nnz * sizeof(Entry));
  double *y0 = read_file(argv[2], "y0.txt", ny), *yp0 = read_file(argv[2], "yp0.txt", ny);
  double *nodes = read_file(argv[2], "nodes.txt", N), *ref = read_file(argv[2], "ref.txt", N);
  double *id = malloc(ny * sizeof(double));
  for (long i = 0; i < ny; i++) id[i] = (i < NQ || (i >= 2 * NQ && i < 3 * NQ)) ? 1.0 : 0.0;
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  const double tols[] = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11};
  printf("problem,tol,error,seconds,steps\n");
  for (size_t k = 0; k < sizeof tols / sizeof tols[0]; k++) {
    double times[3], err = 0;
    long steps = 0;
    for (int r = 0; r < 3; r++) {
      double t0 = now();
      N_Vector y = N_VNew_Serial(ny, ctx), yp = N_VNew_Serial(ny, ctx), ids = N_VNew_Serial(ny, ctx);
      memcpy(N_VGetArrayPointer(y), y0, ny * sizeof(double));
      memcpy(N_VGetArrayPointer(yp), yp0, ny * sizeof(double));
      memcpy(N_VGetArrayPointer(ids), id, ny * sizeof(double));
      void *mem = IDACreate(ctx);
      IDAInit(mem, res, 0.0, y, yp);
      IDASStolerances(mem, tols[k], tols[k]);
      SUNMatrix A = SUNSparseMatrix(ny, ny, nnz, CSC_MAT, ctx);
      SUNLinearSolver LS = SUNLinSol_KLU(y, A, ctx);
      IDASetLinearSolver(mem, LS, A);
      IDASetJacFn(mem, jac);
      IDASetId(mem, ids);
      IDASetSuppressAlg(mem, SUNTRUE);
      IDASetMaxNumSteps(mem, 1000000);
      IDASetStopTime(mem, 10.0);
      double t;
      int flag = IDASolve(mem, 10.0, &t, y, yp, IDA_NORMAL);
      times[r] = now() - t0;
      IDAGetNumSteps(mem, &steps);
      if (flag < 0) steps = -1;
      double *out = N_VGetArrayPointer(y);
      err = 0;
      for (long j = 0; j < N; j++) {
        double e = fabs(out[(long)nodes[j]] - ref[j]);
        if (e > err) err = e;
      }
      IDAFree(&mem);
      SUNLinSolFree(LS);
      SUNMatDestroy(A);
      N_VDestroy(y); N_VDestroy(yp); N_VDestroy(ids);
    }
    qsort(times, 3, sizeof(double), cmp);
    printf("ladder,%g,%.3e,%.6e,%ld\n", tols[k], err, times[1], steps);
  }
  SUNContext_Free(&ctx);
  return 0;
}
