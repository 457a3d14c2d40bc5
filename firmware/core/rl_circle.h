/* rl_circle: circles fitted to edge points, and the small linear solver
 * they need (internal).
 *
 *   double x[3] = {10, 0, -10}, y[3] = {0, 10, 0};   // edge points
 *   rl_circle_fit f;
 *   rl_circle_clear(&f);
 *   for (i = 0; i < 3; i++)
 *       rl_circle_add(&f, x[i], y[i]);
 *   if (rl_circle_solve(&f, &cx, &cy, &r))   // 0 here: fewer than 5 points
 *       rl_circle_refine(x, y, 3, &cx, &cy, &r);     // geometric, from there
 */
#ifndef RL_CIRCLE_H
#define RL_CIRCLE_H

/* Algebraic least-squares circle (Kasa) as accumulated normal equations:
 * rows [x y 1] . (D E F) = -(x^2 + y^2). */
typedef struct {
    double s[3][4];
    int n;
} rl_circle_fit;

void rl_circle_clear(rl_circle_fit *f);
void rl_circle_add(rl_circle_fit *f, double x, double y);

/* Centre and radius of the fit; 0 with fewer than 5 points, a singular
 * system or no real radius. */
int rl_circle_solve(const rl_circle_fit *f, double *cx, double *cy, double *r);

/* Gauss-Newton on the geometric distances of the n points to the circle,
 * from (*cx, *cy, *r): the algebraic fit leans inwards on a partial arc.
 * Points more than 1.5 px off the circle are left out; stops with fewer
 * than 6 points left. */
void rl_circle_refine(const double *x, const double *y, int n, double *cx, double *cy, double *r);

/* Solve the n x n system A x = b by Gaussian elimination with partial
 * pivoting, A given row by row with b as its last column (n rows of
 * n + 1, destroyed); 0 if singular. */
int rl_solve(int n, double *A, double *x);

/* Solve the 3 x 3 system A x = A[.][3] by Gaussian elimination with
 * partial pivoting (A is destroyed); 0 if singular. */
int rl_solve3(double A[3][4], double x[3]);

#endif
