#include "ParachuteCaseWriter.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "ParachuteMaterials.hpp"

namespace chute::mesh {

namespace {

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  std::string s = b;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";  // TOML: a float, not an integer
  return s;
}

// Whether s is valid UTF-8 (TOML text must be; a path of other bytes cannot be named in a case).
bool validUtf8(const std::string& s) {
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const size_t extra = c < 0x80           ? 0
                         : (c >> 5) == 0x6  ? 1
                         : (c >> 4) == 0xe  ? 2
                         : (c >> 3) == 0x1e ? 3
                                            : 4;
    if (extra == 4 || i + extra >= s.size()) return false;
    for (size_t k = 1; k <= extra; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return false;
    i += 1 + extra;
  }
  return true;
}

// A TOML basic string of s: quotes, backslashes and control characters escaped, so a path or name
// with a quote or a newline is the value it is, not the end of it (`option` names the source).
std::string tomlString(const std::string& s, const std::string& option) {
  if (!validUtf8(s))
    throw std::invalid_argument(option + ": not UTF-8 text; a TOML case cannot name it");
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04X", static_cast<unsigned>(c));
      out += esc;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

// Text for a comment line: control characters (a newline would end the comment) shown as '?'.
std::string commentText(std::string s) {
  for (char& ch : s)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ch = '?';
  return s;
}

std::string vec(double x, double y, double z) {
  std::ostringstream s;
  s << "[" << num(x) << ", " << num(y) << ", " << num(z) << "]";
  return s.str();
}

}  // namespace

void checkParachuteCaseOptions(const ParachuteCaseOptions& o) {
  auto bad = [](const std::string& option, const std::string& why) {
    throw std::invalid_argument(option + ": " + why);
  };
  if (!std::isnan(o.pressure) && !(std::isfinite(o.pressure) && std::abs(o.pressure) <= 1e6))
    bad("--pressure", "must be finite and at most 1e6");
  // 0 (none) or within 1e-5 to 1e5 times the default (1e-6 to 1e4 psf, 4.8e-5 to 4.8e5 Pa; a
  // 500-knot deployment at sea level is 850 psf): the explicit step of the generated case blew
  // up at 1e5 psf, and at 1e-12 psf its energies were rounding noise the energy balance refused.
  if (!std::isnan(o.pressure) && o.pressure != 0.0 && (o.units == "ft" || o.units == "si")) {
    const double q = parachuteMaterials(o.units).defaultPressure;
    auto g = [](double x) {
      char b[32];
      std::snprintf(b, sizeof b, "%g", x);
      return std::string(b);
    };
    if (std::abs(o.pressure) < 1e-5 * q * (1 - 1e-12) ||
        std::abs(o.pressure) > 1e5 * q * (1 + 1e-12))
      bad("--pressure", "0 or between " + g(1e-5 * q) + " and " + g(1e5 * q) +
                            " in magnitude (1e-5 to 1e5 times the default " + g(q) + ")");
  }
  if (!(o.dt > 0.0 && o.dt <= 1e3)) bad("--dt", "must be in (0, 1e3]");
  if (!(o.tEnd > 0.0 && o.tEnd <= 1e6)) bad("--t-end", "must be in (0, 1e6]");
  // As the case reader's [solver] checks (docs/limits.md): one step at least, at most 1e9.
  if (o.dt > o.tEnd) bad("--dt", "is larger than --t-end: not one step fits");
  if (o.tEnd / o.dt > 1e9) bad("--dt", "--t-end / --dt is more than 1e9 steps");
  if (!(o.rampTime >= 0.0 && o.rampTime <= 1e6)) bad("--ramp-time", "must be in [0, 1e6]");
  if (!(o.probeInterval > 0.0)) bad("--probe-interval", "must be positive");
  if (!(o.vtuInterval >= 0.0)) bad("--vtu-interval", "must not be negative");
  if (o.units != "ft" && o.units != "si") bad("--units", "expected ft or si");
}

void writeParachuteCase(const ParachuteSpec& spec, const GeneratedParachute& generated,
                        const std::string& caseFile, const std::string& msh,
                        const ParachuteCaseOptions& o) {
  checkParachuteCaseOptions(o);
  const ParachuteMaterials mat = parachuteMaterials(o.units);
  namespace fs = std::filesystem;
  const fs::path dir = fs::absolute(caseFile).parent_path();
  const std::string mshRef = fs::relative(fs::absolute(msh), dir).generic_string();
  // The case's name (its default output directory) is a plain file name: the reader refuses
  // control characters and backslashes in it.
  std::string name = fs::path(caseFile).stem().string();
  for (char& ch : name)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f || ch == '\\') ch = '_';
  if (name.empty() || name == "." || name == "..") name = "parachute";
  const GmshMesh& mesh = generated.mesh;
  const bool si = o.units == "si";
  const double p = std::isnan(o.pressure) ? mat.defaultPressure : o.pressure;
  const double V = std::sqrt(2.0 * std::abs(p) / mat.airDensity);  // q = rho V^2 / 2
  const std::string wind = "wind = " + vec(0.0, 0.0, V);
  const std::string air = "air_density = " + num(mat.airDensity);
  const bool risers = mesh.group("risers", 1) != nullptr;
  const MeshGroup* payload = mesh.group("payload", 0);
  const std::string pu = si ? "Pa" : "psf", lu = si ? "m" : "ft";

  std::ostringstream f;
  f << "# Generated by chute mesh parachute: " << spec.gores << " gores, D = " << spec.diameter
    << " " << lu << ", lines " << spec.lineLength << " " << lu << " (" << spec.lineElements
    << " elements)" << (spec.ventDiameter > 0 ? ", vent" : "")
    << (spec.hasSlider() ? ", slider" : "")
    << (spec.hasBox()          ? ", payload box"
        : spec.payloadMass > 0 ? ", payload"
                               : "")
    << ", " << spec.start << " start, " << generated.triangles << " canopy triangles.\n";
  f << "#   chute mesh parachute --gores " << spec.gores << " --diameter " << spec.diameter
    << " --vent-diameter " << spec.ventDiameter << " --line-length " << spec.lineLength
    << " --line-elements " << spec.lineElements << " --element-size " << spec.elementSize;
  if (spec.hasSlider()) f << " --slider " << spec.sliderSide;
  if (spec.payloadMass > 0) f << " --payload-mass " << spec.payloadMass;
  if (spec.hasBox())
    f << " --payload-box " << spec.payloadBox[0] << "," << spec.payloadBox[1] << ","
      << spec.payloadBox[2];
  if (spec.riserLength > 0) f << " --riser-length " << spec.riserLength;
  f << " --start " << spec.start << " --units " << o.units << " --pressure " << num(p) << " --out "
    << commentText(msh) << " --case " << commentText(caseFile) << "\n";
  if (!o.commandLine.empty()) f << "#   " << commentText(o.commandLine) << "\n";
  f << "# Flight: the frame of the falling payload (payload held, gravity 0, the air streaming up\n"
       "# at the speed whose dynamic pressure is the canopy pressure), the settings that fly the\n"
       "# half-scale C-9 (docs/applications/c9.md). Materials: docs/meshing.md, \"Materials of a\n"
       "# generated case\". Run:  chute run "
    << commentText(fs::path(caseFile).filename().string()) << "\n";
  f << "name = " << tomlString(name, "--case") << "\n"
    << "description = \"Flat circular canopy, " << spec.gores << " gores, D = " << spec.diameter
    << " " << lu << ", " << spec.start << " start, generated by chute mesh parachute\"\n"
    << "units = \"" << mat.unitsLabel << "\"\n\n";

  f << "[mesh]\nfile = " << tomlString(mshRef, "--out") << "\n";
  if (mesh.views.count("initial_displacement"))
    f << "initial_displacement = \"initial_displacement\"   # the " << spec.start
      << " start; the reference is the flat pattern\n";

  std::ostringstream fab, crd;
  fab << "kind = \"membrane\"\nE = " << num(mat.fabricE)
      << "   # E t = 144 lbf/in: Zhou, Accorsi & Leonard 2004 (C-9 model)\nnu = "
      << num(mat.fabricNu) << "   # the paper's\nthickness = " << num(mat.fabricThickness)
      << "   # 4e-4 ft, the paper's; only E t and the mass count\ndensity = "
      << num(mat.fabricDensity)
      << "   # 1.1 oz/yd^2 (37.3 g/m^2): MIL-C-7020 ripstop nylon, the C-9's cloth\n\n";
  crd << "kind = \"cable\"\nE = " << num(mat.cordE)
      << "   # E A = 1300 lbf: 400 lb at ~30 % elongation\narea = " << num(mat.cordArea)
      << "   # MIL-C-5040 type II 400 lb nylon cord (the C-9 cases')\ndensity = "
      << num(mat.cordDensity) << "   # 0.0058 lb/ft\n\n";
  const std::string fabric = fab.str(), cord = crd.str();
  f << "\n[materials.canopy_fabric]   # MIL-C-7020 ripstop nylon\n" << fabric;
  f << "[materials.tape]   # radial seams and bands: the lines run over the canopy (as on a C-9)\n"
    << cord;
  f << "[materials.suspension_line]   # MIL-C-5040 type II cord, 400 lb\n" << cord;
  if (spec.hasSlider()) f << "[materials.slider_fabric]   # the canopy's cloth\n" << fabric;
  if (risers) {
    // A riser gathers gores / risers lines: give it their section (same strength per line).
    const double share = double(spec.gores) / double(mesh.group("risers", 1)->elements.size() /
                                                     std::max(1, spec.riserElements));
    f << "[materials.riser]   # the section of the " << share
      << " cords it gathers: as strong as they are\n"
      << "kind = \"cable\"\nE = " << num(mat.cordE) << "\narea = " << num(share * mat.cordArea)
      << "\ndensity = " << num(mat.cordDensity) << "\n\n";
  }
  if (spec.hasBox())
    f << "[materials.payload_frame]   # the box's frame: stiff and massless (mass at corners)\n"
         "kind = \"truss\"\nE = "
      << num(mat.frameE) << "\narea = " << num(mat.frameArea) << "\ndensity = 0.0\n\n";

  f << "[[membranes]]\nname = \"canopy\"\nmaterial = \"canopy_fabric\"\ngroup = \"canopy\"\n"
       "wrinkling = true   # fabric carries no compression (tension-field model)\n\n";
  if (spec.hasSlider())
    f << "[[membranes]]\nname = \"slider\"\nmaterial = \"slider_fabric\"\ngroup = \"slider\"\n"
         "wrinkling = true\n\n";
  std::vector<std::string> tapes;
  for (const char* band : {"radial_seams", "skirt_band", "vent_band"})
    if (mesh.group(band, 1)) {
      tapes.push_back(band);
      f << "[[cables]]\nname = \"" << band << "\"\nmaterial = \"tape\"\ngroup = \"" << band
        << "\"\n\n";
    }
  std::vector<std::string> lineSets;
  if (spec.hasSlider()) {
    for (int j = 0; j < spec.gores; ++j) {
      const std::string line = "line_" + std::to_string(j);
      lineSets.push_back(line);
      f << "[[sliding_groups]]   # line " << j << " slides through its grommet\nname = \"" << line
        << "\"\nmaterial = \"suspension_line\"\ngroup = \"" << line << "\"\nsliders = [\"grommet_"
        << grommetOfLine(j, spec.gores) << "\"]\n\n";
    }
  } else {
    lineSets.push_back("lines");
    f << "[[cables]]\nname = \"lines\"\nmaterial = \"suspension_line\"\ngroup = \"lines\"\n\n";
  }
  if (risers) f << "[[cables]]\nname = \"risers\"\nmaterial = \"riser\"\ngroup = \"risers\"\n\n";
  if (spec.hasBox())
    f << "[[cables]]\nname = \"payload_box\"\nmaterial = \"payload_frame\"\ngroup = "
         "\"payload_box\"\n\n";
  if (payload)
    f << "[[point_masses]]   # inert while the payload is held (below); counts in free fall\n"
         "group = \"payload\"\nmass = "
      << num(spec.payloadMass / static_cast<double>(payload->nodes().size()))
      << "   # at each node of the group\n\n";

  // The frame of the payload: a payload that falls at about g (heavy, little drag) is an
  // almost-free-falling frame, so gravity cancels and the payload stays put while the air streams
  // up past it (docs/applications/c9.md, "Why this frame").
  f << "[boundary]   # the frame of the falling payload: the payload held\n";
  if (!payload || (!risers && !spec.hasBox()))
    f << "fixed = [\"confluence\"]\n\n";
  else if (!spec.hasBox())
    f << "fixed = [\"payload\"]\n\n";
  else
    f << "[[boundary.constraints]]\nset = \"payload\"\ndofs = \"xyz\"\n\n";
  f << "[loads]\ngravity = [0.0, 0.0, 0.0]   # cancelled in the falling payload's frame ("
    << num(mat.gravity) << " " << lu << "/s^2 when the payload is released)\n\n";
  if (p != 0.0)
    f << "[[loads.pressure]]\nmembranes = \"canopy\"\npressure = " << num(p) << "   # " << pu
      << ": the dynamic pressure of the " << num(V) << " " << lu << "/s wind below\n"
      << "ramp_time = " << num(o.rampTime) << "   # a sudden load would start with a shock\n\n";
  f << "[[loads.face_drag]]   # damps the fabric's motion normal to itself\nmembranes = "
       "\"canopy\"\ncd = 1.2   # a flat plate normal to the flow\n"
    << air << "   # sea level, standard atmosphere\n"
    << wind << "   # " << lu << "/s up: the descent\n";
  if (p != 0.0)
    f << "subtract_steady = true   # the pressure already is the steady load of this wind\n";
  f << "\n";
  auto drag = [&](const std::string& key, const std::string& set, double d, double cd,
                  const std::string& why) {
    f << "[[loads.drag]]   # " << why << "\n"
      << key << " = \"" << set << "\"\ndiameter = " << num(d) << "\ncd = " << num(cd) << "\n"
      << air << "\n"
      << wind << "\n\n";
  };
  for (const auto& t : tapes)
    drag("set", t, mat.cordDragDiameter, 1.0, "a cylinder across the flow (Re ~ 2e3), 0.03 ft");
  for (const auto& l : lineSets)
    drag("set", l, mat.cordDragDiameter, 1.0, "a cylinder across the flow (Re ~ 2e3), 0.03 ft");
  if (risers) drag("set", "risers", mat.cordDragDiameter, 1.0, "as the lines");
  if (spec.hasSlider())
    drag("group", "slider_edges", spec.sliderSide, 1.17 / 4,
         "the four edges carry the slider's flat-plate drag, Cd 1.17 on its area");

  f << "[solver]\ntype = \"dynamic\"\n"
    << "integrator = \"central_difference\"   # explicit: 5-14x less wall time than Bossak on "
       "parachutes at equal accuracy (docs/explicit.md)\n"
    << "dt = " << num(o.dt)
    << "   # the largest step allowed; the step taken is the fabric's stable step\n"
    << "stiffness_damping = 1e-5   # 1-2 % of critical at the highest frequencies: the fabric's "
       "stresses and the lines' forces do not ring\n"
    << "t_end = " << num(o.tEnd) << "   # s of flight\n"
    << "# The implicit alternative, --set solver.integrator='\"bossak\"', runs with these:\n"
    << "rho_inf = 0.0   # Bossak: annihilates the unresolved mesh-size fabric modes that crumple "
       "a canopy\n"
    << "slack_events = false   # locating each slack/taut switch of hundreds of lines costs "
       "thousands of cut steps\n"
    << "slider_events = false   # Bossak: grommets pass line nodes inside the Newton solve (no "
       "micro-steps)\n\n";

  f << "[output]\ninterval = " << num(o.probeInterval) << "   # a probes.csv row every "
    << num(o.probeInterval) << " s\n\n";
  if (o.vtuInterval > 0)
    f << "[output.vtu]   # the ParaView series (" << name
      << ".pvd)\ninterval = " << num(o.vtuInterval)
      << "\nfields = [\"displacement\", \"velocity\"]\n\n";
  const char* top = spec.ventDiameter > 0 ? "vent_band" : "apex";
  f << "[[output.probes]]   # inflation: mean / min / max skirt distance from the axis\n"
       "name = \"skirt\"\nkind = \"skirt_radius\"\nset = \"skirt_points\"\naxis = "
       "[\"confluence\", \""
    << top << "\"]\n\n";
  if (spec.hasSlider())
    f << "[[output.probes]]   # the slider's way down line 0 (s from the skirt end)\n"
         "name = \"slider_0\"\nkind = \"slider\"\ngroup = \"line_0\"\n\n";
  f << "[[output.probes]]   # tension in line 0\nname = \"line_0\"\nkind = \"line_force\"\nset = \""
    << lineSets[0] << "\"\nelement = 0\n\n";
  if (risers)
    f << "[[output.probes]]   # tension in a riser\nname = \"riser\"\nkind = \"line_force\"\n"
         "set = \"risers\"\nelement = 0\n\n";
  f << "[[output.probes]]   # kinetic and strain energy\nname = \"energy\"\nkind = \"energy\"\n";

  std::ofstream file(caseFile);
  if (!file) throw std::runtime_error(caseFile + ": cannot write the case file");
  file << f.str();
  if (!file) throw std::runtime_error(caseFile + ": write failed");
}

}  // namespace chute::mesh
