// A 3-vector of the policy's real, for the general tracer and the scene
// model. Plain arithmetic only; the square root comes from the math policy
// (norm and normalize take it as a template argument).
#pragma once

namespace minrt {

template <class R>
struct Vec3 {
  R x{}, y{}, z{};

  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(R s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(R s) const { return {x / s, y / s, z / s}; }
  // Component-wise product (colours).
  constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
  constexpr Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  constexpr R operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
};

template <class R>
constexpr R dot(const Vec3<R>& a, const Vec3<R>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <class R>
constexpr Vec3<R> cross(const Vec3<R>& a, const Vec3<R>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class M>
typename M::real length(const Vec3<typename M::real>& v) {
  return M::sqrt(dot(v, v));
}

template <class M>
Vec3<typename M::real> normalize(const Vec3<typename M::real>& v) {
  return v / M::sqrt(dot(v, v));
}

}  // namespace minrt
