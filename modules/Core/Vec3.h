// Vec3: a small double-precision 3-vector, the one geometric value type every engine shares.
#ifndef art_Vec3_h
#define art_Vec3_h

#include <cmath>

namespace art
{
struct Vec3
{
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double a, double b, double c) : x(a), y(b), z(c) {}
  explicit Vec3(const double* p) : x(p[0]), y(p[1]), z(p[2]) {}

  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

  Vec3 operator+(const Vec3& o) const { return { x + o.x, y + o.y, z + o.z }; }
  Vec3 operator-(const Vec3& o) const { return { x - o.x, y - o.y, z - o.z }; }
  Vec3 operator-() const { return { -x, -y, -z }; }
  Vec3 operator*(double s) const { return { x * s, y * s, z * s }; }
  Vec3 operator/(double s) const { return { x / s, y / s, z / s }; }
  Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
  bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator!=(const Vec3& o) const { return !(*this == o); }
};

inline Vec3 operator*(double s, const Vec3& v) { return v * s; }
inline double Dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
inline double Length(const Vec3& v) { return std::sqrt(Dot(v, v)); }
inline Vec3 Normalize(const Vec3& v)
{
  const double l = Length(v);
  return l > 0 ? v / l : v;
}
inline Vec3 Min(const Vec3& a, const Vec3& b)
{
  return { std::fmin(a.x, b.x), std::fmin(a.y, b.y), std::fmin(a.z, b.z) };
}
inline Vec3 Max(const Vec3& a, const Vec3& b)
{
  return { std::fmax(a.x, b.x), std::fmax(a.y, b.y), std::fmax(a.z, b.z) };
}
inline bool IsFinite(const Vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
} // namespace art

#endif
