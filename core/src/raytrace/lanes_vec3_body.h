// A dvec3 of kWidth hits, one D per coordinate, for lanes_sse2.h and lanes_avx.h: each
// includes this body inside its namespace (lanes_avx.h inside its AVX target region) once
// D, Mask, select(Mask, D, D) and splat(double) are defined. The operations are glm's, in
// glm's order (dot = (x·x' + y·y') + z·z'), so a lane is glm's value bit for bit. No
// include guard, no includes: it is a body, not a header.
struct V { // a dvec3 of kWidth hits
    D x, y, z;
};
inline V operator+(const V& a, const V& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline V operator-(const V& a, const V& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline V operator*(const V& a, const V& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
inline V operator*(D k, const V& a) {
    return {k * a.x, k * a.y, k * a.z};
}
inline V operator/(const V& a, D k) {
    return {a.x / k, a.y / k, a.z / k};
}
inline D dot(const V& a, const V& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline V select(Mask m, const V& a, const V& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
inline V splat(const glm::dvec3& v) {
    return {splat(v.x), splat(v.y), splat(v.z)};
}
