// rast — the little linear algebra the camera needs: 3-vectors, homogeneous 4-vectors, 4x4 matrices.
#pragma once

#include <array>
#include <cmath>

namespace rast {

struct Vec3 {
    double x = 0, y = 0, z = 0;
    friend bool operator==(const Vec3&, const Vec3&) = default;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a) { return (1 / length(a)) * a; }

struct Vec4 {
    double x = 0, y = 0, z = 0, w = 0;
};

// Row-major: m[r][c]; a matrix acts on column vectors, M * v, as in the lecture.
struct Mat4 {
    std::array<std::array<double, 4>, 4> m{};

    static Mat4 identity() { return {{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}}; }
};

inline Mat4 operator*(const Mat4& a, const Mat4& b) {
    Mat4 p;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            p.m[r][c] = a.m[r][0] * b.m[0][c] + a.m[r][1] * b.m[1][c] + a.m[r][2] * b.m[2][c] + a.m[r][3] * b.m[3][c];
    return p;
}

inline Vec4 operator*(const Mat4& a, Vec4 v) {
    const auto row = [&](int r) { return a.m[r][0] * v.x + a.m[r][1] * v.y + a.m[r][2] * v.z + a.m[r][3] * v.w; };
    return {row(0), row(1), row(2), row(3)};
}

}  // namespace rast
