// The independent intersection check (mesh/IntersectionCheck.hpp): exact predicates against an
// integer reference, known configurations (crossing, touching, coplanar, near misses, adjacent
// elements), and the broad phase against a brute-force count on random soups.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "ExactPredicates.hpp"
#include "IntersectionCheck.hpp"
#include "SegmentTriangle.hpp"

using namespace chute;
using namespace chute::mesh;

namespace {

__extension__ typedef __int128 Int128;  // GCC's 128-bit integer: the exact reference

int sign128(Int128 x) {
  return (x > 0) - (x < 0);
}

// Two separate triangles (no shared index) and their count.
IntersectionCounts pair(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                        const Vec3& f) {
  IntersectionMesh m;
  m.points = {a, b, c, d, e, f};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  return countIntersections(m);
}

IntersectionCounts segmentAndTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                                      const Vec3& c) {
  IntersectionMesh m;
  m.points = {p, q, a, b, c};
  m.segments = {{0, 1}};
  m.triangles = {{2, 3, 4}};
  return countIntersections(m);
}

}  // namespace

// Coordinates in [1, 2) with 40-bit mantissas: differences are exact multiples of 2^-40, so the
// determinants are exact integers times 2^-80 (2-D) or 2^-120 (3-D) that fit in 128 bits.
TEST(ExactPredicates, SignsMatchAnIntegerReferenceOnNearlyDegenerateInputs) {
  std::mt19937_64 rng(7);
  const double unit = std::ldexp(1.0, -40);
  std::uniform_int_distribution<long long> mant(0, (1LL << 40) - 1);
  auto coord = [&](long long k) { return 1.0 + static_cast<double>(k) * unit; };
  const long before = exactFallbacks();
  int naiveWrong3 = 0, trials = 20000, zeros = 0;
  for (int t = 0; t < trials; ++t) {
    long long A[3], B[3], C[3], D[3];
    for (int i = 0; i < 3; ++i) {
      A[i] = mant(rng) >> 1;
      B[i] = mant(rng) >> 1;
      C[i] = mant(rng) >> 1;
    }
    // d near the plane: a + (b - a) + (c - a) lies on it exactly; nudge by a few units.
    for (int i = 0; i < 3; ++i) D[i] = B[i] + C[i] - A[i] + static_cast<long long>(rng() % 3) - 1;
    bool inRange = true;
    for (int i = 0; i < 3; ++i) inRange &= D[i] >= 0 && D[i] < (1LL << 40);
    if (!inRange) continue;
    Int128 ad[3], bd[3], cd[3];
    for (int i = 0; i < 3; ++i) {
      ad[i] = A[i] - D[i];
      bd[i] = B[i] - D[i];
      cd[i] = C[i] - D[i];
    }
    const Int128 det = ad[0] * (bd[1] * cd[2] - bd[2] * cd[1]) +
                       bd[0] * (cd[1] * ad[2] - cd[2] * ad[1]) +
                       cd[0] * (ad[1] * bd[2] - ad[2] * bd[1]);
    const Vec3 a(coord(A[0]), coord(A[1]), coord(A[2])), b(coord(B[0]), coord(B[1]), coord(B[2]));
    const Vec3 c(coord(C[0]), coord(C[1]), coord(C[2])), d(coord(D[0]), coord(D[1]), coord(D[2]));
    ASSERT_EQ(orient3d(a, b, c, d), sign128(det)) << t;
    zeros += det == 0;
    const Vec3 u = a - d, v = b - d, w = c - d;
    const double naive = u.dot(v.cross(w));
    naiveWrong3 += ((naive > 0) - (naive < 0)) != sign128(det);
  }
  int naiveWrong2 = 0;
  for (int t = 0; t < trials; ++t) {  // 2-D: c on or next to the line through a and b
    const long long ax = mant(rng) >> 1, ay = mant(rng) >> 1, bx = mant(rng) >> 1,
                    by = mant(rng) >> 1;
    const long long cx = 2 * bx - ax, cy = 2 * by - ay + static_cast<long long>(rng() % 3) - 1;
    if (cx < 0 || cx >= (1LL << 40) || cy < 0 || cy >= (1LL << 40)) continue;
    const Int128 det =
        static_cast<Int128>(ax - cx) * (by - cy) - static_cast<Int128>(ay - cy) * (bx - cx);
    const double dax = coord(ax), day = coord(ay), dbx = coord(bx), dby = coord(by),
                 dcx = coord(cx), dcy = coord(cy);
    ASSERT_EQ(orient2d(dax, day, dbx, dby, dcx, dcy), sign128(det)) << t;
    const double naive = (dax - dcx) * (dby - dcy) - (day - dcy) * (dbx - dcx);
    naiveWrong2 += ((naive > 0) - (naive < 0)) != sign128(det);
  }
  const long fallbacks = exactFallbacks() - before;
  std::printf(
      "exact predicates: %d + %d nearly degenerate cases agree with 128-bit integers (%d exactly "
      "coplanar); exact fallbacks %ld; a plain double evaluation got %d (3-D) and %d (2-D) "
      "signs wrong\n",
      trials, trials, zeros, fallbacks, naiveWrong3, naiveWrong2);
  EXPECT_GT(fallbacks, 0);
  EXPECT_GT(zeros, 0);
}

TEST(IntersectionCheck, KnownTrianglePairs) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  struct Case {
    const char* what;
    Vec3 d, e, f;
    long expected;
  };
  const double tiny = 1e-12;
  const Case cases[] = {
      {"crossing (a link through the other)", {0.2, 0.2, -0.5}, {0.2, 0.2, 0.5}, {-1, 0.2, 0}, 1},
      {"vertex touching the other's interior", {0.2, 0.2, 0}, {0.2, 0.2, 1}, {1, 1, 1}, 1},
      {"vertex on a vertex (distinct nodes)", {1, 0, 0}, {2, 0, 1}, {2, 1, 1}, 1},
      {"edge on edge, crossing at a point", {0.5, -0.5, 0}, {0.5, 0.5, 0}, {0.5, 0, 1}, 1},
      {"coplanar, overlapping", {0.2, 0.2, 0}, {1.2, 0.2, 0}, {0.2, 1.2, 0}, 1},
      {"coplanar, nested", {0.1, 0.1, 0}, {0.3, 0.1, 0}, {0.1, 0.3, 0}, 1},
      {"coplanar, disjoint", {0.6, 0.6, 0}, {1.6, 0.6, 0}, {0.6, 1.6, 0}, 0},
      {"coplanar, touching along an edge", {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, 1},
      {"parallel, 1e-12 apart", {0, 0, tiny}, {1, 0, tiny}, {0, 1, tiny}, 0},
      {"crossing its plane beside it, 1e-12 off the edge",
       {0.5 + tiny, 0.5 + tiny, -1},
       {0.5 + tiny, 0.5 + tiny, 1},
       {2, 2, 0},
       0},
      {"crossing its plane through the hypotenuse", {0.5, 0.5, -1}, {0.5, 0.5, 1}, {2, 2, 0}, 1},
  };
  for (const auto& k : cases) {
    const auto n = pair(a, b, c, k.d, k.e, k.f);
    const auto swapped = pair(k.d, k.e, k.f, a, b, c);
    std::printf("%-52s %ld\n", k.what, n.trianglePairs);
    EXPECT_EQ(n.trianglePairs, k.expected) << k.what;
    EXPECT_EQ(swapped.trianglePairs, k.expected) << k.what << " (swapped)";
  }
}

TEST(IntersectionCheck, KnownSegmentTriangleConfigurations) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  struct Case {
    const char* what;
    Vec3 p, q;
    long expected;
  };
  const Case cases[] = {
      {"through the interior", {0.2, 0.2, -1}, {0.2, 0.2, 1}, 1},
      {"through a vertex", {0, 0, -1}, {0, 0, 1}, 1},
      {"ending on the triangle", {0.2, 0.2, 0}, {0.2, 0.2, 1}, 1},
      {"ending 1e-12 short of it", {0.2, 0.2, 1e-12}, {0.2, 0.2, 1}, 0},
      {"in its plane, crossing it", {-1, 0.2, 0}, {2, 0.2, 0}, 1},
      {"in its plane, outside", {-1, 2, 0}, {2, 2, 0}, 0},
      {"in its plane, inside", {0.1, 0.1, 0}, {0.2, 0.1, 0}, 1},
      {"parallel above it", {0, 0, 1}, {1, 1, 1}, 0},
      {"passing beside the hypotenuse", {0.6, 0.6, -1}, {0.6, 0.6, 1}, 0},
  };
  for (const auto& k : cases) {
    const auto n = segmentAndTriangle(k.p, k.q, a, b, c);
    const auto reversed = segmentAndTriangle(k.q, k.p, c, a, b);
    std::printf("segment %-40s %ld\n", k.what, n.segmentTriangle);
    EXPECT_EQ(n.segmentTriangle, k.expected) << k.what;
    EXPECT_EQ(reversed.segmentTriangle, k.expected) << k.what << " (reversed)";
  }
}

TEST(IntersectionCheck, AdjacentElementsAreNeverCountedAndDegenerateOnesAreSetApart) {
  IntersectionMesh m;
  // Two triangles sharing vertex 0 and crossing each other elsewhere, a segment from vertex 0
  // through the first triangle, a degenerate triangle.
  m.points = {{0, 0, 0},     {1, 0, 0},       {0, 1, 0},      {0.3, 0.3, -1},
              {0.3, 0.3, 1}, {0.5, 0.0, 0.5}, {1.0, 0.0, 1.0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}, {0, 5, 6}};
  m.segments = {{0, 4}, {3, 4}};
  const auto n = countIntersections(m);
  std::printf(
      "adjacent crossing triangles: %ld pairs; segment from the shared vertex: %ld; "
      "degenerate %ld\n",
      n.trianglePairs, n.segmentTriangle, n.degenerateTriangles);
  EXPECT_EQ(n.trianglePairs, 0);
  EXPECT_EQ(n.segmentTriangle, 1);  // only segment (3, 4), which shares no vertex with triangle 0
  ASSERT_EQ(n.segmentHits.size(), 1u);
  EXPECT_EQ(n.segmentHits[0], std::make_pair(1, 0));
  EXPECT_EQ(n.degenerateTriangles, 1);  // (0, 5, 6) is collinear
}

TEST(IntersectionCheck, BroadPhaseAgreesWithBruteForceOnRandomSoups) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 6; ++trial) {
    IntersectionMesh m;
    const bool grid = trial % 2 == 0;  // grid points: coplanar, touching and repeated points
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::uniform_int_distribution<int> g(0, 4);
    const int nPoints = 600;
    Vec3 base = Vec3::Zero();
    for (int i = 0; i < nPoints; ++i) {
      if (i % 8 == 0) base = Vec3(u(rng), u(rng), u(rng));  // neighbours in index are near
      if (grid)
        m.points.emplace_back(0.25 * g(rng), 0.25 * g(rng), 0.25 * g(rng));
      else
        m.points.push_back(base + 0.15 * Vec3(u(rng), u(rng), u(rng)));
    }
    // Small elements: a vertex and its neighbours in index order, so that some share vertices.
    std::uniform_int_distribution<int> pick(0, nPoints - 1), near(1, 8);
    for (int t = 0; t < 400; ++t) {
      const int a = pick(rng);
      const int b = (a + near(rng)) % nPoints, c = (a + near(rng) + 8) % nPoints;
      m.triangles.push_back({a, b, c});
    }
    for (int s = 0; s < 200; ++s) {
      const int a = pick(rng);
      m.segments.push_back({a, (a + near(rng)) % nPoints});
    }
    const auto fast = countIntersections(m);
    const auto slow = countIntersectionsBruteForce(m);
    std::printf(
        "soup %d (%s): %ld triangle pairs, %ld segment-triangle, %ld degenerate; brute "
        "force %ld, %ld; candidates %ld of %ld\n",
        trial, grid ? "grid" : "random", fast.trianglePairs, fast.segmentTriangle,
        fast.degenerateTriangles, slow.trianglePairs, slow.segmentTriangle, fast.candidatePairs,
        slow.candidatePairs);
    EXPECT_EQ(fast.triangleHits, slow.triangleHits);
    EXPECT_EQ(fast.segmentHits, slow.segmentHits);
    EXPECT_GT(fast.total(), 0);
  }
}

TEST(IntersectionCheck, CostGrowsAboutAsNLogNOnAFoldedSheet) {
  // A flat n x n sheet folded in a zigzag of 1e-3 pitch: no intersection, many near pairs.
  double prev = 0.0;
  long prevTriangles = 0;
  for (int n : {40, 80, 160}) {
    IntersectionMesh m;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        m.points.emplace_back(static_cast<double>(j) / n, 1e-3 * (i % 2), 0.01 * i / n);
    auto id = [&](int i, int j) { return i * (n + 1) + j; };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) m.addQuad(id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j));
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = countIntersections(m);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("folded sheet, %zu triangles: %ld intersections, %ld candidate pairs, %.3f s\n",
                m.triangles.size(), r.total(), r.candidatePairs, s);
    if (prev > 0)
      std::printf("  time ratio %.2f for %.1fx the triangles\n", s / prev,
                  double(m.triangles.size()) / prevTriangles);
    EXPECT_EQ(r.total(), 0);
    prev = s;
    prevTriangles = static_cast<long>(m.triangles.size());
  }
}
