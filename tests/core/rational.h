#pragma once
// Exact rational numbers for reference answers of the course's exercises (small
// numerators only: overflow is checked, not avoided).
#include <cstdint>
#include <numeric>
#include <stdexcept>

namespace wb::test {

struct Rational {
    std::int64_t num = 0, den = 1;
    Rational(std::int64_t n = 0, std::int64_t d = 1) : num(n), den(d) { normalise(); }
    void normalise() {
        if (den == 0) throw std::domain_error("Rational: zero denominator");
        if (den < 0) num = -num, den = -den;
        const std::int64_t g = std::gcd(num < 0 ? -num : num, den);
        if (g > 1) num /= g, den /= g;
    }
    static std::int64_t mul(std::int64_t a, std::int64_t b) {
        std::int64_t r;
        if (__builtin_mul_overflow(a, b, &r)) throw std::overflow_error("Rational overflow");
        return r;
    }
    friend Rational operator+(Rational a, Rational b) {
        return {mul(a.num, b.den) + mul(b.num, a.den), mul(a.den, b.den)};
    }
    friend Rational operator-(Rational a, Rational b) { return a + Rational(-b.num, b.den); }
    friend Rational operator*(Rational a, Rational b) {
        return {mul(a.num, b.num), mul(a.den, b.den)};
    }
    friend Rational operator/(Rational a, Rational b) {
        return {mul(a.num, b.den), mul(a.den, b.num)};
    }
    friend bool operator==(Rational a, Rational b) { return a.num == b.num && a.den == b.den; }
    double toDouble() const { return double(num) / double(den); }
};

} // namespace wb::test
