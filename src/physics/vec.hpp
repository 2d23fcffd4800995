// Small value types for 2D and 3D vectors in the table frame (x east, y north, z up).
#pragma once

#include <cmath>

namespace physics {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;
};

struct Vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) {
    return {a.x + b.x, a.y + b.y};
}
constexpr Vec2 operator-(Vec2 a, Vec2 b) {
    return {a.x - b.x, a.y - b.y};
}
constexpr Vec2 operator-(Vec2 a) {
    return {-a.x, -a.y};
}
constexpr Vec2 operator*(double s, Vec2 a) {
    return {s * a.x, s * a.y};
}
constexpr Vec2 operator*(Vec2 a, double s) {
    return {s * a.x, s * a.y};
}
constexpr bool operator==(Vec2 a, Vec2 b) {
    return a.x == b.x && a.y == b.y;
}
constexpr double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
constexpr double cross(Vec2 a, Vec2 b) {
    return a.x * b.y - a.y * b.x;
}
constexpr double norm2(Vec2 a) {
    return dot(a, a);
}
inline double norm(Vec2 a) {
    return std::sqrt(norm2(a));
}
/// The vector turned 90 degrees counter-clockwise: z × a.
constexpr Vec2 perp(Vec2 a) {
    return {-a.y, a.x};
}

constexpr Vec3 operator+(Vec3 a, Vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
constexpr Vec3 operator-(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
constexpr Vec3 operator*(double s, Vec3 a) {
    return {s * a.x, s * a.y, s * a.z};
}
constexpr bool operator==(Vec3 a, Vec3 b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}
constexpr double dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double norm2(Vec3 a) {
    return dot(a, a);
}
inline double norm(Vec3 a) {
    return std::sqrt(norm2(a));
}
constexpr Vec3 lift(Vec2 a, double z = 0.0) {
    return {a.x, a.y, z};
}
constexpr Vec2 flat(Vec3 a) {
    return {a.x, a.y};
}

}  // namespace physics
