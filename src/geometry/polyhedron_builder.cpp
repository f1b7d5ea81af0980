// SPDX-License-Identifier: MIT
// ConvexPolyhedron::FromMesh: validation of a face list (topology, geometry, convexity), merging
// of coplanar faces, and the half-edge numbering of the result. Errors name the input's indices.
// Coordinates out of range and vertex sets too small to resolve are refused up front, and the
// result is checked once more before it is handed out (shape_checks.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "geometry/point_box_tree.hpp"
#include "geometry/shape_checks.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn {

namespace {

using Loop = std::vector<std::int32_t>;

std::size_t U(std::int32_t i) { return static_cast<std::size_t>(i); }

std::string Num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

// How a vertex / face index of the current stage is named in messages (its input index).
struct Names {
  std::vector<std::int32_t> vertex;  // input index of each vertex
  std::vector<std::string> face;     // "face 3" or "merged face (input faces 3, 4)"
  std::string V(std::int32_t v) const { return std::to_string(vertex[U(v)]); }
  const std::string& F(std::int32_t f) const { return face[U(f)]; }
};

// Half-edges numbered face after face (face f owns [first[f], first[f + 1])); twin by matching.
struct Linked {
  std::vector<std::int32_t> origin, face, next, prev, twin, first;
  std::int32_t Dest(std::int32_t h) const { return origin[U(next[U(h)])]; }
};

// Links the loops into half-edges and checks that they form a closed, consistently wound
// 2-manifold: every edge used by exactly two faces in opposite directions, and the faces around
// every used vertex forming a single fan.
Result<Linked> LinkHalfEdges(const std::vector<Loop>& loops, std::size_t vertex_count,
                             const Names& names) {
  Linked l;
  for (std::size_t f = 0; f < loops.size(); ++f) {
    const auto first = static_cast<std::int32_t>(l.origin.size());
    const auto n = static_cast<std::int32_t>(loops[f].size());
    l.first.push_back(first);
    for (std::int32_t i = 0; i < n; ++i) {
      l.origin.push_back(loops[f][U(i)]);
      l.face.push_back(static_cast<std::int32_t>(f));
      l.next.push_back(first + (i + 1) % n);
      l.prev.push_back(first + (i + n - 1) % n);
    }
  }
  l.first.push_back(static_cast<std::int32_t>(l.origin.size()));
  l.twin.assign(l.origin.size(), -1);

  // Group the half-edges by undirected edge.
  struct Key {
    std::int32_t lo, hi, h;
  };
  std::vector<Key> keys;
  keys.reserve(l.origin.size());
  for (std::size_t h = 0; h < l.origin.size(); ++h) {
    const std::int32_t a = l.origin[h], b = l.Dest(static_cast<std::int32_t>(h));
    keys.push_back({std::min(a, b), std::max(a, b), static_cast<std::int32_t>(h)});
  }
  std::sort(keys.begin(), keys.end(), [](const Key& x, const Key& y) {
    return std::tie(x.lo, x.hi, x.h) < std::tie(y.lo, y.hi, y.h);
  });
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && keys[j].lo == keys[i].lo && keys[j].hi == keys[i].hi) ++j;
    const std::string edge = "edge (" + names.V(keys[i].lo) + "," + names.V(keys[i].hi) + ")";
    if (j - i == 1) {
      return Error{edge + " is used only by " + names.F(l.face[U(keys[i].h)]) +
                   ": the surface is open (a boundary edge)"};
    }
    if (j - i > 2) {
      std::string list;
      for (std::size_t k = i; k < j; ++k) {
        list += (k > i ? ", " : "") + names.F(l.face[U(keys[k].h)]);
      }
      return Error{edge + " is used by " + std::to_string(j - i) + " faces (" + list +
                   "); a closed 2-manifold needs exactly 2"};
    }
    const std::int32_t h1 = keys[i].h, h2 = keys[i + 1].h;
    if (l.origin[U(h1)] == l.origin[U(h2)]) {
      return Error{names.F(l.face[U(h1)]) + " and " + names.F(l.face[U(h2)]) +
                   " both run through " + edge + " from vertex " + names.V(l.origin[U(h1)]) +
                   ": inconsistent winding (neighbouring faces must traverse a shared edge in "
                   "opposite directions)"};
    }
    l.twin[U(h1)] = h2;
    l.twin[U(h2)] = h1;
    i = j;
  }

  // Every used vertex: turning h -> twin(prev(h)) must visit all of its outgoing half-edges.
  std::vector<std::int32_t> outgoing_count(vertex_count, 0), any_outgoing(vertex_count, -1);
  for (std::size_t h = 0; h < l.origin.size(); ++h) {
    ++outgoing_count[U(l.origin[h])];
    any_outgoing[U(l.origin[h])] = static_cast<std::int32_t>(h);
  }
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (any_outgoing[v] < 0) continue;
    std::int32_t steps = 0, h = any_outgoing[v];
    do {
      ++steps;
      h = l.twin[U(l.prev[U(h)])];
    } while (h != any_outgoing[v] && steps <= outgoing_count[v]);
    if (steps != outgoing_count[v]) {
      return Error{"vertex " + names.V(static_cast<std::int32_t>(v)) + " is not manifold: its " +
                   std::to_string(outgoing_count[v]) +
                   " faces form more than one fan (the surface pinches there)"};
    }
  }
  return l;
}

Status CheckEuler(const Linked& l, std::size_t used_vertices, std::size_t face_count) {
  const auto v = static_cast<long>(used_vertices);
  const auto e = static_cast<long>(l.origin.size() / 2);
  const auto f = static_cast<long>(face_count);
  if (v - e + f != 2) {
    return Error{"Euler characteristic V - E + F = " + std::to_string(v) + " - " +
                 std::to_string(e) + " + " + std::to_string(f) + " = " + std::to_string(v - e + f) +
                 ", expected 2 (the surface is not one sphere-like shell)"};
  }
  return Status::Ok();
}

struct FacePlane {
  Eigen::Vector3d normal;
  double offset = 0.0;
  double area = 0.0;
};

// Newell's normal (relative to the first vertex, for precision) and the mean offset.
FacePlane FitPlane(const std::vector<Eigen::Vector3d>& points, const Loop& loop) {
  const Eigen::Vector3d& o = points[U(loop[0])];
  Eigen::Vector3d newell = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
    newell += (points[U(loop[i])] - o).cross(points[U(loop[i + 1])] - o);
  }
  FacePlane plane;
  plane.area = 0.5 * newell.norm();
  plane.normal = plane.area > 0.0 ? Eigen::Vector3d(newell.normalized()) : Eigen::Vector3d::Zero();
  for (const std::int32_t v : loop) plane.offset += plane.normal.dot(points[U(v)]);
  plane.offset /= static_cast<double>(loop.size());
  return plane;
}

// Largest distance of the loop's vertices from the plane, and the vertex attaining it.
std::pair<double, std::int32_t> MaxDistance(const std::vector<Eigen::Vector3d>& points,
                                            const Loop& loop, const FacePlane& plane) {
  std::pair<double, std::int32_t> worst{0.0, loop[0]};
  for (const std::int32_t v : loop) {
    const double d = std::abs(plane.normal.dot(points[U(v)]) - plane.offset);
    if (d > worst.first) worst = {d, v};
  }
  return worst;
}

// Per-face shape checks: not degenerate (not all on a line) and planar within tolerance.
Result<std::vector<FacePlane>> FitFaces(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<Loop>& loops, const Names& names,
                                        double tolerance, const std::string& tolerance_text) {
  std::vector<FacePlane> planes;
  planes.reserve(loops.size());
  for (std::size_t f = 0; f < loops.size(); ++f) {
    const Loop& loop = loops[f];
    const FacePlane plane = FitPlane(points, loop);
    double longest = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      longest =
          std::max(longest, (points[U(loop[(i + 1) % loop.size()])] - points[U(loop[i])]).norm());
    }
    // 2 * area / longest edge is the polygon's width across its longest edge (up to 2x).
    const double width = longest > 0.0 ? 2.0 * plane.area / longest : 0.0;
    const auto face = static_cast<std::int32_t>(f);
    if (width <= tolerance) {
      return Error{names.F(face) + " is degenerate: its vertices lie within " + Num(width) +
                   " of a line (" + tolerance_text + ")"};
    }
    const auto [off, vertex] = MaxDistance(points, loop, plane);
    if (off > tolerance) {
      return Error{names.F(face) + " is not planar: vertex " + names.V(vertex) + " lies " +
                   Num(off) + " off its best-fit plane (" + tolerance_text + ")"};
    }
    planes.push_back(plane);
  }
  return planes;
}

// Six times the signed volume enclosed by the loops (positive for outward winding).
double SixSignedVolume(const std::vector<Eigen::Vector3d>& points, const std::vector<Loop>& loops,
                       const Eigen::Vector3d& reference) {
  double six_volume = 0.0;
  for (const Loop& loop : loops) {
    const Eigen::Vector3d a = points[U(loop[0])] - reference;
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      six_volume +=
          a.dot((points[U(loop[i])] - reference).cross(points[U(loop[i + 1])] - reference));
    }
  }
  return six_volume;
}

struct UnionFind {
  std::vector<std::int32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t Find(std::int32_t x) {
    while (parent[U(x)] != x) x = parent[U(x)] = parent[U(parent[U(x)])];
    return x;
  }
  // The smaller index becomes the root, so a group is named by its first face.
  void Join(std::int32_t a, std::int32_t b) {
    a = Find(a);
    b = Find(b);
    if (a != b) parent[U(std::max(a, b))] = std::min(a, b);
  }
};

struct Merged {
  std::vector<Loop> loops;                         // one per group, input vertex indices
  std::vector<std::vector<std::int32_t>> members;  // input faces of each group
};

// Unites adjacent faces whose planes agree within tolerance and traces each group's boundary.
Result<Merged> MergeCoplanarFaces(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<Loop>& loops, const Linked& l,
                                  const std::vector<FacePlane>& planes, const Names& names,
                                  const MeshValidation& options, double tolerance,
                                  const std::string& tolerance_text) {
  UnionFind groups(loops.size());
  for (std::size_t h = 0; h < l.origin.size(); ++h) {
    const std::int32_t f = l.face[h], g = l.face[U(l.twin[h])];
    if (f > g || groups.Find(f) == groups.Find(g)) continue;
    if (planes[U(f)].normal.dot(planes[U(g)].normal) <= 0.0) continue;
    const double gap = std::max(MaxDistance(points, loops[U(g)], planes[U(f)]).first,
                                MaxDistance(points, loops[U(f)], planes[U(g)]).first);
    if (gap > tolerance) continue;
    if (!options.merge_coplanar_faces) {
      return Error{names.F(f) + " and " + names.F(g) + " are coplanar (vertices within " +
                   Num(gap) + " of each other's plane, " + tolerance_text +
                   ") and merging is disabled"};
    }
    groups.Join(f, g);
  }

  Merged merged;
  std::vector<std::int32_t> group_of(loops.size(), -1);
  for (std::size_t f = 0; f < loops.size(); ++f) {
    const std::int32_t root = groups.Find(static_cast<std::int32_t>(f));
    if (group_of[U(root)] < 0) {
      group_of[U(root)] = static_cast<std::int32_t>(merged.members.size());
      merged.members.emplace_back();
    }
    group_of[f] = group_of[U(root)];
    merged.members[U(group_of[f])].push_back(static_cast<std::int32_t>(f));
  }

  // Trace each group's outer boundary: half-edges whose twin lies in another group, chained by
  // "the boundary half-edge leaving my destination".
  std::vector<std::int32_t> leaving(points.size(), -1);
  for (std::size_t g = 0; g < merged.members.size(); ++g) {
    const auto& members = merged.members[g];
    if (members.size() == 1) {
      merged.loops.push_back(loops[U(members[0])]);
      continue;
    }
    std::string list;
    for (const std::int32_t f : members) list += (list.empty() ? "" : ", ") + names.F(f);
    std::vector<std::int32_t> boundary;
    for (const std::int32_t f : members) {
      for (std::int32_t h = l.first[U(f)]; h < l.first[U(f) + 1]; ++h) {
        if (group_of[U(l.face[U(l.twin[U(h)])])] == static_cast<std::int32_t>(g)) continue;
        if (leaving[U(l.origin[U(h)])] >= 0) {
          return Error{"the coplanar faces " + list + " do not form a simple polygon: vertex " +
                       names.V(l.origin[U(h)]) + " is on their boundary twice"};
        }
        leaving[U(l.origin[U(h)])] = h;
        boundary.push_back(h);
      }
    }
    Loop loop;
    std::int32_t h = boundary.front();
    do {
      loop.push_back(l.origin[U(h)]);
      h = leaving[U(l.Dest(h))];
    } while (h != boundary.front() && h >= 0 && loop.size() <= boundary.size());
    for (const std::int32_t b : boundary) leaving[U(l.origin[U(b)])] = -1;
    if (h < 0 || loop.size() != boundary.size()) {
      return Error{"the coplanar faces " + list +
                   " do not form a simple polygon: their boundary has more than one loop "
                   "(another face lies inside them)"};
    }
    merged.loops.push_back(std::move(loop));
  }
  return merged;
}

// Arguments and the basic shape of the input: finite coordinates within kMaxCoordinate, enough
// faces, faces of at least 3 distinct in-range vertices.
Status CheckInput(const PolygonMesh& mesh, const MeshValidation& options) {
  if (!(options.tolerance >= 0.0 && options.tolerance < 0.1)) {
    return Error{"MeshValidation::tolerance must be in [0, 0.1), got " + Num(options.tolerance)};
  }
  const std::size_t input_vertex_count = mesh.vertices.size();
  if (Status coordinates = CheckCoordinates(mesh.vertices, "vertex"); !coordinates) {
    return coordinates;
  }
  if (mesh.faces.size() < 4) {
    return Error{"a polyhedron needs at least 4 faces, the mesh has " +
                 std::to_string(mesh.faces.size())};
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& loop = mesh.faces[f];
    if (loop.size() < 3) {
      return Error{"face " + std::to_string(f) + " has " + std::to_string(loop.size()) +
                   " vertices; a face needs at least 3"};
    }
    for (std::size_t i = 0; i < loop.size(); ++i) {
      if (loop[i] < 0 || U(loop[i]) >= input_vertex_count) {
        return Error{"face " + std::to_string(f) + " refers to vertex " + std::to_string(loop[i]) +
                     ", but the mesh has " + std::to_string(input_vertex_count) + " vertices"};
      }
      if (std::find(loop.begin() + static_cast<std::ptrdiff_t>(i) + 1, loop.end(), loop[i]) !=
          loop.end()) {
        return Error{"face " + std::to_string(f) + " uses vertex " + std::to_string(loop[i]) +
                     " more than once"};
      }
    }
  }
  return Status::Ok();
}

// Convexity: each face a convex polygon, and no vertex above any face plane.
Status CheckConvexity(const std::vector<Eigen::Vector3d>& points, const std::vector<Loop>& loops,
                      const std::vector<FacePlane>& planes, const Names& names, double tolerance,
                      const std::string& tolerance_text) {
  for (std::size_t f = 0; f < loops.size(); ++f) {
    const Loop& loop = loops[f];
    const Eigen::Vector3d& n = planes[f].normal;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector3d& a = points[U(loop[(i + loop.size() - 1) % loop.size()])];
      const Eigen::Vector3d& b = points[U(loop[i])];
      const Eigen::Vector3d& c = points[U(loop[(i + 1) % loop.size()])];
      // Signed distance of c from the line a-b inside the face plane; > 0 turns left (convex).
      const double turn = (b - a).cross(c - b).dot(n) / (b - a).norm();
      if (turn < -tolerance) {
        return Error{names.F(static_cast<std::int32_t>(f)) +
                     " is not a convex polygon: it turns the wrong way at vertex " +
                     names.V(loop[i]) + " (by " + Num(-turn) + ", " + tolerance_text + ")"};
      }
    }
  }
  // The vertex highest above any face plane: the first face's lowest-numbered one on ties, as
  // a loop over every face and vertex would find it, but only in the boxes that reach it.
  double worst = 0.0;
  std::int32_t worst_face = -1, worst_vertex = -1;
  const PointBoxTree tree(points);
  for (std::size_t f = 0; f < loops.size(); ++f) {
    const auto face = static_cast<std::int32_t>(f);
    tree.ForEachAbove(
        planes[f].normal, planes[f].offset, [&] { return worst; },
        [&](std::uint32_t v, double above) {
          const auto vertex = static_cast<std::int32_t>(v);
          if (above > worst || (above == worst && face == worst_face && vertex < worst_vertex)) {
            worst = above;
            worst_face = face;
            worst_vertex = vertex;
          }
        });
  }
  if (worst > tolerance) {
    return Error{"the mesh is not convex: vertex " + names.V(worst_vertex) + " lies " + Num(worst) +
                 " above the plane of " + names.F(worst_face) + " (" + tolerance_text + ")"};
  }
  return Status::Ok();
}

}  // namespace

Result<ConvexPolyhedron> ConvexPolyhedron::FromMesh(const PolygonMesh& mesh,
                                                    MeshValidation options) {
  if (Status input = CheckInput(mesh, options); !input) return input.error();
  const std::size_t input_vertex_count = mesh.vertices.size();
  std::vector<Loop> loops = mesh.faces;

  // Topology of the input: closed, consistently wound, manifold, genus 0.
  Names names;
  names.vertex.resize(input_vertex_count);
  std::iota(names.vertex.begin(), names.vertex.end(), 0);
  for (std::size_t f = 0; f < loops.size(); ++f) names.face.push_back("face " + std::to_string(f));
  Result<Linked> linked = LinkHalfEdges(loops, input_vertex_count, names);
  if (!linked) return linked.error();
  std::vector<bool> used(input_vertex_count, false);
  for (const Loop& loop : loops) {
    for (const std::int32_t v : loop) used[U(v)] = true;
  }
  const auto used_count = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
  if (Status euler = CheckEuler(*linked, used_count, loops.size()); !euler) return euler.error();
  std::vector<Eigen::Vector3d> used_vertices;
  for (std::size_t v = 0; v < input_vertex_count; ++v) {
    if (used[v]) used_vertices.push_back(mesh.vertices[v]);
  }
  // Before any tolerance is taken relative to the scale: a scale of 0 or round-off makes none.
  if (Status extent = CheckExtent(used_vertices, "vertices"); !extent) return extent.error();

  // Scale (bounding box diagonal of the used vertices) and the absolute tolerance.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo,
                  mean = Eigen::Vector3d::Zero();
  for (std::size_t v = 0; v < input_vertex_count; ++v) {
    if (!used[v]) continue;
    lo = lo.cwiseMin(mesh.vertices[v]);
    hi = hi.cwiseMax(mesh.vertices[v]);
    mean += mesh.vertices[v];
  }
  mean /= static_cast<double>(used_count);
  const double scale = (hi - lo).norm();
  const double tolerance = options.tolerance * scale;
  const std::string tolerance_text =
      "tolerance " + Num(options.tolerance) + " x scale " + Num(scale) + " = " + Num(tolerance);

  // Face shapes, then the orientation from the sign of the enclosed volume.
  Result<std::vector<FacePlane>> planes =
      FitFaces(mesh.vertices, loops, names, tolerance, tolerance_text);
  if (!planes) return planes.error();
  std::vector<std::string> warnings;
  const double six_volume = SixSignedVolume(mesh.vertices, loops, mean);
  if (std::abs(six_volume) / 6.0 <= options.tolerance * scale * scale * scale) {
    return Error{"the mesh encloses no volume (signed volume " + Num(six_volume / 6.0) +
                 "): it is flat within tolerance"};
  }
  if (six_volume < 0.0) {
    if (!options.flip_inward_winding) {
      return Error{"the faces are wound clockwise seen from outside (signed volume " +
                   Num(six_volume / 6.0) + ") and flipping is disabled"};
    }
    for (Loop& loop : loops) std::reverse(loop.begin(), loop.end());
    for (FacePlane& plane : *planes) {
      plane.normal = -plane.normal;
      plane.offset = -plane.offset;
    }
    linked = LinkHalfEdges(loops, input_vertex_count, names);
    if (!linked) return linked.error();
    warnings.push_back("the faces were wound clockwise seen from outside (signed volume " +
                       Num(six_volume / 6.0) + "); all " + std::to_string(loops.size()) +
                       " faces were flipped");
  }

  // Merge coplanar neighbours into polygons.
  Result<Merged> merged = MergeCoplanarFaces(mesh.vertices, loops, *linked, *planes, names, options,
                                             tolerance, tolerance_text);
  if (!merged) return merged.error();
  if (merged->loops.size() < loops.size()) {
    warnings.push_back("merged " + std::to_string(loops.size()) + " input faces into " +
                       std::to_string(merged->loops.size()) + " (adjacent coplanar faces)");
  }

  // Drop the vertices that are no longer corners: unused ones, those left inside a merged face
  // (degree 0) and those left in the middle of a straight edge (shared by only 2 faces).
  std::vector<std::int32_t> degree(input_vertex_count, 0);
  for (const Loop& loop : merged->loops) {
    for (const std::int32_t v : loop) ++degree[U(v)];
  }
  for (Loop& loop : merged->loops) {
    std::erase_if(loop, [&](std::int32_t v) { return degree[U(v)] < 3; });
  }
  Names final_names;
  std::vector<std::int32_t> new_index(input_vertex_count, -1);
  std::vector<Eigen::Vector3d> points;
  for (std::size_t v = 0; v < input_vertex_count; ++v) {
    if (degree[v] < 3) continue;
    new_index[v] = static_cast<std::int32_t>(points.size());
    points.push_back(mesh.vertices[v]);
    final_names.vertex.push_back(static_cast<std::int32_t>(v));
  }
  if (points.size() < input_vertex_count) {
    warnings.push_back("dropped " + std::to_string(input_vertex_count - points.size()) + " of " +
                       std::to_string(input_vertex_count) +
                       " vertices (unused, inside a merged face or on a straight edge)");
  }
  for (std::size_t g = 0; g < merged->loops.size(); ++g) {
    const auto& members = merged->members[g];
    std::string name = names.F(members[0]);
    if (members.size() > 1) {
      name = "merged face (input faces " + std::to_string(members[0]);
      for (std::size_t i = 1; i < members.size(); ++i) name += ", " + std::to_string(members[i]);
      name += ")";
    }
    final_names.face.push_back(std::move(name));
    Loop& loop = merged->loops[g];
    if (loop.size() < 3) {
      return Error{final_names.face.back() + " collapsed to " + std::to_string(loop.size()) +
                   " corners after removing vertices on straight edges"};
    }
    for (std::int32_t& v : loop) v = new_index[U(v)];
  }

  // Topology and shape of the result.
  Result<Linked> result_links = LinkHalfEdges(merged->loops, points.size(), final_names);
  if (!result_links) return Error{"after merging coplanar faces: " + result_links.error().message};
  if (Status euler = CheckEuler(*result_links, points.size(), merged->loops.size()); !euler) {
    return Error{"after merging coplanar faces: " + euler.error().message};
  }
  Result<std::vector<FacePlane>> result_planes =
      FitFaces(points, merged->loops, final_names, tolerance, tolerance_text);
  if (!result_planes) return result_planes.error();
  const Linked& l = *result_links;
  for (std::size_t h = 0; h < l.origin.size(); ++h) {
    const std::int32_t a = l.origin[h], b = l.Dest(static_cast<std::int32_t>(h));
    const double length = (points[U(b)] - points[U(a)]).norm();
    if (length <= tolerance) {
      return Error{"edge (" + final_names.V(std::min(a, b)) + "," + final_names.V(std::max(a, b)) +
                   ") is degenerate: its length " + Num(length) + " is within " + tolerance_text};
    }
  }

  if (Status convex = CheckConvexity(points, merged->loops, *result_planes, final_names, tolerance,
                                     tolerance_text);
      !convex) {
    return convex.error();
  }

  // Number the result: edge e owns half-edges 2e (in the first face to use it) and 2e + 1.
  ConvexPolyhedron poly;
  poly.vertices_ = std::move(points);
  std::vector<std::int32_t> id(l.origin.size(), -1);
  for (std::size_t h = 0; h < l.origin.size(); ++h) {
    if (id[h] >= 0) continue;
    const std::int32_t twin = l.twin[h];
    const auto e = static_cast<std::int32_t>(poly.edges_.size());
    id[h] = 2 * e;
    id[U(twin)] = 2 * e + 1;
    poly.edges_.push_back(Edge{{l.origin[h], l.origin[U(twin)]}, {l.face[h], l.face[U(twin)]}});
  }
  poly.half_edges_.resize(l.origin.size());
  for (std::size_t h = 0; h < l.origin.size(); ++h) {
    poly.half_edges_[U(id[h])] =
        HalfEdge{l.origin[h], l.face[h], id[U(l.next[h])], id[U(l.prev[h])]};
  }
  for (std::size_t f = 0; f < merged->loops.size(); ++f) {
    Face face;
    face.first = l.first[f];
    face.count = l.first[f + 1] - l.first[f];
    poly.faces_.push_back(face);
    for (std::int32_t h = l.first[f]; h < l.first[f + 1]; ++h) {
      poly.face_half_edges_.push_back(id[U(h)]);
      poly.face_edges_.push_back(id[U(h)] >> 1);
      poly.face_vertices_.push_back(l.origin[U(h)]);
    }
  }
  poly.tolerance_ = options.tolerance;
  poly.warnings_ = std::move(warnings);
  poly.ComputeDerivedData();
  if (Status finished = CheckFinishedPolyhedron(poly); !finished) return finished.error();
  return poly;
}

}  // namespace sparsedyn
