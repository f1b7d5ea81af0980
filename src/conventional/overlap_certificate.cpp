// SPDX-License-Identifier: MIT
#include "conventional/overlap_certificate.hpp"

#include <array>

namespace sparsedyn {
namespace {

using Vec = Eigen::Vector3d;

// Searches past this many support points are degenerate (origin on the boundary): give up.
constexpr int kMaxIterations = 64;

// The point of the Minkowski difference A - B furthest along d (world frame).
struct Difference {
  const ConvexPolyhedron& a;
  const Pose& X_WA;
  const ConvexPolyhedron& b;
  const Pose& X_WB;
  Vec Support(const Vec& d) const {
    const Vec on_a = X_WA.ToWorld(a.vertex(a.SupportVertex(X_WA.rotation.conjugate() * d)));
    const Vec on_b = X_WB.ToWorld(b.vertex(b.SupportVertex(X_WB.rotation.conjugate() * -d)));
    return on_a - on_b;
  }
};

// The normal of face (p, q, r) turned away from `opposite`.
Vec OutwardNormal(const Vec& p, const Vec& q, const Vec& r, const Vec& opposite) {
  const Vec n = (q - p).cross(r - p);
  return n.dot(opposite - p) > 0 ? Vec(-n) : n;
}

// The origin strictly inside tetrahedron s: on the inner side of all four faces.
bool Encloses(const std::array<Vec, 4>& s) {
  static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
  for (const auto& f : kFaces) {
    const Vec n = OutwardNormal(s[f[0]], s[f[1]], s[f[2]], s[f[3]]);
    if (!(n.dot(-s[f[0]]) < 0)) return false;
  }
  return true;
}

// The simplex (newest point last) reduced to the feature nearest the origin's side, and the
// next search direction towards the origin. Returns true when a tetrahedron encloses it.
class Simplex {
 public:
  void Push(const Vec& w) { p_[n_++] = w; }

  bool Update(Vec& d) {
    if (n_ == 2) return Line(d);
    if (n_ == 3) return Triangle(d);
    return Tetrahedron(d);
  }

 private:
  bool Line(Vec& d) {
    const Vec& a = p_[1];
    const Vec ab = p_[0] - a;
    const Vec ao = -a;
    if (ab.dot(ao) > 0) {
      d = ab.cross(ao).cross(ab);
    } else {
      p_[0] = a;
      n_ = 1;
      d = ao;
    }
    return false;
  }

  bool Triangle(Vec& d) {
    const Vec a = p_[2], b = p_[1], c = p_[0];
    const Vec ab = b - a, ac = c - a, ao = -a;
    const Vec abc = ab.cross(ac);
    if (abc.cross(ac).dot(ao) > 0) {
      // Beyond edge ac (or vertex a).
      if (ac.dot(ao) > 0) {
        Set({c, a});
        d = ac.cross(ao).cross(ac);
        return false;
      }
      Set({b, a});
      return Line(d);
    }
    if (ab.cross(abc).dot(ao) > 0) {
      Set({b, a});
      return Line(d);
    }
    // Above or below the triangle: keep it, wound so that d is its normal.
    if (abc.dot(ao) > 0) {
      d = abc;
    } else {
      Set({b, c, a});
      d = -abc;
    }
    return false;
  }

  bool Tetrahedron(Vec& d) {
    const Vec a = p_[3];
    const std::array<std::array<Vec, 3>, 3> faces = {{{p_[2], p_[1], p_[0]},  // b c d
                                                      {p_[1], p_[0], p_[2]},
                                                      {p_[0], p_[2], p_[1]}}};
    for (const auto& f : faces) {
      // Face (a, f[0], f[1]); f[2] is the vertex opposite it.
      const Vec n = OutwardNormal(a, f[0], f[1], f[2]);
      if (n.dot(-a) > 0) {
        Set({f[1], f[0], a});
        return Triangle(d);
      }
    }
    return Encloses({p_[0], p_[1], p_[2], p_[3]});
  }

  void Set(std::initializer_list<Vec> points) {
    n_ = 0;
    for (const Vec& q : points) p_[n_++] = q;
  }

  std::array<Vec, 4> p_;
  int n_ = 0;
};

}  // namespace

bool CertainlyOverlap(const ConvexPolyhedron& a, const Pose& X_WA, const ConvexPolyhedron& b,
                      const Pose& X_WB) {
  const Difference m{a, X_WA, b, X_WB};
  Vec d = X_WB.translation - X_WA.translation;
  if (d.squaredNorm() == 0) d = Vec::UnitX();
  Simplex simplex;
  const Vec first = m.Support(d);
  simplex.Push(first);
  d = -first;
  for (int k = 0; k < kMaxIterations; ++k) {
    if (d.squaredNorm() == 0) return false;  // the origin on the simplex: touching at most
    const Vec w = m.Support(d);
    // No point beyond the origin along d: d separates (or only touches) the difference.
    if (!(w.dot(d) > 0)) return false;
    simplex.Push(w);
    if (simplex.Update(d)) return true;
  }
  return false;
}

}  // namespace sparsedyn
