// Bad input, table-driven (issue 9, item 1): every row is a small case file (a valid base case
// with one edit, or a whole text) or a `--set`, the fragment the message must contain and the
// line it must name. Each row is read with readCase from a file in a temporary directory; the
// message must be ONE line "file:line: key: reason" (or "--set k=v: key: reason"), and nothing
// but a CaseError may come out. A sample of rows also goes through the real `chute run`: exit
// status 2, one line on stderr, no output directory. The counts per kind are printed at the end
// (the issue's closing table).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "case/CaseError.hpp"
#include "case/CaseSpec.hpp"

namespace fs = std::filesystem;
using namespace chute;

namespace {

// A small valid case with a cable, a sliding group, a membrane, a point mass and a probe.
const std::string kBase = R"(name = "base"

[nodes]
a = [0.0, 0.0, 0.0]
b = [2.0, 0.0, 0.0]
s = [1.0, 0.0, -0.5]
c = [0.0, 1.0, 0.0]
d = [1.0, 1.0, 0.0]
e = [0.0, 2.0, 0.0]
f = [1.0, 2.0, 0.0]

[materials.rope]
kind = "cable"
E = 1.0e6
area = 1.0e-3
density = 1.0

[materials.film]
kind = "membrane"
E = 1.0e5
nu = 0.3
thickness = 1.0e-3
density = 0.5

[[cables]]
name = "tether"
material = "rope"
path = ["a", "c"]

[[sliding_groups]]
name = "loop"
material = "rope"
path = ["a", "s", "b"]
sliders = ["s"]
elements = 3

[[membranes]]
name = "patch"
material = "film"
mesh = "elements"
triangles = [["c", "d", "e"]]
quads = [["d", "f", "e", "c"]]

[[point_masses]]
node = "s"
mass = 1.0

[boundary]
fixed = ["a", "b"]

[loads]
gravity = [0.0, 0.0, -9.81]

[solver]
type = "dynamic"
dt = 1.0e-3
t_end = 0.01
rho_inf = 0.9

[output]
interval = 0.005

[[output.probes]]
name = "slider"
kind = "node_position"
node = "s"
)";

std::string edited(std::string t, const std::string& from, const std::string& to) {
  const auto at = t.find(from);
  if (at == std::string::npos) throw std::logic_error("test table: '" + from + "' not in base");
  return t.replace(at, from.size(), to);
}
std::string replaced(const std::string& from, const std::string& to) {
  return edited(kBase, from, to);
}
std::string appended(const std::string& text) {
  return kBase + text;
}

struct Row {
  std::string kind;
  std::string text;               // the case file
  std::vector<std::string> sets;  // --set overrides
  std::string fragment;           // the message must contain this
  std::string lineOf;             // the line named: where this text first appears; "" = none
  int line = 0;                   // or this line number (when lineOf is empty)
};

// Kinds (the closing table's rows).
const char* kSyntax = "malformed TOML";
const char* kFile = "missing or unreadable file";
const char* kUnknownKey = "unknown key (did-you-mean)";
const char* kType = "wrong type";
const char* kRange = "out-of-range value";
const char* kPhysical = "zero/negative length, area, thickness, density, E";
const char* kNonFinite = "NaN/Inf value";
const char* kMissing = "missing required key";
const char* kReference = "node/material/set name that does not exist";
const char* kDuplicate = "duplicated name";
const char* kSlider = "sliding group: slider not on its active element";
const char* kEmpty = "empty set";
const char* kDegenerate = "degenerate element";
const char* kSize = "size beyond the limit (memory)";
const char* kSet = "--set path or value";
const char* kUnused = "key the chosen variant does not use";
const char* kMesh = "mesh: physical group missing or of the wrong dimension, mesh file";

// The gmsh example (mesh/examples/flat_canopy.toml over flat_canopy.msh) with one
// edit: physical-group errors belong to the [mesh] import.
std::vector<Row> meshRows() {
  const std::string dir = std::string(CHUTE_SOURCE_DIR) + "/mesh/examples/";
  std::ifstream in(dir + "flat_canopy.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string base = ss.str();
  const std::string file = "file = \"flat_canopy.msh\"";
  base.replace(base.find(file), file.size(), "file = \"" + dir + "flat_canopy.msh\"");
  auto edit = [&](const std::string& from, const std::string& to) {
    std::string t = base;
    const auto at = t.find(from);
    if (at == std::string::npos)
      throw std::logic_error("test table: '" + from + "' not in example");
    return t.replace(at, from.size(), to);
  };
  return {
      {kMesh,
       edit("group = \"canopy\"", "group = \"canpy\""),
       {},
       "membranes[0].group: no physical group 'canpy'",
       "group = \"canpy\""},
      {kMesh,
       edit("group = \"lines\"", "group = \"canopy\" # wrong"),
       {},
       "cables[0].group: physical group 'canopy'",
       "# wrong"},
      {kMesh, edit(dir + "flat_canopy.msh", dir + "no_such.msh"), {}, "mesh.file:", "file = "},
  };
}

std::vector<Row> rows() {
  const std::string fixedLine = "fixed = [\"a\", \"b\"]";
  return {
      // ---- malformed TOML: one line with file and line, never toml11's multi-line report
      {kSyntax, replaced("dt = 1.0e-3", "dt = "), {}, "malformed TOML: missing value", "dt = "},
      {kSyntax,
       replaced("rho_inf = 0.9", "rho_inf = 0.9\ndt = 2.0"),
       {},
       "already exists",
       "dt = 2.0"},
      {kSyntax, appended("[solver] # again\n"), {}, "already exists", "[solver] # again"},
      {kSyntax,
       replaced("kind = \"cable\"", "kind = \"cable"),
       {},
       "malformed TOML",
       "kind = \"cable"},
      {kSyntax,
       replaced("path = [\"a\", \"c\"]", "path = [\"a\", \"c\""),
       {},
       "missing array separator",
       "[[sliding_groups]]"},  // toml11 notices at the next token
      {kSyntax, replaced("node = \"s\"", "node = \"s\xff\""), {}, "utf8", "node = \"s"},
      {kSyntax, replaced("E = 1.0e6", "E = 1.0.0"), {}, "malformed TOML", "E = 1.0.0"},
      {kSyntax, replaced("area = 1.0e-3", "area 1.0e-3"), {}, "malformed TOML", "area 1.0e-3"},
      {kSyntax,
       replaced("[materials.rope]", "[materials.rope"),
       {},
       "malformed TOML",
       "[materials.rope\n"},
      {kSyntax,
       replaced("name = \"tether\"", "name = \"te\\qther\""),
       {},
       "malformed TOML",
       "name = \"te"},
      {kSyntax, std::string("\0\0\0", 3), {}, "malformed TOML", "", 1},
      // ---- unknown keys, with a did-you-mean from the keys of that table
      {kUnknownKey,
       replaced("[solver]", "[solvr]"),
       {},
       "solvr: unknown key (did you mean 'solver'",
       "[solvr]"},
      {kUnknownKey,
       replaced("t_end = 0.01", "t_end = 0.01\ndtt = 1.0"),
       {},
       "solver.dtt: unknown key (did you mean 'dt'?)",
       "dtt = 1.0"},
      {kUnknownKey,
       appended("[[loads.face_drag]]\nmembranes = \"patch\"\ncd = 1.0\nair_density = 1.2\n"
                "subtract_stedy = true\n"),
       {},
       "loads.face_drag[0].subtract_stedy: unknown key (did you mean 'subtract_steady'?)",
       "subtract_stedy"},
      {kUnknownKey,
       replaced("E = 1.0e6", "EE = 1.0e6"),
       {},
       "materials.rope.EE: unknown key (did you mean 'E'?",
       "EE = 1.0e6"},
      {kUnknownKey,
       replaced("kind = \"node_position\"\nnode = \"s\"",
                "kind = \"node_position\"\nnode = \"s\"\nnodee = \"a\""),
       {},
       "output.probes[0].nodee: unknown key (did you mean 'node'?)",
       "nodee"},
      {kUnknownKey,
       replaced("mesh = \"elements\"", "mesh = \"elements\"\nwrinkle = false"),
       {},
       "membranes[0].wrinkle: unknown key (did you mean 'wrinkling'?)",
       "wrinkle ="},
      {kUnknownKey,
       replaced(fixedLine, "fixd = [\"a\", \"b\"]"),
       {},
       "boundary.fixd: unknown key (did you mean 'fixed'?)",
       "fixd"},
      {kUnknownKey,
       replaced("gravity =", "gravty ="),
       {},
       "loads.gravty: unknown key (did you mean 'gravity'?)",
       "gravty"},
      {kUnknownKey,
       replaced("path = [\"a\", \"c\"]", "path = [\"a\", \"c\"]\nelement_per_segment = 2"),
       {},
       "cables[0].element_per_segment: unknown key (did you mean 'elements_per_segment'?)",
       "element_per_segment"},
      {kUnknownKey,
       replaced("sliders = [\"s\"]", "slider = [\"s\"]"),
       {},
       "sliding_groups[0].slider: unknown key (did you mean 'sliders'?",
       "slider = "},
      {kUnknownKey,
       appended("[output.vtu]\nevry = 2\n"),
       {},
       "output.vtu.evry: unknown key (did you mean 'every'?)",
       "evry"},
      {kUnknownKey,
       appended("[[pointmasses]]\nnode = \"s\"\nmass = 1.0\n"),
       {},
       "pointmasses: unknown key (did you mean 'point_masses'?)",
       "[[pointmasses]]"},
      {kUnknownKey,
       replaced("rho_inf = 0.9", "rho_inf = 0.9\nbanana = 1"),
       {},
       "solver.banana: unknown key",
       "banana"},
      // ---- keys of the schema that the chosen variant does not use
      {kUnused,
       replaced("type = \"dynamic\"", "type = \"static\""),
       {},
       "solver.dt: not used by static runs (type = \"static\")",
       "dt = 1.0e-3"},
      {kUnused,
       replaced("mesh = \"elements\"", "mesh = \"elements\"\nradius = 1.0"),
       {},
       "membranes[0].radius: not used with mesh = \"elements\"",
       "radius = 1.0"},
      {kUnused,
       appended("[[output.probes]]\nname = \"E\"\nkind = \"energy\"\nnode = \"d\"\n"),
       {},
       "output.probes[1].node: not used by a probe of kind \"energy\"",
       "node = \"d\""},
      {kUnused,
       appended("[[membranes]]\nname = \"sheet\"\nmaterial = \"film\"\nmesh = \"rectangle\"\n"
                "size = [1.0, 1.0, 0.0]\ndivisions = [2, 2]\nbulge_extent = [0.5, 0.5, 0.0]\n"),
       {},
       "membranes[1].bulge_extent: not used without bulge",
       "bulge_extent"},
      // ---- wrong types
      {kType,
       replaced("dt = 1.0e-3", "dt = \"1.0e-3\""),
       {},
       "solver.dt: expected a number, found a string",
       "dt = \"1.0e-3\""},
      {kType,
       replaced("E = 1.0e6", "E = true"),
       {},
       "materials.rope.E: expected a number",
       "E = true"},
      {kType,
       replaced("path = [\"a\", \"c\"]", "path = \"a\""),
       {},
       "cables[0].path: expected an array of strings",
       "path = \"a\""},
      {kType,
       replaced("sliders = [\"s\"]", "sliders = [1]"),
       {},
       "sliding_groups[0].sliders: expected a string",
       "sliders = [1]"},
      {kType,
       replaced("a = [0.0, 0.0, 0.0]", "a = [0.0, 0.0]"),
       {},
       "nodes.a: expected an array of 3 numbers",
       "a = [0.0, 0.0]"},
      {kType,
       replaced("b = [2.0, 0.0, 0.0]", "b = [2.0, \"0\", 0.0]"),
       {},
       "nodes.b: expected a number, found a string",
       "b = [2.0,"},
      {kType,
       replaced("elements = 3", "elements = 3.0"),
       {},
       "sliding_groups[0].elements: expected an integer, found a float",
       "elements = 3.0"},
      {kType,
       replaced("mesh = \"elements\"", "mesh = \"elements\"\nwrinkling = 1"),
       {},
       "membranes[0].wrinkling: expected true or false",
       "wrinkling = 1"},
      {kType,
       "solver = 3\n" +
           replaced("[solver]\ntype = \"dynamic\"\ndt = 1.0e-3\nt_end = 0.01\nrho_inf = 0.9\n", ""),
       {},
       "solver: expected a table, found an integer",
       "solver = 3"},
      {kType,
       "materials.rope = 5\n" +
           replaced("[materials.rope]\nkind = \"cable\"\nE = 1.0e6\narea = 1.0e-3\ndensity = 1.0\n",
                    ""),
       {},
       "materials.rope: expected a table",
       "materials.rope = 5"},
      {kType,
       replaced("triangles = [[\"c\", \"d\", \"e\"]]", "triangles = [\"c\", \"d\", \"e\"]"),
       {},
       "membranes[0].triangles: each element needs 3 node names",
       "triangles ="},
      {kType,
       replaced("name = \"base\"", "name = 1979-05-27"),
       {},
       "name: expected a string",
       "name = 1979"},
      // ---- out-of-range values
      {kRange,
       replaced("nu = 0.3", "nu = 0.5"),
       {},
       "materials.film.nu: must be in [0, 0.5)",
       "nu = 0.5"},
      {kRange,
       replaced("nu = 0.3", "nu = -0.1"),
       {},
       "materials.film.nu: must be in [0, 0.5)",
       "nu = -0.1"},
      {kRange,
       replaced("rho_inf = 0.9", "rho_inf = 1.5"),
       {},
       "solver.rho_inf: must be in [0, 1]",
       "rho_inf = 1.5"},
      {kRange,
       replaced("rho_inf = 0.9", "rho_inf = -0.1"),
       {},
       "solver.rho_inf: must be in [0, 1]",
       "rho_inf = -0.1"},
      {kRange, replaced("dt = 1.0e-3", "dt = 0"), {}, "solver.dt: must be > 0", "dt = 0"},
      {kRange, replaced("dt = 1.0e-3", "dt = -1.0e-3"), {}, "solver.dt: must be > 0", "dt = -1"},
      {kRange, replaced("t_end = 0.01", "t_end = 0.0"), {}, "solver.t_end: must be > 0", "t_end"},
      {kRange,
       replaced("t_end = 0.01", "t_end = 0.01\ndt_min = 0.1"),
       {},
       "solver.dt_min: must not exceed dt",
       "dt_min"},
      {kRange,
       replaced("elements = 3", "elements = 0"),
       {},
       "sliding_groups[0].elements: must be in [1",
       "elements = 0"},
      {kRange,
       replaced("elements = 3", "elements = -3"),
       {},
       "sliding_groups[0].elements: must be in [1",
       "elements = -3"},
      {kRange,
       replaced("t_end = 0.01", "t_end = 0.01\nnewton_max_iterations = 0"),
       {},
       "solver.newton_max_iterations: must be in [1, 1000]",
       "newton_max"},
      {kRange,
       replaced("type = \"dynamic\"\ndt = 1.0e-3\nt_end = 0.01\nrho_inf = 0.9",
                "type = \"static\"\ninitial_load_factor = 2.0"),
       {},
       "solver.initial_load_factor: must be in (0, 1]",
       "initial_load"},
      {kReference,
       appended("[[output.probes]]\nname = \"S\"\nkind = \"membrane_stress\"\nnode = \"a\"\n"),
       {},
       "output.probes[1].node: node 'a' is on no membrane element",
       "node = \"a\""},
      {kReference,
       appended("[[loads.pressure]]\nmembranes = \"Patch\"\npressure = 1.0\n"),
       {},
       "unknown membrane set 'Patch' (did you mean 'patch'? known: patch)",
       "membranes = \"Patch\""},
      {kReference,
       replaced("kind = \"node_position\"\nnode = \"s\"",
                "kind = \"node_position\"\nnode = \"ss\""),
       {},
       "unknown node 'ss' (did you mean 's'?",
       "node = \"ss\""},
      {kUnused,
       replaced("t_end = 0.01", "t_end = 0.01\nload_steps = 3"),
       {},
       "solver.load_steps: not used by dynamic runs",
       "load_steps"},
      {kRange,
       replaced("path = [\"a\", \"c\"]", "path = [\"a\", \"c\"]\nprestrain = -1.0"),
       {},
       "cables[0].prestrain: must be > -1",
       "prestrain"},
      {kRange,
       replaced("rho_inf = 0.9", "rho_inf = 0.9\nintegrator = \"euler\""),
       {},
       "solver.integrator: \"euler\" is not one of \"bossak\", \"generalized_alpha\"",
       "integrator"},
      {kRange,
       replaced("rho_inf = 0.9",
                "rho_inf = 0.9\nintegrator = \"generalized_alpha\"\nslider_events = false"),
       {},
       "solver.slider_events: false needs integrator = \"bossak\"",
       "slider_events"},
      {kRange,
       replaced("kind = \"cable\"", "kind = \"chain\""),
       {},
       "materials.rope.kind: \"chain\" is not one of",
       "kind = \"chain\""},
      {kRange,
       appended("[[boundary.constraints]]\nnodes = [\"s\"]\ndofs = \"xw\"\n"),
       {},
       "boundary.constraints[0].dofs: expected a combination of x, y, z",
       "dofs = \"xw\""},
      {kRange,
       replaced("interval = 0.005", "every = 0"),
       {},
       "output.every: must be in [1,",
       "every = 0"},
      {kRange,
       appended(
           "[[output.probes]]\nname = \"N\"\nkind = \"line_force\"\nset = \"loop\"\nelement = 3\n"),
       {},
       "output.probes[1].element: must be in [0, 2]",
       "element = 3"},
      {kRange,
       replaced("interval = 0.005", "interval = 0.005\nevery = 2"),
       {},
       "output.every: give either every or interval",
       "every = 2"},
      {kRange,
       replaced("t_end = 0.01", "t_end = 0.01\nmass_damping = -1.0"),
       {},
       "solver.mass_damping: must be >= 0",
       "mass_damping"},
      {kRange,
       replaced("t_end = 0.01", "t_end = 0.01\nmass_damping = 1.7976931348623157e308"),
       {},
       "solver.mass_damping: must be at most 1e12",
       "mass_damping"},
      // ---- zero or negative physical quantities
      {kPhysical, replaced("E = 1.0e6", "E = 0.0"), {}, "materials.rope.E: must be > 0", "E = 0.0"},
      {kRange,
       replaced("E = 1.0e6", "E = 1.0e6\ncompression_stiffness_ratio = 1e300"),
       {},
       "materials.rope.compression_stiffness_ratio: must be in [0, 1]",
       "compression_stiffness_ratio"},
      {kPhysical,
       replaced("area = 1.0e-3", "area = -1.0e-3"),
       {},
       "materials.rope.area: must be > 0",
       "area = -1"},
      {kPhysical,
       replaced("thickness = 1.0e-3", "thickness = 0"),
       {},
       "materials.film.thickness: must be > 0",
       "thickness = 0"},
      {kPhysical,
       replaced("density = 1.0", "density = -1.0"),
       {},
       "materials.rope.density: must be >= 0",
       "density = -1.0"},
      {kPhysical,
       replaced("density = 0.5", "density = -0.5"),
       {},
       "materials.film.density: must be >= 0",
       "density = -0.5"},
      {kPhysical,
       replaced("E = 1.0e5", "E = -1.0e5"),
       {},
       "materials.film.E: must be > 0",
       "E = -1.0e5"},
      {kPhysical,
       replaced("mass = 1.0", "mass = 0.0"),
       {},
       "point_masses[0].mass: must be > 0",
       "mass = 0.0"},
      {kPhysical,
       appended("[[membranes]]\nname = \"disk\"\nmaterial = \"film\"\nradius = 0.0\n"),
       {},
       "membranes[1].radius: must be > 0",
       "radius = 0.0"},
      {kPhysical,
       appended("[[membranes]]\nname = \"sheet\"\nmaterial = \"film\"\nmesh = \"rectangle\"\n"
                "size = [0.0, 1.0, 0.0]\ndivisions = [2, 2]\n"),
       {},
       "membranes[1].size: needs positive x and y extents",
       "size = [0.0"},
      {kPhysical,
       appended("[[membranes]]\nname = \"sheet\"\nmaterial = \"film\"\nmesh = \"rectangle\"\n"
                "size = [1.0, 1.0, 0.0]\ndivisions = [2, 2]\nbulge = 0.1\n"
                "bulge_centre = [0.5, 0.5, 0.0]\nbulge_extent = [0.0, 0.5, 0.0]\n"),
       {},
       "membranes[1].bulge_extent: needs positive x and y extents",
       "bulge_extent"},
      {kPhysical,
       appended("[[loads.drag]]\nset = \"tether\"\ndiameter = 0.0\ncd = 1.0\nair_density = 1.2\n"),
       {},
       "loads.drag[0].diameter: must be > 0",
       "diameter = 0.0"},
      {kPhysical,
       appended(
           "[[loads.drag]]\nset = \"tether\"\ndiameter = 0.01\ncd = 1.0\nair_density = -1.2\n"),
       {},
       "loads.drag[0].air_density: must be > 0",
       "air_density"},
      // [contact] (docs/contact.md): a thickness the mesh's own neighbours would violate at rest
      // (CT11), a set that does not exist, a negative coefficient, a misspelt key.
      {kRange,
       appended("[contact]\nthickness = 0.4\n"),
       {},
       "contact.thickness: contact thickness 0.4 is not below half the smallest altitude",
       "thickness = 0.4"},
      {kMissing,
       appended("[contact]\nmembranes = [\"pach\"]\n"),
       {},
       "contact.membranes: unknown membrane set 'pach'",
       "membranes = [\"pach\"]"},
      {kPhysical,
       appended("[contact]\nfriction = -0.2\n"),
       {},
       "contact.friction: must be >= 0",
       "friction = -0.2"},
      {kUnknownKey,
       appended("[contact]\nthicknes = 0.01\n"),
       {},
       "contact.thicknes: unknown key (did you mean 'thickness'?)",
       "thicknes = 0.01"},
      {kPhysical,
       appended("[[loads.face_drag]]\nmembranes = \"patch\"\ncd = -1.0\nair_density = 1.2\n"),
       {},
       "loads.face_drag[0].cd: must be > 0",
       "cd = -1.0"},
      {kPhysical,
       appended("[[loads.face_drag]]\nmembranes = \"patch\"\ncd = 1.0\nair_density = nan\n"),
       {},
       "loads.face_drag[0].air_density: must be finite",
       "air_density = nan"},
      {kRange,
       replaced("b = [2.0, 0.0, 0.0]", "b = [2.0e200, 0.0, 0.0]"),
       {},
       "nodes.b: coordinates beyond +-1e100",
       "b = [2.0e200"},
      {kRange,
       appended("[[membranes]]\nname = \"disk\"\nmaterial = \"film\"\nradius = 1e300\n"),
       {},
       "membranes[1].radius: lengths beyond 1e100",
       "radius = 1e300"},
      {kRange,
       replaced("name = \"tether\"", "name = \"teth.er\""),
       {},
       "cables[0].name: cannot contain '.'",
       "name = \"teth.er\""},
      // ---- NaN and Inf (TOML has nan and inf literals)
      {kNonFinite,
       replaced("dt = 1.0e-3", "dt = nan"),
       {},
       "solver.dt: must be finite",
       "dt = nan"},
      {kNonFinite,
       replaced("E = 1.0e6", "E = inf"),
       {},
       "materials.rope.E: must be finite",
       "E = inf"},
      {kNonFinite,
       replaced("E = 1.0e5", "E = -inf"),
       {},
       "materials.film.E: must be finite",
       "E = -inf"},
      {kNonFinite,
       replaced("a = [0.0, 0.0, 0.0]", "a = [nan, 0.0, 0.0]"),
       {},
       "nodes.a: must be finite",
       "a = [nan"},
      {kNonFinite,
       replaced("gravity = [0.0, 0.0, -9.81]", "gravity = [0.0, 0.0, -inf]"),
       {},
       "loads.gravity: must be finite",
       "gravity"},
      {kNonFinite,
       replaced("nu = 0.3", "nu = nan"),
       {},
       "materials.film.nu: must be finite",
       "nu = nan"},
      {kNonFinite,
       replaced("rho_inf = 0.9", "rho_inf = +nan"),
       {},
       "solver.rho_inf: must be finite",
       "rho_inf"},
      {kNonFinite,
       replaced("mass = 1.0", "mass = inf"),
       {},
       "point_masses[0].mass: must be finite",
       "mass = inf"},
      {kNonFinite,
       appended("[[loads.pressure]]\nmembranes = \"patch\"\npressure = nan\n"),
       {},
       "loads.pressure[0].pressure: must be finite",
       "pressure = nan"},
      {kNonFinite,
       appended("[[loads.pressure]]\nmembranes = \"patch\"\npressure = 1.0\n"
                "element_factors = [1.0, inf]\n"),
       {},
       "loads.pressure[0].element_factors: must be finite",
       "element_factors"},
      {kNonFinite,
       replaced("interval = 0.005", "interval = inf"),
       {},
       "output.interval: must be finite",
       "interval = inf"},
      // ---- missing required keys (named at the line of their table)
      {kMissing,
       replaced("E = 1.0e6\n", ""),
       {},
       "materials.rope.E: required key is missing",
       "[materials.rope]"},
      {kMissing,
       replaced("dt = 1.0e-3\n", ""),
       {},
       "solver.dt: required key is missing",
       "[solver]"},
      {kMissing,
       replaced("material = \"rope\"\npath = [\"a\", \"c\"]", "path = [\"a\", \"c\"]"),
       {},
       "cables[0].material: required key is missing",
       "[[cables]]"},
      {kMissing,
       replaced("[solver]\ntype = \"dynamic\"\ndt = 1.0e-3\nt_end = 0.01\nrho_inf = 0.9\n", ""),
       {},
       "solver: required key is missing",
       "",
       1},
      // ---- names that do not exist
      {kReference,
       replaced("path = [\"a\", \"c\"]", "path = [\"a\", \"zz\"]"),
       {},
       "cables[0].path: unknown node 'zz'",
       "path = [\"a\", \"zz\"]"},
      {kReference,
       replaced("sliders = [\"s\"]", "sliders = [\"zz\"]"),
       {},
       "sliding_groups[0].sliders: unknown node 'zz'",
       "sliders = [\"zz\"]"},
      {kReference,
       replaced(fixedLine, "fixed = [\"a\", \"zz\"]"),
       {},
       "boundary.fixed: unknown node 'zz'",
       "fixed = [\"a\", \"zz\"]"},
      {kReference,
       replaced("node = \"s\"\nmass", "node = \"zz\"\nmass"),
       {},
       "point_masses[0].node: unknown node 'zz'",
       "node = \"zz\""},
      {kReference,
       replaced("kind = \"node_position\"\nnode = \"s\"",
                "kind = \"node_position\"\nnode = \"zz\""),
       {},
       "output.probes[0].node: unknown node 'zz'",
       "node = \"zz\""},
      {kReference,
       replaced("[[\"c\", \"d\", \"e\"]]", "[[\"c\", \"d\", \"zz\"]]"),
       {},
       "membranes[0].triangles: unknown node 'zz'",
       "\"zz\"]]"},
      {kReference,
       replaced("material = \"rope\"\npath = [\"a\", \"c\"]",
                "material = \"rop\"\npath = [\"a\", \"c\"]"),
       {},
       "cables[0].material: unknown material 'rop' (did you mean 'rope'?",
       "\"rop\""},
      {kReference,
       replaced("material = \"film\"", "material = \"rope\""),
       {},
       "membranes[0].material: no membrane material 'rope'",
       "material = \"rope\"\nmesh"},
      {kReference,
       replaced("material = \"rope\"\npath = [\"a\", \"c\"]",
                "material = \"film\"\npath = [\"a\", \"c\"]"),
       {},
       "cables[0].material: 'film' is a membrane material",
       "material = \"film\"\npath"},
      {kReference,
       appended("[[output.probes]]\nname = \"p\"\nkind = \"slider\"\ngroup = \"lop\"\n"),
       {},
       "output.probes[1].group: unknown sliding group 'lop'",
       "group = \"lop\""},
      {kReference,
       appended("[[loads.drag]]\nset = \"teher\"\ndiameter = 0.01\ncd = 1.0\nair_density = 1.2\n"),
       {},
       "loads.drag[0].set: unknown cable set or sliding group 'teher'",
       "set = \"teher\""},
      {kReference,
       appended("[[loads.face_drag]]\nmembranes = \"ptch\"\ncd = 1.0\nair_density = 1.2\n"),
       {},
       "loads.face_drag[0].membranes: unknown membrane set 'ptch'",
       "membranes = \"ptch\""},
      {kReference,
       appended("[[loads.pressure]]\nmembranes = \"ptch\"\npressure = 1.0\n"),
       {},
       "loads.pressure[0].membranes: unknown membrane set 'ptch'",
       "membranes = \"ptch\""},
      {kReference,
       appended("[[boundary.constraints]]\nset = \"rim\"\ndofs = \"z\"\n"),
       {},
       "boundary.constraints[0].set: unknown node set 'rim'",
       "set = \"rim\""},
      {kReference,
       appended("[reference]\nkind = \"free_fall\"\nprobe = \"bead\"\n"),
       {},
       "reference.probe: no node_position probe named 'bead'",
       "probe = \"bead\""},
      {kReference,
       appended(
           "[[loads.drag]]\nedge = \"patch.rim\"\ndiameter = 0.01\ncd = 1.0\nair_density = 1.2\n"),
       {},
       "loads.drag[0].edge: no node set 'patch.rim'",
       "edge = "},
      // ---- duplicated names
      {kDuplicate,
       replaced("name = \"loop\"", "name = \"tether\""),
       {},
       "sliding_groups[0].name: duplicate name: 'tether' is already a cable set",
       "name = \"tether\"\nmaterial = \"rope\"\npath = [\"a\", \"s\""},
      {kDuplicate,
       replaced("name = \"patch\"", "name = \"loop\""),
       {},
       "membranes[0].name: duplicate name: 'loop' is already a sliding group",
       "name = \"loop\"\nmaterial = \"film\""},
      {kDuplicate,
       appended("[[cables]]\nname = \"tether\"\nmaterial = \"rope\"\npath = [\"b\", \"d\"]\n"),
       {},
       "cables[1].name: duplicate name: 'tether'",
       "name = \"tether\"\nmaterial = \"rope\"\npath = [\"b\""},
      {kDuplicate,
       appended("[[output.probes]]\nname = \"slider\"\nkind = \"energy\"\n"),
       {},
       "output.probes[1].name: duplicate probe name 'slider'",
       "name = \"slider\"\nkind = \"energy\""},
      {kDuplicate,
       replaced("sliders = [\"s\"]", "sliders = [\"s\", \"s\"]"),
       {},
       "sliding_groups[0].sliders: a slider is listed twice",
       "sliders = [\"s\", \"s\"]"},
      {kDuplicate,
       replaced("f = [1.0, 2.0, 0.0]", "f = [1.0, 2.0, 0.0]\nd = [3.0, 3.0, 3.0]"),
       {},
       "already exists",
       "d = [3.0"},
      {kDuplicate,
       appended("[materials.rope]\nE = 1.0\narea = 1.0\n"),
       {},
       "already exists",
       "[materials.rope]\nE = 1.0\n"},
      // ---- sliding groups whose slider is not on its initially active element
      {kSlider,
       replaced("elements = 3", "elements = 3\nactive = [0]"),
       {},
       "sliding_groups[0].active: slider 's' is not on element 0",
       "active = [0]"},
      {kSlider,
       replaced("elements = 3", "elements = 3\nactive = [7]"),
       {},
       "sliding_groups[0].active: element 7 out of range [0, 2]",
       "active = [7]"},
      {kSlider,
       replaced("elements = 3", "elements = 3\nactive = [-1]"),
       {},
       "sliding_groups[0].active: element -1 out of range",
       "active = [-1]"},
      {kSlider,
       replaced("elements = 3", "elements = 3\nactive = [1, 2]"),
       {},
       "sliding_groups[0].active: needs one element index per slider (1)",
       "active = [1, 2]"},
      {kSlider,
       replaced("path = [\"a\", \"s\", \"b\"]\nsliders = [\"s\"]",
                "path = [\"a\", \"b\"]\nsliders = [\"s\"]"),
       {},
       "sliding_groups[0].active: slider 's' is not on the path",
       "[[sliding_groups]]"},
      {kSlider,
       replaced("path = [\"a\", \"s\", \"b\"]\nsliders = [\"s\"]\nelements = 3",
                "path = [\"a\", \"b\"]\nsliders = [\"s\"]\nelements = 3\nactive = [1]"),
       {},
       "sliding_groups[0].active: slider 's' is not on element 1",
       "active = [1]"},
      {kSlider,
       replaced("path = [\"a\", \"s\", \"b\"]", "path = [\"a\", \"s\", \"d\", \"b\"]"),
       {},
       "sliding_groups[0].path: interior path node 'd' is not a slider",
       "path = [\"a\", \"s\", \"d\""},
      {kSlider,
       replaced("sliders = [\"s\"]", "sliders = [\"s\", \"b\"]"),
       {},
       "sliding_groups[0].path: the chain's end nodes cannot be sliders",
       "path = [\"a\", \"s\", \"b\"]"},
      {kSlider,
       replaced("sliders = [\"s\"]\nelements = 3",
                "sliders = [\"s\", \"d\"]\nelements = 3\nactive = [1, 1]"),
       {},
       "sliding_groups[0].active: slider 'd' is not on element 1",
       "active = [1, 1]"},
      // ---- empty sets
      {kEmpty,
       "name = \"still\"\n[materials.rope]\nkind = \"cable\"\nE = 1.0e6\narea = 1.0e-3\n"
       "[nodes]\na = [0.0, 0.0, 0.0]\nb = [1.0, 0.0, 0.0]\n"
       "[[cables]]\nname = \"c\"\nmaterial = \"rope\"\npath = [\"a\", \"b\"]\n"
       "[boundary]\nfixed = [\"a\", \"b\"]\n[solver]\ndt = 0.01\nt_end = 0.1\n",
       {},
       "boundary: every degree of freedom is fixed or prescribed: there is nothing to solve",
       "[boundary]"},
      {kEmpty,
       replaced("sliders = [\"s\"]", "sliders = []"),
       {},
       "sliding_groups[0].sliders: a sliding group needs at least one slider",
       "sliders = []"},
      {kEmpty,
       replaced("path = [\"a\", \"c\"]", "path = [\"a\"]"),
       {},
       "cables[0].path: needs at least two nodes",
       "path = [\"a\"]"},
      {kEmpty,
       appended("[[boundary.constraints]]\nnodes = []\ndofs = \"z\"\n"),
       {},
       "boundary.constraints[0].nodes: give nodes = [...] or set = \"...\"",
       "nodes = []"},
      {kEmpty,
       replaced("triangles = [[\"c\", \"d\", \"e\"]]\nquads = [[\"d\", \"f\", \"e\", \"c\"]]\n",
                ""),
       {},
       "membranes[0].mesh: an \"elements\" mesh needs triangles",
       "mesh = \"elements\""},
      {kEmpty,
       replaced("triangles = [[\"c\", \"d\", \"e\"]]\nquads = [[\"d\", \"f\", \"e\", \"c\"]]\n",
                "triangles = []\n"),
       {},
       "membranes[0].mesh: an \"elements\" mesh needs triangles",
       "mesh = \"elements\""},
      {kEmpty,
       "name = \"x\"\n[solver]\ndt = 1.0\nt_end = 1.0\n",
       {},
       "nodes: the case has no nodes",
       "",
       1},
      {kEmpty,
       appended("[[loads.drag]]\nedge = \"\"\ndiameter = 0.01\ncd = 1.0\nair_density = 1.2\n"),
       {},
       "loads.drag[0].edge: no node set ''",
       "edge = "},
      {kEmpty,
       replaced("name = \"base\"", "name = \"\""),
       {},
       "name: must be a plain file name",
       "name = \"\""},
      // ---- degenerate elements
      {kDegenerate,
       replaced("path = [\"a\", \"c\"]", "path = [\"a\", \"a\"]"),
       {},
       "cables[0].path: zero-length segment between 'a' and 'a'",
       "path = [\"a\", \"a\"]"},
      {kDegenerate,
       replaced("c = [0.0, 1.0, 0.0]", "c = [0.0, 0.0, 0.0]"),
       {},
       "cables[0].path: zero-length segment between 'a' and 'c'",
       "path = [\"a\", \"c\"]"},
      {kDegenerate,
       replaced("e = [0.0, 2.0, 0.0]", "e = [2.0, 1.0, 0.0]"),
       {},
       "membranes[0].triangles: degenerate element: zero area (its nodes are collinear)",
       "triangles ="},
      {kDegenerate,
       replaced("[[\"c\", \"d\", \"e\"]]", "[[\"c\", \"d\", \"c\"]]"),
       {},
       "membranes[0].triangles: degenerate element: node 'c' appears twice",
       "triangles ="},
      {kDegenerate,
       replaced("[[\"d\", \"f\", \"e\", \"c\"]]", "[[\"d\", \"e\", \"f\", \"c\"]]"),
       {},
       "membranes[0].quads: degenerate element: zero area (its diagonals are parallel)",
       "quads ="},  // a bow-tie
      {kDegenerate,
       edited(replaced("f = [1.0, 2.0, 0.0]", "f = [1.0, 2.0, 0.0]\ng = [0.2, 1.2, 0.0]"),
              "[[\"d\", \"f\", \"e\", \"c\"]]", "[[\"c\", \"d\", \"g\", \"e\"]]"),
       {},
       "membranes[0].quads: degenerate element: not convex at node 'g'",
       "quads ="},  // a dart
      {kDegenerate,
       replaced("[[\"d\", \"f\", \"e\", \"c\"]]", "[[\"d\", \"f\", \"f\", \"c\"]]"),
       {},
       "membranes[0].quads: degenerate element: node 'f' appears twice",
       "quads ="},
      {kDegenerate,
       replaced("b = [2.0, 0.0, 0.0]\ns = [1.0, 0.0, -0.5]",
                "b = [0.0, 0.0, 0.0]\ns = [0.0, 0.0, 0.0]"),
       {},
       "sliding_groups[0].path: the path has zero length",
       "path = [\"a\", \"s\", \"b\"]"},
      // ---- sizes that would exhaust memory
      {kSize,
       replaced("elements = 3", "elements = 100000000"),
       {},
       "sliding_groups[0].elements: must be in [1, 1000000]",
       "elements = 100000000"},
      {kSize,
       appended(
           "[[membranes]]\nname = \"disk\"\nmaterial = \"film\"\nradius = 1.0\nrings = 100000\n"),
       {},
       "membranes[1].rings: would make a model of more than 1000000 nodes",
       "rings = 100000"},
      {kSize,
       appended("[[membranes]]\nname = \"sheet\"\nmaterial = \"film\"\nmesh = \"rectangle\"\n"
                "size = [1.0, 1.0, 0.0]\ndivisions = [100000, 100000]\n"),
       {},
       "membranes[1].divisions: would make a model of more than 1000000 nodes",
       "divisions ="},
      {kSize,
       appended("[[membranes]]\nname = \"sheet\"\nmaterial = \"film\"\nmesh = \"rectangle\"\n"
                "size = [1.0, 1.0, 0.0]\ndivisions = [9223372036854775807, 2]\n"),
       {},
       "membranes[1].divisions: more than 1000000 divisions",
       "divisions ="},
      // Within the node limit, beyond the equation limit: 500 x 500 divisions are 251,001 nodes
      // (753,003 equations), minutes per step.
      {kSize,
       appended("[[membranes]]\nname = \"sheet\"\nmaterial = \"film\"\nmesh = \"rectangle\"\n"
                "size = [1.0, 1.0, 0.0]\ndivisions = [500, 500]\n"),
       {},
       "solver.max_equations: the model has",
       "[solver]"},
      {kSize, kBase, {"solver.max_equations=5"}, "more than the limit 5", "[solver]"},
      {kSize,
       replaced("path = [\"a\", \"c\"]",
                "path = [\"a\", \"c\", \"d\"]\nelements_per_segment = 900000"),
       {},
       "cables[0].elements_per_segment: would make a model of more than 1000000 nodes",
       "elements_per_segment"},
      // ---- --set: paths that do not exist, wrong types, bad values
      {kSet, kBase, {"solvr.dt=1e-3"}, "has no such table (did you mean 'solver'?)", ""},
      {kSet,
       kBase,
       {"solver.dtt=1e-3"},
       "--set solver.dtt=1e-3: solver.dtt: unknown key (did you mean 'dt'?)",
       ""},
      {kSet,
       kBase,
       {"solver.dt=\"fast\""},
       "--set solver.dt=\"fast\": solver.dt: expected a number, found a string",
       ""},
      {kSet, kBase, {"solver.dt=-1"}, "--set solver.dt=-1: solver.dt: must be > 0", ""},
      {kSet, kBase, {"solver.dt=nan"}, "--set solver.dt=nan: solver.dt: must be finite", ""},
      {kSet,
       kBase,
       {"solver.dt=1e"},
       "--set solver.dt=1e: solver.dt: not a TOML value: the exponent after '1e' has no digits",
       ""},
      {kSet, kBase, {"solver.dt"}, "--set solver.dt: expected key=value", ""},
      {kSet, kBase, {"=3"}, "--set =3: expected key=value", ""},
      {kSet, kBase, {"solver..dt=1"}, "--set solver..dt=1: empty key", ""},
      {kSet, kBase, {"solver.=1"}, "--set solver.=1: empty key", ""},
      {kSet, kBase, {"solver=1"}, "--set solver=1: solver: is a table in", ""},
      {kSet,
       kBase,
       {"cables.5.name=x"},
       "--set cables.5.name=x: cables: '5' is not an index of its 1 entries",
       ""},
      {kSet, kBase, {"cables.99999999999999999999.name=x"}, "is not an index of its 1 entries", ""},
      {kSet,
       kBase,
       {"cables.name=x"},
       "--set cables.name=x: cables: an array of tables: give an index",
       ""},
      {kSet, kBase, {"solver.dt.x=1"}, "--set solver.dt.x=1: solver.dt: is not a table", ""},
      // Steps that would never end: dt lost against t_end, or a least step lost in rounding.
      {kSet,
       kBase,
       {"solver.dt=5e-324"},
       "solver.dt: t_end / dt is inf steps, more than 1e+09",
       ""},
      {kSet, kBase, {"solver.dt=1e308"}, "solver.dt: is larger than t_end: not one step fits", ""},
      {kSet,
       kBase,
       {"solver.dt_min=1e-300"},
       "solver.dt_min: the least step (dt_min = 1e-300)",
       ""},
      // An array of values takes its index last; nothing more can follow it.
      {kSet,
       kBase,
       {"boundary.fixed.0.0=1"},
       "--set boundary.fixed.0.0=1: boundary.fixed.0: is a value, not a table",
       ""},
      {kSet,
       kBase,
       {"boundary.fixed.7=\"a\""},
       "boundary.fixed: '7' is not an index of its 2 values",
       ""},
      {kSet,
       kBase,
       {"solver.dt=" + std::string(6000, '[') + std::string(6000, ']')},
       "solver.dt: nested deeper than 64 levels",
       ""},
      {kSyntax,
       "a = " + std::string(6000, '[') + std::string(6000, ']') + "\n",
       {},
       "arrays or inline tables nested deeper than 64 levels",
       "",
       1},
      // Arrays of values are set whole and judged by the reader; tables key by key.
      {kSet,
       kBase,
       {"solver.dt=[1, 2]"},
       "--set solver.dt=[1, 2]: solver.dt: expected a number",
       ""},
      {kSet,
       kBase,
       {"solver={dt = 1}"},
       "--set solver={dt = 1}: solver: a table is set one key at a time (solver.key=value)",
       ""},
      {kSet,
       kBase,
       {"boundary.fixed.0=[1]"},
       "boundary.fixed.0: an entry of an array takes a value, not an array",
       ""},
      {kSet,
       kBase,
       {"boundary.fixed=[a, b]"},
       "--set boundary.fixed=[a, b]: boundary.fixed: not a TOML value: strings in an array are "
       "quoted: '[\"a\", \"b\"]'",
       ""},
      {kSet, kBase, {"boundary.fixed=[\"a\", \"zz\"]"}, "unknown node 'zz'", ""},
      // Numbers with units: the case's numbers are plain numbers in its units.
      {kSet,
       kBase,
       {"solver.t_end=1s"},
       "--set solver.t_end=1s: solver.t_end: numbers take no units (give the number in the "
       "case's units)",
       ""},
      {kSet,
       replaced("name = \"base\"", "name = \"base\"\nunits = \"m, kg, s, N\""),
       {"solver.dt=2ms"},
       "solver.dt: numbers take no units (give 0.002 for 2ms in the case's units, m, kg, s, N)",
       ""},
      {kSet,
       replaced("name = \"base\"", "name = \"base\"\nunits = \"ft, slug, s, lbf\""),
       {"materials.film.E=200 MPa"},
       "numbers take no units (give 4.17709e+06 for 200 MPa in the case's units, ft, slug, s, lbf)",
       ""},
      {kSet,
       replaced("name = \"base\"", "name = \"base\"\nunits = \"m, kg, s, N\""),
       {"loads.gravity.2=-9.81 m/s2"},
       "give -9.81 for -9.81 m/s2 in the case's units",
       ""},
      {kSet, kBase, {"solver.dt=2.5e-3 furlongs"}, "numbers take no units (give the number", ""},
      {kSet,
       kBase,
       {"solver.dt=0,001"},
       "not a TOML value: a decimal point, not a comma (0.001)",
       ""},
      {kSet, kBase, {"boundary.fixed=[\"a\""}, "an array needs its closing ']'", ""},
      {kSet, kBase, {"solver.dt=1e-"}, "solver.dt: not a TOML value: the exponent after '1e'", ""},
      {kSet,
       kBase,
       {"materials.rope.E=0"},
       "--set materials.rope.E=0: materials.rope.E: must be > 0",
       ""},
      {kSet,
       kBase,
       {"sliding_groups.0.elements=2.5"},
       "--set sliding_groups.0.elements=2.5: sliding_groups[0].elements: expected an integer",
       ""},
      {kSet, kBase, {"name=../../etc"}, "--set name=../../etc: name: not a TOML value", ""},
      {kSet,
       kBase,
       {"name=\"../../etc\""},
       "--set name=\"../../etc\": name: must be a plain file name",
       ""},
  };
}

fs::path tempDir() {
  const fs::path d = fs::temp_directory_path() / "chute_test_bad_input";
  fs::create_directories(d);
  return d;
}

// The line number of the first occurrence of `needle` in `text` (1-based).
int lineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  if (at == std::string::npos) return -1;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

}  // namespace

TEST(BadInput, ValidBaseAndShippedCasesRead) {
  const fs::path f = tempDir() / "base.toml";
  std::ofstream(f) << kBase;
  const CaseSpec c = readCase(f.string());
  EXPECT_EQ(c.model.numNodes(), 7 + 2);  // 7 named + 2 interior chain nodes of the loop
  for (const auto& e : fs::directory_iterator(fs::path(CHUTE_SOURCE_DIR) / "cases"))
    if (e.path().extension() == ".toml") {
      EXPECT_NO_THROW(readCase(e.path().string())) << e.path();
    }
}

// --set replaces an array of values whole, read as the file's own array would be; a bare word
// is a string; a number keeps its exact spelling.
TEST(BadInput, SetTakesArraysAndBareWords) {
  const fs::path f = tempDir() / "base_set.toml";
  std::ofstream(f) << kBase;
  const CaseSpec c = readCase(f.string(), {"loads.gravity=[0.0, -3.5, 0]", "solver.dt=2.5e-3"});
  EXPECT_EQ(c.model.gravity, chute::Vec3(0.0, -3.5, 0.0));
  EXPECT_EQ(c.solver.dt, 2.5e-3);
  const CaseSpec one = readCase(f.string(), {"boundary.fixed=[\"a\"]"});
  int fixedNodes = 0;
  for (const auto& k : one.model.constraint) fixedNodes += k.fixed[0] && k.fixed[1] && k.fixed[2];
  EXPECT_EQ(fixedNodes, 1) << "boundary.fixed set to one node";
}

TEST(BadInput, EveryRowGivesOneClearLine) {
  const fs::path dir = tempDir();
  std::map<std::string, int> count, crashes;
  int n = 0;
  auto all = rows();
  for (auto& r : meshRows()) all.push_back(r);
  for (const Row& row : all) {
    ++n;
    const fs::path file = dir / "base.toml";
    std::ofstream(file, std::ios::binary) << row.text;
    std::string message;
    try {
      readCase(file.string(), row.sets);
      ADD_FAILURE() << "row " << n << " (" << row.kind << "): accepted; expected '" << row.fragment
                    << "'";
    } catch (const CaseError& e) {
      message = e.what();
    } catch (const std::exception& e) {
      ++crashes[row.kind];
      ADD_FAILURE() << "row " << n << ": not a CaseError: " << e.what();
    }
    ++count[row.kind];
    if (message.empty()) continue;
    SCOPED_TRACE("row " + std::to_string(n) + " (" + row.kind + "): " + message);
    EXPECT_EQ(message.find('\n'), std::string::npos) << "more than one line";
    EXPECT_NE(message.find(row.fragment), std::string::npos) << "expected '" << row.fragment << "'";
    if (!row.sets.empty()) {
      EXPECT_EQ(message.rfind("--set ", 0), 0u) << "a --set error names the --set";
    } else if (row.kind == kFile) {
      EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u);
    } else {
      const int line = row.lineOf.empty() ? row.line : lineOf(row.text, row.lineOf);
      ASSERT_GT(line, 0) << "test table: '" << row.lineOf << "' not in the text";
      EXPECT_EQ(message.rfind(file.string() + ":" + std::to_string(line) + ": ", 0), 0u)
          << "expected line " << line;
    }
  }
  // Files that cannot be read.
  for (const fs::path& bad : {dir / "no_such_case.toml", dir}) {
    ++n;
    ++count[kFile];
    try {
      readCase(bad.string());
      ADD_FAILURE() << bad << " accepted";
    } catch (const CaseError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind(bad.string() + ": cannot open", 0), 0u) << m;
    }
  }
  std::printf("\nbad inputs tried, per kind (readCase; every one a one-line CaseError):\n");
  int total = 0, totalCrashes = 0;
  for (const auto& [kind, k] : count) {
    std::printf("  %-52s %3d   crashes %d\n", kind.c_str(), k, crashes[kind]);
    total += k, totalCrashes += crashes[kind];
  }
  std::printf("  %-52s %3d   crashes %d\n", "total", total, totalCrashes);
  EXPECT_EQ(totalCrashes, 0);
}

// The real command line: exit status 2, one line on stderr, no output directory.
TEST(BadInput, ChuteRunExitsTwoAndWritesNothing) {
  const fs::path dir = tempDir() / "cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  struct Cli {
    std::string text, args, fragment;
  };
  const std::vector<Cli> cases = {
      {replaced("dt = 1.0e-3", "dt = "), "",
       "base.toml:" + std::to_string(lineOf(kBase, "dt = 1.0e-3")) + ": malformed TOML"},
      {replaced("[solver]", "[solvr]"), "", "did you mean 'solver'"},
      {replaced("nu = 0.3", "nu = 0.5"), "", "materials.film.nu: must be in [0, 0.5)"},
      {replaced("dt = 1.0e-3", "dt = nan"), "", "solver.dt: must be finite"},
      {replaced("elements = 3", "elements = 3\nactive = [0]"), "", "is not on element 0"},
      {kBase, "--set solvr.dt=1", "did you mean 'solver'"},
      {kBase, "--set solver.dt=x",
       "--set solver.dt=x: solver.dt: expected a number, found a string"},
      {"", "", "base.toml:1: nodes: the case has no nodes"},
  };
  int k = 0;
  for (const auto& c : cases) {
    const fs::path work = dir / std::to_string(k++);
    fs::create_directories(work);
    std::ofstream(work / "base.toml") << c.text;
    const std::string cmd = "cd " + work.string() + " && " + std::string(CHUTE_BINARY) +
                            " run base.toml --quiet " + c.args + " > stdout.txt 2> stderr.txt";
    const int status = std::system(cmd.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream err(work / "stderr.txt");
    std::stringstream ss;
    ss << err.rdbuf();
    const std::string text = ss.str();
    std::printf("  chute run %-22s -> exit %d, stderr: %s", c.args.c_str(), code, text.c_str());
    EXPECT_EQ(code, 2) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
    EXPECT_NE(text.find(c.fragment), std::string::npos) << text;
    EXPECT_FALSE(fs::exists(work / "out")) << "an output directory was created";
  }
  // Command lines CLI11 rejects: one line too, status 2.
  for (const std::string args : {"run", "run a.toml --checkpoint-every -3", "walk a.toml"}) {
    const std::string line =
        std::string(CHUTE_BINARY) + " " + args + " > /dev/null 2> " + (dir / "cli.err").string();
    const int rc = std::system(line.c_str());
    std::ifstream err(dir / "cli.err");
    std::stringstream ss;
    ss << err.rdbuf();
    const std::string text = ss.str();
    std::printf("  chute %-32s -> exit %d, stderr: %s", args.c_str(),
                WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, text.c_str());
    EXPECT_EQ(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, 2);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  }
  // A missing case file.
  const std::string cmd = std::string(CHUTE_BINARY) + " run " + (dir / "none.toml").string() +
                          " --out " + (dir / "none_out").string() + " 2> " +
                          (dir / "none.err").string();
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2);
  EXPECT_FALSE(fs::exists(dir / "none_out"));
}
