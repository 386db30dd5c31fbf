#include "ExactPredicates.hpp"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace chute::mesh {

namespace {

thread_local long fallbackCount = 0;

// a + b = s + e exactly, |e| <= ulp(s) / 2 (Knuth's two-sum; round to nearest).
inline void twoSum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a, av = s - bv;
  e = (a - av) + (b - bv);
}

// a b = p + e exactly: the fused multiply-add rounds once, so fma(a, b, -p) is the exact error.
inline void twoProduct(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

// A real number as a sum of non-overlapping doubles in order of increasing magnitude, zeros
// dropped. Every operation is built from one step, adding a double (Shewchuk's grow-expansion),
// which keeps that form; so the sign is the sign of the last (largest) component.
class Expansion {
 public:
  Expansion() = default;
  static Expansion difference(double a, double b) {
    Expansion r;
    r.add(a);
    r.add(-b);
    return r;
  }
  void add(double b) {
    std::vector<double> h;
    h.reserve(c_.size() + 1);
    double q = b;
    for (double ci : c_) {
      double s, e;
      twoSum(q, ci, s, e);
      if (e != 0.0) h.push_back(e);
      q = s;
    }
    if (q != 0.0) h.push_back(q);
    c_ = std::move(h);
  }
  Expansion operator+(const Expansion& o) const {
    Expansion r = *this;
    for (double x : o.c_) r.add(x);
    return r;
  }
  Expansion operator-(const Expansion& o) const {
    Expansion r = *this;
    for (double x : o.c_) r.add(-x);
    return r;
  }
  Expansion operator*(const Expansion& o) const {
    Expansion r;
    for (double x : o.c_)
      for (double y : c_) {
        double p, e;
        twoProduct(x, y, p, e);
        r.add(e);
        r.add(p);
      }
    return r;
  }
  int sign() const { return c_.empty() ? 0 : (c_.back() > 0.0 ? 1 : -1); }

 private:
  std::vector<double> c_;
};

int signOf(double x) {
  return (x > 0.0) - (x < 0.0);
}

// Relative error bound of the double evaluations below, against their permanent. The evaluation
// order is the one Shewchuk analyses, whose bounds are (3 + 16 eps) eps (2-D) and (7 + 56 eps)
// eps (3-D); 64 eps covers both with room for the rounding of the permanent itself.
constexpr double kBound = 64.0 * std::numeric_limits<double>::epsilon() / 2.0;

}  // namespace

long exactFallbacks() {
  return fallbackCount;
}

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double acx = ax - cx, bcx = bx - cx, acy = ay - cy, bcy = by - cy;
  const double l = acx * bcy, r = acy * bcx;
  const double det = l - r, permanent = std::abs(l) + std::abs(r);
  // A zero permanent: every product has a zero factor (differences of doubles are exact zeros
  // only for equal doubles; products are assumed not to underflow), so the determinant is 0.
  if (std::abs(det) > kBound * permanent || permanent == 0.0) return signOf(det);
  ++fallbackCount;
  using E = Expansion;
  const E det2 =
      E::difference(ax, cx) * E::difference(by, cy) - E::difference(ay, cy) * E::difference(bx, cx);
  return det2.sign();
}

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a.x() - d.x(), bdx = b.x() - d.x(), cdx = c.x() - d.x();
  const double ady = a.y() - d.y(), bdy = b.y() - d.y(), cdy = c.y() - d.y();
  const double adz = a.z() - d.z(), bdz = b.z() - d.z(), cdz = c.z() - d.z();
  const double bc = bdy * cdz - bdz * cdy, ca = cdy * adz - cdz * ady, ab = ady * bdz - adz * bdy;
  const double det = adx * bc + bdx * ca + cdx * ab;
  const double permanent = std::abs(adx) * (std::abs(bdy * cdz) + std::abs(bdz * cdy)) +
                           std::abs(bdx) * (std::abs(cdy * adz) + std::abs(cdz * ady)) +
                           std::abs(cdx) * (std::abs(ady * bdz) + std::abs(adz * bdy));
  if (std::abs(det) > kBound * permanent || permanent == 0.0) return signOf(det);
  ++fallbackCount;
  using E = Expansion;
  const E ex = E::difference(a.x(), d.x()), fx = E::difference(b.x(), d.x()),
          gx = E::difference(c.x(), d.x());
  const E ey = E::difference(a.y(), d.y()), fy = E::difference(b.y(), d.y()),
          gy = E::difference(c.y(), d.y());
  const E ez = E::difference(a.z(), d.z()), fz = E::difference(b.z(), d.z()),
          gz = E::difference(c.z(), d.z());
  const E exact = ex * (fy * gz - fz * gy) + fx * (gy * ez - gz * ey) + gx * (ey * fz - ez * fy);
  return exact.sign();
}

}  // namespace chute::mesh
