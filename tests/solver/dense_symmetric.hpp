// Small dense symmetric linear algebra for the tests, written out (Eigen's AVX-512 kernels
// trip GCC 12's -Wmaybe-uninitialized false positives under -march=native).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace slipfront::verification {

// Row-major n x n matrix.
struct Dense {
  int n = 0;
  std::vector<double> a;
  explicit Dense(int size) : n(size), a(std::size_t(size) * size, 0.0) {}
  double& operator()(int r, int c) { return a[std::size_t(r) * n + c]; }
  double operator()(int r, int c) const { return a[std::size_t(r) * n + c]; }
};

// Eigenvalues of a symmetric matrix by cyclic Jacobi rotations (ascending). For small n.
inline std::vector<double> jacobi_eigenvalues(Dense A, double tolerance = 1e-15) {
  const int n = A.n;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0, total = 0;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        (r == c ? total : off) += A(r, c) * A(r, c);
    if (off <= tolerance * tolerance * (total + off)) break;
    for (int p = 0; p < n - 1; ++p)
      for (int q = p + 1; q < n; ++q) {
        if (A(p, q) == 0.0) continue;
        const double theta = (A(q, q) - A(p, p)) / (2 * A(p, q));
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < n; ++k) { // A <- A J
          const double akp = A(k, p), akq = A(k, q);
          A(k, p) = c * akp - s * akq;
          A(k, q) = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) { // A <- J^T A
          const double apk = A(p, k), aqk = A(q, k);
          A(p, k) = c * apk - s * aqk;
          A(q, k) = s * apk + c * aqk;
        }
      }
  }
  std::vector<double> ev(n);
  for (int i = 0; i < n; ++i)
    ev[i] = A(i, i);
  std::sort(ev.begin(), ev.end());
  return ev;
}

// True if the symmetric A is positive definite (Cholesky succeeds).
inline bool positive_definite(Dense A) {
  const int n = A.n;
  for (int j = 0; j < n; ++j) {
    double d = A(j, j);
    for (int k = 0; k < j; ++k)
      d -= A(j, k) * A(j, k);
    if (!(d > 0)) return false;
    const double l = std::sqrt(d);
    A(j, j) = l;
    for (int i = j + 1; i < n; ++i) {
      double s = A(i, j);
      for (int k = 0; k < j; ++k)
        s -= A(i, k) * A(j, k);
      A(i, j) = s / l;
    }
  }
  return true;
}

} // namespace slipfront::verification
