#include "ParachuteGenerator.hpp"

#include <gmsh.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "GmshSession.hpp"
#include "PackedStart.hpp"
#include "ParachuteStart.hpp"

namespace chute::mesh {

namespace {
std::string shortNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}
}  // namespace

void ParachuteSpec::validate() const {
  auto bad = [](const std::string& option, const std::string& why) {
    throw std::invalid_argument(option + ": " + why);
  };
  checkFinite();
  if (gores < 4) bad("--gores", "give at least 4 gores");
  // Squares of lengths far below 1e-6 D underflow (the canopy's height over the confluence,
  // sqrt(L^2 - R^2), became 0 at D = 1e-300).
  if (!(diameter >= 1e-6)) bad("--diameter", "must be at least 1e-6");
  // Every feature the geometry is built of is at least kLeastFeature D, or absent (0): a vent,
  // a canopy ring, a slider or a riser of 1e-9 D is below gmsh's geometric tolerance (its
  // meshing threw inside a parallel region and aborted chute) or a model no step can run.
  const double least = kLeastFeature * diameter;
  const std::string leastText = "at least D/" + std::to_string(int(1.0 / kLeastFeature));
  auto feature = [&](const char* option, double x, bool zeroAllowed) {
    // (1 - 1e-12): D/1000 typed as a number is not refused for its last bit.
    if (x < 0.0 || (x == 0.0 && !zeroAllowed) || (x > 0.0 && x < least * (1.0 - 1e-12)))
      bad(option, (zeroAllowed ? "0 or " : "") + leastText + " (" + shortNumber(least) + "), got " +
                      shortNumber(x));
  };
  feature("--vent-diameter", ventDiameter, true);
  if (ventDiameter > diameter - least * (1.0 - 1e-12))
    bad("--vent-diameter", "leaves no canopy: the ring (diameter - vent) must be " + leastText);
  feature("--slider", sliderSide, true);
  feature("--riser-length", riserLength, true);
  feature("--bundle-radius", bundleRadius, true);
  feature("--slider-drop", sliderDrop, true);
  if (payloadBox[0] != 0.0 || payloadBox[1] != 0.0 || payloadBox[2] != 0.0)
    for (const double edge : payloadBox) feature("--payload-box", edge, false);
  if (payloadMass != 0.0 && !(payloadMass >= kLeastMass))
    bad("--payload-mass", "0 or at least " + shortNumber(kLeastMass));
  if (!(lineLength > diameter / 2) ||
      lineLength * lineLength - diameter * diameter / 4 < least * least)
    bad("--line-length",
        "must exceed the canopy radius (the flat pattern's lines run from the "
        "skirt to the confluence on the axis, at least D/1000 below the canopy)");
  if (lineElements < 1) bad("--line-elements", "must be at least 1");
  // Line, riser and slider elements at least a tenth of the canopy's: the explicit step is set
  // by the shortest element (docs/explicit.md), and lines far finer than the canopy made the
  // generated case take hours for a second of flight (3,000 elements a line of 2 ft: over a
  // minute for 4 ms) or trip the energy monitor at its first steps (10,000).
  auto fineness = [&](const char* option, double length, int elements) {
    if (length / elements < 0.1 * elementSize)
      bad(option, "elements of " + shortNumber(length / elements) +
                      ", shorter than a tenth of --element-size (" + shortNumber(elementSize) +
                      "): at most " +
                      std::to_string(static_cast<long long>(10 * length / elementSize)) + " here");
  };
  if (!(elementSize > 0.0) || elementSize > diameter / 2)
    bad("--element-size", "must be in (0, diameter / 2]");
  if (sliderSide < 0.0) bad("--slider", "the slider side must be positive");
  if (sliderDivisions < 1) bad("--slider-divisions", "must be at least 1");
  if (payloadMass < 0.0) bad("--payload-mass", "must not be negative");
  if (hasBox() && (payloadBox[1] <= 0.0 || payloadBox[2] <= 0.0))
    bad("--payload-box", "needs three positive edge lengths");
  if (hasBox() && payloadMass <= 0.0) bad("--payload-box", "needs --payload-mass");
  if (riserLength < 0.0) bad("--riser-length", "must not be negative");
  if (hasBox() && riserLength > 0.0 &&
      riserLength <= 0.5 * std::hypot(payloadBox[0], payloadBox[1]))
    bad("--riser-length", "must exceed half the diagonal of the box's top face");
  if (riserElements < 1) bad("--riser-elements", "must be at least 1");
  if (elementSize > 0.0 && elementSize <= diameter / 2) {
    fineness("--line-elements", lineLength, lineElements);
    if (riserLength > 0.0) fineness("--riser-elements", riserLength, riserElements);
    if (sliderSide > 0.0 && sliderDivisions >= 1)
      fineness("--slider-divisions", sliderSide, sliderDivisions);
  }
  if (start != "flat" && start != "folded" && start != "inflated" && start != "packed")
    bad("--start", "expected flat, folded, inflated or packed");
  if (!(inflatedRatio > 2.0 / std::numbers::pi && inflatedRatio < 1.0))
    bad("--inflated-ratio", "must be in (2/pi, 1): a cap no deeper than a hemisphere");
  if (bundleRadius < 0.0 || bundleRadius >= diameter / 2)
    bad("--bundle-radius", "must be in [0, diameter / 2)");
  if (sliderDrop < 0.0) bad("--slider-drop", "must not be negative");
  if (lineSlack < 0.0 || lineSlack >= 0.5) bad("--line-slack", "must be in [0, 0.5)");
  if (packLength < 0.0) bad("--pack-length", "must not be negative");
  if (packDiameter < 0.0) bad("--pack-diameter", "must not be negative");
  // A bag wider than the canopy's flat diameter packs nothing (1e6 was refused naming
  // --pack-length: its runs' crossings took up the whole canopy).
  if (packDiameter > diameter) bad("--pack-diameter", "larger than the canopy's --diameter");
  if (packGap < 0.0) bad("--pack-gap", "must not be negative");
  checkLimits();
  if (start == "packed") packLayout(*this);  // throws naming the --pack-* option
}

void ParachuteSpec::checkFinite() const {
  auto bad = [](const std::string& option, const std::string& why) {
    throw std::invalid_argument(option + ": " + why);
  };
  for (const auto& [option, x] : {std::pair<const char*, double>{"--diameter", diameter},
                                  {"--line-length", lineLength},
                                  {"--element-size", elementSize},
                                  {"--vent-diameter", ventDiameter},
                                  {"--slider", sliderSide},
                                  {"--payload-mass", payloadMass},
                                  {"--riser-length", riserLength},
                                  {"--bundle-radius", bundleRadius},
                                  {"--slider-drop", sliderDrop},
                                  {"--line-slack", lineSlack},
                                  {"--pack-length", packLength},
                                  {"--pack-diameter", packDiameter},
                                  {"--pack-gap", packGap},
                                  {"--payload-box", payloadBox[0]},
                                  {"--payload-box", payloadBox[1]},
                                  {"--payload-box", payloadBox[2]}})
    if (!std::isfinite(x) || std::abs(x) > 1e6) bad(option, "must be finite and at most 1e6");
}

// Sizes a user can ask for, bounded before gmsh starts (docs/limits.md): a typo must give an
// error, not minutes of meshing or gigabytes of memory.
void ParachuteSpec::checkLimits() const {
  auto bad = [](const std::string& option, const std::string& why) {
    throw std::invalid_argument(option + ": " + why);
  };
  if (gores > 1000) bad("--gores", "at most 1000");
  if (lineElements > 10000) bad("--line-elements", "at most 10000 per line");
  if (riserElements > 10000) bad("--riser-elements", "at most 10000 per riser");
  if (sliderDivisions > 1000) bad("--slider-divisions", "at most 1000");
  // gmsh 4.8's algorithm 8 (quads) crashes on these geometries; 2, 3, 7, 9 are untested here.
  if (meshAlgorithm != 1 && meshAlgorithm != 5 && meshAlgorithm != 6)
    bad("--mesh-algorithm", "expected 6 (Frontal-Delaunay), 5 (Delaunay) or 1 (MeshAdapt)");
  if (!(maxElements >= 1.0 && maxElements <= 1e8)) bad("--max-elements", "must be in [1, 1e8]");
  // An equilateral triangle of side h has area sqrt(3)/4 h^2.
  const double canopy = std::numbers::pi / 4 * (diameter * diameter - ventDiameter * ventDiameter) /
                        (std::sqrt(3.0) / 4 * elementSize * elementSize);
  const double estimate = canopy + double(gores) * lineElements + 4.0 * riserElements +
                          double(sliderDivisions) * sliderDivisions + 64.0;
  if (estimate > maxElements)
    bad("--element-size", "about " + std::to_string(static_cast<long long>(estimate)) +
                              " elements, more than the limit of " +
                              std::to_string(static_cast<long long>(maxElements)) +
                              " (--max-elements)");
  // Nodes: about half the canopy's triangles, the lines' inner nodes, the slider's grid. More
  // than a case reads by default ([mesh] max_nodes) is refused for a case (checkForCase).
  const double nodes = canopy / 2 + double(gores) * lineElements + 4.0 * riserElements +
                       double(sliderDivisions + 1) * (sliderDivisions + 1) + 64.0;
  const char* finest =
      sliderDivisions * sliderDivisions > canopy ? "--slider-divisions" : "--element-size";
  if (caseLimits.maxNodes > 0 && nodes > double(caseLimits.maxNodes))
    bad(finest, "about " + std::to_string(static_cast<long long>(nodes)) +
                    " nodes, more than the " + std::to_string(caseLimits.maxNodes) +
                    " a case reads ([mesh] max_nodes)");
  // Equations: three per node. The mesh's own count is checked after meshing (checkForCase);
  // here a mesh well beyond the limit (the estimate above it by a fifth, more than the
  // estimate's error) is refused before gmsh spends minutes on it (--element-size 0.002 on a
  // 1.5 m canopy: 1.5 million equations found after 67 s of meshing).
  if (caseLimits.maxEquations > 0 && 3.0 * nodes > 1.2 * double(caseLimits.maxEquations))
    bad(finest, "about " + std::to_string(static_cast<long long>(3.0 * nodes)) +
                    " equations, more than the " + std::to_string(caseLimits.maxEquations) +
                    " a run takes (solver.max_equations): mesh coarser or leave out --case");
}

namespace {

// A case is written for the mesh: it must be one `chute run` takes with its default limits
// (docs/limits.md), or the user gets a case that is refused.
void checkForCase(const ParachuteSpec& spec, const GmshMesh& m) {
  const CaseLimits& lim = spec.caseLimits;
  if (lim.maxNodes == 0) return;
  std::size_t inGroups = 0;
  for (const auto& g : m.groups) inGroups += g.elements.size();
  const std::size_t nodes = m.nodeTags.size();
  // At least one node is held (the confluence or the payload): 3 (nodes - 1) bounds the
  // equations from above.
  const std::size_t equations = 3 * (nodes - 1);
  auto refuse = [](const std::string& what) {
    throw std::invalid_argument("--case: the mesh has " + what +
                                ": the case would be refused; mesh coarser (--element-size, "
                                "--line-elements, --slider-divisions) or leave out --case");
  };
  if (nodes > lim.maxNodes)
    refuse(std::to_string(nodes) + " nodes, more than the " + std::to_string(lim.maxNodes) +
           " a case reads ([mesh] max_nodes)");
  if (inGroups > lim.maxElements)
    refuse(std::to_string(inGroups) + " elements in its groups, more than the " +
           std::to_string(lim.maxElements) + " a case reads ([mesh] max_elements)");
  if (lim.maxEquations > 0 && equations > lim.maxEquations)
    refuse("up to " + std::to_string(equations) + " equations, more than the " +
           std::to_string(lim.maxEquations) + " a run takes (solver.max_equations)");
}

int physical(int dim, const std::vector<int>& tags, const std::string& name) {
  const int g = gmsh::model::addPhysicalGroup(dim, tags);
  gmsh::model::setPhysicalName(dim, g, name);
  return g;
}

}  // namespace

GeneratedParachute generateParachute(const ParachuteSpec& spec, const std::string& msh) {
  spec.validate();
  namespace geo = gmsh::model::geo;
  GeneratedParachute out;
  GmshScope scope;
  const auto t0 = std::chrono::steady_clock::now();
  callGmsh("gmsh: building the parachute", [&] {
    gmsh::model::add("parachute");
    const int n = spec.gores;
    const double R = spec.diameter / 2, r = spec.ventDiameter / 2, L = spec.lineLength;
    const double H = std::sqrt(L * L - R * R), h = spec.elementSize;
    const double dTheta = 2.0 * std::numbers::pi / n;

    // Canopy: gore k between the radial seams at angles k dTheta and (k + 1) dTheta, in bands
    // between hoop circles where a packed start creases it (outermost band first).
    const std::vector<double> rings =
        spec.start == "packed" ? packLayout(spec).foldRadii : std::vector<double>{};
    const int nr = static_cast<int>(rings.size());
    const int centre = geo::addPoint(0.0, 0.0, H, h);
    std::vector<int> skirtPt(n), ventPt(n), skirtArc(n), ventArc(n), seamPieces;
    std::vector<std::vector<int>> ringPt(nr, std::vector<int>(n)), ringArc(nr, std::vector<int>(n));
    std::vector<std::vector<int>> gore(n);
    for (int k = 0; k < n; ++k) {
      const double c = std::cos(k * dTheta), s = std::sin(k * dTheta);
      skirtPt[k] = geo::addPoint(R * c, R * s, H, h);
      ventPt[k] = r > 0.0 ? geo::addPoint(r * c, r * s, H, h) : centre;
      for (int i = 0; i < nr; ++i) ringPt[i][k] = geo::addPoint(rings[i] * c, rings[i] * s, H, h);
    }
    // piece[k][b]: seam k across band b, from its inner to its outer circle.
    std::vector<std::vector<int>> piece(n, std::vector<int>(nr + 1));
    for (int k = 0; k < n; ++k) {
      for (int b = 0; b <= nr; ++b) {
        const int outer = b == 0 ? skirtPt[k] : ringPt[b - 1][k];
        const int inner = b == nr ? ventPt[k] : ringPt[b][k];
        piece[k][b] = geo::addLine(inner, outer);
        seamPieces.push_back(piece[k][b]);
      }
      skirtArc[k] = geo::addCircleArc(skirtPt[k], centre, skirtPt[(k + 1) % n]);
      if (r > 0.0) ventArc[k] = geo::addCircleArc(ventPt[k], centre, ventPt[(k + 1) % n]);
      for (int i = 0; i < nr; ++i)
        ringArc[i][k] = geo::addCircleArc(ringPt[i][k], centre, ringPt[i][(k + 1) % n]);
    }
    std::vector<int> allGores;
    for (int k = 0; k < n; ++k)
      for (int b = 0; b <= nr; ++b) {
        const int outerArc = b == 0 ? skirtArc[k] : ringArc[b - 1][k];
        std::vector<int> loop = {piece[k][b], outerArc, -piece[(k + 1) % n][b]};
        if (b < nr)
          loop.push_back(-ringArc[b][k]);
        else if (r > 0.0)
          loop.push_back(-ventArc[k]);
        gore[k].push_back(geo::addPlaneSurface({geo::addCurveLoop(loop)}));
        allGores.push_back(gore[k].back());
      }

    // Suspension lines: skirt point j to the confluence at the origin.
    const int confluence = geo::addPoint(0.0, 0.0, 0.0, h);
    std::vector<int> line(n);
    for (int j = 0; j < n; ++j) {
      line[j] = geo::addLine(skirtPt[j], confluence);
      geo::mesh::setTransfiniteCurve(line[j], spec.lineElements + 1);
    }

    // Slider: a square centred on the axis, corner k at the mean angle of its group of lines.
    std::vector<int> grommet, sliderEdge;
    int slider = -1;
    if (spec.hasSlider()) {
      double phi0 = 0.0;
      int count = 0;
      for (int j = 0; j < n && grommetOfLine(j, n) == 0; ++j, ++count) phi0 += j * dTheta;
      phi0 /= count;
      const double rho = spec.sliderSide / std::sqrt(2.0), z = 0.5 * H;
      for (int k = 0; k < 4; ++k) {
        const double a = phi0 + k * std::numbers::pi / 2;
        grommet.push_back(geo::addPoint(rho * std::cos(a), rho * std::sin(a), z, h));
      }
      for (int k = 0; k < 4; ++k) {
        sliderEdge.push_back(geo::addLine(grommet[k], grommet[(k + 1) % 4]));
        geo::mesh::setTransfiniteCurve(sliderEdge.back(), spec.sliderDivisions + 1);
      }
      slider = geo::addPlaneSurface({geo::addCurveLoop(sliderEdge)});
      geo::mesh::setTransfiniteSurface(slider);
      geo::mesh::setRecombine(2, slider);
    }

    // Payload: a point at the confluence or riserLength below it, or a braced box hanging from
    // the confluence by four risers to its top corners.
    std::vector<int> payloadPts, risers, boxBars;
    if (spec.payloadMass > 0.0 && !spec.hasBox()) {
      if (spec.riserLength > 0.0) {
        payloadPts.push_back(geo::addPoint(0.0, 0.0, -spec.riserLength, h));
        risers.push_back(geo::addLine(confluence, payloadPts[0]));
      } else {
        payloadPts.push_back(confluence);
      }
    } else if (spec.hasBox()) {
      const auto& b = spec.payloadBox;
      const double half = 0.5 * std::hypot(b[0], b[1]);
      const double l = spec.riserLength > 0.0 ? spec.riserLength : 2.0 * half;
      const double zTop = -std::sqrt(l * l - half * half);
      for (int level = 0; level < 2; ++level)
        for (int c = 0; c < 4; ++c) {
          const double sx = (c == 0 || c == 3) ? -0.5 : 0.5, sy = c < 2 ? -0.5 : 0.5;
          payloadPts.push_back(geo::addPoint(sx * b[0], sy * b[1], zTop - level * b[2], h));
        }
      for (int c = 0; c < 4; ++c) risers.push_back(geo::addLine(confluence, payloadPts[c]));
      auto bar = [&](int a, int bb) {
        boxBars.push_back(geo::addLine(payloadPts[a], payloadPts[bb]));
      };
      for (int level = 0; level < 2; ++level)
        for (int c = 0; c < 4; ++c) bar(4 * level + c, 4 * level + (c + 1) % 4);  // rims
      for (int c = 0; c < 4; ++c) bar(c, 4 + c);                                  // posts
      bar(0, 2);  // one diagonal per face: the triangulated box is rigid (18 = 3 * 8 - 6 bars)
      bar(4, 6);
      for (int c = 0; c < 4; ++c) bar(c, 4 + (c + 1) % 4);
    }
    for (int c : risers) geo::mesh::setTransfiniteCurve(c, spec.riserElements + 1);
    for (int c : boxBars) geo::mesh::setTransfiniteCurve(c, 2);
    geo::synchronize();

    physical(2, allGores, "canopy");
    for (int k = 0; k < n; ++k) physical(2, gore[k], "gore_" + std::to_string(k));
    physical(1, seamPieces, "radial_seams");
    physical(1, skirtArc, "skirt_band");
    if (r > 0.0) physical(1, ventArc, "vent_band");
    physical(1, line, "lines");
    for (int j = 0; j < n; ++j) physical(1, {line[j]}, "line_" + std::to_string(j));
    physical(0, skirtPt, "skirt_points");
    for (int j = 0; j < n; ++j) physical(0, {skirtPt[j]}, "skirt_" + std::to_string(j));
    physical(0, {confluence}, "confluence");
    if (r == 0.0) physical(0, {centre}, "apex");
    if (slider > 0) {
      physical(2, {slider}, "slider");
      physical(1, sliderEdge, "slider_edges");
      physical(0, grommet, "grommets");
      for (int k = 0; k < 4; ++k) physical(0, {grommet[k]}, "grommet_" + std::to_string(k));
    }
    if (!risers.empty()) physical(1, risers, "risers");
    if (!boxBars.empty()) physical(1, boxBars, "payload_box");
    if (!payloadPts.empty()) physical(0, payloadPts, "payload");

    gmsh::option::setNumber("Mesh.MeshSizeMax", h);
    gmsh::option::setNumber("Mesh.Algorithm", spec.meshAlgorithm);
    gmsh::model::mesh::generate(2);
    out.meshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.mesh = currentMesh();

    // Figures: canopy area against the analytic flat area, line lengths against L.
    const GmshMesh& m = out.mesh;
    for (const auto& e : m.group("canopy", 2)->elements) {
      const Vec3 a = m.at(e[0]), b = m.at(e[1]), c = m.at(e[2]);
      out.canopyArea += 0.5 * (b - a).cross(c - a).norm();
      if (e.size() == 4) out.canopyArea += 0.5 * (c - a).cross(m.at(e[3]) - a).norm();
      out.triangles += e.size() == 3;
    }
    out.flatArea = std::numbers::pi * (R * R - r * r);
    for (int j = 0; j < n; ++j) {
      double len = 0.0;
      for (const auto& e : m.group("line_" + std::to_string(j), 1)->elements)
        len += (m.at(e[1]) - m.at(e[0])).norm();
      out.maxLineLengthError = std::max(out.maxLineLengthError, std::abs(len - L));
      if (spec.hasSlider()) ++out.linesPerGrommet[grommetOfLine(j, n)];
    }

    if (spec.start != "flat" || spec.hasSlider()) {
      const StartConfiguration s = parachuteStart(spec, out.mesh);
      out.mesh.views["initial_displacement"] = s.displacement;
      out.maxStartStretch = s.maxStretch;
    } else {
      out.maxStartStretch = 1.0;
    }
    checkForCase(spec, out.mesh);
    if (!msh.empty()) writeCurrentMesh(msh, out.mesh.views);
  });
  return out;
}

}  // namespace chute::mesh
