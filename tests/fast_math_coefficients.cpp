// The polynomial coefficients of phong/core/fast_math.hpp: interpolation at Chebyshev nodes in long
// double (near-minimax), rounded to float, with each degree's relative error (exact arithmetic and
// float Horner). fast_math.hpp uses log2 degree 7 and exp2 degree 5. A tool, not a test:
//   g++ -std=c++20 -O2 tests/fast_math_coefficients.cpp -o coefficients && ./coefficients
#include <cmath>
#include <cstdio>
#include <vector>
using W = long double;
// Interpolate g at Chebyshev nodes of [a,b] with a degree-d polynomial (monomial coefficients).
std::vector<W> fit(W (*g)(W), W a, W b, int d) {
    int n = d + 1;
    std::vector<std::vector<W>> A(n, std::vector<W>(n + 1));
    for (int i = 0; i < n; ++i) {
        W x = (a + b) / 2 + (b - a) / 2 * cosl((2 * i + 1) * 3.14159265358979323846264338327950288L / (2 * n));
        W p = 1;
        for (int j = 0; j < n; ++j) { A[i][j] = p; p *= x; }
        A[i][n] = g(x);
    }
    for (int c = 0; c < n; ++c) { int piv = c; for (int r = c + 1; r < n; ++r) if (fabsl(A[r][c]) > fabsl(A[piv][c])) piv = r; std::swap(A[c], A[piv]);
        for (int r = 0; r < n; ++r) if (r != c) { W f = A[r][c] / A[c][c]; for (int k = c; k <= n; ++k) A[r][k] -= f * A[c][k]; } }
    std::vector<W> co(n); for (int i = 0; i < n; ++i) co[i] = A[i][n] / A[i][i];
    return co;
}
W lg(W r) { return r == 0 ? 1 / logl(2.0L) : log1pl(r) / r / logl(2.0L); }
W ex(W t) { return exp2l(t); }
int main() {
    const W a = sqrtl(0.5L) - 1, b = sqrtl(2.0L) - 1;
    for (int d = 5; d <= 9; ++d) {
        auto c = fit(lg, a, b, d); std::vector<float> cf(c.begin(), c.end());
        W worst = 0, worstf = 0;
        for (int i = 0; i <= 200000; ++i) { W r = a + (b - a) * i / 200000; float rf = (float)r; r = rf;
            W p = 0; for (int j = d; j >= 0; --j) p = p * r + (W)cf[j];
            float pf = 0; for (int j = d; j >= 0; --j) pf = std::fma(pf, rf, cf[j]);
            W ex_ = lg(r); worst = fmaxl(worst, fabsl(p / ex_ - 1)); worstf = fmaxl(worstf, fabsl((W)pf / ex_ - 1)); }
        std::printf("log2 degree %d: rel %.3Le (float Horner %.3Le):", d, worst, worstf);
        for (float x : cf) std::printf(" %a", x);
        std::printf("\n");
    }
    for (int d = 4; d <= 7; ++d) {
        auto c = fit(ex, -0.5L, 0.5L, d); std::vector<float> cf(c.begin(), c.end()); cf[0] = 1.0f;
        W worst = 0, worstf = 0;
        for (int i = 0; i <= 200000; ++i) { W t = -0.5L + (W)i / 200000; float tf = (float)t; t = tf;
            W p = 0; for (int j = d; j >= 0; --j) p = p * t + (W)cf[j];
            float pf = 0; for (int j = d; j >= 0; --j) pf = std::fma(pf, tf, cf[j]);
            worst = fmaxl(worst, fabsl(p / ex(t) - 1)); worstf = fmaxl(worstf, fabsl((W)pf / ex(t) - 1)); }
        std::printf("exp2 degree %d: rel %.3Le (float Horner %.3Le):", d, worst, worstf);
        for (float x : cf) std::printf(" %a", x);
        std::printf("\n");
    }
}
