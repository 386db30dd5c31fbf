#include "ParachuteCaseWriter.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "ParachuteMaterials.hpp"
#include "TomlText.hpp"

namespace chute::mesh {

namespace {

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  std::string s = b;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";  // TOML: a float, not an integer
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
  const double metre = o.units == "si" ? 1.0 : 1.0 / 0.3048;  // case length units per m
  // NaN is the default (20 m/s); given: above 0 and at most 200 m/s (656 ft/s, Mach 0.6 at sea
  // level, 390 knots), the outside flow of the airflow's loads being subsonic and incompressible
  // (docs/flight.md). Measured on a small generated parachute (8 gores, D = 2 ft): held at
  // 274 m/s its canopy flow broke down within 0.01 s, at 244 m/s it flew. Held, the wind is the
  // only load: at least 0.01 m/s (a dynamic pressure 1e-5 times --pressure's default, the
  // least --pressure takes); at 1e-4 m/s its energies were rounding noise the energy balance
  // refused. Free, gravity loads it from any speed.
  if (!std::isnan(o.speed) && !(o.speed > 0.0 && o.speed <= 200.0 * metre))
    bad("--speed", "must be above 0 and at most 200 m/s (656 ft/s)");
  if (o.held && !std::isnan(o.speed) && !(o.speed >= 0.01 * metre))
    bad("--speed", "held, the wind must be at least 0.01 m/s (0.0328 ft/s)");
  if (!(std::isfinite(o.altitude) && o.altitude >= -500.0 * metre && o.altitude <= 11000.0 * metre))
    bad("--altitude", "must be within the standard atmosphere's troposphere (-500 m to 11 km)");
  if (!(o.clothPermeability >= 0.0 && o.clothPermeability <= 1e4))
    bad("--cloth-permeability", "must be in [0, 1e4] ft^3/ft^2/min");
  if (o.held && !std::isnan(o.pressure))
    bad("--held", "goes with the airflow's loads, not --pressure");
  if (!std::isnan(o.speed) && !std::isnan(o.pressure))
    bad("--speed", "goes with the airflow's loads, not --pressure");
  // Finite: an infinite interval would be written as a number TOML does not have.
  if (!(o.probeInterval > 0.0 && std::isfinite(o.probeInterval)))
    bad("--probe-interval", "must be positive and finite");
  if (!(o.vtuInterval >= 0.0 && std::isfinite(o.vtuInterval)))
    bad("--vtu-interval", "must not be negative and must be finite");
  // As the case reader's [output] checks (docs/limits.md): at most output.max_rows = 1,000,000
  // probe rows and output.vtu.max_frames = 10,000 frames by default, so that the generated case
  // is never one `chute run` refuses.
  if (o.tEnd / o.probeInterval + 1.0 > 1e6)
    bad("--probe-interval",
        "--t-end / --probe-interval is more than the 1,000,000 probe rows a "
        "case writes by default (output.max_rows)");
  if (o.vtuInterval > 0.0 && o.tEnd / o.vtuInterval + 1.0 > 1e4)
    bad("--vtu-interval",
        "--t-end / --vtu-interval is more than the 10,000 frames a case "
        "writes by default (output.vtu.max_frames)");
  if (o.units != "ft" && o.units != "si") bad("--units", "expected ft or si");
}

namespace {

// What every step of the writing shares: the parachute, its mesh, the options and what follows
// from them (units, the flight frame).
struct CaseContext {
  CaseContext(const ParachuteSpec& s, const GmshMesh& m, const ParachuteCaseOptions& opt)
      : spec(s), mesh(m), o(opt), mat(parachuteMaterials(opt.units, opt.clothPermeability)) {}
  const ParachuteSpec& spec;
  const GmshMesh& mesh;
  const ParachuteCaseOptions& o;
  ParachuteMaterials mat;
  bool si = false, risers = false, legacyPressure = false;
  const MeshGroup* payload = nullptr;
  double pressure = 0.0;  // legacy: the constant canopy pressure
  double speed = 0.0;     // the system's speed at line stretch, or the wind's when held
  bool held = false;
  std::string lu, pu, su;  // length, pressure, speed units
  std::vector<std::string> tapes, lineSets;
  std::string windLine() const {
    return "wind = " + vec(0.0, 0.0, held || legacyPressure ? speed : 0.0);
  }
};

void writeHeader(std::ostream& f, const CaseContext& c, const GeneratedParachute& generated,
                 const std::string& caseFile, const std::string& msh, const std::string& name) {
  const auto& spec = c.spec;
  f << "# Generated by chute mesh parachute: " << spec.gores << " gores, D = " << spec.diameter
    << " " << c.lu << ", lines " << spec.lineLength << " " << c.lu << " (" << spec.lineElements
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
  f << " --start " << spec.start << " --units " << c.o.units;
  if (c.legacyPressure)
    f << " --pressure " << num(c.pressure);
  else
    f << " --speed " << num(c.speed) << " --altitude " << num(c.o.altitude)
      << (c.held ? " --held" : "");
  // The case options given other than their defaults, so that the line makes this file again.
  const ParachuteCaseOptions defaults;
  auto option = [&](const char* flag, double value, double byDefault) {
    if (value != byDefault) f << " " << flag << " " << num(value);
  };
  if (c.legacyPressure)
    option("--ramp-time", c.o.rampTime, defaults.rampTime);
  else
    option("--cloth-permeability", c.o.clothPermeability, defaults.clothPermeability);
  option("--dt", c.o.dt, defaults.dt);
  option("--t-end", c.o.tEnd, defaults.tEnd);
  option("--probe-interval", c.o.probeInterval, defaults.probeInterval);
  option("--vtu-interval", c.o.vtuInterval, defaults.vtuInterval);
  f << " --out " << commentText(msh) << " --case " << commentText(caseFile) << "\n";
  if (!c.o.commandLine.empty()) f << "#   " << commentText(c.o.commandLine) << "\n";
  if (c.legacyPressure)
    f << "# Flight: the frame of the falling payload (payload held, gravity 0, the air streaming "
         "up\n# at the speed whose dynamic pressure is the canopy pressure), the settings that "
         "fly the\n# half-scale C-9 (docs/applications/c9.md).";
  else if (c.held)
    f << "# Flight: held in a steady wind of " << num(c.speed) << " " << c.su
      << " (the wind tunnel: the payload fixed,\n# infinite mass), the canopy loaded by the "
         "airflow relative to it (docs/flight.md).";
  else
    f << "# Flight: free, from line stretch at " << num(c.speed) << " " << c.su
      << " downward, gravity on, the canopy loaded\n# by the airflow relative to it "
         "(docs/flight.md); the summary reports the opening force,\n# filling time, descent "
         "speed and drag coefficient.";
  f << " Materials: docs/meshing.md, \"Materials of a\n# generated case\". Run:  chute run "
    << commentText(std::filesystem::path(caseFile).filename().string()) << "\n";
  f << "name = " << tomlString(name, "--case") << "\n"
    << "description = \"Flat circular canopy, " << spec.gores << " gores, D = " << spec.diameter
    << " " << c.lu << ", " << spec.start << " start, generated by chute mesh parachute\"\n"
    << "units = \"" << c.mat.unitsLabel << "\"\n\n";
}

void writeMaterials(std::ostream& f, const CaseContext& c) {
  const auto& mat = c.mat;
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
  if (c.spec.hasSlider()) f << "[materials.slider_fabric]   # the canopy's cloth\n" << fabric;
  if (c.risers) {
    // A riser gathers gores / risers lines: give it their section (same strength per line).
    const double share = double(c.spec.gores) / double(c.mesh.group("risers", 1)->elements.size() /
                                                       std::max(1, c.spec.riserElements));
    f << "[materials.riser]   # the section of the " << share
      << " cords it gathers: as strong as they are\n"
      << "kind = \"cable\"\nE = " << num(mat.cordE) << "\narea = " << num(share * mat.cordArea)
      << "\ndensity = " << num(mat.cordDensity) << "\n\n";
  }
  if (c.spec.hasBox())
    f << "[materials.payload_frame]   # the box's frame: stiff and massless (mass at corners)\n"
         "kind = \"truss\"\nE = "
      << num(mat.frameE) << "\narea = " << num(mat.frameArea) << "\ndensity = 0.0\n\n";
}

void writeElements(std::ostream& f, CaseContext& c) {
  const auto& spec = c.spec;
  f << "[[membranes]]\nname = \"canopy\"\nmaterial = \"canopy_fabric\"\ngroup = \"canopy\"\n"
       "wrinkling = true   # fabric carries no compression (tension-field model)\n\n";
  if (spec.hasSlider())
    f << "[[membranes]]\nname = \"slider\"\nmaterial = \"slider_fabric\"\ngroup = \"slider\"\n"
         "wrinkling = true\n\n";
  for (const char* band : {"radial_seams", "skirt_band", "vent_band"})
    if (c.mesh.group(band, 1)) {
      c.tapes.push_back(band);
      f << "[[cables]]\nname = \"" << band << "\"\nmaterial = \"tape\"\ngroup = \"" << band
        << "\"\n\n";
    }
  if (spec.hasSlider()) {
    for (int j = 0; j < spec.gores; ++j) {
      const std::string line = "line_" + std::to_string(j);
      c.lineSets.push_back(line);
      f << "[[sliding_groups]]   # line " << j << " slides through its grommet\nname = \"" << line
        << "\"\nmaterial = \"suspension_line\"\ngroup = \"" << line << "\"\nsliders = [\"grommet_"
        << grommetOfLine(j, spec.gores) << "\"]\n\n";
    }
  } else {
    c.lineSets.push_back("lines");
    f << "[[cables]]\nname = \"lines\"\nmaterial = \"suspension_line\"\ngroup = \"lines\"\n\n";
  }
  if (c.risers) f << "[[cables]]\nname = \"risers\"\nmaterial = \"riser\"\ngroup = \"risers\"\n\n";
  if (spec.hasBox())
    f << "[[cables]]\nname = \"payload_box\"\nmaterial = \"payload_frame\"\ngroup = "
         "\"payload_box\"\n\n";
  if (c.payload)
    f << "[[point_masses]]\ngroup = \"payload\"\nmass = "
      << num(spec.payloadMass / static_cast<double>(c.payload->nodes().size()))
      << "   # at each node of the group\n\n";
}

// The frame: held payload (the legacy constant pressure, or a wind tunnel), or free flight with
// gravity from line stretch; the air (the standard atmosphere at the altitude).
void writeFrame(std::ostream& f, const CaseContext& c) {
  const bool hold = c.held || c.legacyPressure;
  if (hold) {
    f << "[boundary]   # "
      << (c.legacyPressure ? "the frame of the falling payload" : "the wind tunnel")
      << ": the payload held\n";
    if (!c.payload || (!c.risers && !c.spec.hasBox()))
      f << "fixed = [\"confluence\"]\n\n";
    else if (!c.spec.hasBox())
      f << "fixed = [\"payload\"]\n\n";
    else
      f << "[[boundary.constraints]]\nset = \"payload\"\ndofs = \"xyz\"\n\n";
  }
  if (!c.legacyPressure) {
    f << "[air]\naltitude = " << num(c.o.altitude) << "   # " << c.lu
      << ": the U.S. Standard Atmosphere 1976 there\n";
    if (c.held) f << c.windLine() << "   # " << c.su << " up past the held parachute\n";
    f << "\n";
    if (!c.held)
      f << "[initial]   # line stretch: everything moving down at the deployment speed\n"
           "velocity = "
        << vec(0.0, 0.0, -c.speed) << "   # " << c.su << "\n\n";
  }
  f << "[loads]\n";
  if (hold)
    f << "gravity = [0.0, 0.0, 0.0]   # "
      << (c.legacyPressure ? "cancelled in the falling payload's frame" : "held: no weight") << " ("
      << num(c.mat.gravity) << " " << c.lu << "/s^2 in free flight)\n\n";
  else
    f << "gravity = " << vec(0.0, 0.0, -c.mat.gravity) << "   # standard gravity\n\n";
}

void writeLoads(std::ostream& f, const CaseContext& c) {
  const std::string air = "air_density = " + num(c.mat.airDensity);
  if (c.legacyPressure) {
    if (c.pressure != 0.0)
      f << "[[loads.pressure]]\nmembranes = \"canopy\"\npressure = " << num(c.pressure) << "   # "
        << c.pu << ": the dynamic pressure of the " << num(c.speed) << " " << c.su
        << " wind below\n"
        << "ramp_time = " << num(c.o.rampTime) << "   # a sudden load would start with a shock\n\n";
    f << "[[loads.face_drag]]   # damps the fabric's motion normal to itself\nmembranes = "
         "\"canopy\"\ncd = 1.2   # a flat plate normal to the flow\n"
      << air << "   # sea level, standard atmosphere\n"
      << c.windLine() << "   # " << c.su << " up: the descent\n";
    if (c.pressure != 0.0)
      f << "subtract_steady = true   # the pressure already is the steady load of this wind\n";
    f << "\n";
  } else {
    f << "[[loads.canopy_flow]]   # the airflow's loads on the canopy (docs/flight.md FL1-FL12)\n"
         "membranes = \"canopy\"\n";
    if (c.mat.clothPermeability > 0.0)
      f << "permeability = " << num(c.mat.clothPermeability) << "   # " << c.su
        << " through the cloth at the test pressure: " << num(c.o.clothPermeability)
        << " ft^3/ft^2/min\npermeability_pressure = " << num(c.mat.permeabilityTestPressure)
        << "   # " << c.pu << ": 0.5 in of water (MIL-C-7020 type I: 80-120 ft^3/ft^2/min)\n";
    if (c.spec.start == "inflated")
      f << "initial_inside_pressure = " << num(0.5 * c.mat.airDensity * c.speed * c.speed)
        << "   # " << c.pu << ": an open canopy holds its ram pressure (the start's q)\n";
    f << "\n";
  }
  auto drag = [&](const std::string& key, const std::string& set, double d, double cd,
                  const std::string& why) {
    f << "[[loads.drag]]   # " << why << "\n"
      << key << " = \"" << set << "\"\ndiameter = " << num(d) << "\ncd = " << num(cd) << "\n"
      << air << "\n"
      << c.windLine() << "\n\n";
  };
  const std::string cyl = "a cylinder across the flow (Re ~ 2e3), 0.03 ft";
  for (const auto& t : c.tapes) drag("set", t, c.mat.cordDragDiameter, 1.0, cyl);
  for (const auto& l : c.lineSets) drag("set", l, c.mat.cordDragDiameter, 1.0, cyl);
  if (c.risers) drag("set", "risers", c.mat.cordDragDiameter, 1.0, "as the lines");
  if (c.spec.hasSlider())
    drag("group", "slider_edges", c.spec.sliderSide, 1.17 / 4,
         "the four edges carry the slider's flat-plate drag, Cd 1.17 on its area");
}

void writeSolver(std::ostream& f, const CaseContext& c) {
  f << "[solver]\ntype = \"dynamic\"\n"
    << "integrator = \"central_difference\"   # explicit: 5-14x less wall time than Bossak on "
       "parachutes at equal accuracy (docs/explicit.md)"
    << (c.legacyPressure ? "" : "; the airflow's loads need it") << "\n"
    << "dt = " << num(c.o.dt)
    << "   # the largest step allowed; the step taken is the fabric's stable step\n"
    << "stiffness_damping = 1e-5   # EX7: xi = beta omega / 2, 3-22 % of critical at the finest "
       "elements' frequencies (the fabric's stresses and the lines' forces do not ring), under "
       "0.5 % below 150 Hz\n"
    << "mass_scaling_quantile = 0.01   # EX8: the 1 % of nodes with the shortest own stable step "
       "(on fine meshes the vent band's short segments) get the mass that lifts it to the "
       "quantile's: 1.4x fewer steps at 12k-24k triangles for 0.1 % of the canopy's mass, "
       "flight figures unchanged within round-off (docs/explicit.md); 0 turns it off\n"
    << "t_end = " << num(c.o.tEnd) << "   # s of flight\n";
  if (c.legacyPressure)
    f << "# The implicit alternative, --set solver.integrator='\"bossak\"', runs with these:\n"
      << "rho_inf = 0.0   # Bossak: annihilates the unresolved mesh-size fabric modes that "
         "crumple a canopy\n"
      << "slack_events = false   # locating each slack/taut switch of hundreds of lines costs "
         "thousands of cut steps\n"
      << "slider_events = false   # Bossak: grommets pass line nodes inside the Newton solve (no "
         "micro-steps)\n";
  f << "\n";
}

void writeOutput(std::ostream& f, const CaseContext& c, const std::string& name) {
  f << "[output]\ninterval = " << num(c.o.probeInterval) << "   # a probes.csv row every "
    << num(c.o.probeInterval) << " s\n\n";
  if (c.o.vtuInterval > 0)
    f << "[output.vtu]   # the ParaView series (" << name
      << ".pvd)\ninterval = " << num(c.o.vtuInterval)
      << "\nfields = [\"displacement\", \"velocity\"]\n\n";
  const char* top = c.spec.ventDiameter > 0 ? "vent_band" : "apex";
  f << "[[output.probes]]   # inflation: mean / min / max skirt distance from the axis\n"
       "name = \"skirt\"\nkind = \"skirt_radius\"\nset = \"skirt_points\"\naxis = "
       "[\"confluence\", \""
    << top << "\"]\n\n";
  if (!c.legacyPressure) {
    f << "[[output.probes]]   # volume, projected diameter, pressures, airspeed, descent, swing\n"
         "name = \"canopy\"\nkind = \"canopy\"\nmembranes = \"canopy\"\n\n";
    if (c.held) {
      f << "[[output.probes]]   # the force the held parachute puts on its support\n"
           "name = \"opening_force\"\nkind = \"support_force\"\n";
      if (!c.payload || (!c.risers && !c.spec.hasBox()))
        f << "nodes = [\"confluence\"]\n\n";
      else
        f << "set = \"payload\"\n\n";
    } else {
      f << "[[output.probes]]   # the suspension lines' pull on the confluence: the opening "
           "force\nname = \"opening_force\"\nkind = \"line_pull\"\nnode = \"confluence\"\nsets = [";
      for (size_t i = 0; i < c.lineSets.size(); ++i)
        f << (i ? ", " : "") << "\"" << c.lineSets[i] << "\"";
      f << "]\n\n";
    }
    f << "[[output.probes]]   # the most loaded line element\nname = \"line_max\"\n"
         "kind = \"line_force_max\"\n\n";
  }
  if (c.spec.hasSlider())
    f << "[[output.probes]]   # the slider's way down line 0 (s from the skirt end)\n"
         "name = \"slider_0\"\nkind = \"slider\"\ngroup = \"line_0\"\n\n";
  f << "[[output.probes]]   # tension in line 0\nname = \"line_0\"\nkind = \"line_force\"\nset = \""
    << c.lineSets[0] << "\"\nelement = 0\n\n";
  if (c.risers)
    f << "[[output.probes]]   # tension in a riser\nname = \"riser\"\nkind = \"line_force\"\n"
         "set = \"risers\"\nelement = 0\n\n";
  f << "[[output.probes]]   # kinetic and strain energy\nname = \"energy\"\nkind = \"energy\"\n";
}

}  // namespace

void writeParachuteCase(const ParachuteSpec& spec, const GeneratedParachute& generated,
                        const std::string& caseFile, const std::string& msh,
                        const ParachuteCaseOptions& o) {
  checkParachuteCaseOptions(o);
  CaseContext c(spec, generated.mesh, o);
  c.si = o.units == "si";
  c.lu = c.si ? "m" : "ft";
  c.pu = c.si ? "Pa" : "psf";
  c.su = c.lu + "/s";
  c.risers = c.mesh.group("risers", 1) != nullptr;
  c.payload = c.mesh.group("payload", 0);
  c.legacyPressure = !std::isnan(o.pressure);
  c.held = o.held;
  if (c.legacyPressure) {
    c.pressure = o.pressure;
    c.speed = std::sqrt(2.0 * std::abs(c.pressure) / c.mat.airDensity);  // q = rho V^2 / 2
  } else {
    c.speed = std::isnan(o.speed) ? c.mat.defaultSpeed : o.speed;
  }
  namespace fs = std::filesystem;
  const fs::path dir = fs::absolute(caseFile).parent_path();
  const std::string mshRef = fs::relative(fs::absolute(msh), dir).generic_string();
  const std::string name = caseNameOf(caseFile, "parachute");

  std::ostringstream f;
  writeHeader(f, c, generated, caseFile, msh, name);
  f << "[mesh]\nfile = " << tomlString(mshRef, "--out") << "\n";
  if (c.mesh.views.count("initial_displacement"))
    f << "initial_displacement = \"initial_displacement\"   # the " << spec.start
      << " start; the reference is the flat pattern\n";
  writeMaterials(f, c);
  writeElements(f, c);
  writeFrame(f, c);
  writeLoads(f, c);
  writeSolver(f, c);
  writeOutput(f, c, name);

  std::ofstream file(caseFile);
  if (!file) throw std::runtime_error(caseFile + ": cannot write the case file");
  file << f.str();
  if (!file) throw std::runtime_error(caseFile + ": write failed");
}

}  // namespace chute::mesh
