#pragma once
// 8-point Gauss–Legendre on a rectangle split into cells: the quadrature of the radiosity
// closed-form tests and of the bench's exact area-to-area form factors.
#include <cstddef>
#include <vector>

namespace wb::rad::test {

// Nodes and weights on [-1, 1] (Abramowitz & Stegun, table 25.4).
constexpr double kGaussX8[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                0.7966664774136267,  0.9602898564975363};
constexpr double kGaussW8[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                0.2223810344533745, 0.1012285362903763};

// ∫∫ f over [xs.front(), xs.back()] × [ys.front(), ys.back()] divided by its area, by 8-point
// Gauss–Legendre on each cell between consecutive breaks.
template <class F>
double gaussAverage(const std::vector<double>& xs, const std::vector<double>& ys, const F& f) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
        for (std::size_t j = 0; j + 1 < ys.size(); ++j)
            for (int p = 0; p < 8; ++p)
                for (int q = 0; q < 8; ++q) {
                    const double hx = xs[i + 1] - xs[i], hy = ys[j + 1] - ys[j];
                    const double x = xs[i] + 0.5 * hx * (1 + kGaussX8[p]);
                    const double y = ys[j] + 0.5 * hy * (1 + kGaussX8[q]);
                    sum += 0.25 * hx * hy * kGaussW8[p] * kGaussW8[q] * f(x, y);
                }
    const double area = (xs.back() - xs.front()) * (ys.back() - ys.front());
    return sum / area;
}

} // namespace wb::rad::test
