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

// The largest |component| of v.
template <class R>
R largest_component(const Vec3<R>& v) {
  const R x = v.x < R(0) ? -v.x : v.x, y = v.y < R(0) ? -v.y : v.y, z = v.z < R(0) ? -v.z : v.z;
  return x > y ? (x > z ? x : z) : (y > z ? y : z);
}

// Whether dot(v, v) is safely inside float's range: a squared length
// outside (1e-30, 1e30) is near float's underflow (1e-38) or overflow (3e38).
template <class R>
bool squarable(const Vec3<R>& v) {
  const R v2 = dot(v, v);
  return v2 > R(1e-30) && v2 < R(1e30);
}

// v, or, when its squared length is not squarable, v divided by its largest
// component: the same direction with a length in [1, 1.8]. Readers use it
// on the vectors a scene gives before squaring them (every other vector
// keeps its bits); a zero vector stays zero.
template <class R>
Vec3<R> squarable_direction(const Vec3<R>& v) {
  if (squarable(v)) return v;
  const R big = largest_component(v);
  return big > R(0) ? Vec3<R>{v.x / big, v.y / big, v.z / big} : v;
}

}  // namespace minrt
